// Subpatches sharing the original domain: lookup by parameter, borders, continuity kept
// by point and weight edits (C0, C1), undo (the scene round trip: tests/scene/kinds_io_test.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "core/doc/commands.hpp"
#include "core/doc/patches.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "tests/doc/doc_fixtures.hpp"

namespace isoparm::doc {
namespace {

using geom::Dir;
using namespace testing;

TEST(Patches, SplitPiecesShareTheOriginalDomain) {
    PaperSplit p;
    const std::uint64_t group = p.doc.find(p.right)->patch_group;
    EXPECT_NE(group, 0u);
    EXPECT_EQ(p.doc.find(p.left_low)->patch_group, group);
    EXPECT_EQ(p.doc.find(p.left_high)->patch_group, group);
    EXPECT_EQ(patch_members(p.doc, group).size(), 3u);
    const geom::ParamRect r = tracing_domain(p.doc, *p.doc.find(p.left_low));
    EXPECT_EQ(r.u.lo, 0.0);
    EXPECT_EQ(r.u.hi, 1.0);
    EXPECT_EQ(r.v.lo, 0.0);
    EXPECT_EQ(r.v.hi, 1.0);
    EXPECT_FALSE(check_patch_groups(p.doc));
}

TEST(Patches, PatchByParameter) {
    PaperSplit p;
    const std::uint64_t group = p.doc.find(p.right)->patch_group;
    EXPECT_EQ(patch_at(p.doc, group, {0.2, 0.2}), p.left_low);
    EXPECT_EQ(patch_at(p.doc, group, {0.2, 0.8}), p.left_high);
    EXPECT_EQ(patch_at(p.doc, group, {0.9, 0.1}), p.right);
    // On the border the current patch stays current.
    EXPECT_EQ(patch_at(p.doc, group, {0.75, 0.3}, p.right), p.right);
    EXPECT_EQ(patch_at(p.doc, group, {0.75, 0.3}, p.left_low), p.left_low);
    EXPECT_EQ(patch_at(p.doc, group, {1.5, 0.3}), 0u);
}

TEST(Patches, BordersSayWhichConform) {
    PaperSplit p;
    const auto borders = shared_borders(p.doc, p.doc.find(p.right)->patch_group);
    ASSERT_EQ(borders.size(), 3u);
    int conforming = 0;
    for (const SharedBorder& b : borders) {
        if (b.low == p.left_low && b.high == p.left_high) {
            EXPECT_TRUE(b.conforming);
            EXPECT_TRUE(b.c1_possible);
            EXPECT_EQ(b.across, Dir::v);
            EXPECT_EQ(b.count, p.surface(p.left_low).n_u);
        } else {
            // The right part's v knots have 0.5 once: its border curve does not split there.
            EXPECT_EQ(b.high, p.right);
            EXPECT_FALSE(b.conforming);
            EXPECT_NE(b.why_not.find("multiplicity"), std::string::npos) << b.why_not;
        }
        conforming += b.conforming;
    }
    EXPECT_EQ(conforming, 1);
}

// First u-derivatives of both pieces along the border u = t.
double max_cross_derivative_gap(const geom::Surface& a, const geom::Surface& b, double t) {
    double gap = 0;
    for (double v = 0; v <= 1.0; v += 0.125) {
        const auto da = geom::surface_derivatives(a, t, v, 1);
        const auto db = geom::surface_derivatives(b, t, v, 1);
        EXPECT_TRUE(da && db);
        gap = std::max(gap, glm::length(da->D[0][0] - db->D[0][0]));
        gap = std::max(gap, glm::length(da->D[1][0] - db->D[1][0]));
    }
    return gap;
}

struct OneSplit {
    Document doc = default_document();
    History history;
    std::uint64_t a = 0, b = 0;
    explicit OneSplit(Continuity c) {
        doc.continuity = c;
        std::tie(a, b) = split(doc, history, doc.objects[0].id, Dir::u, 0.5);
        history.seal();
    }
    geom::Surface& surface(std::uint64_t id) {
        return std::get<SurfaceObject>(doc.find(id)->shape).surface;
    }
};

TEST(Patches, OffLeavesTheNeighbourAlone) {
    OneSplit s(Continuity::off);
    const geom::Surface before = s.surface(s.b);
    const int n = s.surface(s.a).n_u;
    ASSERT_TRUE(s.history.execute(s.doc, move_control_point(s.a, n - 1, 2, {0.1, 0.2, 3})));
    EXPECT_EQ(s.surface(s.b).points, before.points);
    EXPECT_FALSE(continuity_holds(s.doc, s.doc.find(s.a)->patch_group, Continuity::c0));
}

TEST(Patches, C0MovesTheSharedBorderPointAndUndoRestoresBoth) {
    OneSplit s(Continuity::c0);
    const Document before = s.doc;
    const int n = s.surface(s.a).n_u;
    // A drag in three steps: one undo step.
    for (double z : {1.0, 2.0, 3.0})
        ASSERT_TRUE(s.history.execute(s.doc, move_control_point(s.a, n - 1, 2, {0.1, 0.2, z})));
    EXPECT_EQ(s.history.size(), 2u);
    EXPECT_EQ(s.surface(s.b).point(0, 2), glm::dvec3(0.1, 0.2, 3));
    EXPECT_TRUE(continuity_holds(s.doc, s.doc.find(s.a)->patch_group, Continuity::c0, 0));
    // The surfaces meet along the whole border.
    for (double v = 0; v <= 1; v += 0.1) {
        const auto pa = geom::surface_point(s.surface(s.a), 0.5, v);
        const auto pb = geom::surface_point(s.surface(s.b), 0.5, v);
        ASSERT_TRUE(pa && pb);
        EXPECT_EQ(*pa, *pb);
    }
    // A weight on the border follows too.
    ASSERT_TRUE(s.history.execute(s.doc, set_weight(s.b, 0, 1, 3.5)));
    EXPECT_EQ(s.surface(s.a).weight(n - 1, 1), 3.5);
    s.history.undo(s.doc);
    s.history.undo(s.doc);
    EXPECT_TRUE(same_geometry(s.doc, before));
    s.history.redo(s.doc);
    EXPECT_EQ(s.surface(s.b).point(0, 2), glm::dvec3(0.1, 0.2, 3));
}

TEST(Patches, C1KeepsTheCrossDerivativeForPointsAndWeights) {
    OneSplit s(Continuity::c1);
    const std::uint64_t group = s.doc.find(s.a)->patch_group;
    // Right after the split the pieces are C2 (a bicubic split at a simple knot).
    EXPECT_LT(max_cross_derivative_gap(s.surface(s.a), s.surface(s.b), 0.5), 1e-12);
    const int n = s.surface(s.a).n_u;
    // The inner row next to the border, then a border point, then a weight on the inner row.
    ASSERT_TRUE(s.history.execute(s.doc, move_control_point(s.a, n - 2, 1, {-0.3, -1, 2.5})));
    s.history.seal();
    ASSERT_TRUE(s.history.execute(s.doc, move_control_point(s.b, 0, 3, {0.2, 1.1, -0.7})));
    s.history.seal();
    ASSERT_TRUE(s.history.execute(s.doc, set_weight(s.a, n - 2, 2, 4.0)));
    EXPECT_TRUE(continuity_holds(s.doc, group, Continuity::c1, 1e-14));
    EXPECT_LT(max_cross_derivative_gap(s.surface(s.a), s.surface(s.b), 0.5), 1e-12);
    // Without continuity the same edit would break it: the check can fail.
    s.doc.continuity = Continuity::off;
    ASSERT_TRUE(s.history.execute(s.doc, move_control_point(s.a, n - 2, 1, {-0.3, -1, 0})));
    EXPECT_FALSE(continuity_holds(s.doc, group, Continuity::c1, 1e-14));
    EXPECT_GT(max_cross_derivative_gap(s.surface(s.a), s.surface(s.b), 0.5), 1e-3);
}

TEST(Patches, C1AcrossUnequalSpansAndDegrees) {
    // Split at 0.3 (spans 0.3 and 0.2 beside the border), then raise the right piece to degree
    // 4 across it: the C1 rows need the ratio (p_a dt_b) / (p_b dt_a), not a mirror image.
    Document doc = default_document();
    doc.continuity = Continuity::c1;
    History h;
    const auto [a, b] = split(doc, h, doc.objects[0].id, Dir::u, 0.3);
    ASSERT_TRUE(h.execute(doc, elevate_degree(b, Dir::u)));
    const auto surface = [&](std::uint64_t id) -> const geom::Surface& {
        return std::get<SurfaceObject>(doc.find(id)->shape).surface;
    };
    EXPECT_LT(max_cross_derivative_gap(surface(a), surface(b), 0.3), 1e-12);
    const int n = surface(a).n_u;
    ASSERT_TRUE(h.execute(doc, move_control_point(a, n - 2, 3, {-1.2, 0.9, 1.8})));
    h.seal();
    ASSERT_TRUE(h.execute(doc, move_control_point(b, 0, 0, {-1.1, -2.2, 0.4})));
    h.seal();
    ASSERT_TRUE(h.execute(doc, set_weight(a, n - 1, 2, 0.6)));
    EXPECT_TRUE(continuity_holds(doc, doc.find(a)->patch_group, Continuity::c1, 1e-14));
    EXPECT_LT(max_cross_derivative_gap(surface(a), surface(b), 0.3), 1e-12);
}

TEST(Patches, CornerOfFourPatchesStaysClosed) {
    Document doc = default_document();
    doc.continuity = Continuity::c0;
    History h;
    const auto [a, b] = split(doc, h, doc.objects[0].id, Dir::u, 0.5);
    const auto [a1, a2] = split(doc, h, a, Dir::v, 0.5);
    const auto [b1, b2] = split(doc, h, b, Dir::v, 0.5);
    const geom::Surface& sa1 = std::get<SurfaceObject>(doc.find(a1)->shape).surface;
    // The corner at (0.5, 0.5) of the lower-left piece moves: all four patches follow.
    ASSERT_TRUE(h.execute(doc, move_control_point(a1, sa1.n_u - 1, sa1.n_v - 1, {0, 0, 5})));
    for (std::uint64_t id : {a2, b1, b2}) {
        const geom::Surface& s = std::get<SurfaceObject>(doc.find(id)->shape).surface;
        const auto p = geom::surface_point(s, 0.5, 0.5);
        ASSERT_TRUE(p);
        EXPECT_EQ(*p, glm::dvec3(0, 0, 5)) << doc.find(id)->name;
    }
    EXPECT_TRUE(continuity_holds(doc, doc.find(a1)->patch_group, Continuity::c0, 0));
}

TEST(Patches, SplitWithContinuityRefinesTheNeighbourSoBordersConform) {
    Document doc = default_document();
    doc.continuity = Continuity::c1;
    History h;
    const auto [left, right] = split(doc, h, doc.objects[0].id, Dir::u, 0.75);
    const Document before = doc;
    doc.view.selection = {right, 1, 2};
    const geom::Surface right_before = std::get<SurfaceObject>(doc.find(right)->shape).surface;
    auto second = split_object(left, Dir::v, 0.5);
    const Command* r2 = second.get();
    ASSERT_TRUE(h.execute(doc, std::move(second)));
    EXPECT_NE(r2->label().find("1 neighbour refined"), std::string::npos) << r2->label();
    const auto [low, high] = split_piece_ids(*r2);
    const geom::Surface& rs = std::get<SurfaceObject>(doc.find(right)->shape).surface;
    EXPECT_EQ(geom::multiplicity(rs.knots_v, 0.5), 3);
    // Shape unchanged.
    for (double u = 0.75; u <= 1; u += 0.05)
        for (double v = 0; v <= 1; v += 0.1)
            EXPECT_LT(glm::length(*geom::surface_point(rs, u, v) -
                                  *geom::surface_point(right_before, u, v)),
                      1e-14);
    // Every border conforms now, and moving a point on one keeps C1.
    for (const SharedBorder& b : shared_borders(doc, doc.find(right)->patch_group))
        EXPECT_TRUE(b.conforming) << b.why_not;
    const geom::Surface& ls = std::get<SurfaceObject>(doc.find(low)->shape).surface;
    ASSERT_TRUE(h.execute(doc, move_control_point(low, ls.n_u - 2, 1, {0.5, -1, 1.5})));
    EXPECT_TRUE(continuity_holds(doc, doc.find(right)->patch_group, Continuity::c1, 1e-14));
    // Undo both: the neighbour and the selection on it come back exactly.
    h.undo(doc);
    h.undo(doc);
    EXPECT_TRUE(same_geometry(doc, before));
    EXPECT_EQ(doc.view.selection, (Selection{right, 1, 2}));
    (void)high;
}

TEST(Patches, RedoReplaysTheContinuityTheEditWasMadeWith) {
    OneSplit s(Continuity::c0);
    const int n = s.surface(s.a).n_u;
    ASSERT_TRUE(s.history.execute(s.doc, move_control_point(s.a, n - 1, 2, {0.1, 0.2, 3})));
    const Document after = s.doc;
    s.history.undo(s.doc);
    s.doc.continuity = Continuity::off; // the setting changes between undo and redo
    ASSERT_TRUE(s.history.redo(s.doc));
    EXPECT_TRUE(same_geometry(s.doc, after));

    // A split that refined its neighbour refines it again on redo, whatever the setting now.
    Document doc = default_document();
    doc.continuity = Continuity::c1;
    History h;
    const auto [left, right] = split(doc, h, doc.objects[0].id, Dir::u, 0.75);
    split(doc, h, left, Dir::v, 0.5);
    const Document split_twice = doc;
    h.undo(doc);
    doc.continuity = Continuity::off;
    ASSERT_TRUE(h.redo(doc));
    EXPECT_TRUE(same_geometry(doc, split_twice));
    (void)right;
}

// How many of the group's borders pair up point for point (and allow C1).
int conforming_borders(const Document& doc, std::uint64_t group, int* total = nullptr) {
    int n = 0;
    const auto borders = shared_borders(doc, group);
    for (const SharedBorder& b : borders) n += b.conforming && b.c1_possible;
    if (total) *total = static_cast<int>(borders.size());
    return n;
}

const geom::Surface& surface_in(const Document& doc, std::uint64_t id) {
    return std::get<SurfaceObject>(doc.find(id)->shape).surface;
}

// The paper's Fig. 6 as a lecture does it live on the 5x5 bicubic: C1 on, split at
// u = 0.75, pick the left piece, split it at v = 0.5. Every border (3 of 3) pairs up, C1 holds
// after a point beside a border moves (the cross-border derivatives agree), and one undo step
// takes the second split back together with the refinement it made.
TEST(Patches, Fig6LiveSequenceKeepsEveryBorderC1) {
    Document doc = default_document();
    doc.continuity = Continuity::c1;
    History h;
    const std::uint64_t group = doc.objects[0].id;
    const auto [left, right] = split(doc, h, doc.objects[0].id, Dir::u, 0.75);
    doc.view.selection = {left, -1, -1}; // the left piece picked
    const Document after_first = doc;
    const std::size_t steps = h.size();
    auto second = split_object(left, Dir::v, 0.5);
    const Command* cmd = second.get();
    ASSERT_TRUE(h.execute(doc, std::move(second)));
    EXPECT_EQ(h.size(), steps + 1); // one undo step
    // The label says what the split did to the neighbour.
    EXPECT_NE(cmd->label().find("1 neighbour refined"), std::string::npos) << cmd->label();
    EXPECT_NE(cmd->label().find("v = 0.5 x2"), std::string::npos) << cmd->label();
    int total = 0;
    EXPECT_EQ(conforming_borders(doc, group, &total), 3);
    EXPECT_EQ(total, 3);

    // A point of the lower-left piece next to its border with the right part moves: C1 kept.
    const auto [low, high] = split_piece_ids(*cmd);
    const geom::Surface& ls = surface_in(doc, low);
    h.seal();
    ASSERT_TRUE(h.execute(doc, move_control_point(low, ls.n_u - 2, 1, {0.3, -1.2, 1.4})));
    EXPECT_TRUE(continuity_holds(doc, group, Continuity::c1, 1e-12));
    // The first u-derivatives agree across u = 0.75 on both parts of the border.
    for (double v = 0.05; v < 1; v += 0.1) {
        const std::uint64_t piece = v < 0.5 ? low : high;
        const auto a = geom::surface_derivatives(surface_in(doc, piece), 0.75, v, 1);
        const auto b = geom::surface_derivatives(surface_in(doc, right), 0.75, v, 1);
        ASSERT_TRUE(a && b);
        EXPECT_LT(glm::length(a->D[0][0] - b->D[0][0]), 1e-12) << v;
        EXPECT_LT(glm::length(a->D[1][0] - b->D[1][0]), 1e-10) << v;
    }
    h.undo(doc);
    h.undo(doc); // the split and its refinement, as one step
    EXPECT_TRUE(same_geometry(doc, after_first));
    EXPECT_EQ(doc.objects.size(), 2u);
}

// The split gives the pieces knots a neighbour has and they lack: the right part was given
// v = 0.3 before the left part is split at v = 0.5.
TEST(Patches, SplitGivesThePiecesTheNeighboursKnotsToo) {
    Document doc = default_document();
    doc.continuity = Continuity::c1;
    History h;
    const std::uint64_t group = doc.objects[0].id;
    const auto [left, right] = split(doc, h, doc.objects[0].id, Dir::u, 0.75);
    ASSERT_TRUE(h.execute(doc, insert_knot(right, Dir::v, 0.3)));
    EXPECT_EQ(conforming_borders(doc, group), 0); // the knots along u = 0.75 differ
    const geom::Surface left_before = surface_in(doc, left);
    const auto [low, high] = split(doc, h, left, Dir::v, 0.5);
    EXPECT_EQ(conforming_borders(doc, group), 3);
    EXPECT_EQ(geom::multiplicity(surface_in(doc, low).knots_v, 0.3), 1);
    EXPECT_EQ(geom::multiplicity(surface_in(doc, right).knots_v, 0.5), 3);
    // The pieces still trace the left part exactly.
    for (double u = 0; u <= 0.75; u += 0.075)
        for (double v = 0; v <= 1; v += 0.1) {
            const auto before = geom::surface_point(left_before, u, v);
            const auto after = geom::surface_point(surface_in(doc, v <= 0.5 ? low : high), u, v);
            ASSERT_TRUE(before && after);
            EXPECT_LT(glm::length(*before - *after), 1e-13) << u << " " << v;
        }
}

// A split must not break a border that conformed: three parts side by side in u, then the
// first split at v = 0.5. The middle part gains v = 0.5 up to the degree, and so must the
// third (its border with the middle part stays paired).
TEST(Patches, SplitRefinesOnSoNoBorderBreaks) {
    Document doc = default_document();
    doc.continuity = Continuity::c0;
    History h;
    const std::uint64_t group = doc.objects[0].id;
    const auto [a, rest] = split(doc, h, doc.objects[0].id, Dir::u, 0.25);
    const auto [b, c] = split(doc, h, rest, Dir::u, 0.6);
    EXPECT_EQ(conforming_borders(doc, group), 2);
    split(doc, h, a, Dir::v, 0.5);
    int total = 0;
    EXPECT_EQ(conforming_borders(doc, group, &total), 4);
    EXPECT_EQ(total, 4);
    EXPECT_EQ(geom::multiplicity(surface_in(doc, b).knots_v, 0.5), 3);
    EXPECT_EQ(geom::multiplicity(surface_in(doc, c).knots_v, 0.5), 3);
    // A corner point of the split line moved: the C0 chain reaches the third part.
    h.seal();
    const geom::Surface& bs = surface_in(doc, b);
    ASSERT_TRUE(h.execute(doc, move_control_point(b, bs.n_u - 1, 3, {0.2, 0.1, 2})));
    EXPECT_TRUE(continuity_holds(doc, group, Continuity::c0, 0));
}

// A Bezier neighbour given a knot becomes a B-spline: the split's label says so.
TEST(Patches, ABezierNeighbourRefinedSaysItBecomesABspline) {
    Document doc;
    Object o;
    o.id = doc.allocate_id();
    o.name = "sheet";
    o.shape = SurfaceObject{make_planar_grid(4, 4, 3, 3, geom::SplineType::bezier)};
    doc.objects.push_back(o);
    doc.continuity = Continuity::c0;
    History h;
    const auto [left, right] = split(doc, h, o.id, Dir::u, 0.5);
    EXPECT_EQ(surface_in(doc, right).type, geom::SplineType::bezier);
    auto second = split_object(left, Dir::v, 0.5);
    const Command* cmd = second.get();
    ASSERT_TRUE(h.execute(doc, std::move(second)));
    EXPECT_EQ(surface_in(doc, right).type, geom::SplineType::bspline);
    EXPECT_NE(cmd->label().find("v = 0.5 x3, Bezier becomes B-spline"), std::string::npos)
        << cmd->label();
    EXPECT_EQ(conforming_borders(doc, o.id), 3);
}

// Continuity switched on after splitting: conform_borders inserts what the borders lack
// (shape unchanged) in one undo step.
TEST(Patches, ConformBordersAfterTheFact) {
    PaperSplit p; // continuity off: only the left parts' border pairs up
    const std::uint64_t group = p.doc.find(p.right)->patch_group;
    EXPECT_EQ(conforming_borders(p.doc, group), 1);
    EXPECT_EQ(conforming_insertions(p.doc, group).size(), 1u);
    const Document before = p.doc;
    const geom::Surface right_before = p.surface(p.right);
    auto cmd = conform_borders(group);
    const Command* raw = cmd.get();
    ASSERT_TRUE(p.history.execute(p.doc, std::move(cmd)));
    EXPECT_EQ(raw->label(),
              "Refine so the borders pair up (" + p.doc.find(p.right)->name + ": v = 0.5 x2)");
    EXPECT_EQ(conforming_borders(p.doc, group), 3);
    EXPECT_TRUE(conforming_insertions(p.doc, group).empty());
    for (double u = 0.75; u <= 1; u += 0.05)
        for (double v = 0; v <= 1; v += 0.1)
            EXPECT_LT(glm::length(*geom::surface_point(p.surface(p.right), u, v) -
                                  *geom::surface_point(right_before, u, v)),
                      1e-14);
    p.history.undo(p.doc);
    EXPECT_TRUE(same_geometry(p.doc, before));
}

} // namespace
} // namespace isoparm::doc
