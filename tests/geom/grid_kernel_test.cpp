// Every build of the grid kernel (baseline, AVX2, AVX-512: each runs only where the CPU has it
// and is reported SKIPPED elsewhere) and every degree-specialised instantiation against the
// generic run-time-degree code of the baseline build, at 1e-15 relative for positions and
// 4e-15 times the condition for unit normals (see below); and that reference
// against the pointwise evaluator (A4.3 / A4.4), an independent algorithm.
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/geom/evaluate.hpp"
#include "core/geom/grid_tessellator.hpp"
#include "core/geom/knots.hpp"
#include "tests/support/random_geometry.hpp"
#include "tests/support/small_surfaces.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;

namespace {

struct Grid {
    std::vector<glm::dvec3> positions, normals;
    std::vector<std::uint8_t> exists;
};

Grid run(const Surface& s, int su, int sv, kernel::Path path, bool generic, bool normals,
         int threads = 1) {
    GridTessellator t(s, su, sv);
    EXPECT_TRUE(t.use_kernel(path, generic));
    Grid g;
    if (normals)
        t.evaluate_vertices(s, g.positions, g.normals, g.exists, threads);
    else
        t.evaluate_positions(s, g.positions, g.exists, threads);
    return g;
}

double t_u(const Surface& s, int su, size_t i) {
    return uniform_params(s.knots_u[s.degree_u], s.knots_u[s.n_u], su)[i];
}
double t_v(const Surface& s, int sv, size_t j) {
    return uniform_params(s.knots_v[s.degree_v], s.knots_v[s.n_v], sv)[j];
}

// How much the quotient by w = sum N_i w_i amplifies rounding: sum N_i |w_i| / |w| (1 where
// every weight is positive), read from two surfaces whose projected x is 1 / w and 1 / sum N|w|.
double weight_condition(const Surface& s, double u, double v) {
    Surface a = s, b = s;
    for (size_t k = 0; k < s.weights.size(); ++k) {
        a.points[k] = {1.0 / s.weights[k], 0, 0};
        b.weights[k] = std::abs(s.weights[k]);
        b.points[k] = {1.0 / b.weights[k], 0, 0};
    }
    const auto x = surface_point(a, u, v), y = surface_point(b, u, v);
    return x && y ? std::abs(x->x / y->x) : 1e300;
}

// The rounding the rational first derivatives carry, relative to their size: S_u =
// (A_u - w_u S) / w loses digits where w_u S is large against w S_u (1 for polynomial
// surfaces). w_u comes from the surface whose projected x is 1 / w: x_u = -w_u / w^2.
double derivative_condition(const Surface& s, double u, double v, double size) {
    Surface a = s;
    for (size_t k = 0; k < s.weights.size(); ++k) a.points[k] = {1.0 / s.weights[k], 0, 0};
    const auto da = surface_derivatives(a, u, v, 1), d = surface_derivatives(s, u, v, 1);
    if (!da || !d) return 1e300;
    const double w = 1.0 / da->D[0][0].x;
    const double wu = -da->D[1][0].x * w * w, wv = -da->D[0][1].x * w * w;
    const double S = std::max(size, glm::length(d->D[0][0]));
    const double ku = 1 + std::abs(wu) * S / std::abs(w * glm::length(d->D[1][0]));
    const double kv = 1 + std::abs(wv) * S / std::abs(w * glm::length(d->D[0][1]));
    return std::max(ku, kv);
}

double net_size(const Surface& s) {
    double m = 0;
    for (const auto& p : s.points) m = std::max(m, glm::length(p));
    return m;
}

// The surfaces of the comparison: every degree pair 1..5, some beyond (the generic code),
// polynomial and rational, weights of both signs, nets from the smallest (n = degree + 1, the
// band is the whole net) to many spans per sample.
std::vector<Surface> surfaces() {
    RandomGeometry g(2222);
    std::vector<Surface> out;
    for (int p = 1; p <= 5; ++p)
        for (int q = 1; q <= 5; ++q) out.push_back(g.surface(p, q, p + 4, q + 7, (p + q) % 2 == 0));
    for (auto [p, q] : {std::pair{6, 7}, {7, 6}, {6, 2}, {3, 7}})
        out.push_back(g.surface(p, q, p + 3, q + 5, true));
    out.push_back(g.surface(3, 3, 4, 4, true));   // one span each way
    out.push_back(g.surface(2, 3, 60, 70, true)); // several spans per sample
    Surface mixed = g.surface(3, 2, 9, 8, true);  // weights of both signs: a pole curve
    for (auto& w : mixed.weights) w = g.uniform(-1.0, 2.0);
    out.push_back(mixed);
    return out;
}

class GridKernelPath : public ::testing::TestWithParam<kernel::Path> {};

TEST_P(GridKernelPath, AgreesWithTheGenericBaselineAt1e15) {
    const kernel::Path path = GetParam();
    if (!kernel::supported(path))
        GTEST_SKIP() << "this CPU (or build) has no " << kernel::name(path) << " kernel";
    double worst_p = 0, worst_n = 0;
    for (const Surface& s : surfaces()) {
        // Sample counts that are not multiples of 4 or 8: partial chunks at the block ends.
        const int su = 37, sv = 77;
        const double size = net_size(s);
        for (bool normals : {false, true}) {
            const Grid ref = run(s, su, sv, kernel::Path::baseline, true, normals);
            const Grid spec = run(s, su, sv, path, false, normals);
            const Grid gen = run(s, su, sv, path, true, normals);
            // The specialised instantiations do what the generic one does, bit for bit.
            EXPECT_EQ(spec.positions, gen.positions);
            EXPECT_EQ(spec.normals, gen.normals);
            EXPECT_EQ(spec.exists, ref.exists);
            for (size_t k = 0; k < ref.positions.size(); ++k) {
                if (!ref.exists.empty() && !ref.exists[k]) continue;
                const double u = t_u(s, su, k / sv), v = t_v(s, sv, k % sv);
                const double kw = weight_condition(s, u, v);
                const double scale = kw * std::max(size, glm::length(ref.positions[k]));
                const double e = glm::length(spec.positions[k] - ref.positions[k]) / scale;
                worst_p = std::max(worst_p, e);
                EXPECT_LE(e, 1e-15) << "degrees " << s.degree_u << ", " << s.degree_v;
                if (!normals) continue;
                // A unit normal from S_u x S_v carries the rounding of S_u and S_v (amplified
                // by the quotient rule) times |S_u| |S_v| / |S_u x S_v| (1 for orthogonal
                // derivatives).
                const auto d = surface_derivatives(s, u, v, 1);
                ASSERT_TRUE(d);
                const glm::dvec3 Su = d->D[1][0], Sv = d->D[0][1];
                const double cond =
                    glm::length(Su) * glm::length(Sv) / glm::length(glm::cross(Su, Sv));
                const double en = glm::length(spec.normals[k] - ref.normals[k]) /
                                  (cond * kw * derivative_condition(s, u, v, size));
                worst_n = std::max(worst_n, en);
                // Positions hold 1e-15; normals, about ten roundings deep, 4e-15 of that.
                // Why not 1e-15: the paths differ only where an FMA rounds once what the
                // baseline rounds twice, in the sums of the derivatives, and those sums cancel
                // (basis derivatives of both signs), which this scale does not divide out; no
                // formula applied after the sums removes that. Measured on these surfaces: 18
                // of 91168 vertices exceed 1e-15, the worst (2.4e-15) where the terms of S_u
                // are 56 times |S_u|. Without FMA the AVX2 build equals the baseline bit for
                // bit (checked), but was 5-8% slower on one thread (Zen 3): FMA is kept.
                EXPECT_LE(en, 4e-15) << "degrees " << s.degree_u << ", " << s.degree_v;
            }
        }
    }
    std::printf("  %s: worst relative position difference %.3g, normal %.3g (x condition)\n",
                kernel::name(path), worst_p, worst_n);
}

TEST_P(GridKernelPath, PointsThatDoNotExistAndLocalUpdates) {
    const kernel::Path path = GetParam();
    if (!kernel::supported(path))
        GTEST_SKIP() << "this CPU (or build) has no " << kernel::name(path) << " kernel";
    // Weights (1, -1) in u: the denominator is exactly zero along u = 0.5.
    const Surface s = isoparm::testing::bilinear_patch(1, 1, -1, -1);
    for (bool normals : {false, true}) {
        const Grid g = run(s, 5, 13, path, false, normals);
        ASSERT_EQ(g.exists.size(), 65u);
        for (int k = 0; k < 65; ++k) EXPECT_EQ(g.exists[k] != 0, k / 13 != 2) << k;
    }
    // A local update through this path equals its full pass, bit for bit.
    RandomGeometry r(77);
    for (int trial = 0; trial < 6; ++trial) {
        Surface t = r.surface(1 + trial % 5, 1 + (trial + 2) % 5, 11, 13, true);
        GridTessellator tess(t, 41, 45);
        ASSERT_TRUE(tess.use_kernel(path));
        Mesh mesh;
        tess.evaluate(t, mesh);
        const int i = r.integer(0, t.n_u - 1), j = r.integer(0, t.n_v - 1);
        t.point(i, j) += glm::dvec3(0.4, -0.1, 0.3);
        t.weight(i, j) *= 1.3;
        tess.update_control_point(t, mesh, i, j);
        Mesh full;
        tess.evaluate(t, full, 2);
        EXPECT_EQ(mesh.positions, full.positions);
        EXPECT_EQ(mesh.normals, full.normals);
    }
}

// The two FMA paths run the same multiply-adds in the same order (only the lanes per vector
// and the output's interleaving differ): the same bits, which the protocol recordings
// (tests/identity) rely on whichever of the two the dispatch takes.
TEST(GridKernel, Avx2AndAvx512GiveTheSameBits) {
    if (!kernel::supported(kernel::Path::avx2) || !kernel::supported(kernel::Path::avx512))
        GTEST_SKIP() << "this CPU (or build) lacks AVX2 or AVX-512";
    for (const Surface& s : surfaces())
        for (bool normals : {false, true})
            for (int threads : {1, 2}) {
                // 77 columns: partial chunks at the ends; 67 x 256 as the benchmarks' rows.
                for (auto [su, sv] : {std::pair{37, 77}, {67, 256}}) {
                    const Grid a = run(s, su, sv, kernel::Path::avx2, false, normals, threads);
                    const Grid b = run(s, su, sv, kernel::Path::avx512, false, normals, threads);
                    ASSERT_EQ(a.positions.size(), b.positions.size());
                    ASSERT_EQ(a.normals.size(), b.normals.size());
                    const size_t bytes = a.positions.size() * sizeof(glm::dvec3);
                    EXPECT_EQ(std::memcmp(a.positions.data(), b.positions.data(), bytes), 0)
                        << s.degree_u << " " << s.degree_v << " " << su << "x" << sv;
                    if (normals) {
                        EXPECT_EQ(std::memcmp(a.normals.data(), b.normals.data(), bytes), 0)
                            << s.degree_u << " " << s.degree_v << " " << su << "x" << sv;
                    }
                    EXPECT_EQ(a.exists, b.exists);
                }
            }
}

INSTANTIATE_TEST_SUITE_P(Paths, GridKernelPath,
                         ::testing::Values(kernel::Path::baseline, kernel::Path::avx2,
                                           kernel::Path::avx512),
                         [](const auto& info) { return std::string(kernel::name(info.param)); });

// The reference itself against the pointwise evaluator (a different algorithm: A4.3 / A4.4).
TEST(GridKernel, GenericBaselineMatchesPointwiseEvaluation) {
    for (const Surface& s : surfaces()) {
        const int su = 19, sv = 23;
        const Grid g = run(s, su, sv, kernel::Path::baseline, true, true);
        const double size = net_size(s);
        for (int i = 0; i < su; ++i) {
            for (int j = 0; j < sv; ++j) {
                const size_t k = static_cast<size_t>(i) * sv + j;
                const auto p = surface_point(s, t_u(s, su, i), t_v(s, sv, j));
                ASSERT_EQ(p.has_value(), g.exists.empty() || g.exists[k]);
                if (!p) continue;
                EXPECT_LE(glm::length(*p - g.positions[k]),
                          1e-12 * std::max(size, glm::length(*p)));
                const glm::dvec3 n = surface_normal_or_limit(s, t_u(s, su, i), t_v(s, sv, j));
                EXPECT_LE(glm::length(n - g.normals[k]), 1e-8) << s.degree_u << " " << s.degree_v;
            }
        }
    }
}

TEST(GridKernel, ActivePathIsSupportedAndNamed) {
    EXPECT_TRUE(kernel::supported(kernel::active_path()));
    EXPECT_TRUE(kernel::supported(kernel::Path::baseline));
    std::printf("  active kernel: %s\n", kernel::name(kernel::active_path()));
}

} // namespace
