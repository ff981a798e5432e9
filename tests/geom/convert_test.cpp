// Type conversion keeps the shape: Bezier pieces tile the original domain and agree with it;
// weights go only when they are all equal.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/geom/convert.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/validate.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;

namespace {

// The piece whose domain holds t (the first one on a shared end).
template <class Pieces> const Curve& piece_at(const Pieces& pieces, double t) {
    for (const Curve& c : pieces)
        if (t <= c.knots.back()) return c;
    return pieces.back();
}

TEST(Convert, AMultiSpanCurveBecomesBezierPiecesOfTheSameShape) {
    RandomGeometry g(5);
    for (bool rational : {false, true}) {
        Curve c = g.curve(3, 9, rational, true, 2); // interior knots up to multiplicity 2
        c.knots = clamped_uniform_knots(9, 3);
        c.knots[5] = c.knots[4]; // a double knot
        if (rational)
            for (double& w : c.weights) w = g.uniform(0.5, 2);
        const SplineType to = rational ? SplineType::rational_bezier : SplineType::bezier;
        auto pieces = convert(c, to);
        ASSERT_TRUE(pieces.ok()) << pieces.error().message;
        EXPECT_EQ(pieces->size(), 5u); // 6 spans, one of them empty
        for (const Curve& piece : *pieces) {
            EXPECT_EQ(piece.type, to);
            EXPECT_EQ(piece.count(), 4);
            EXPECT_TRUE(validate_curve(piece).ok());
        }
        for (double t = 0; t <= 1; t += 1.0 / 64) {
            const Curve& piece = piece_at(*pieces, t);
            EXPECT_LT(glm::length(*curve_point(piece, t) - *curve_point(c, t)), 1e-12) << t;
        }
    }
}

TEST(Convert, ASurfaceBecomesItsGridOfBezierPatchesInUMajorOrder) {
    RandomGeometry g(6);
    Surface s = g.surface(2, 3, 4, 5, false);
    s.knots_u = clamped_uniform_knots(4, 2); // 2 spans
    s.knots_v = clamped_uniform_knots(5, 3); // 2 spans
    auto pieces = convert(s, SplineType::bezier);
    ASSERT_TRUE(pieces.ok());
    ASSERT_EQ(pieces->size(), 4u);
    EXPECT_EQ((*pieces)[1].knots_u.front(), 0.0); // second piece: first u-strip,
    EXPECT_EQ((*pieces)[1].knots_v.front(), 0.5); // second v-piece
    const Surface& last = (*pieces)[3];
    EXPECT_LT(glm::length(*surface_point(last, 0.8, 0.9) - *surface_point(s, 0.8, 0.9)), 1e-12);
}

TEST(Convert, WeightsGoOnlyWhenEqual) {
    Curve c;
    c.type = SplineType::nurbs;
    c.degree = 1;
    c.knots = {0, 0, 1, 1};
    c.points = {{0, 0, 0}, {1, 1, 0}};
    c.weights = {3, 3};
    auto plain = convert(c, SplineType::bspline);
    ASSERT_TRUE(plain.ok());
    EXPECT_EQ((*plain)[0].weights, (std::vector<double>{1, 1}));
    EXPECT_EQ((*plain)[0].type, SplineType::bspline);
    c.weights = {3, 2};
    auto refused = convert(c, SplineType::bezier);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().code, ErrorCode::weights);
    EXPECT_EQ(refused.error().path, "/weights/1");
    // Up to a rational type: one piece, weights kept.
    auto up = convert(c, SplineType::nurbs);
    ASSERT_TRUE(up.ok());
    EXPECT_EQ(up->size(), 1u);
}

} // namespace
