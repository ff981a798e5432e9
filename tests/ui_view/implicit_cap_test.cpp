// The implicit panel's mesh cache when the polygonizer stops at the mesh cap: the cap's message
// reaches the panel (View::error), nothing is drawn, and the next edit polygonizes again.
#include <gtest/gtest.h>

#include <thread>

#include "core/doc/document.hpp"
#include "core/geom/implicit/polygonize.hpp"
#include "ui/view/implicit_meshes.hpp"
#include "ui/view/implicit_support.hpp"

using namespace isoparm;
using namespace isoparm::ui;

namespace {

doc::Document rippled(std::uint64_t& id) {
    doc::Document d;
    doc::Object o;
    o.id = id = d.allocate_id();
    o.name = "ripples";
    doc::ImplicitObject f;
    f.expression = "sin(40*x)*sin(40*y)*sin(40*z)";
    f.lo = {-1, -1, -1};
    f.hi = {1, 1, 1};
    f.cell = 0.01; // 201^3 grid points: within the evaluation cap, the mesh is far above its cap
    o.shape = f;
    d.objects.push_back(o);
    return d;
}

// Polls the background job until it has an answer (no timing in the test).
ImplicitMeshes::View settle(ImplicitMeshes& cache, const doc::Document& d, std::uint64_t id) {
    ImplicitMeshes::Mode mode; // background, as in the window
    cache.update(d, mode);
    ImplicitMeshes::View v = cache.view(id);
    while (v.progress >= 0 || (v.error.empty() && !v.mesh)) {
        std::this_thread::yield();
        cache.update(d, mode);
        v = cache.view(id);
    }
    return v;
}

TEST(ImplicitMeshCap, TheCapMessageReachesThePanel) {
    std::uint64_t id = 0;
    doc::Document d = rippled(id);
    ImplicitMeshes cache;
    const ImplicitMeshes::View v = settle(cache, d, id);
    EXPECT_NE(v.error.find("more than " + std::to_string(geom::max_mesh_vertices) + " vertices"),
              std::string::npos)
        << v.error;
    EXPECT_NE(v.error.find("larger cell"), std::string::npos) << v.error;
    EXPECT_TRUE(v.mesh == nullptr || v.mesh->triangles.empty());

    // A coarser cell (the user's fix) polygonizes again and clears the message.
    std::get<doc::ImplicitObject>(d.objects[0].shape).cell = 0.05;
    const ImplicitMeshes::View again = settle(cache, d, id);
    EXPECT_TRUE(again.error.empty()) << again.error;
    ASSERT_NE(again.mesh, nullptr);
    EXPECT_FALSE(again.mesh->triangles.empty());
}

} // namespace
