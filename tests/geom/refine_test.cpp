// Refinement leaves the shape unchanged: insertion, elevation and splitting, sampled tightly.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/refine.hpp"
#include "core/geom/validate.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;

namespace {

double net_size(const Curve& c) {
    double m = 1;
    for (auto& p : c.points) m = std::max(m, glm::length(p));
    return m;
}

void expect_same_curve(const Curve& a, const Curve& b, double lo, double hi, double tol) {
    for (int k = 0; k <= 64; ++k) {
        const double t = k == 64 ? hi : lo + (hi - lo) * k / 64;
        const auto pa = curve_point(a, t), pb = curve_point(b, t);
        ASSERT_EQ(pa.has_value(), pb.has_value()) << "t=" << t;
        if (pa) {
            EXPECT_LT(glm::length(*pa - *pb), tol) << "t=" << t;
        }
    }
}

void expect_same_surface(const Surface& a, const Surface& b, Interval du, Interval dv, double tol) {
    for (int i = 0; i <= 12; ++i) {
        for (int j = 0; j <= 12; ++j) {
            const double u = i == 12 ? du.hi : du.lo + (du.hi - du.lo) * i / 12;
            const double v = j == 12 ? dv.hi : dv.lo + (dv.hi - dv.lo) * j / 12;
            const auto pa = surface_point(a, u, v), pb = surface_point(b, u, v);
            ASSERT_EQ(pa.has_value(), pb.has_value());
            if (pa) {
                EXPECT_LT(glm::length(*pa - *pb), tol) << u << "," << v;
            }
        }
    }
}

} // namespace

TEST(Refine, InsertionKeepsShape) {
    RandomGeometry g(31);
    for (int trial = 0; trial < 150; ++trial) {
        const int p = g.integer(1, 9);
        const Curve c = g.curve(p, g.integer(p + 1, p + 8), trial % 2 == 0, trial % 3 != 0);
        const Interval d = domain(c.knots, p, c.count());
        double t = g.uniform(d.lo, d.hi);
        if (trial % 5 == 0) t = c.knots[g.integer(p, c.count())]; // at an existing knot
        const int room = p - multiplicity(c.knots, t);
        if (room < 1) continue;
        const int times = g.integer(1, room);
        auto r = insert_knot(c, t, times);
        ASSERT_TRUE(r.ok()) << r.error().message;
        EXPECT_EQ(r->count(), c.count() + times);
        EXPECT_EQ(multiplicity(r->knots, t), multiplicity(c.knots, t) + times);
        EXPECT_TRUE(validate_curve(*r).ok());
        expect_same_curve(c, *r, d.lo, d.hi, 1e-11 * net_size(c));
    }
}

TEST(Refine, InsertionAtUnclampedDomainEnds) {
    Curve c;
    c.degree = 3;
    c.knots = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    c.points = {{0, 0, 0}, {1, 2, 0}, {3, 2, 1}, {4, 0, 0}, {5, 1, 2}};
    c.weights.assign(5, 1.0);
    for (double t : {3.0, 5.0}) {
        auto r = insert_knot(c, t, 2);
        ASSERT_TRUE(r.ok()) << r.error().message;
        expect_same_curve(c, *r, 3, 5, 1e-13);
    }
}

TEST(Refine, InsertionErrors) {
    Curve c;
    c.type = SplineType::nurbs;
    c.degree = 3;
    c.knots = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
    c.points = {{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}, {5, 1, 0}};
    c.weights = {1, 1, 2, 1, 1};
    auto m = insert_knot(c, 0.5, 3);
    ASSERT_FALSE(m.ok());
    EXPECT_EQ(m.error().code, ErrorCode::multiplicity);
    EXPECT_EQ(m.error().path, "/times");
    EXPECT_EQ(m.error().message,
              "inserting 0.5 3 time(s) would make its multiplicity exceed the degree 3");
    auto d = insert_knot(c, 1.5);
    ASSERT_FALSE(d.ok());
    EXPECT_EQ(d.error().code, ErrorCode::domain);
    EXPECT_EQ(d.error().path, "/knot");
    EXPECT_EQ(insert_knot(c, 1.0).error().code, ErrorCode::multiplicity); // clamped end
}

TEST(Refine, InsertionIntoBezierGivesBSpline) {
    Curve c;
    c.type = SplineType::rational_bezier;
    c.degree = 2;
    c.knots = bezier_knots(2);
    c.points = {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    c.weights = {1, std::sqrt(0.5), 1};
    auto r = insert_knot(c, 0.5);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->type, SplineType::nurbs);
    expect_same_curve(c, *r, 0, 1, 1e-15);
}

TEST(Refine, ElevationKeepsShapeClampedAndUnclamped) {
    RandomGeometry g(37);
    for (int trial = 0; trial < 120; ++trial) {
        const int p = g.integer(1, 6);
        const bool clamped = trial % 3 != 0;
        const Curve c = g.curve(p, g.integer(p + 1, p + 7), trial % 2 == 0, clamped, p + 1);
        const int times = g.integer(1, 3);
        auto r = elevate_degree(c, times);
        ASSERT_TRUE(r.ok()) << r.error().message;
        EXPECT_EQ(r->degree, p + times);
        ASSERT_TRUE(validate_curve(*r).ok()) << validate_curve(*r).error().message;
        const Interval d = domain(c.knots, p, c.count());
        const Interval e = domain(*r);
        EXPECT_EQ(d.lo, e.lo);
        EXPECT_EQ(d.hi, e.hi);
        if (clamped) { // the unique result: every distinct knot's multiplicity raised by times
            for (const KnotRun& run : knot_runs(c.knots))
                EXPECT_EQ(multiplicity(r->knots, run.value), run.multiplicity + times);
        }
        expect_same_curve(c, *r, d.lo, d.hi, 1e-10 * net_size(c));
    }
}

TEST(Refine, ElevateBezierTwiceMatchesReference) {
    // Shared example 0058-like check through the closed form: a degree-1 segment elevated
    // twice has equally spaced control points.
    Curve c;
    c.type = SplineType::bezier;
    c.degree = 1;
    c.knots = bezier_knots(1);
    c.points = {{0, 0, 0}, {3, 6, 9}};
    c.weights = {1, 1};
    auto r = elevate_degree(c, 2);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->type, SplineType::bezier);
    ASSERT_EQ(r->count(), 4);
    EXPECT_NEAR(glm::length(r->points[1] - glm::dvec3(1, 2, 3)), 0, 1e-15);
    EXPECT_NEAR(glm::length(r->points[2] - glm::dvec3(2, 4, 6)), 0, 1e-15);
    EXPECT_EQ(r->knots, bezier_knots(3));
}

TEST(Refine, SplitPiecesKeepDomainsAndShape) {
    RandomGeometry g(41);
    for (int trial = 0; trial < 100; ++trial) {
        const int p = g.integer(1, 7);
        const Curve c = g.curve(p, g.integer(p + 1, p + 8), trial % 2 == 0, trial % 3 != 0, p + 1);
        const Interval d = domain(c.knots, p, c.count());
        double t = g.uniform(d.lo, d.hi);
        if (trial % 4 == 0 && c.count() > p + 1) t = c.knots[g.integer(p + 1, c.count() - 1)];
        if (!(d.lo < t && t < d.hi)) continue;
        auto r = split(c, t);
        ASSERT_TRUE(r.ok()) << r.error().message;
        const auto& [a, b] = *r;
        ASSERT_TRUE(validate_curve(a).ok()) << validate_curve(a).error().message;
        ASSERT_TRUE(validate_curve(b).ok()) << validate_curve(b).error().message;
        EXPECT_EQ(domain(a.knots, p, a.count()).lo, d.lo);
        EXPECT_EQ(domain(a.knots, p, a.count()).hi, t);
        EXPECT_EQ(domain(b.knots, p, b.count()).lo, t);
        EXPECT_EQ(domain(b.knots, p, b.count()).hi, d.hi);
        EXPECT_EQ(multiplicity(a.knots, t), p + 1);
        EXPECT_EQ(multiplicity(b.knots, t), p + 1);
        const double tol = 1e-10 * net_size(c);
        for (int k = 0; k <= 20; ++k) {
            const double ta = d.lo + (t - d.lo) * k / 20, tb = t + (d.hi - t) * k / 20;
            if (k < 20) {
                EXPECT_LT(glm::length(*curve_point(a, ta) - *curve_point(c, ta)), tol);
            }
            if (k > 0) {
                EXPECT_LT(glm::length(*curve_point(b, tb) - *curve_point(c, tb)), tol);
            }
        }
    }
}

TEST(Refine, SplitOutsideDomainIsAnError) {
    Curve c;
    c.degree = 1;
    c.knots = {0, 0, 1, 1};
    c.points = {{0, 0, 0}, {1, 0, 0}};
    c.weights = {1, 1};
    for (double t : {0.0, 1.0, -0.5, 2.0}) {
        auto r = split(c, t);
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().code, ErrorCode::domain);
        EXPECT_EQ(r.error().path, "/param");
    }
}

TEST(Refine, SurfaceOperationsKeepShapeInBothDirections) {
    RandomGeometry g(43);
    for (int trial = 0; trial < 16; ++trial) {
        const Surface s =
            g.surface(g.integer(1, 4), g.integer(1, 4), 6, 5, trial % 2 == 0, trial % 4 != 0);
        const Interval du = domain(s, Dir::u);
        const Interval dv = domain(s, Dir::v);
        const Dir dir = trial % 2 ? Dir::u : Dir::v;
        const Interval dd = dir == Dir::u ? du : dv;
        const double t = dd.lo + 0.37 * (dd.hi - dd.lo);
        auto ins = insert_knot(s, dir, t, 1);
        ASSERT_TRUE(ins.ok());
        EXPECT_TRUE(validate_surface(*ins).ok());
        expect_same_surface(s, *ins, du, dv, 1e-10);
        auto el = elevate_degree(s, dir, 2);
        ASSERT_TRUE(el.ok());
        EXPECT_TRUE(validate_surface(*el).ok());
        expect_same_surface(s, *el, du, dv, 1e-9);
        auto sp = split(s, dir, t);
        ASSERT_TRUE(sp.ok());
        Interval first_u = du, first_v = dv;
        (dir == Dir::u ? first_u : first_v).hi = t;
        expect_same_surface(s, sp->first, first_u, first_v, 1e-10);
    }
}

TEST(Refine, PointAtInfinityIsAWeightsError) {
    // Weights 1 and -1: inserting 0.5 gives a homogeneous weight 0 with x != 0.
    Curve c;
    c.type = SplineType::nurbs;
    c.degree = 2;
    c.knots = bezier_knots(2);
    c.points = {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}};
    c.weights = {1, -1, 1};
    auto r = insert_knot(c, 0.5);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::weights);
}

TEST(Refine, ElevationAcrossAKnotOfFullMultiplicity) {
    // Found by the constructions work: an interior knot at multiplicity p + 1 overflowed A5.9.
    Curve c;
    c.degree = 1;
    c.knots = {0, 0, 0.5, 0.5, 1, 1};
    c.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 0}};
    c.weights.assign(4, 1.0);
    auto r = elevate_degree(c, 2);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ(r->degree, 3);
    EXPECT_EQ(multiplicity(r->knots, 0.5), 4);
    ASSERT_TRUE(validate_curve(*r).ok());
    for (double t : {0.0, 0.2, 0.49, 0.5, 0.7, 1.0}) {
        EXPECT_LT(glm::length(*curve_point(*r, t) - *curve_point(c, t)), 1e-14) << t;
    }
    // Left limit at the jump is the first piece's end point.
    const auto left = *curve_point(*r, 0.5 - 1e-12);
    EXPECT_LT(glm::length(left - glm::dvec3(1, 0, 0)), 1e-9);
}
