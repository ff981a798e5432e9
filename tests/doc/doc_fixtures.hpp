// Documents and checks shared by the document tests.
#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "core/doc/command.hpp"
#include "core/doc/command_spec.hpp"
#include "core/doc/commands.hpp"
#include "core/doc/commands_triangle.hpp"
#include "core/doc/document.hpp"
#include "core/doc/patches.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::doc::testing {

// A small NURBS curve in the xy-plane on clamped knots with one interior double knot.
inline geom::Curve sample_curve() {
    geom::Curve c;
    c.type = geom::SplineType::nurbs;
    c.degree = 3;
    c.knots = {0, 0, 0, 0, 0.25, 0.5, 0.5, 1, 1, 1, 1};
    c.points = {{0, 0, 0}, {1, 2, 0}, {2, 2.5, 0}, {3, 1, 0}, {4, -1, 0}, {5, 0.5, 0}, {6, 0, 0}};
    c.weights = {1, 0.5, 2, 1, -0.25, 1, 1};
    return c;
}

// A rational cubic triangle, lifted in the middle, with one heavy and one negative weight.
inline geom::TrianglePatch sample_triangle() {
    geom::TrianglePatch t = make_flat_triangle(3, true).value();
    t.points[geom::TrianglePatch::index(3, 1, 1)].z = 1.5;
    t.weights[geom::TrianglePatch::index(3, 1, 1)] = 2;
    t.weights[geom::TrianglePatch::index(3, 2, 0)] = -0.5;
    return t;
}

// The default scene plus a curve, a B-spline grid, a Bezier patch and an implicit sphere:
// every tensor-product type tag (with_triangle below adds the triangular patch).
inline Document sample_document() {
    Document doc = default_document();
    Object curve;
    curve.id = doc.allocate_id();
    curve.name = "profile";
    curve.shape = CurveObject{sample_curve(), CurvePlane::xy};
    doc.objects.push_back(curve);

    Object grid;
    grid.id = doc.allocate_id();
    grid.name = "grid";
    geom::Surface g = make_planar_grid(4, 5, 2, 3, geom::SplineType::bspline);
    g.point(1, 2).z = 0.75;
    grid.shape = SurfaceObject{g};
    doc.objects.push_back(grid);

    Object patch;
    patch.id = doc.allocate_id();
    patch.name = "patch";
    patch.visible = false;
    geom::Surface b = make_planar_grid(3, 4, 2, 3, geom::SplineType::bezier);
    b.point(1, 1).z = -0.5;
    patch.shape = SurfaceObject{b};
    doc.objects.push_back(patch);

    Object sphere;
    sphere.id = doc.allocate_id();
    sphere.name = "ball";
    ImplicitObject f;
    f.expression = "x^2 + y^2 + z^2 - r^2";
    f.parameter_names = {"r"};
    f.parameter_values = {0.8};
    f.lo = {-1, -1, -1.5};
    f.hi = {1, 1, 1.5};
    f.cell = 0.1;
    sphere.shape = f;
    doc.objects.push_back(sphere);
    return doc;
}

// sample_document() and a triangular patch "tri" (tri_id): every kind of object.
inline Document sample_document_with_triangle() {
    Document doc = sample_document();
    Object tri;
    tri.id = doc.allocate_id();
    tri.name = "tri";
    tri.shape = TriangleObject{sample_triangle()};
    doc.objects.push_back(tri);
    return doc;
}

// Ids in sample_document() (tri_id: sample_document_with_triangle()).
constexpr std::uint64_t hill_id = 1, curve_id = 2, grid_id = 3, patch_id = 4, ball_id = 5,
                        tri_id = 6;

inline const geom::Surface& surface_of(const Document& doc, std::uint64_t id) {
    return std::get<SurfaceObject>(doc.find(id)->shape).surface;
}
inline const geom::Curve& curve_of(const Document& doc, std::uint64_t id) {
    return std::get<CurveObject>(doc.find(id)->shape).curve;
}

// The command as data gives the same command: its spec, built and applied to `before`, gives
// `after` (a script replays exactly what was done; that the spec survives its JSON form is
// tests/scene/command_json_test.cpp's, for every command).
inline void expect_replays_as_data(const Command& applied, const Document& before,
                                   const Document& after) {
    const std::optional<CommandSpec> spec = applied.spec();
    ASSERT_TRUE(spec.has_value());
    Document replay = before;
    const auto st = make_command(*spec)->apply(replay);
    ASSERT_TRUE(st.ok()) << command_name(*spec) << ": " << st.error().message;
    EXPECT_TRUE(same_document(replay, after)) << command_name(*spec);
}

// Executes cmd through a history and checks that check() agreed beforehand, that undo gives
// the state before, bit for bit, redo the state after, and undo again the state before, and
// that the command replays from its spec. Returns the state after.
inline Document expect_undo_redo_exact(Document& doc, std::unique_ptr<Command> cmd) {
    History history;
    const Document before = doc;
    const auto checked = cmd->check(doc);
    EXPECT_TRUE(checked.ok()) << (checked.ok() ? "" : checked.error().message);
    EXPECT_TRUE(same_document(doc, before)) << "check() changed the document";
    const Command* applied = cmd.get();
    const auto st = history.execute(doc, std::move(cmd));
    EXPECT_TRUE(st.ok()) << (st.ok() ? "" : st.error().message);
    const Document after = doc;
    expect_replays_as_data(*applied, before, after);
    EXPECT_FALSE(same_geometry(before, after)) << "the command changed nothing";
    EXPECT_TRUE(history.undo(doc));
    EXPECT_TRUE(same_document(doc, before));
    EXPECT_EQ(doc.next_id, before.next_id);
    EXPECT_TRUE(history.redo(doc));
    EXPECT_TRUE(same_document(doc, after));
    EXPECT_EQ(doc.next_id, after.next_id);
    EXPECT_TRUE(history.undo(doc));
    EXPECT_TRUE(same_document(doc, before));
    EXPECT_TRUE(history.redo(doc));
    return after;
}

// Executes cmd, expects a refusal with this code and path, and an untouched document and
// history; check() gives the same refusal beforehand.
inline void expect_refused(Document& doc, std::unique_ptr<Command> cmd, geom::ErrorCode code,
                           const std::string& path) {
    History history;
    const Document before = doc;
    const auto checked = cmd->check(doc);
    ASSERT_FALSE(checked.ok()) << "check() accepts what apply refuses";
    EXPECT_EQ(geom::name_of(checked.error().code), std::string(geom::name_of(code)));
    EXPECT_EQ(checked.error().path, path) << checked.error().message;
    EXPECT_TRUE(same_document(doc, before)) << "check() changed the document";
    const auto st = history.execute(doc, std::move(cmd));
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(geom::name_of(st.error().code), std::string(geom::name_of(code)))
        << st.error().message;
    EXPECT_EQ(st.error().path, path) << st.error().message;
    EXPECT_FALSE(st.error().message.empty());
    EXPECT_TRUE(same_document(doc, before));
    EXPECT_EQ(doc.next_id, before.next_id);
    EXPECT_FALSE(history.can_undo());
}

// Splits through the history; the pieces' ids.
inline std::pair<std::uint64_t, std::uint64_t> split(Document& doc, History& h, std::uint64_t id,
                                                     geom::Dir dir, double t) {
    auto cmd = split_object(id, dir, t);
    const Command* raw = cmd.get();
    EXPECT_TRUE(h.execute(doc, std::move(cmd)));
    return split_piece_ids(*raw);
}

// The paper's example on the default hill: split at u = 0.75, then the left part at v = 0.5.
struct PaperSplit {
    Document doc = default_document();
    History history;
    std::uint64_t left = 0, right = 0, left_low = 0, left_high = 0;

    PaperSplit() {
        const std::uint64_t hill = doc.objects[0].id;
        std::tie(left, right) = split(doc, history, hill, geom::Dir::u, 0.75);
        std::tie(left_low, left_high) = split(doc, history, left, geom::Dir::v, 0.5);
    }
    const geom::Surface& surface(std::uint64_t id) const {
        return std::get<SurfaceObject>(doc.find(id)->shape).surface;
    }
};

} // namespace isoparm::doc::testing
