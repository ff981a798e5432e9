// Curvature from exact derivatives against closed forms: sphere, cylinder, torus (surfaces);
// circle, twisted cubic, straight line (curves); and against the fundamental forms of a random
// rational surface.
#include <gtest/gtest.h>

#include "core/geom/knots.hpp"
#include "core/geom/tessellate.hpp"

#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/construct.hpp"
#include "core/geom/curvature.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/primitives.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;

namespace {

Surface revolved(const Curve& profile) {
    auto s = revolve(profile, 360);
    EXPECT_TRUE(s.ok());
    return *s;
}

// The meridian circle x = R + r cos a, z = r sin a (a full circle in the xz-plane).
Curve meridian_circle(double R, double r) {
    auto c = full_circle({R, 0, 0}, r, Plane::xz);
    EXPECT_TRUE(c.ok());
    return *c;
}

TEST(Curvature, SphereHasKOneOverRSquaredAndUmbilicPoints) {
    const double r = 2;
    auto arc = circular_arc({0, 0, 0}, r, -90, 90, Plane::xz);
    ASSERT_TRUE(arc.ok());
    const Surface sphere = revolved(*arc);
    for (double u : {0.1, 0.3, 0.5, 0.77, 0.9}) {
        for (double v : {0.0, 0.2, 0.45, 0.8}) {
            auto k = surface_curvature(sphere, u, v);
            ASSERT_TRUE(k) << u << " " << v;
            EXPECT_NEAR(k->gaussian, 1 / (r * r), 1e-13);
            EXPECT_NEAR(std::abs(k->mean), 1 / r, 1e-13);
            EXPECT_NEAR(k->k1, k->k2, 1e-6); // umbilic: the spread is a square root of ~0
            // The sign follows n = S_u x S_v: mean = -1/r exactly when n points outwards.
            const glm::dvec3 p = *surface_point(sphere, u, v);
            const glm::dvec3 n = *surface_normal(sphere, u, v);
            EXPECT_NEAR(k->mean, glm::dot(n, p) > 0 ? -1 / r : 1 / r, 1e-13);
        }
    }
    // The poles: S_v = 0, no normal, so nothing is defined there.
    EXPECT_FALSE(surface_curvature(sphere, 0, 0.3));
}

TEST(Curvature, CylinderIsFlatOneWayAndCurvedTheOther) {
    const double r = 1.5;
    const Surface cylinder = revolved(line_segment({r, 0, -1}, {r, 0, 2}));
    for (double u : {0.2, 0.6}) {
        for (double v : {0.1, 0.35, 0.9}) {
            auto k = surface_curvature(cylinder, u, v);
            ASSERT_TRUE(k);
            EXPECT_NEAR(k->gaussian, 0, 1e-13);
            EXPECT_NEAR(std::abs(k->mean), 1 / (2 * r), 1e-13);
            // The curved principal direction runs around the axis (no z), the flat one along it.
            const glm::dvec3 around = std::abs(k->k1) > std::abs(k->k2) ? k->d1 : k->d2;
            const glm::dvec3 along = std::abs(k->k1) > std::abs(k->k2) ? k->d2 : k->d1;
            EXPECT_NEAR(around.z, 0, 1e-12);
            EXPECT_NEAR(std::abs(along.z), 1, 1e-12);
        }
    }
}

TEST(Curvature, TorusMatchesItsClosedForm) {
    const double R = 3, r = 1;
    const Surface torus = revolved(meridian_circle(R, r));
    for (double u : {0.0, 0.1, 0.25, 0.4, 0.5, 0.66, 0.9}) {
        for (double v : {0.05, 0.5}) {
            auto k = surface_curvature(torus, u, v);
            ASSERT_TRUE(k);
            const glm::dvec3 p = *surface_point(torus, u, v);
            // cos a from the distance to the axis: rho = R + r cos a.
            const double cos_a = (std::hypot(p.x, p.y) - R) / r;
            EXPECT_NEAR(k->gaussian, cos_a / (r * (R + r * cos_a)), 1e-12) << u;
            EXPECT_NEAR(std::abs(k->mean),
                        std::abs((R + 2 * r * cos_a) / (2 * r * (R + r * cos_a))), 1e-12);
            EXPECT_GE(k->k1, k->k2);
        }
    }
}

// On any surface, k1 and k2 are the normal curvatures along d1 and d2, the extremes of
// II(x, x) / I(x, x), and d1, d2, n are orthonormal.
TEST(Curvature, PrincipalDirectionsAreEigenvectorsOfTheShapeOperator) {
    isoparm::testing::RandomGeometry g(4242);
    for (int trial = 0; trial < 20; ++trial) {
        Surface s = g.surface(3, 2, 6, 5, true);
        s.knots_u = clamped_uniform_knots(6, 3); // the domain [0, 1]^2
        s.knots_v = clamped_uniform_knots(5, 2);
        const double u = g.uniform(0.05, 0.95), v = g.uniform(0.05, 0.95);
        auto d = surface_derivatives(s, u, v, 2);
        ASSERT_TRUE(d);
        auto k = curvature_from_derivatives(*d);
        if (!k) continue;
        const glm::dvec3 n = *normal_from_derivatives(*d);
        const glm::dvec3 &Su = d->D[1][0], &Sv = d->D[0][1];
        auto normal_curvature = [&](const glm::dvec3& dir) {
            // dir = a S_u + b S_v, solved in the tangent plane by least squares (it lies in it).
            const double E = glm::dot(Su, Su), F = glm::dot(Su, Sv), G = glm::dot(Sv, Sv);
            const double x = glm::dot(dir, Su), y = glm::dot(dir, Sv), det = E * G - F * F;
            const double a = (G * x - F * y) / det, b = (E * y - F * x) / det;
            const double II = a * a * glm::dot(d->D[2][0], n) +
                              2 * a * b * glm::dot(d->D[1][1], n) + b * b * glm::dot(d->D[0][2], n);
            const glm::dvec3 w = a * Su + b * Sv;
            return II / glm::dot(w, w);
        };
        const double scale = std::max({1.0, std::abs(k->k1), std::abs(k->k2)});
        EXPECT_NEAR(normal_curvature(k->d1), k->k1, 1e-8 * scale);
        EXPECT_NEAR(normal_curvature(k->d2), k->k2, 1e-8 * scale);
        EXPECT_NEAR(glm::dot(k->d1, k->d2), 0, 1e-12);
        EXPECT_NEAR(glm::dot(k->d1, n), 0, 1e-12);
        EXPECT_NEAR(glm::length(k->d1), 1, 1e-12);
        EXPECT_NEAR(k->k1 * k->k2, k->gaussian, 1e-9 * scale * scale);
        EXPECT_NEAR((k->k1 + k->k2) / 2, k->mean, 1e-9 * scale);
    }
}

TEST(Curvature, CircleHasCurvatureOneOverRAndNoTorsion) {
    const double r = 0.75;
    auto c = full_circle({1, 2, 0}, r, Plane::xy);
    ASSERT_TRUE(c.ok());
    for (double t : {0.0, 0.125, 0.3, 0.5, 0.81, 1.0}) {
        auto k = curve_curvature(*c, t);
        ASSERT_TRUE(k && k->curvature && k->torsion && k->normal);
        EXPECT_NEAR(*k->curvature, 1 / r, 1e-13);
        EXPECT_NEAR(*k->torsion, 0, 1e-13);
        // The principal normal points to the centre.
        const glm::dvec3 p = *curve_point(*c, t);
        EXPECT_NEAR(glm::dot(*k->normal, glm::normalize(glm::dvec3(1, 2, 0) - p)), 1, 1e-12);
        EXPECT_NEAR(std::abs(k->binormal->z), 1, 1e-12);
    }
}

// The twisted cubic (t, t^2, t^3) as a Bezier curve: kappa = 2 sqrt(9t^4 + 9t^2 + 1) /
// (1 + 4t^2 + 9t^4)^(3/2), tau = 3 / (9t^4 + 9t^2 + 1).
TEST(Curvature, TwistedCubicMatchesItsClosedForms) {
    Curve c;
    c.type = SplineType::bezier;
    c.degree = 3;
    c.knots = {0, 0, 0, 0, 1, 1, 1, 1};
    c.points = {{0, 0, 0}, {1.0 / 3, 0, 0}, {2.0 / 3, 1.0 / 3, 0}, {1, 1, 1}};
    c.weights = {1, 1, 1, 1};
    for (double t : {0.0, 0.2, 0.5, 0.9, 1.0}) {
        auto k = curve_curvature(c, t);
        ASSERT_TRUE(k && k->curvature && k->torsion);
        const double q = 9 * t * t * t * t + 9 * t * t + 1;
        EXPECT_NEAR(*k->curvature,
                    2 * std::sqrt(q) / std::pow(1 + 4 * t * t + 9 * t * t * t * t, 1.5), 1e-13);
        EXPECT_NEAR(*k->torsion, 3 / q, 1e-13);
        // A right-handed orthonormal frame.
        EXPECT_NEAR(glm::dot(glm::cross(*k->tangent, *k->normal), *k->binormal), 1, 1e-12);
    }
}

TEST(Curvature, AStraightLineHasZeroCurvatureAndNoNormal) {
    Curve c;
    c.degree = 2;
    c.knots = {0, 0, 0, 1, 1, 1};
    c.points = {{0, 0, 0}, {1, 2, 3}, {2, 4, 6}};
    c.weights = {1, 1, 1};
    auto k = curve_curvature(c, 0.4);
    ASSERT_TRUE(k && k->curvature && k->tangent);
    EXPECT_EQ(*k->curvature, 0);
    EXPECT_FALSE(k->torsion);
    EXPECT_FALSE(k->normal);
    EXPECT_FALSE(k->binormal);
    // A curve that stops (C' = 0): nothing but the point.
    c.points = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
    auto still = curve_curvature(c, 0.5);
    ASSERT_TRUE(still);
    EXPECT_FALSE(still->curvature);
    EXPECT_FALSE(still->tangent);
}

} // namespace

namespace {

TEST(CurvatureGrid, SphereGridIsOneOverRSquaredWithPolesUndefined) {
    const double r = 2;
    auto arc = circular_arc({0, 0, 0}, r, -90, 90, Plane::xz);
    ASSERT_TRUE(arc.ok());
    const Surface sphere = revolved(*arc);
    const int su = 9, sv = 7;
    const auto K = curvature_grid(sphere, su, sv, CurvatureKind::gaussian);
    ASSERT_EQ(K.size(), static_cast<std::size_t>(su * sv));
    // u runs along the profile (pole to pole): rows 0 and su - 1 are the poles.
    int undefined = 0;
    for (int i = 0; i < su; ++i)
        for (int j = 0; j < sv; ++j) {
            const double k = K[static_cast<std::size_t>(i) * sv + j];
            const Interval du = domain(sphere, Dir::u);
            const bool pole = !surface_curvature(sphere, uniform_params(du.lo, du.hi, su)[i], 0.5);
            if (std::isnan(k)) {
                ++undefined;
                EXPECT_TRUE(pole) << i << " " << j;
            } else {
                EXPECT_NEAR(k, 1 / (r * r), 1e-12) << i << " " << j;
            }
        }
    EXPECT_EQ(undefined, 2 * sv); // the two pole rows
    // A range of vertices gives the same values as the whole grid.
    const auto part = curvature_grid(sphere, su, sv, CurvatureKind::mean, 10, 5);
    const auto whole = curvature_grid(sphere, su, sv, CurvatureKind::mean);
    ASSERT_EQ(part.size(), 5u);
    for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(part[k], whole[10 + k]);
}

TEST(CurvatureGrid, PrincipalCurvaturesOfACylinderAndAFlatGrid) {
    const Surface cylinder = revolved(line_segment({1, 0, -1}, {1, 0, 1}));
    for (double k : curvature_grid(cylinder, 6, 9, CurvatureKind::gaussian))
        EXPECT_NEAR(k, 0, 1e-12);
    const auto kmax = curvature_grid(cylinder, 6, 9, CurvatureKind::k_max);
    const auto kmin = curvature_grid(cylinder, 6, 9, CurvatureKind::k_min);
    for (std::size_t q = 0; q < kmax.size(); ++q) {
        EXPECT_NEAR(std::max(std::abs(kmax[q]), std::abs(kmin[q])), 1.0, 1e-12);
        EXPECT_NEAR(std::min(std::abs(kmax[q]), std::abs(kmin[q])), 0.0, 1e-12);
    }
}

} // namespace
