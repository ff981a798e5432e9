// A surface's trim loops in the document: set and removed as one undo step each, checked with
// the loop validator's errors, compared and counted as part of the surface kind.
#include <gtest/gtest.h>

#include "core/doc/commands_trim.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/trim/trim.hpp"
#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::doc::testing;

namespace {

// The grid's domain with a square outer loop inside it and a round hole in the middle.
geom::Trim square_with_hole(const geom::Surface& s) {
    const geom::ParamRect d = geom::domain(s);
    const double du = d.u.hi - d.u.lo, dv = d.v.hi - d.v.lo;
    const glm::dvec2 lo{d.u.lo + 0.1 * du, d.v.lo + 0.1 * dv};
    const glm::dvec2 hi{d.u.hi - 0.1 * du, d.v.hi - 0.1 * dv};
    geom::Trim t;
    t.outer = geom::polygon_loop({lo, {hi.x, lo.y}, hi, {lo.x, hi.y}});
    t.holes.push_back(
        geom::circle_loop((lo + hi) * 0.5, 0.2 * std::min(du, dv), /*clockwise=*/true).value());
    return t;
}

const geom::Trim& trim_of_object(const Document& doc, std::uint64_t id) {
    return std::get<SurfaceObject>(doc.find(id)->shape).trim;
}

TEST(TrimCommands, SetTrimIsOneUndoStepThatReplaysAsData) {
    Document doc = sample_document();
    const geom::Trim trim = square_with_hole(surface_of(doc, grid_id));
    const geom::Surface surface_before = surface_of(doc, grid_id);
    const Document after = expect_undo_redo_exact(doc, set_trim(grid_id, trim));
    EXPECT_EQ(trim_of_object(after, grid_id).loop_count(), 2);
    EXPECT_TRUE(is_trimmed(*after.find(grid_id)));
    EXPECT_FALSE(is_trimmed(*after.find(hill_id)));
    // The surface itself is untouched.
    EXPECT_TRUE(same_bits(SurfaceObject{surface_before, {}},
                          SurfaceObject{surface_of(after, grid_id), {}}));
}

TEST(TrimCommands, RemoveTrimGivesTheWholeDomainBack) {
    Document doc = sample_document();
    History h;
    ASSERT_TRUE(h.execute(doc, set_trim(grid_id, square_with_hole(surface_of(doc, grid_id)))).ok());
    const Document after = expect_undo_redo_exact(doc, remove_trim(grid_id));
    EXPECT_TRUE(trim_of_object(after, grid_id).empty());
    // An empty trim given to set_trim removes it as well.
    Document again = sample_document();
    ASSERT_TRUE(set_trim(grid_id, square_with_hole(surface_of(again, grid_id)))->apply(again).ok());
    ASSERT_TRUE(set_trim(grid_id, geom::Trim{})->apply(again).ok());
    EXPECT_TRUE(trim_of_object(again, grid_id).empty());
}

TEST(TrimCommands, RefusalsNameTheLoopAndTheProblem) {
    Document doc = sample_document();
    const Document before = doc;
    const geom::Surface& s = surface_of(doc, grid_id);
    // A hole run counter-clockwise: the wrong orientation, named at the hole.
    geom::Trim wrong = square_with_hole(s);
    wrong.holes[0] = geom::reversed(wrong.holes[0]);
    auto st = set_trim(grid_id, wrong)->apply(doc);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().path.rfind("/trim/holes/0", 0), 0u) << st.error().path;
    EXPECT_NE(st.error().message.find("hole 0"), std::string::npos) << st.error().message;
    EXPECT_NE(st.error().message.find("clockwise"), std::string::npos) << st.error().message;
    // A loop outside the domain.
    const geom::ParamRect d = geom::domain(s);
    geom::Trim outside;
    outside.outer = geom::polygon_loop(
        {{d.u.lo, d.v.lo}, {d.u.hi + 1, d.v.lo}, {d.u.hi + 1, d.v.hi}, {d.u.lo, d.v.hi}});
    st = set_trim(grid_id, outside)->apply(doc);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, geom::ErrorCode::domain);
    EXPECT_EQ(st.error().path.rfind("/trim/outer", 0), 0u) << st.error().path;
    // Another kind of object, and a surface with no trim to remove.
    st = set_trim(curve_id, square_with_hole(s))->apply(doc);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().path, "/id");
    EXPECT_NE(st.error().message.find("curve"), std::string::npos) << st.error().message;
    st = remove_trim(grid_id)->apply(doc);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().path, "/id");
    EXPECT_TRUE(same_document(doc, before)) << "a refusal changed the document";
}

TEST(TrimCommands, TheTrimIsPartOfTheSurfaceKindsFacts) {
    const Document doc = sample_document();
    const SurfaceObject plain{surface_of(doc, grid_id), {}};
    const SurfaceObject trimmed{plain.surface, square_with_hole(plain.surface)};
    EXPECT_TRUE(validate(trimmed).ok());
    EXPECT_FALSE(same_bits(plain, trimmed));
    EXPECT_TRUE(same_bits(trimmed, SurfaceObject{trimmed}));
    EXPECT_GT(heap_bytes(trimmed), heap_bytes(plain));
    // Its mesh keeps only the trimmed domain: fewer grid points than the whole grid, plus the
    // loops' points, and no triangle in the hole.
    const auto whole = mesh_form(plain, 16);
    const auto cut = mesh_form(trimmed, 16);
    ASSERT_TRUE(whole.ok() && cut.ok());
    const geom::Mesh& mw = std::get<geom::Mesh>(*whole);
    const geom::Mesh& mc = std::get<geom::Mesh>(*cut);
    EXPECT_NE(mw.triangles.size(), mc.triangles.size());
    EXPECT_FALSE(mc.triangles.empty());
    // validate names the loop under "/trim".
    SurfaceObject bad = trimmed;
    bad.trim.outer = geom::reversed(*bad.trim.outer);
    const auto st = validate(bad);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().path.rfind("/trim/outer", 0), 0u) << st.error().path;
}

TEST(TrimCommands, RefinementKeepsTheTrimAndSplitsAreRefusedNotSilentlyUntrimmed) {
    Document doc = sample_document();
    const geom::Trim trim = square_with_hole(surface_of(doc, grid_id));
    History h;
    ASSERT_TRUE(h.execute(doc, set_trim(grid_id, trim)).ok());
    // Knot insertion and degree elevation keep the domain, so the loops stay.
    ASSERT_TRUE(h.execute(doc, insert_knot(grid_id, geom::Dir::u, 0.3)).ok());
    ASSERT_TRUE(h.execute(doc, elevate_degree(grid_id, geom::Dir::v, 1)).ok());
    EXPECT_EQ(trim_of_object(doc, grid_id).loop_count(), 2);
    // A split and a conversion into several Bezier pieces would have to divide the loops:
    // refused, saying so, and the document is unchanged.
    const Document before = doc;
    auto st = split_object(grid_id, geom::Dir::u, 0.5)->apply(doc);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("trim"), std::string::npos) << st.error().message;
    st = convert_object(grid_id, geom::SplineType::bezier, false)->apply(doc);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("trim"), std::string::npos) << st.error().message;
    EXPECT_TRUE(same_document(doc, before));
    // One piece: the trim stays.
    ASSERT_TRUE(h.execute(doc, convert_object(grid_id, geom::SplineType::nurbs, false)).ok());
    EXPECT_EQ(trim_of_object(doc, grid_id).loop_count(), 2);
}

TEST(TrimCommands, AnEndKnotCannotMovePastTheLoops) {
    Document doc = sample_document();
    // Unclamped u knots: the domain's ends are the knots u2 = 2 and u4 = 4, which may move.
    std::get<SurfaceObject>(doc.find(grid_id)->shape).surface.knots_u = {0, 1, 2, 3, 4, 5, 6};
    History h;
    ASSERT_TRUE(h.execute(doc, set_trim(grid_id, square_with_hole(surface_of(doc, grid_id)))).ok());
    const Document before = doc;
    // The lower u end moved in past the outer loop (at u = 2.2): refused.
    auto st = move_knot_run(grid_id, geom::Dir::u, 2, 1, 2.5)->apply(doc);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().path, "/value");
    EXPECT_NE(st.error().message.find("trim"), std::string::npos) << st.error().message;
    EXPECT_TRUE(same_document(doc, before));
    // Moved outward: the loops stay inside.
    EXPECT_TRUE(h.execute(doc, move_knot_run(grid_id, geom::Dir::u, 2, 1, 1.5)).ok());
}

} // namespace
