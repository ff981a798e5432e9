// The implicit-surface editor's logic: parameter detection, presets, the mesh cache key and
// coarse-cell rule, the merging edit command and the mesh cache (no GL needed).
#include <gtest/gtest.h>

#include <thread>

#include "core/doc/command.hpp"
#include "core/doc/commands.hpp"
#include "core/geom/implicit/expression.hpp"
#include "core/geom/implicit/polygonize.hpp"
#include "ui/view/implicit_meshes.hpp"
#include "ui/view/implicit_support.hpp"
#include "ui/view/scene_builder.hpp"

using namespace isoparm;
using namespace isoparm::ui;

using Names = std::vector<std::string>;

TEST(ImplicitParameters, DetectedInOrderWithoutVariablesFunctionsOrExponents) {
    EXPECT_EQ(detect_parameters("x^2 + a*y - sin(b*z) + 1e-3*c + a - exp(x) + 2.5E+2*d_2"),
              (Names{"a", "b", "c", "d_2"}));
    EXPECT_EQ(detect_parameters("x + y + z - sqrt(abs(log(tan(cos(x)))))"), Names{});
    EXPECT_EQ(detect_parameters("(x^2 + R^2 - r^2)"), (Names{"R", "r"}));
    EXPECT_EQ(detect_parameters(".5e2*xy"), Names{"xy"}); // a name that starts with x
}

TEST(ImplicitParameters, NewExpressionKeepsValuesOfNamesThatStay) {
    doc::ImplicitObject o;
    o.expression = "x^2 + y^2 + z^2 - a - b";
    o.parameter_names = {"a", "b"};
    o.parameter_values = {0.25, 3.0};
    const doc::ImplicitObject n = with_expression(o, "c*x + b*y + z");
    EXPECT_EQ(n.expression, "c*x + b*y + z");
    EXPECT_EQ(n.parameter_names, (Names{"c", "b"}));
    EXPECT_EQ(n.parameter_values, (std::vector<double>{1.0, 3.0}));
}

TEST(ImplicitCache, KeyChangesWithEveryInput) {
    const doc::ImplicitObject base = implicit_presets()[1].object; // torus
    const ImplicitKey k = implicit_key(base, base.cell);
    EXPECT_EQ(k, implicit_key(base, base.cell));
    EXPECT_NE(k, implicit_key(base, base.cell * 2));
    doc::ImplicitObject o = base;
    o.expression += " + 0";
    EXPECT_NE(k, implicit_key(o, o.cell));
    o = base;
    o.parameter_values[1] = 0.41;
    EXPECT_NE(k, implicit_key(o, o.cell));
    o = base;
    o.lo.z = -0.7;
    EXPECT_NE(k, implicit_key(o, o.cell));
    o = base;
    o.hi.x = 1.6;
    EXPECT_NE(k, implicit_key(o, o.cell));
}

TEST(ImplicitCache, CoarseCellRule) {
    const glm::dvec3 lo(-1), hi(1, 1, 0.5);               // longest extent 2
    EXPECT_DOUBLE_EQ(coarse_cell(lo, hi, 0.05), 0.05);    // 40 cells: already coarse
    EXPECT_DOUBLE_EQ(coarse_cell(lo, hi, 0.03), 0.06);    // 67 cells: twice the cell
    EXPECT_DOUBLE_EQ(coarse_cell(lo, hi, 0.01), 2 / 48.); // 200 cells: capped at 48
    EXPECT_LE(2 / coarse_cell(lo, hi, 0.001), coarse_cells_per_axis + 1e-9);
}

TEST(ImplicitPresets, AllCompileAndPolygonizeInTheirBounds) {
    const auto& presets = implicit_presets();
    ASSERT_EQ(presets.size(), 6u);
    for (const ImplicitPreset& p : presets) {
        SCOPED_TRACE(p.name);
        const doc::ImplicitObject& o = p.object;
        EXPECT_EQ(detect_parameters(o.expression), o.parameter_names);
        ASSERT_EQ(o.parameter_names.size(), o.parameter_values.size());
        const auto program = geom::implicit::compile(o.expression, o.parameter_names);
        ASSERT_TRUE(program) << program.error().message;
        geom::implicit::PolygonizeOptions opt;
        opt.lo = o.lo;
        opt.hi = o.hi;
        opt.cell = o.cell;
        opt.parameters = o.parameter_values;
        const auto mesh = geom::implicit::polygonize(*program, opt);
        ASSERT_TRUE(mesh) << mesh.error().message;
        EXPECT_GT(mesh->triangles.size(), 1000u);
        for (const glm::dvec3& v : mesh->positions)
            for (int a = 0; a < 3; ++a) {
                EXPECT_GE(v[a], o.lo[a] - 1e-9);
                EXPECT_LE(v[a], o.hi[a] + 1e-9);
            }
    }
}

namespace {

doc::Document one_implicit(std::uint64_t& id) {
    doc::Document d;
    doc::Object o;
    o.id = id = d.allocate_id();
    o.name = "f";
    o.shape = implicit_presets()[0].object; // sphere, r = 1
    d.objects.push_back(o);
    return d;
}

} // namespace

TEST(ImplicitEdit, DragMergesIntoOneUndoStepAndUndoRestores) {
    std::uint64_t id = 0;
    doc::Document d = one_implicit(id);
    const doc::Document before = d;
    doc::History h;
    for (double r : {1.1, 1.2, 1.3}) {
        doc::ImplicitObject next = std::get<doc::ImplicitObject>(d.objects[0].shape);
        next.parameter_values[0] = r;
        ASSERT_TRUE(h.execute(d, doc::edit_shape(id, next, "Edit implicit parameter r",
                                                 "Edit implicit parameter r")));
    }
    h.seal();
    EXPECT_EQ(h.size(), 1u);
    EXPECT_EQ(std::get<doc::ImplicitObject>(d.objects[0].shape).parameter_values[0], 1.3);
    const doc::Document after = d;
    ASSERT_TRUE(h.undo(d));
    EXPECT_TRUE(doc::same_geometry(d, before));
    ASSERT_TRUE(h.redo(d));
    EXPECT_TRUE(doc::same_geometry(d, after));
    // Another label is another step.
    doc::ImplicitObject next = std::get<doc::ImplicitObject>(d.objects[0].shape);
    next.cell = 0.1;
    ASSERT_TRUE(
        h.execute(d, doc::edit_shape(id, next, "Edit implicit cell", "Edit implicit cell")));
    EXPECT_EQ(h.size(), 2u);
}

TEST(ImplicitEdit, RefusesWithoutChangingTheDocument) {
    std::uint64_t id = 0;
    doc::Document d = one_implicit(id);
    const doc::Document before = d;
    doc::History h;
    doc::ImplicitObject bad = std::get<doc::ImplicitObject>(d.objects[0].shape);
    bad.lo.x = 5; // min >= max
    EXPECT_FALSE(
        h.execute(d, doc::edit_shape(id, bad, "Edit implicit bounds", "Edit implicit bounds")));
    EXPECT_FALSE(
        h.execute(d, doc::edit_shape(id + 7, bad, "Edit implicit bounds", "Edit implicit bounds")));
    EXPECT_TRUE(doc::same_geometry(d, before));
    EXPECT_EQ(h.size(), 0u);
}

TEST(ImplicitMeshes, CachedPerKeyAndCoarseWhileDragging) {
    std::uint64_t id = 0;
    doc::Document d = one_implicit(id);
    auto& f = std::get<doc::ImplicitObject>(d.objects[0].shape);
    f.cell = 0.02; // 125 cells per axis: the drag preview is coarser
    ImplicitMeshes cache;
    ImplicitMeshes::Mode wait;
    wait.wait = true;
    cache.update(d, wait);
    EXPECT_EQ(cache.synchronous_runs(), 1);
    ImplicitMeshes::View v = cache.view(id);
    ASSERT_NE(v.mesh, nullptr);
    EXPECT_FALSE(v.mesh->triangles.empty());
    EXPECT_EQ(v.cell, 0.02);
    EXPECT_TRUE(v.error.empty());
    const std::uint64_t full_revision = v.revision;

    cache.update(d, wait); // unchanged: nothing to do
    EXPECT_EQ(cache.synchronous_runs(), 1);
    EXPECT_EQ(cache.view(id).revision, full_revision);

    ImplicitMeshes::Mode drag = wait;
    drag.coarse_id = id;
    f.parameter_values[0] = 0.9;
    cache.update(d, drag);
    v = cache.view(id);
    EXPECT_EQ(v.cell, coarse_cell(f.lo, f.hi, f.cell));
    EXPECT_NE(v.revision, full_revision);

    cache.update(d, wait); // released: the full cell again
    EXPECT_EQ(cache.view(id).cell, 0.02);

    d.objects.clear(); // removed objects are dropped
    cache.update(d, wait);
    EXPECT_EQ(cache.view(id).mesh, nullptr);
}

TEST(ImplicitMeshes, FineGridFinishesInTheBackground) {
    std::uint64_t id = 0;
    doc::Document d = one_implicit(id);
    std::get<doc::ImplicitObject>(d.objects[0].shape).cell = 0.02; // > 48^3 cells
    ImplicitMeshes cache;
    ImplicitMeshes::Mode mode; // not waiting
    cache.update(d, mode);
    EXPECT_EQ(cache.synchronous_runs(), 0);
    ImplicitMeshes::View v = cache.view(id);
    while (!v.mesh) { // no timing: poll until the worker's mesh is adopted
        std::this_thread::yield();
        cache.update(d, mode);
        v = cache.view(id);
    }
    EXPECT_EQ(v.cell, 0.02);
    EXPECT_LT(v.progress, 0);
    EXPECT_FALSE(v.mesh->triangles.empty());
    EXPECT_EQ(cache.synchronous_runs(), 0);
}

// The 3D view's level (implicit_screen_level.hpp): an object drawn coarser is polygonized at
// that grid only, unless it is the one whose own mesh the panel needs; going back to level 0
// makes the own mesh, and the coarse one is kept for the next time.
TEST(ImplicitMeshes, DrawnAtTheViewsLevelOwnMeshOnlyWhereNeeded) {
    std::uint64_t panel_id = 0;
    doc::Document d = one_implicit(panel_id);
    doc::Object other = d.objects[0];
    other.id = d.allocate_id();
    d.objects.push_back(other);
    const double cell = std::get<doc::ImplicitObject>(d.objects[0].shape).cell;
    ImplicitMeshes cache;
    ImplicitMeshes::Mode far;
    far.wait = true;
    far.screen_level = [](const doc::ImplicitObject&) { return 1; };
    far.own_mesh_id = panel_id;
    cache.update(d, far);
    EXPECT_EQ(cache.synchronous_runs(), 3); // two at 2 x cell, the panel's own one
    ASSERT_NE(cache.view(panel_id).mesh, nullptr);
    EXPECT_EQ(cache.view(panel_id).cell, cell);
    EXPECT_EQ(cache.view(other.id).mesh, nullptr); // never made
    for (std::uint64_t id : {panel_id, other.id}) {
        const ImplicitMeshes::View v = cache.drawn(id);
        ASSERT_NE(v.mesh, nullptr);
        EXPECT_EQ(v.cell, 2 * cell);
        EXPECT_EQ(v.seen_side, 1);
    }
    // Half the cell across, a quarter of the triangles or so.
    const double ratio = static_cast<double>(cache.drawn(other.id).mesh->triangles.size()) /
                         static_cast<double>(cache.view(panel_id).mesh->triangles.size());
    EXPECT_GT(ratio, 0.2);
    EXPECT_LT(ratio, 0.3);

    ImplicitMeshes::Mode near = far;
    near.screen_level = [](const doc::ImplicitObject&) { return 0; };
    cache.update(d, near);
    EXPECT_EQ(cache.synchronous_runs(), 4); // the other one's own mesh
    EXPECT_EQ(cache.drawn(other.id).cell, cell);
    EXPECT_EQ(cache.drawn(other.id).mesh, cache.view(other.id).mesh);

    cache.update(d, far); // farther again: the coarse mesh is still there
    EXPECT_EQ(cache.synchronous_runs(), 4);
    EXPECT_EQ(cache.drawn(other.id).cell, 2 * cell);

    ImplicitMeshes::Mode beyond = far; // levels past the last are the last
    beyond.screen_level = [](const doc::ImplicitObject&) { return 9; };
    cache.update(d, beyond);
    EXPECT_EQ(cache.drawn(other.id).cell, 4 * cell);
}

// Gesture frames draw a coarse mesh made once, at the first of them, and kept while the object
// stays as it is, whatever the view's level does meanwhile; twice the view's cell when that is
// coarser than the usual 2.5 cells.
TEST(ImplicitMeshes, TheGestureMeshIsMadeOnceAndCoarserThanTheView) {
    std::uint64_t id = 0;
    doc::Document d = one_implicit(id);
    auto& f = std::get<doc::ImplicitObject>(d.objects[0].shape);
    ASSERT_EQ(f.cell, 0.05); // the sphere preset: 50 cells across
    ImplicitMeshes cache;
    ImplicitMeshes::Mode orbit;
    orbit.wait = true;
    orbit.gesture = true;
    orbit.screen_level = [](const doc::ImplicitObject&) { return 0; };
    cache.update(d, orbit);
    EXPECT_EQ(cache.synchronous_runs(), 2); // the own mesh and the gesture one
    EXPECT_EQ(cache.drawn(id).cell, 2.5 * 0.05);
    EXPECT_EQ(cache.view(id).cell, 0.05); // the panel's is the own mesh
    cache.end_gesture_frame();
    EXPECT_EQ(cache.drawn(id).cell, 0.05);

    orbit.screen_level = [](const doc::ImplicitObject&) { return 1; };
    cache.update(d, orbit); // the view's level changed: only its mesh is new
    EXPECT_EQ(cache.synchronous_runs(), 3);
    EXPECT_EQ(cache.drawn(id).cell, 2.5 * 0.05);

    f.parameter_values[0] = 0.9; // the object changed: a new gesture mesh, twice the view's cell
    cache.update(d, orbit);
    EXPECT_EQ(cache.drawn(id).cell, 4 * 0.05);
    cache.end_gesture_frame();
    EXPECT_EQ(cache.drawn(id).cell, 2 * 0.05);
}

// While the level's mesh is made in the background, the view draws the object's mesh of the
// other level (the same surface, another grid) rather than nothing.
TEST(ImplicitMeshes, TheOtherLevelIsDrawnWhileTheLevelsMeshIsMade) {
    std::uint64_t id = 0;
    doc::Document d = one_implicit(id);
    std::get<doc::ImplicitObject>(d.objects[0].shape).cell = 0.02; // > 48^3 cells
    ImplicitMeshes cache;
    ImplicitMeshes::Mode far;
    far.screen_level = [](const doc::ImplicitObject&) { return 1; }; // 0.04: 63^3 cells
    ImplicitMeshes::View v;
    while (!v.mesh || v.progress >= 0) { // no timing: poll until the worker's mesh is adopted
        std::this_thread::yield();
        cache.update(d, far);
        v = cache.drawn(id);
    }
    EXPECT_EQ(v.cell, 0.04);
    ImplicitMeshes::Mode near; // level 0, the own mesh: made in the background
    cache.update(d, near);
    v = cache.drawn(id);
    ASSERT_NE(v.mesh, nullptr);
    if (cache.view(id).mesh == nullptr) {
        EXPECT_EQ(v.cell, 0.04); // not made yet: the coarse one
    }
    while (v.cell != 0.02) {
        std::this_thread::yield();
        cache.update(d, near);
        v = cache.drawn(id);
        ASSERT_NE(v.mesh, nullptr);
    }
    EXPECT_EQ(cache.synchronous_runs(), 0);
}

TEST(ImplicitScene, ImplicitObjectsBecomeMeshDrawsWithTheirBox) {
    std::uint64_t id = 0;
    doc::Document d = one_implicit(id);
    d.view.selection.object = id;
    EXPECT_TRUE(build_scene(d, {}).surfaces.empty()); // no cache: not drawn
    ImplicitMeshes cache;
    ImplicitMeshes::Mode wait;
    wait.wait = true;
    cache.update(d, wait);
    const BuiltScene s = build_scene(d, {}, &cache);
    ASSERT_EQ(s.surfaces.size(), 1u);
    EXPECT_EQ(s.surfaces[0].mesh, cache.view(id).mesh);
    EXPECT_EQ(s.surfaces[0].surface, nullptr);
    std::size_t lines = 0;
    for (const auto& b : s.overlay.lines) lines += b.vertices.size();
    EXPECT_EQ(lines, 24u); // the selected object's bounds: 12 edges
    // The unit sphere inside its bounds is closed, seen from f > 0 outside its box.
    const auto& f = std::get<doc::ImplicitObject>(d.objects[0].shape);
    EXPECT_EQ(s.surfaces[0].seen_side, 1);
    EXPECT_EQ(s.surfaces[0].box_lo, f.lo);
    EXPECT_EQ(s.surfaces[0].box_hi, f.hi);
}

// While a new mesh is made in the background, the view keeps the shown mesh's side and box,
// not the object's new bounds: culling decides by the box the shown mesh was made in.
TEST(ImplicitScene, TheCullingBoxIsTheShownMeshs) {
    std::uint64_t id = 0;
    doc::Document d = one_implicit(id);
    ImplicitMeshes cache;
    ImplicitMeshes::Mode wait;
    wait.wait = true;
    cache.update(d, wait);
    auto& f = std::get<doc::ImplicitObject>(d.objects[0].shape);
    const glm::dvec3 lo = f.lo, hi = f.hi;
    f.lo.x = -0.5; // cuts the sphere: open
    f.cell = 0.02; // a fine grid: made in the background
    cache.update(d, ImplicitMeshes::Mode{});
    ImplicitMeshes::View v = cache.view(id);
    ASSERT_NE(v.mesh, nullptr);
    if (v.lo == lo) { // the new mesh may already be there on a fast machine
        EXPECT_EQ(v.seen_side, 1);
        EXPECT_EQ(v.hi, hi);
        const BuiltScene s = build_scene(d, {}, &cache);
        ASSERT_EQ(s.surfaces.size(), 1u);
        EXPECT_EQ(s.surfaces[0].box_lo, lo); // not f.lo
    }
    while (v.lo == lo) { // no timing: poll until the worker's mesh is adopted
        std::this_thread::yield();
        cache.update(d, ImplicitMeshes::Mode{});
        v = cache.view(id);
    }
    EXPECT_EQ(v.lo, f.lo);
    EXPECT_EQ(v.seen_side, 0);
}
