// The curve designer's commands, primitives, knot modes in scenes, and Construct menu builds.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/doc/commands_curve.hpp"
#include "core/doc/curve_constructions.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/interpolate.hpp"
#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::doc::testing;
using geom::ErrorCode;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// sample_document() plus a designed curve (id 6): five points in the xy-plane, degree 3,
// clamped uniform knots.
constexpr std::uint64_t designed_id = 6;
Document designer_document(CurveKnotMode mode = CurveKnotMode::clamped_uniform) {
    Document doc = sample_document();
    auto o = new_curve_object("wave", CurvePlane::xy,
                              {{0, 0, 0}, {1, 1, 0}, {2, -1, 0}, {3, 2, 0}, {4, 0, 0}}, 3, mode);
    EXPECT_TRUE(o.ok());
    o->id = doc.allocate_id();
    doc.objects.push_back(*o);
    EXPECT_EQ(o->id, designed_id);
    return doc;
}

const CurveObject& curve_object_of(const Document& doc, std::uint64_t id) {
    return std::get<CurveObject>(doc.find(id)->shape);
}

geom::Knots mode_knots(const geom::Curve& c, geom::KnotMode mode) {
    auto k = geom::knots_for_points(c.points, c.degree, mode);
    EXPECT_TRUE(k.ok());
    return k.ok() ? *k : geom::Knots{};
}

TEST(NewCurveObject, KnotsFromTheMode) {
    auto a = new_curve_object("a", CurvePlane::xz, {{0, 0, 0}, {1, 0, 0}, {3, 0, 1}}, 2,
                              CurveKnotMode::chord);
    ASSERT_TRUE(a.ok());
    const auto& c = std::get<CurveObject>(a->shape);
    EXPECT_EQ(c.plane, CurvePlane::xz);
    EXPECT_EQ(c.knot_mode, CurveKnotMode::chord);
    EXPECT_EQ(c.curve.knots, mode_knots(c.curve, geom::KnotMode::chord));
    EXPECT_EQ(c.curve.weights, std::vector<double>(3, 1.0));
}

TEST(NewCurveObject, Refusals) {
    auto one = new_curve_object("a", CurvePlane::xy, {{0, 0, 0}}, 1, CurveKnotMode::chord);
    ASSERT_FALSE(one.ok());
    EXPECT_EQ(one.error().path, "/points");
    auto high = new_curve_object("a", CurvePlane::xy, {{0, 0, 0}, {1, 0, 0}}, 2,
                                 CurveKnotMode::clamped_uniform);
    ASSERT_FALSE(high.ok());
    EXPECT_EQ(high.error().code, ErrorCode::degree);
    EXPECT_NE(high.error().message.find("got 2"), std::string::npos);
    auto custom =
        new_curve_object("a", CurvePlane::xy, {{0, 0, 0}, {1, 0, 0}}, 1, CurveKnotMode::custom);
    ASSERT_FALSE(custom.ok());
    EXPECT_EQ(custom.error().path, "/knot_mode");
    auto twice = new_curve_object("a", CurvePlane::xy, {{0, 0, 0}, {0, 0, 0}}, 1,
                                  CurveKnotMode::centripetal);
    ASSERT_FALSE(twice.ok());
    EXPECT_EQ(twice.error().code, ErrorCode::geometry);
}

TEST(InsertCurvePoint, RecomputesKnotsSelectsItAndUndoesExactly) {
    Document doc = designer_document();
    doc.view.selection = {designed_id, 4, -1};
    const Document after =
        expect_undo_redo_exact(doc, insert_curve_point(designed_id, 2, {1.5, 3, 0}));
    const geom::Curve& c = curve_of(after, designed_id);
    ASSERT_EQ(c.count(), 6);
    EXPECT_EQ(c.points[2], glm::dvec3(1.5, 3, 0));
    EXPECT_EQ(c.weights[2], 1.0);
    EXPECT_EQ(c.knots, geom::clamped_uniform_knots(6, 3));
    EXPECT_EQ(after.view.selection, (Selection{designed_id, 2, -1}));
    // Appending: index = count.
    const Document appended =
        expect_undo_redo_exact(doc, insert_curve_point(designed_id, 6, {9, 9, 0}));
    EXPECT_EQ(curve_of(appended, designed_id).points.back(), glm::dvec3(9, 9, 0));
}

TEST(InsertCurvePoint, ChordModeKnotsFollowThePolygon) {
    Document doc = designer_document(CurveKnotMode::chord);
    const Document after =
        expect_undo_redo_exact(doc, insert_curve_point(designed_id, 0, {-2, 0, 0}));
    const geom::Curve& c = curve_of(after, designed_id);
    EXPECT_EQ(c.knots, mode_knots(c, geom::KnotMode::chord));
}

TEST(InsertCurvePoint, BezierRaisesItsDegree) {
    Document doc = sample_document();
    Object b;
    b.name = "bez";
    geom::Curve c;
    c.type = geom::SplineType::rational_bezier;
    c.degree = 2;
    c.knots = geom::bezier_knots(2);
    c.points = {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}};
    c.weights = {1, 2, 1};
    b.shape = CurveObject{c, CurvePlane::xy}; // custom knots: the Bezier rule still applies
    ASSERT_TRUE(History().execute(doc, add_object(b)).ok());
    const std::uint64_t id = doc.objects.back().id;
    const Document after = expect_undo_redo_exact(doc, insert_curve_point(id, 3, {3, 1, 0}));
    EXPECT_EQ(curve_of(after, id).degree, 3);
    EXPECT_EQ(curve_of(after, id).knots, geom::bezier_knots(3));
    // doc holds the four-point cubic now: deleting a point lowers the degree to 2.
    const Document deleted = expect_undo_redo_exact(doc, delete_curve_point(id, 0));
    EXPECT_EQ(curve_of(deleted, id).degree, 2);
    EXPECT_EQ(curve_of(deleted, id).points[0], glm::dvec3(1, 1, 0));
}

TEST(InsertCurvePoint, Refusals) {
    Document doc = designer_document();
    expect_refused(doc, insert_curve_point(designed_id, -1, {0, 0, 0}), ErrorCode::schema, "/i");
    expect_refused(doc, insert_curve_point(designed_id, 6, {0, 0, 0}), ErrorCode::schema, "/i");
    expect_refused(doc, insert_curve_point(designed_id, 1, {0, inf, 0}), ErrorCode::schema,
                   "/position/1");
    expect_refused(doc, insert_curve_point(hill_id, 0, {0, 0, 0}), ErrorCode::schema, "/id");
    expect_refused(doc, insert_curve_point(99, 0, {0, 0, 0}), ErrorCode::schema, "/id");
    // The sample curve has custom knots.
    expect_refused(doc, insert_curve_point(curve_id, 0, {0, 0, 0}), ErrorCode::knots, "/knot_mode");
    Document chord = designer_document(CurveKnotMode::chord);
    expect_refused(chord, insert_curve_point(designed_id, 1, {0, 0, 0}), ErrorCode::geometry,
                   "/position");
}

TEST(DeleteCurvePoint, RecomputesKnotsAndKeepsTheSelectionNear) {
    Document doc = designer_document(CurveKnotMode::centripetal);
    doc.view.selection = {designed_id, 3, -1};
    const Document after = expect_undo_redo_exact(doc, delete_curve_point(designed_id, 1));
    const geom::Curve& c = curve_of(after, designed_id);
    ASSERT_EQ(c.count(), 4);
    EXPECT_EQ(c.points[1], glm::dvec3(2, -1, 0));
    EXPECT_EQ(c.knots, mode_knots(c, geom::KnotMode::centripetal));
    EXPECT_EQ(after.view.selection.i, 2); // P3 is now P2
    Document fresh = designer_document(CurveKnotMode::centripetal);
    fresh.view.selection = {designed_id, 4, -1};
    const Document last = expect_undo_redo_exact(fresh, delete_curve_point(designed_id, 4));
    EXPECT_EQ(last.view.selection.i, 3);
}

TEST(DeleteCurvePoint, Refusals) {
    Document doc = designer_document();
    expect_refused(doc, delete_curve_point(designed_id, 5), ErrorCode::schema, "/i");
    History h;
    ASSERT_TRUE(h.execute(doc, delete_curve_point(designed_id, 0)).ok());
    // Four points are the fewest a cubic takes.
    expect_refused(doc, delete_curve_point(designed_id, 0), ErrorCode::degree, "/i");
    expect_refused(doc, delete_curve_point(curve_id, 0), ErrorCode::knots, "/knot_mode");
}

TEST(MoveCurvePoint, ChordKnotsFollowAndADragIsOneStep) {
    Document doc = designer_document(CurveKnotMode::chord);
    const Document before = doc;
    History h;
    ASSERT_TRUE(h.execute(doc, move_curve_point(designed_id, 2, {2, -2, 0})).ok());
    ASSERT_TRUE(h.execute(doc, move_curve_point(designed_id, 2, {2, -3, 0})).ok());
    EXPECT_EQ(h.size(), 1u);
    EXPECT_EQ(h.undo_label(), "Move P2");
    const geom::Curve& c = curve_of(doc, designed_id);
    EXPECT_EQ(c.points[2], glm::dvec3(2, -3, 0));
    EXPECT_EQ(c.knots, mode_knots(c, geom::KnotMode::chord));
    const Document after = doc;
    ASSERT_TRUE(h.undo(doc));
    EXPECT_TRUE(same_document(doc, before));
    ASSERT_TRUE(h.redo(doc));
    EXPECT_TRUE(same_document(doc, after));
    // Clamped uniform knots do not depend on the points.
    Document uniform = designer_document();
    const Document moved =
        expect_undo_redo_exact(uniform, move_curve_point(designed_id, 2, {2, 5, 0}));
    EXPECT_EQ(curve_of(moved, designed_id).knots, geom::clamped_uniform_knots(5, 3));
    expect_refused(doc, move_curve_point(designed_id, 2, {1, 1, 0}), ErrorCode::geometry,
                   "/position");
}

TEST(SetCurveDegree, RecomputesKnotsAndRefusesWhatItCannot) {
    Document doc = designer_document();
    const Document after = expect_undo_redo_exact(doc, set_curve_degree(designed_id, 2));
    EXPECT_EQ(curve_of(after, designed_id).degree, 2);
    EXPECT_EQ(curve_of(after, designed_id).knots, geom::clamped_uniform_knots(5, 2));
    expect_undo_redo_exact(doc, set_curve_degree(designed_id, 4));
    History h;
    const auto st = h.execute(doc, set_curve_degree(designed_id, 5));
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("got 5"), std::string::npos) << st.error().message;
    expect_refused(doc, set_curve_degree(designed_id, 5), ErrorCode::degree, "/degree");
    expect_refused(doc, set_curve_degree(designed_id, 0), ErrorCode::degree, "/degree");
    expect_refused(doc, set_curve_degree(curve_id, 2), ErrorCode::knots, "/knot_mode");
}

TEST(SetCurveKnotMode, RecomputesOrKeeps) {
    Document doc = sample_document();
    const Document chord =
        expect_undo_redo_exact(doc, set_curve_knot_mode(curve_id, CurveKnotMode::chord));
    EXPECT_EQ(curve_object_of(chord, curve_id).knot_mode, CurveKnotMode::chord);
    const geom::Curve& c = curve_of(chord, curve_id);
    EXPECT_EQ(c.knots, mode_knots(c, geom::KnotMode::chord));
    // Custom keeps the knots; only the mode changes (and undo puts it back).
    Document designed = designer_document();
    const Document custom =
        expect_undo_redo_exact(designed, set_curve_knot_mode(designed_id, CurveKnotMode::custom));
    EXPECT_EQ(curve_of(custom, designed_id).knots, curve_of(designed, designed_id).knots);
    // Now the designed curve's points can be dragged apart from its knots and set_knot works.
    History h;
    ASSERT_TRUE(h.execute(designed, set_curve_knot_mode(designed_id, CurveKnotMode::custom)).ok());
    ASSERT_TRUE(h.execute(designed, set_knot(designed_id, geom::Dir::u, 4, 0.3)).ok());
    // A degenerate polygon cannot take chord knots.
    ASSERT_TRUE(h.execute(designed, move_control_point(designed_id, 1, -1, {0, 0, 0})).ok());
    expect_refused(designed, set_curve_knot_mode(designed_id, CurveKnotMode::chord),
                   ErrorCode::geometry, "/knot_mode");
}

TEST(SetCurvePlane, CarriesTheDrawingIntoTheNewPlane) {
    Document doc = designer_document();
    const Document xz =
        expect_undo_redo_exact(doc, set_curve_plane(designed_id, CurvePlane::xz, true));
    EXPECT_EQ(curve_object_of(xz, designed_id).plane, CurvePlane::xz);
    EXPECT_EQ(curve_of(xz, designed_id).points[1], glm::dvec3(1, 0, 1));
    Document doc2 = designer_document();
    const Document yz =
        expect_undo_redo_exact(doc2, set_curve_plane(designed_id, CurvePlane::yz, true));
    EXPECT_EQ(curve_of(yz, designed_id).points[3], glm::dvec3(0, 3, 2));
    Document doc3 = designer_document();
    const Document view =
        expect_undo_redo_exact(doc3, set_curve_plane(designed_id, CurvePlane::free3d, false));
    EXPECT_EQ(curve_of(view, designed_id).points,
              curve_of(designer_document(), designed_id).points);
}

TEST(CurvePrimitiveObjects, ExactCirclesArcsAndLines) {
    auto circle = circle_object("ring", CurvePlane::xz, {0, 0, 1}, 2);
    ASSERT_TRUE(circle.ok());
    const auto& c = std::get<CurveObject>(circle->shape);
    EXPECT_EQ(c.knot_mode, CurveKnotMode::custom);
    EXPECT_EQ(c.curve.count(), 9);
    for (double t = 0; t <= 1; t += 0.05) {
        const auto p = geom::curve_point(c.curve, t);
        ASSERT_TRUE(p.has_value());
        EXPECT_NEAR(std::hypot(p->x, p->z - 1), 2, 1e-12);
        EXPECT_EQ(p->y, 0);
    }
    auto arc = arc_object("arc", CurvePlane::xy, {0, 0, 0}, 1, 0, 90);
    ASSERT_TRUE(arc.ok());
    auto bad_plane = arc_object("arc", CurvePlane::free3d, {0, 0, 0}, 1, 0, 90);
    ASSERT_FALSE(bad_plane.ok());
    EXPECT_EQ(bad_plane.error().path, "/plane");
    auto bad_radius = circle_object("c", CurvePlane::xy, {0, 0, 0}, -1);
    ASSERT_FALSE(bad_radius.ok());
    EXPECT_EQ(bad_radius.error().path, "/radius");
    auto line = line_object("l", CurvePlane::xy, {0, 0, 0}, {2, 0, 0});
    ASSERT_TRUE(line.ok());
    EXPECT_FALSE(line_object("l", CurvePlane::xy, {1, 1, 1}, {1, 1, 1}).ok());
    // Added as any object, undoably.
    Document doc = sample_document();
    expect_undo_redo_exact(doc, add_object(*circle));
}

TEST(MakeCurvesCompatible, OneStepSameDegreeAndKnotsShapesKept) {
    Document doc = designer_document();
    const geom::Curve a = curve_of(doc, curve_id), b = curve_of(doc, designed_id);
    ASSERT_TRUE(History().execute(doc, set_curve_degree(designed_id, 2)).ok());
    const geom::Curve b2 = curve_of(doc, designed_id);
    const Document after =
        expect_undo_redo_exact(doc, make_curves_compatible({curve_id, designed_id}));
    const geom::Curve &ca = curve_of(after, curve_id), &cb = curve_of(after, designed_id);
    EXPECT_EQ(ca.degree, cb.degree);
    EXPECT_EQ(ca.knots, cb.knots);
    EXPECT_EQ(curve_object_of(after, designed_id).knot_mode, CurveKnotMode::custom);
    for (double s = 0; s <= 1; s += 0.125) {
        EXPECT_NEAR(glm::distance(*geom::curve_point(ca, s), *geom::curve_point(a, s)), 0, 1e-9);
        EXPECT_NEAR(glm::distance(*geom::curve_point(cb, s), *geom::curve_point(b2, s)), 0, 1e-9);
    }
    (void)b;
}

TEST(MakeCurvesCompatible, RefusalsNameTheCurve) {
    Document doc = designer_document();
    expect_refused(doc, make_curves_compatible({curve_id}), ErrorCode::schema, "/ids");
    expect_refused(doc, make_curves_compatible({curve_id, hill_id}), ErrorCode::schema, "/ids/1");
    expect_refused(doc, make_curves_compatible({curve_id, curve_id}), ErrorCode::schema, "/ids/1");
    History h;
    const auto st = h.execute(doc, make_curves_compatible({curve_id, hill_id}));
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("'hill'"), std::string::npos) << st.error().message;
}

// ---------------------------------------------------------------------------------------

// designer_document() plus "top", the designed curve lifted to z = 2 (id 7).
Document two_curve_document() {
    Document doc = designer_document();
    auto top = new_curve_object("top", CurvePlane::xy,
                                {{0, 0, 2}, {1, 1, 2}, {2, -1, 2}, {3, 2, 2}, {4, 0, 2}}, 3,
                                CurveKnotMode::clamped_uniform);
    EXPECT_TRUE(top.ok());
    top->id = doc.allocate_id();
    doc.objects.push_back(*top);
    return doc;
}
constexpr std::uint64_t top_id = 7;

TEST(BuildConstruction, RuledAndSkinGiveSurfacesAndNotes) {
    Document doc = two_curve_document();
    const Document before = doc;
    ConstructionRequest r;
    r.kind = Construction::ruled;
    r.curves = {designed_id, top_id};
    auto ruled = build_construction(doc, r);
    ASSERT_TRUE(ruled.ok()) << ruled.error().message;
    EXPECT_EQ(ruled->object.name, "ruled wave-top");
    const geom::Surface& s = std::get<SurfaceObject>(ruled->object.shape).surface;
    EXPECT_EQ(s.degree_v, 1);
    // Halfway between the two curves: z = 1 over the bottom curve's point.
    const auto mid = geom::surface_point(s, 0.3, 0.5);
    const auto low = geom::curve_point(curve_of(doc, designed_id), 0.3);
    ASSERT_TRUE(mid && low);
    EXPECT_NEAR(glm::distance(*mid, *low + glm::dvec3(0, 0, 1)), 0, 1e-12);
    EXPECT_TRUE(same_document(doc, before)); // building adds nothing

    auto lifted = new_curve_object("high", CurvePlane::xy,
                                   {{0, 0, 3}, {1, 1, 3}, {2, -1, 4}, {3, 2, 3}, {4, 0, 3}}, 3,
                                   CurveKnotMode::clamped_uniform);
    ASSERT_TRUE(lifted.ok());
    lifted->id = doc.allocate_id();
    doc.objects.push_back(*lifted);
    r.kind = Construction::skin;
    r.curves = {designed_id, top_id, lifted->id};
    r.parametrization = geom::Parametrization::centripetal;
    auto skin = build_construction(doc, r);
    ASSERT_TRUE(skin.ok()) << skin.error().message;
    EXPECT_NE(skin->note.find("v-degree 2"), std::string::npos) << skin->note;
}

TEST(BuildConstruction, RefusalsNameTheCurveAndTheReason) {
    Document doc = two_curve_document();
    ConstructionRequest r;
    r.kind = Construction::skin;
    r.curves = {curve_id};
    auto one = build_construction(doc, r);
    ASSERT_FALSE(one.ok());
    EXPECT_EQ(one.error().path, "/curves");
    EXPECT_NE(one.error().message.find("got 1"), std::string::npos);

    r.curves = {designed_id, top_id};
    r.skin_degree = 2;
    auto high = build_construction(doc, r);
    ASSERT_FALSE(high.ok());
    EXPECT_EQ(high.error().path, "/degree");

    r.skin_degree = 0;
    r.curves = {designed_id, designed_id};
    auto same = build_construction(doc, r);
    ASSERT_FALSE(same.ok());
    EXPECT_EQ(same.error().code, ErrorCode::geometry);
    EXPECT_NE(same.error().message.find("'wave'"), std::string::npos) << same.error().message;

    r.kind = Construction::swing;
    r.curves = {designed_id, curve_id}; // the profile lies in xy, not xz
    auto plane = build_construction(doc, r);
    ASSERT_FALSE(plane.ok());
    EXPECT_EQ(plane.error().code, ErrorCode::geometry);
    EXPECT_EQ(plane.error().path, "/curves/0/points/1");
    EXPECT_NE(plane.error().message.find("'wave'"), std::string::npos) << plane.error().message;

    r.kind = Construction::revolve;
    r.curves = {hill_id};
    auto surface = build_construction(doc, r);
    ASSERT_FALSE(surface.ok());
    EXPECT_EQ(surface.error().path, "/curves/0");
    EXPECT_NE(surface.error().message.find("'hill'"), std::string::npos);

    r.curves = {designed_id};
    r.angle = 400;
    auto angle = build_construction(doc, r);
    ASSERT_FALSE(angle.ok());
    EXPECT_EQ(angle.error().path, "/angle");
}

TEST(BuildConstruction, OrientedSweepReportsItsDeviation) {
    Document doc = sample_document();
    auto profile = circle_object("ring", CurvePlane::yz, {0, 0, 0}, 0.25);
    auto path = arc_object("path", CurvePlane::xy, {0, 2, 0}, 2, 270, 360);
    ASSERT_TRUE(profile.ok() && path.ok());
    History h;
    ASSERT_TRUE(h.execute(doc, add_object(*profile)).ok());
    ASSERT_TRUE(h.execute(doc, add_object(*path)).ok());
    ConstructionRequest r;
    r.kind = Construction::oriented_sweep;
    r.curves = {doc.objects[doc.objects.size() - 2].id, doc.objects.back().id};
    r.sections = 8;
    auto swept = build_construction(doc, r);
    ASSERT_TRUE(swept.ok()) << swept.error().message;
    EXPECT_NE(swept->note.find("deviation"), std::string::npos);
}

} // namespace
