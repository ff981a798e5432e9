// The skinned surface: S(u, v_k) = C_k(u) at every section, parameters by convention 15.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geom/construct.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/validate.hpp"
#include "tests/geom/construct_test_util.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::point_at_unit;
using isoparm::testing::RandomGeometry;
using isoparm::testing::samples;

namespace {

void expect_interpolates(const std::vector<Curve>& curves, const Skinned& s, double tol) {
    ASSERT_TRUE(validate_surface(s.surface).ok()) << validate_surface(s.surface).error().message;
    ASSERT_EQ(s.params.size(), curves.size());
    EXPECT_EQ(s.params.front(), 0.0);
    EXPECT_EQ(s.params.back(), 1.0);
    for (size_t k = 0; k < curves.size(); ++k) {
        if (k > 0) {
            EXPECT_GT(s.params[k], s.params[k - 1]);
        }
        for (double u : samples(0, 1, 40)) {
            const auto C = point_at_unit(curves[k], u);
            const auto S = surface_point(s.surface, u, s.params[k]);
            ASSERT_EQ(C.has_value(), S.has_value());
            if (C) {
                EXPECT_LT(glm::distance(*C, *S), tol) << "section " << k << " u=" << u;
            }
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

// A translated copy of c.
Curve moved(Curve c, const glm::dvec3& d) {
    for (auto& p : c.points) p += d;
    return c;
}

} // namespace

TEST(Skin, InterpolatesEverySectionForEveryDegreeAndParametrization) {
    RandomGeometry g(641);
    int trial = 0;
    for (Parametrization mode :
         {Parametrization::chord, Parametrization::centripetal, Parametrization::uniform}) {
        for (int rep = 0; rep < 30; ++rep, ++trial) {
            const int count = g.integer(2, 7);
            std::vector<Curve> curves;
            for (int k = 0; k < count; ++k) {
                const int p = g.integer(1, 4);
                curves.push_back(
                    g.curve(p, g.integer(p + 1, p + 4), trial % 2 == 0, (trial + k) % 3 != 0));
            }
            const int q = g.integer(1, std::min(3, count - 1));
            auto s = skin(curves, q, mode);
            ASSERT_TRUE(s.ok()) << s.error().message;
            EXPECT_EQ(s->surface.degree_v, q);
            EXPECT_EQ(s->surface.n_v, count);
            expect_interpolates(curves, *s, 1e-8);
        }
    }
}

TEST(Skin, ParametersFollowConvention15) {
    // Two control points per section: index 0 moves by 1, 3, 1 and index 1 by 4, 4, 4.
    const Knots U = {0, 0, 1, 1};
    const std::vector<Curve> curves = {
        bspline(1, U, {{0, 0, 0}, {0, 1, 0}}), bspline(1, U, {{1, 0, 0}, {4, 1, 0}}),
        bspline(1, U, {{4, 0, 0}, {8, 1, 0}}), bspline(1, U, {{4, 0, 1}, {12, 1, 0}})};
    // Chord: index 0 lengths 1, 3, 1 (total 5); index 1 lengths 4, 4, 4 (total 12).
    auto chord = skin(curves, 2, Parametrization::chord);
    ASSERT_TRUE(chord.ok()) << chord.error().message;
    const std::vector<double> want_chord = {0, (1.0 / 5 + 4.0 / 12) / 2, (4.0 / 5 + 8.0 / 12) / 2,
                                            1};
    for (int k = 0; k < 4; ++k) EXPECT_DOUBLE_EQ(chord->params[k], want_chord[k]);
    // Knots v by averaging (eq. 9.8): one interior knot (v1 + v2) / 2 for degree 2.
    EXPECT_EQ(chord->surface.knots_v.size(), 7u);
    EXPECT_DOUBLE_EQ(chord->surface.knots_v[3], (want_chord[1] + want_chord[2]) / 2);
    // Centripetal: square roots 1, sqrt 3, 1 and 2, 2, 2.
    auto centripetal = skin(curves, 3, Parametrization::centripetal);
    ASSERT_TRUE(centripetal.ok());
    const double r3 = std::sqrt(3.0), t0 = 2 + r3;
    EXPECT_DOUBLE_EQ(centripetal->params[1], (1 / t0 + 1.0 / 3) / 2);
    EXPECT_DOUBLE_EQ(centripetal->params[2], ((1 + r3) / t0 + 2.0 / 3) / 2);
    auto uniform = skin(curves, 1, Parametrization::uniform);
    ASSERT_TRUE(uniform.ok());
    EXPECT_EQ(uniform->params, (std::vector<double>{0, 1.0 / 3, 2.0 / 3, 1}));
    EXPECT_EQ(uniform->surface.knots_v, (Knots{0, 0, 1.0 / 3, 2.0 / 3, 1, 1}));
    expect_interpolates(curves, *chord, 1e-12);
    expect_interpolates(curves, *centripetal, 1e-12);
    expect_interpolates(curves, *uniform, 1e-12);
}

// The paper's Figure 9: four degree-3 curves skinned (v-degree 3 by default: min(3, 4 - 1)).
TEST(Skin, PaperFourCubicSections) {
    const Knots U = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
    const Curve c0 = bspline(3, U, {{0, 0, 0}, {1, 0, 1}, {2, 0, 0.5}, {3, 0, 1}, {4, 0, 0}});
    std::vector<Curve> curves = {c0, moved(c0, {0, 1, 0.5}), moved(c0, {0.3, 2.2, 0.2}),
                                 moved(c0, {0, 3, -0.4})};
    curves[2].points[2].z += 1.5; // a bump in the third section
    curves[3].weights = {1, 2, 0.5, 1, 1};
    curves[3].type = SplineType::nurbs;
    EXPECT_EQ(default_skin_degree(4), 3);
    auto s = skin(curves, default_skin_degree(4), Parametrization::chord);
    ASSERT_TRUE(s.ok()) << s.error().message;
    EXPECT_EQ(s->surface.type, SplineType::nurbs);
    EXPECT_EQ(s->surface.degree_u, 3);
    EXPECT_EQ(s->surface.degree_v, 3);
    EXPECT_EQ(s->surface.knots_v, (Knots{0, 0, 0, 0, 1, 1, 1, 1}));
    expect_interpolates(curves, *s, 1e-12);
}

TEST(Skin, IncompatibleUnclampedSectionsAreMadeCompatibleFirst) {
    const Curve a = bspline(2, {0, 1, 2, 3, 4, 5, 6}, {{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}});
    const Curve b = bspline(3, {5, 5, 5, 5, 6, 7, 7, 7, 7},
                            {{0, 0, 2}, {1, 1, 2}, {2, 0, 2}, {3, 3, 2}, {4, 0, 2}});
    const Curve c = bspline(1, {0, 0, 1, 1}, {{0, 1, 4}, {4, 1, 4}});
    auto s = skin({a, b, c}, 2, Parametrization::centripetal);
    ASSERT_TRUE(s.ok()) << s.error().message;
    expect_interpolates({a, b, c}, *s, 1e-12);
}

TEST(Skin, ErrorsNameTheValueAtFault) {
    const Knots U = {0, 0, 1, 1};
    const Curve a = bspline(1, U, {{0, 0, 0}, {1, 0, 0}});
    const Curve b = moved(a, {0, 1, 0});
    const Curve c = moved(a, {0, 2, 0});
    auto expect_error = [](const Expected<Skinned>& r, ErrorCode code, const std::string& path) {
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().code, code) << r.error().message;
        EXPECT_EQ(r.error().path, path) << r.error().message;
        EXPECT_FALSE(r.error().message.empty());
    };
    expect_error(skin({a}, 1), ErrorCode::schema, "/curves");
    expect_error(skin({a, b, c}, 0), ErrorCode::schema, "/degree");
    expect_error(skin({a, b, c}, 3), ErrorCode::schema, "/degree");
    // All sections identical: every total is zero.
    expect_error(skin({a, a, a}, 2), ErrorCode::geometry, "/curves");
    expect_error(skin({a, a}, 1, Parametrization::centripetal), ErrorCode::geometry, "/curves");
    // Two consecutive sections identical: equal parameters.
    expect_error(skin({a, b, b, c}, 2), ErrorCode::geometry, "/curves/2");
    // One control point shared by all sections: its total is zero (convention 15).
    Curve b0 = b, c0 = c;
    b0.points[0] = c0.points[0] = a.points[0];
    expect_error(skin({a, b0, c0}, 2), ErrorCode::geometry, "/curves");
    // Uniform parameters need no lengths: identical sections still have distinct parameters.
    EXPECT_TRUE(skin({a, b0, c0}, 2, Parametrization::uniform).ok());
}

TEST(Skin, AnInterpolatedControlPointAtInfinityIsWeights) {
    // Uniform v = 0, 1/2, 1 with degree 2: R1 = 2 Q1 - (Q0 + Q2) / 2 in homogeneous space;
    // weights 1, 0.5, 1 make its weight 0 while its weighted coordinates are not.
    const Knots U = {0, 0, 1, 1};
    Curve a = bspline(1, U, {{0, 0, 0}, {1, 0, 0}});
    Curve b = bspline(1, U, {{0, 1, 1}, {1, 1, 1}});
    Curve c = bspline(1, U, {{0, 2, 0}, {1, 2, 0}});
    b.type = SplineType::nurbs;
    b.weights = {0.5, 0.5};
    auto r = skin({a, b, c}, 2, Parametrization::uniform);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::weights);
}
