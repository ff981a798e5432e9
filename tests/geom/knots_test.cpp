// Knot vectors: validation messages and paths, spans at knots and domain ends.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geom/knots.hpp"

using namespace isoparm::geom;

TEST(Knots, ValidClampedAndUnclamped) {
    EXPECT_TRUE(validate_knots({0, 0, 0, 0, 0.5, 1, 1, 1, 1}, 3, 5).ok());
    EXPECT_TRUE(validate_knots({0, 1, 2, 3, 4, 5, 6, 7, 8}, 3, 5).ok());
    EXPECT_TRUE(validate_knots({0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1}, 2, 6).ok()); // full interior
}

TEST(Knots, WrongCount) {
    auto s = validate_knots({0, 0, 0, 0.5, 1, 1, 1}, 2, 3);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().code, ErrorCode::knots);
    EXPECT_EQ(s.error().message, "expected 6 knots, got 7");
    EXPECT_EQ(s.error().path, "");
}

TEST(Knots, DecreasingPointsAtFirstSmallerKnot) {
    auto s = validate_knots({0, 0, 0, 0, 0.6, 0.4, 1, 1, 1, 1}, 3, 6);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().path, "/5");
    EXPECT_EQ(s.error().message, "knot vector must be non-decreasing: knot 5 (0.4) < knot 4 (0.6)");
}

TEST(Knots, MultiplicityAboveDegreePlusOne) {
    auto s = validate_knots({0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1}, 2, 7);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().path, "/6");
}

TEST(Knots, EmptyDomain) {
    auto s = validate_knots({0, 0, 0, 0, 1, 1}, 2, 3);
    ASSERT_FALSE(s.ok()); // multiplicity 4 > 3 is found first
    auto e = validate_knots({0, 1, 1, 1, 1, 2}, 2, 3);
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error().code, ErrorCode::knots);
}

TEST(Knots, NonFinite) {
    auto s = validate_knots({0, 0, 0, NAN, 1, 1, 1}, 2, 4);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().path, "/3");
}

TEST(Knots, SpanRightLimitInsideLeftLimitAtEnd) {
    const Knots U{0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1}; // p = 2, n = 6
    EXPECT_EQ(find_span(U, 2, 6, 0.0), 2);
    EXPECT_EQ(find_span(U, 2, 6, 0.25), 2);
    EXPECT_EQ(find_span(U, 2, 6, 0.5), 5); // right limit at a full-multiplicity knot
    EXPECT_EQ(find_span(U, 2, 6, 0.75), 5);
    EXPECT_EQ(find_span(U, 2, 6, 1.0), 5); // left limit at the end
}

TEST(Knots, SpanUnclampedEnds) {
    const Knots U{0, 1, 2, 3, 4, 5, 6, 7, 8}; // p = 3, n = 5: domain [3, 5]
    EXPECT_EQ(find_span(U, 3, 5, 3.0), 3);
    EXPECT_EQ(find_span(U, 3, 5, 4.0), 4);
    EXPECT_EQ(find_span(U, 3, 5, 5.0), 4);
}

TEST(Knots, SpanAtEndWithRepeatedEndKnot) {
    // n = 4, p = 2: U[4] = 2 is the end; the last non-empty span is [1, 2).
    const Knots U{0, 0, 0, 1, 2, 2, 2};
    EXPECT_EQ(find_span(U, 2, 4, 2.0), 3);
}

TEST(Knots, MultiplicityIsExact) {
    const Knots U{0, 0, 0, 0.3, 0.1 + 0.2, 1, 1, 1}; // 0.3 < 0.30000000000000004
    EXPECT_EQ(multiplicity(U, 0.3), 1);              // 0.1 + 0.2 != 0.3: never merged silently
    EXPECT_EQ(multiplicity(U, 0.0), 3);
}

TEST(Knots, ClampedUniform) {
    const Knots U = clamped_uniform_knots(5, 3);
    EXPECT_EQ(U, (Knots{0, 0, 0, 0, 0.5, 1, 1, 1, 1}));
    EXPECT_TRUE(is_clamped(U, 3, 5));
    EXPECT_FALSE(is_clamped({0, 1, 2, 3, 4, 5, 6, 7, 8}, 3, 5));
    EXPECT_EQ(bezier_knots(2, -1, 3), (Knots{-1, -1, -1, 3, 3, 3}));
}

TEST(Knots, Runs) {
    auto runs = knot_runs({0, 0, 0, 0.5, 0.5, 1, 1, 1});
    ASSERT_EQ(runs.size(), 3u);
    EXPECT_EQ(runs[1].value, 0.5);
    EXPECT_EQ(runs[1].multiplicity, 2);
    EXPECT_EQ(runs[1].first_index, 3);
}

TEST(KnotContinuity, MultiplicityLowersContinuityOneOrderAtATime) {
    EXPECT_EQ(isoparm::geom::continuity_at_knot(3, 1), 2);
    EXPECT_EQ(isoparm::geom::continuity_at_knot(3, 3), 0);
    EXPECT_EQ(isoparm::geom::continuity_text(3, 2), "C1 here");
    EXPECT_EQ(isoparm::geom::continuity_text(2, 2),
              "C0 here: the pieces meet, a corner may appear");
    EXPECT_EQ(isoparm::geom::continuity_text(2, 3),
              "not continuous here (C-1): the pieces need not meet");
}
