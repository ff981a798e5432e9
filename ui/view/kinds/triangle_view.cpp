// The triangle kind's view: its mesh (triangle_meshes.hpp owns the cache), triangular net and
// points in the 3D view; the net's lines i, j, k = const as its control net.
#include "ui/view/kinds/kind_view.hpp"
#include "ui/view/scene_builder.hpp"
#include "ui/view/triangle_meshes.hpp"
#include "ui/view/triangle_scene.hpp"

namespace isoparm::ui {

void draw_kind(const doc::TriangleObject& object, const ObjectLook& look, SceneBatches& out) {
    const geom::TrianglePatch& t = object.patch;
    const TriangleMeshes::View v =
        look.triangle_meshes ? look.triangle_meshes->view(look.id) : TriangleMeshes::View{};
    if (v.mesh) {
        SurfaceDraw sd = patch_draw(look);
        sd.mesh = v.mesh;
        sd.mesh_revision = v.revision;
        out.surfaces.push_back(sd);
    }
    if (look.own.control_net) add_triangle_net(out.net, t, to_vec4(look.colors->control_net));
    if (look.own.control_points)
        for (int i = 0; i <= t.degree; ++i)
            for (int j = 0; i + j <= t.degree; ++j)
                add_control_point(
                    look, i, j,
                    t.points[static_cast<std::size_t>(geom::TrianglePatch::index(t.degree, i, j))],
                    out.points);
}

ControlNet kind_net(const doc::TriangleObject& object) {
    const geom::TrianglePatch& t = object.patch;
    ControlNet net;
    const int n = t.degree;
    // In the patch's own order: point (i, j) is at TrianglePatch::index(n, i, j).
    net.points = t.points;
    net.ids.resize(t.points.size());
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j)
            net.ids[static_cast<std::size_t>(geom::TrianglePatch::index(n, i, j))] = {i, j};
    auto at = [n](int i, int j) { return geom::TrianglePatch::index(n, i, j); };
    for (int c = 0; c < n; ++c) { // a line of c + 1 .. n + 1 points: c = 0 is an edge
        std::vector<int>& i_const = net.lines.emplace_back();
        for (int j = 0; j <= n - c; ++j) i_const.push_back(at(c, j));
        std::vector<int>& j_const = net.lines.emplace_back();
        for (int i = 0; i <= n - c; ++i) j_const.push_back(at(i, c));
        std::vector<int>& k_const = net.lines.emplace_back();
        for (int i = 0; i <= n - c; ++i) k_const.push_back(at(i, n - c - i));
    }
    return net;
}

KindTraits kind_traits(const doc::TriangleObject&) {
    return {ObjectEditor::control_points, true, geom::name_of(doc::ObjectKind::triangle)};
}

} // namespace isoparm::ui
