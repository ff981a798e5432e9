// Multiresolution curves and surfaces: the filter bank inverts exactly, a coarse edit keeps
// the detail, a detail edit keeps the coarse points, and refusals name the offending value.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/multires.hpp"
#include "core/geom/multires_edit.hpp"
#include "core/geom/wavelet_filters.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;

namespace {

constexpr double exact = 1e-12;

double largest_gap(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    EXPECT_EQ(a.size(), b.size());
    double gap = 0;
    for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
        gap = std::max(gap, glm::length(a[k] - b[k]));
    return gap;
}

Curve dyadic_curve(RandomGeometry& g, int level) {
    Curve c = g.curve(3, (1 << level) + 3, false);
    c.knots = clamped_uniform_knots(c.count(), 3, g.uniform(-2, 0), g.uniform(0.5, 3));
    return c;
}

Surface dyadic_surface(RandomGeometry& g, int level_u, int level_v) {
    Surface s = g.surface(3, 3, (1 << level_u) + 3, (1 << level_v) + 3, false);
    s.knots_u = clamped_uniform_knots(s.n_u, 3);
    s.knots_v = clamped_uniform_knots(s.n_v, 3, -1, 2);
    return s;
}

double entry_gap(const DenseMatrix& m, bool identity) {
    double gap = 0;
    for (int r = 0; r < m.rows; ++r)
        for (int c = 0; c < m.cols; ++c)
            gap = std::max(gap, std::abs(m(r, c) - (identity && r == c ? 1.0 : 0.0)));
    return gap;
}

DenseMatrix product(const DenseMatrix& a, const DenseMatrix& b) {
    DenseMatrix out(a.rows, b.cols);
    for (int r = 0; r < a.rows; ++r)
        for (int k = 0; k < a.cols; ++k)
            for (int c = 0; c < b.cols; ++c) out(r, c) += a(r, k) * b(k, c);
    return out;
}

TEST(WaveletFilters, AnalysisIsTheInverseOfSynthesis) {
    for (int j = 1; j <= 7; ++j) {
        const WaveletFilters& f = cubic_wavelet_filters(j);
        ASSERT_EQ(f.P.rows, (1 << j) + 3);
        ASSERT_EQ(f.P.cols, (1 << (j - 1)) + 3);
        ASSERT_EQ(f.Q.cols, 1 << (j - 1));
        EXPECT_LT(entry_gap(product(f.A, f.P), true), exact) << "A P = I at level " << j;
        EXPECT_LT(entry_gap(product(f.A, f.Q), false), exact) << "A Q = 0 at level " << j;
        EXPECT_LT(entry_gap(product(f.B, f.P), false), exact) << "B P = 0 at level " << j;
        EXPECT_LT(entry_gap(product(f.B, f.Q), true), exact) << "B Q = I at level " << j;
    }
}

TEST(WaveletFilters, PIsKnotInsertionAtTheMidpoints) {
    // The level-(j-1) curve and the level-j curve of P C are the same curve.
    RandomGeometry g(3);
    for (int j = 1; j <= 5; ++j) {
        Curve coarse = dyadic_curve(g, j - 1 == 0 ? 1 : j - 1);
        if (j == 1) { // level 0: one Bezier span, 4 points
            coarse.points.resize(4);
            coarse.weights.resize(4);
            coarse.knots = clamped_uniform_knots(4, 3);
        }
        CurveDecomposition d{j - 1, coarse.points, {std::vector<glm::dvec3>(1 << (j - 1))}};
        Curve fine = coarse;
        fine.points = reconstruct(d);
        fine.weights.assign(fine.points.size(), 1.0);
        const Interval dom = domain(coarse);
        fine.knots = clamped_uniform_knots(fine.count(), 3, dom.lo, dom.hi);
        for (int k = 0; k <= 20; ++k) {
            const double t = dom.lo + (dom.hi - dom.lo) * k / 20.0;
            EXPECT_LT(glm::length(*curve_point(fine, t) - *curve_point(coarse, t)), 1e-12);
        }
    }
}

TEST(Multires, CurveDecompositionThenReconstructionIsExact) {
    RandomGeometry g(7);
    for (int J = 1; J <= 7; ++J)
        for (int trial = 0; trial < 3; ++trial) {
            const Curve c = dyadic_curve(g, J);
            for (int j = 0; j <= J; ++j) {
                const CurveDecomposition d = decompose(c.points, J, j);
                ASSERT_EQ(d.coarse.size(), static_cast<std::size_t>((1 << j) + 3));
                ASSERT_EQ(d.details.size(), static_cast<std::size_t>(J - j));
                EXPECT_LT(largest_gap(reconstruct(d), c.points), exact) << J << " -> " << j;
            }
        }
}

TEST(Multires, ACoarseEditKeepsTheDetailAndADetailEditKeepsTheCoarsePoints) {
    RandomGeometry g(21);
    for (int J = 2; J <= 6; ++J)
        for (int j = 0; j < J; ++j) {
            const Curve c = dyadic_curve(g, J);
            const CurveDecomposition before = decompose(c.points, J, j);
            const int i = g.integer(0, static_cast<int>(before.coarse.size()) - 1);
            const glm::dvec3 to = before.coarse[i] + glm::dvec3(1.5, -2, 0.25);
            auto moved = multires_move_coarse_point(c, j, i, to);
            ASSERT_TRUE(moved.ok()) << moved.error().message;
            const CurveDecomposition after = decompose(moved->points, J, j);
            for (std::size_t k = 0; k < before.details.size(); ++k)
                EXPECT_LT(largest_gap(after.details[k], before.details[k]), exact);
            EXPECT_LT(glm::length(after.coarse[i] - to), exact);
            EXPECT_GT(largest_gap(moved->points, c.points), 0.1);

            auto scaled = multires_scale_detail(c, j, 0.25);
            ASSERT_TRUE(scaled.ok()) << scaled.error().message;
            const CurveDecomposition rescaled = decompose(scaled->points, J, j);
            EXPECT_LT(largest_gap(rescaled.coarse, before.coarse), exact);
            for (std::size_t k = 0; k < before.details.size(); ++k) {
                std::vector<glm::dvec3> quarter = before.details[k];
                for (glm::dvec3& x : quarter) x *= 0.25;
                EXPECT_LT(largest_gap(rescaled.details[k], quarter), exact);
            }
        }
}

TEST(Multires, ZeroDetailLeavesTheCoarseCurveItself) {
    RandomGeometry g(5);
    const Curve c = dyadic_curve(g, 4);
    auto smooth = multires_scale_detail(c, 1, 0.0);
    ASSERT_TRUE(smooth.ok());
    Curve coarse = c;
    coarse.points = *multires_coarse_points(c, 1);
    coarse.weights.assign(coarse.points.size(), 1.0);
    const Interval dom = domain(c);
    coarse.knots = clamped_uniform_knots(coarse.count(), 3, dom.lo, dom.hi);
    for (int k = 0; k <= 32; ++k) {
        const double t = dom.lo + (dom.hi - dom.lo) * k / 32.0;
        EXPECT_LT(glm::length(*curve_point(*smooth, t) - *curve_point(coarse, t)), 1e-12);
    }
}

TEST(Multires, SurfaceDecompositionThenReconstructionIsExact) {
    RandomGeometry g(13);
    for (int Ju = 1; Ju <= 4; ++Ju)
        for (int Jv = 1; Jv <= 4; ++Jv) {
            const Surface s = dyadic_surface(g, Ju, Jv);
            for (int ju = 0; ju <= Ju; ++ju)
                for (int jv = 0; jv <= Jv; ++jv) {
                    const SurfaceDecomposition d = decompose(s.points, Ju, Jv, ju, jv);
                    ASSERT_EQ(d.coarse.size(),
                              static_cast<std::size_t>(((1 << ju) + 3) * ((1 << jv) + 3)));
                    EXPECT_LT(largest_gap(reconstruct(d), s.points), exact);
                }
        }
}

void expect_same_detail(const SurfaceDecomposition& a, const SurfaceDecomposition& b,
                        double factor = 1.0) {
    for (auto lines : {std::pair{&a.u_lines, &b.u_lines}, std::pair{&a.v_lines, &b.v_lines}}) {
        ASSERT_EQ(lines.first->size(), lines.second->size());
        for (std::size_t l = 0; l < lines.first->size(); ++l)
            for (std::size_t k = 0; k < (*lines.first)[l].details.size(); ++k) {
                std::vector<glm::dvec3> expected = (*lines.second)[l].details[k];
                for (glm::dvec3& x : expected) x *= factor;
                EXPECT_LT(largest_gap((*lines.first)[l].details[k], expected), exact);
            }
    }
}

TEST(Multires, SurfaceEditsKeepWhatTheyDoNotEdit) {
    RandomGeometry g(17);
    const Surface s = dyadic_surface(g, 3, 2);
    const SurfaceDecomposition before = decompose(s.points, 3, 2, 1, 1);
    auto moved = multires_move_coarse_point(s, 1, 1, 2, 3, glm::dvec3(0, 0, 4));
    ASSERT_TRUE(moved.ok()) << moved.error().message;
    const SurfaceDecomposition after = decompose(moved->points, 3, 2, 1, 1);
    expect_same_detail(after, before);
    EXPECT_LT(glm::length(after.coarse[2 * after.n_v + 3] - glm::dvec3(0, 0, 4)), exact);

    auto scaled = multires_scale_detail(s, 1, 1, 3.0);
    ASSERT_TRUE(scaled.ok());
    const SurfaceDecomposition rescaled = decompose(scaled->points, 3, 2, 1, 1);
    EXPECT_LT(largest_gap(rescaled.coarse, before.coarse), exact);
    expect_same_detail(rescaled, before, 3.0);
}

TEST(Multires, RefusalsNameTheOffendingValue) {
    RandomGeometry g(1);
    Curve c = dyadic_curve(g, 3);
    {
        Curve q = c;
        q.degree = 2;
        q.knots = clamped_uniform_knots(q.count(), 2);
        auto r = multires_level(q);
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().path, "/degree");
        EXPECT_NE(r.error().message.find("degree 2"), std::string::npos) << r.error().message;
    }
    {
        Curve six = g.curve(3, 6, false);
        auto r = multires_level(six);
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().path, "/points");
        EXPECT_NE(r.error().message.find("has 6 control points"), std::string::npos);
    }
    {
        Curve bent = c;
        bent.knots[5] += 0.01;
        auto r = multires_level(bent);
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().path, "/knots/5");
        EXPECT_NE(r.error().message.find("knot 5 = "), std::string::npos) << r.error().message;
    }
    {
        // A NURBS curve with equal weights is a B-spline; one weight apart, it is refused.
        Curve rational = c;
        rational.type = SplineType::nurbs;
        EXPECT_TRUE(multires_level(rational).ok());
        rational.weights[7] = 0.5;
        auto r = multires_level(rational);
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().path, "/weights/7");
        EXPECT_NE(r.error().message.find("NURBS with weight 7 = 0.5 unlike weight 0 = 1"),
                  std::string::npos)
            << r.error().message;
    }
    auto level = multires_coarse_points(c, 4);
    ASSERT_FALSE(level.ok());
    EXPECT_EQ(level.error().path, "/level");
    EXPECT_NE(level.error().message.find("level 4 is outside 0..3"), std::string::npos);
    auto index = multires_move_coarse_point(c, 1, 5, glm::dvec3(0));
    ASSERT_FALSE(index.ok());
    EXPECT_EQ(index.error().path, "/i");
    EXPECT_NE(index.error().message.find("i = 5 is outside 0..4"), std::string::npos)
        << index.error().message;
    auto factor = multires_scale_detail(c, 1, std::nan(""));
    ASSERT_FALSE(factor.ok());
    EXPECT_EQ(factor.error().path, "/detail_scale");

    Surface s = dyadic_surface(g, 2, 2);
    s.knots_v[6] += 0.05;
    auto sr = multires_levels(s);
    ASSERT_FALSE(sr.ok());
    EXPECT_EQ(sr.error().path, "/knots_v/6");
    auto sj = multires_move_coarse_point(dyadic_surface(g, 2, 1), 1, 1, 0, 7, glm::dvec3(0));
    ASSERT_FALSE(sj.ok());
    EXPECT_EQ(sj.error().path, "/j");
}

} // namespace
