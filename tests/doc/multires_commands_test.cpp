// The multires_edit command: one undo step per edit (a drag included), exact undo and redo,
// replay from JSON, the detail kept by a coarse move and the sweep kept by a detail edit, and
// refusals at the member at fault.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/doc/commands_multires.hpp"
#include "core/geom/multires.hpp"
#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::doc::testing;

namespace {

constexpr std::uint64_t wave_id = 6, sheet_id = 7;

// sample_document() plus a wavy 11-point cubic (level 3) and a 7 x 11 bicubic sheet (2 x 3).
Document multires_document() {
    Document doc = sample_document();
    Object wave;
    wave.id = doc.allocate_id();
    wave.name = "wave";
    geom::Curve c;
    c.degree = 3;
    for (int i = 0; i < 11; ++i) c.points.push_back({i, (i % 2 ? 0.4 : -0.4) + 0.1 * i, 0});
    c.weights.assign(11, 1.0);
    c.knots = geom::clamped_uniform_knots(11, 3);
    wave.shape = CurveObject{c, CurvePlane::xy, CurveKnotMode::clamped_uniform};
    doc.objects.push_back(wave);

    Object sheet;
    sheet.id = doc.allocate_id();
    sheet.name = "sheet";
    geom::Surface s = make_planar_grid(7, 11, 3, 3, geom::SplineType::bspline);
    for (int i = 0; i < 7; ++i)
        for (int j = 0; j < 11; ++j) s.point(i, j).z = 0.2 * ((i + j) % 3);
    sheet.shape = SurfaceObject{s};
    doc.objects.push_back(sheet);
    EXPECT_EQ(wave.id, wave_id);
    EXPECT_EQ(sheet.id, sheet_id);
    return doc;
}

MultiresEditSpec move_spec(std::uint64_t id, int level, int i, glm::dvec3 to) {
    MultiresEditSpec s;
    s.id = id;
    s.level = level;
    s.i = i;
    s.position = to;
    return s;
}

double largest_gap(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    double gap = 0;
    for (std::size_t k = 0; k < a.size(); ++k) gap = std::max(gap, glm::length(a[k] - b[k]));
    return gap;
}

TEST(MultiresCommand, ACoarseMoveIsOneExactUndoStepAndKeepsTheDetail) {
    Document doc = multires_document();
    const geom::Curve before = curve_of(doc, wave_id);
    const auto d0 = geom::decompose(before.points, 3, 1);
    const Document after =
        expect_undo_redo_exact(doc, multires_edit(move_spec(wave_id, 1, 2, {5, 3, 0})));
    const auto d1 = geom::decompose(curve_of(after, wave_id).points, 3, 1);
    EXPECT_LT(glm::length(d1.coarse[2] - glm::dvec3(5, 3, 0)), 1e-12);
    for (std::size_t k = 0; k < d0.details.size(); ++k)
        EXPECT_LT(largest_gap(d1.details[k], d0.details[k]), 1e-12);
}

TEST(MultiresCommand, ADragMergesIntoOneStepThatUndoRestores) {
    Document doc = multires_document();
    const Document start = doc;
    History h;
    for (double y : {1.0, 2.0, 3.5})
        ASSERT_TRUE(h.execute(doc, multires_edit(move_spec(wave_id, 2, 3, {4, y, 0}))).ok());
    EXPECT_EQ(h.size(), 1u);
    EXPECT_EQ(h.undo_label(), "Move coarse point 3 at level 2 (detail kept)");
    // The merged step's spec is the drag's final value; replayed in one step from the start it
    // gives the same curve up to rounding (the drag decomposed three times, the replay once).
    ASSERT_TRUE(h.top()->spec().has_value());
    Document replay = start;
    ASSERT_TRUE(make_command(*h.top()->spec())->apply(replay).ok());
    EXPECT_LT(largest_gap(curve_of(replay, wave_id).points, curve_of(doc, wave_id).points), 1e-12);
    ASSERT_TRUE(h.undo(doc));
    EXPECT_TRUE(same_document(doc, start));
}

TEST(MultiresCommand, ADetailEditKeepsTheCoarsePointsOnCurvesAndSurfaces) {
    Document doc = multires_document();
    MultiresEditSpec smooth;
    smooth.id = wave_id;
    smooth.level = 1;
    smooth.detail_scale = 0.0;
    const auto coarse = geom::decompose(curve_of(doc, wave_id).points, 3, 1).coarse;
    Document after = expect_undo_redo_exact(doc, multires_edit(smooth));
    const auto d = geom::decompose(curve_of(after, wave_id).points, 3, 1);
    EXPECT_LT(largest_gap(d.coarse, coarse), 1e-12);
    for (const auto& level : d.details)
        for (const glm::dvec3& x : level) EXPECT_LT(glm::length(x), 1e-12);

    MultiresEditSpec sharpen;
    sharpen.id = sheet_id;
    sharpen.level = 1;
    sharpen.level_v = 2;
    sharpen.detail_scale = 2.0;
    const auto net = geom::decompose(surface_of(doc, sheet_id).points, 2, 3, 1, 2).coarse;
    after = expect_undo_redo_exact(doc, multires_edit(sharpen));
    const auto sd = geom::decompose(surface_of(after, sheet_id).points, 2, 3, 1, 2);
    EXPECT_LT(largest_gap(sd.coarse, net), 1e-12);

    MultiresEditSpec lift;
    lift.id = sheet_id;
    lift.level = 0;
    lift.level_v = 1;
    lift.i = 1;
    lift.j = 2;
    lift.position = glm::dvec3(0, 0, 2);
    expect_undo_redo_exact(doc, multires_edit(lift));
}

TEST(MultiresCommand, RefusalsNameTheMemberAtFault) {
    Document doc = multires_document();
    // The sample curve is a NURBS curve with unequal weights: the object does not qualify.
    {
        auto levels = multires_levels_of(*doc.find(curve_id));
        ASSERT_FALSE(levels.ok());
        EXPECT_EQ(levels.error().path, "/id");
        EXPECT_NE(
            levels.error().message.find("object 'profile': the curve is NURBS with weight 1 = 0.5"),
            std::string::npos)
            << levels.error().message;
    }
    expect_refused(doc, multires_edit(move_spec(curve_id, 1, 0, {0, 0, 0})),
                   geom::ErrorCode::weights, "/id");
    expect_refused(doc, multires_edit(move_spec(ball_id, 1, 0, {0, 0, 0})), geom::ErrorCode::schema,
                   "/id");
    expect_refused(doc, multires_edit(move_spec(wave_id, 4, 0, {0, 0, 0})), geom::ErrorCode::schema,
                   "/level");
    expect_refused(doc, multires_edit(move_spec(wave_id, 1, 5, {0, 0, 0})), geom::ErrorCode::schema,
                   "/i");
    expect_refused(doc, multires_edit(move_spec(sheet_id, 1, 0, {0, 0, 0})),
                   geom::ErrorCode::schema, "/level_v");
    MultiresEditSpec both = move_spec(wave_id, 1, 0, {0, 0, 0});
    both.detail_scale = 1.0;
    expect_refused(doc, multires_edit(both), geom::ErrorCode::schema, "/detail_scale");
    MultiresEditSpec neither = move_spec(wave_id, 1, 0, {0, 0, 0});
    neither.position.reset();
    expect_refused(doc, multires_edit(neither), geom::ErrorCode::schema, "/position");
    // A curve whose knots follow its polygon would lose that rule: refused at the object.
    std::get<CurveObject>(doc.find(wave_id)->shape).knot_mode = CurveKnotMode::chord;
    expect_refused(doc, multires_edit(move_spec(wave_id, 1, 0, {0, 0, 0})), geom::ErrorCode::knots,
                   "/id");
}

} // namespace
