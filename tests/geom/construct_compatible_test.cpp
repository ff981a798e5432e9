// make_compatible: one degree, one knot vector, one count, every shape unchanged.
#include <gtest/gtest.h>

#include "core/geom/construct.hpp"
#include "core/geom/validate.hpp"
#include "tests/geom/construct_test_util.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::point_at_unit;
using isoparm::testing::RandomGeometry;
using isoparm::testing::samples;

namespace {

void expect_same_shape(const Curve& original, const Curve& compatible, double tol) {
    for (double s : samples(0.0, 1.0, 80)) {
        const auto a = point_at_unit(original, s);
        const auto b = curve_point(compatible, s);
        ASSERT_EQ(a.has_value(), b.has_value()) << "s=" << s;
        if (a) {
            EXPECT_LT(glm::distance(*a, *b), tol) << "s=" << s;
        }
    }
}

Curve bspline(int p, Knots U, std::vector<glm::dvec3> pts) {
    Curve c;
    c.degree = p;
    c.knots = std::move(U);
    c.weights.assign(pts.size(), 1.0);
    c.points = std::move(pts);
    return c;
}

} // namespace

TEST(MakeCompatible, RandomCurvesKeepTheirShapes) {
    RandomGeometry g(601);
    for (int trial = 0; trial < 120; ++trial) {
        const int count = g.integer(2, 4);
        std::vector<Curve> curves;
        for (int k = 0; k < count; ++k) {
            const int p = g.integer(1, 5);
            curves.push_back(g.curve(p, g.integer(p + 1, p + 6), g.integer(0, 1) == 1,
                                     g.integer(0, 3) != 0, trial % 4 == 0 ? p + 1 : p));
        }
        auto r = make_compatible(curves);
        ASSERT_TRUE(r.ok()) << r.error().message;
        const std::vector<Curve>& out = *r;
        ASSERT_EQ(out.size(), curves.size());
        int P = 0;
        for (const Curve& c : curves) P = std::max(P, c.degree);
        for (size_t k = 0; k < out.size(); ++k) {
            ASSERT_TRUE(validate_curve(out[k]).ok()) << validate_curve(out[k]).error().message;
            EXPECT_EQ(out[k].degree, P);
            EXPECT_EQ(out[k].knots, out[0].knots);
            EXPECT_EQ(out[k].count(), out[0].count());
            EXPECT_TRUE(is_clamped(out[k].knots, P, out[k].count()));
            EXPECT_EQ(out[k].knots.front(), 0.0);
            EXPECT_EQ(out[k].knots.back(), 1.0);
            expect_same_shape(curves[k], out[k], 1e-9);
        }
    }
}

TEST(MakeCompatible, MergesEachInteriorKnotAtItsLargestMultiplicity) {
    // Degree 2 with 0.5 once (twice after elevation to 3) and degree 3 with 0.25 twice.
    const Curve a =
        bspline(2, {0, 0, 0, 0.5, 1, 1, 1}, {{0, 0, 0}, {1, 2, 0}, {2, 0, 0}, {3, 1, 0}});
    const Curve b = bspline(3, {0, 0, 0, 0, 0.25, 0.25, 1, 1, 1, 1},
                            {{0, 0, 1}, {1, 1, 1}, {2, 0, 1}, {3, 3, 1}, {4, 0, 1}, {5, 1, 1}});
    auto r = make_compatible({a, b});
    ASSERT_TRUE(r.ok()) << r.error().message;
    const Knots expected = {0, 0, 0, 0, 0.25, 0.25, 0.5, 0.5, 1, 1, 1, 1};
    EXPECT_EQ((*r)[0].knots, expected);
    EXPECT_EQ((*r)[1].knots, expected);
    EXPECT_EQ((*r)[0].count(), 8);
    expect_same_shape(a, (*r)[0], 1e-12);
    expect_same_shape(b, (*r)[1], 1e-12);
}

TEST(MakeCompatible, MapsEachDomainToTheUnitInterval) {
    // The same knot in relative terms (1/2 of each domain) merges into one knot.
    const Curve a = bspline(1, {2, 2, 3, 4, 4}, {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}});
    const Curve b = bspline(1, {-1, -1, 0, 1, 1}, {{0, 0, 1}, {1, 0, 1}, {2, 0, 1}});
    auto r = make_compatible({a, b});
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ((*r)[0].knots, (Knots{0, 0, 0.5, 1, 1}));
    EXPECT_EQ((*r)[0].points, a.points); // nothing to insert: the control points are kept
    expect_same_shape(a, (*r)[0], 1e-15);
}

TEST(MakeCompatible, ClampsUnclampedCurves) {
    const Curve a = bspline(2, {0, 1, 2, 3, 4, 5, 6}, {{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}});
    const Curve b = bspline(2, {0, 0, 0, 1, 1, 1}, {{0, 0, 1}, {1, 1, 1}, {2, 0, 1}});
    auto r = make_compatible({a, b});
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ((*r)[0].knots, (Knots{0, 0, 0, 0.5, 1, 1, 1}));
    expect_same_shape(a, (*r)[0], 1e-12);
    expect_same_shape(b, (*r)[1], 1e-12);
}

TEST(MakeCompatible, ReachesMultiplicityDegreePlusOne) {
    // An interior knot at multiplicity p + 1 (a curve in two pieces) forces the other to it.
    const Curve a =
        bspline(1, {0, 0, 0.5, 0.5, 1, 1}, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 0}});
    const Curve b = bspline(1, {0, 0, 1, 1}, {{0, 0, 1}, {2, 0, 1}});
    auto r = make_compatible({a, b});
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ((*r)[1].knots, a.knots);
    EXPECT_EQ((*r)[1].count(), 4);
    expect_same_shape(b, (*r)[1], 1e-15);
    expect_same_shape(a, (*r)[0], 1e-15);
}

TEST(MakeCompatible, ElevatesACurveInTwoPieces) {
    const Curve a =
        bspline(1, {0, 0, 0.5, 0.5, 1, 1}, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 0}});
    const Curve b =
        bspline(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0, 1}, {1, 2, 1}, {2, -1, 1}, {3, 0, 1}});
    auto r = make_compatible({a, b});
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ((*r)[0].degree, 3);
    EXPECT_EQ((*r)[0].knots, (*r)[1].knots);
    expect_same_shape(a, (*r)[0], 1e-12);
    expect_same_shape(b, (*r)[1], 1e-12);
}

TEST(MakeCompatible, KeepsRationalCurvesExact) {
    RandomGeometry g(602);
    for (int trial = 0; trial < 40; ++trial) {
        const Curve a = g.curve(2, g.integer(3, 7), true, trial % 2 == 0);
        const Curve b = g.curve(g.integer(1, 4), 6, true, trial % 3 == 0);
        auto r = make_compatible({a, b});
        ASSERT_TRUE(r.ok()) << r.error().message;
        EXPECT_EQ((*r)[0].type, SplineType::nurbs);
        expect_same_shape(a, (*r)[0], 1e-9);
        expect_same_shape(b, (*r)[1], 1e-9);
    }
}

TEST(MakeCompatible, FewerThanTwoCurvesIsSchema) {
    auto r = make_compatible({bspline(1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}})});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::schema);
    EXPECT_EQ(r.error().path, "/curves");
}

TEST(MakeCompatible, APointAtInfinityIsWeightsAtThatCurve) {
    // Weights 1 and -1: inserting 0.5 gives the homogeneous point (-0.5, 0, 0, 0).
    Curve a = bspline(1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}});
    a.type = SplineType::nurbs;
    a.weights = {1, -1};
    const Curve b = bspline(1, {0, 0, 0.5, 1, 1}, {{0, 0, 1}, {1, 0, 1}, {2, 0, 1}});
    auto r = make_compatible({b, a});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::weights);
    EXPECT_TRUE(r.error().has_path);
    EXPECT_EQ(r.error().path, "/curves/1");
}

TEST(MakeCompatible, TooManyPointsInAllIsLimit) {
    // 1001 lines, each with its own interior knot: 1003 points each, 1,004,003 in all.
    std::vector<Curve> curves;
    for (int k = 0; k < 1001; ++k) {
        const double t = (k + 1) / 1002.0;
        curves.push_back(bspline(1, {0, 0, t, 1, 1}, {{0, 0, 0}, {t, 1, 0}, {1, 0, 0}}));
    }
    auto r = make_compatible(curves);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::limit);
    EXPECT_FALSE(r.error().has_path);
    curves.resize(900); // 902 x 900 = 811,800: within the caps
    EXPECT_TRUE(make_compatible(curves).ok());
}
