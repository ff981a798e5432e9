// Basis functions: partition of unity, non-negativity, derivatives, worked examples.
#include <gtest/gtest.h>

#include <numeric>

#include "core/geom/basis.hpp"
#include "core/geom/knots.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;

TEST(Basis, PiegTillerExample2_3) {
    // The NURBS Book, Ex. 2.3: U = {0,0,0,1,2,3,4,4,5,5,5}, p = 2, u = 5/2:
    // N_{2,2} = 1/8, N_{3,2} = 6/8, N_{4,2} = 1/8.
    const Knots U{0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5};
    const BasisAt b = basis_at(U, 2, 8, 2.5);
    EXPECT_EQ(b.span, 4);
    EXPECT_DOUBLE_EQ(b.values[0][0], 1.0 / 8);
    EXPECT_DOUBLE_EQ(b.values[0][1], 6.0 / 8);
    EXPECT_DOUBLE_EQ(b.values[0][2], 1.0 / 8);
    // Ex. 2.4: derivatives at 5/2: N'_{2,2} = -1/2, N'_{3,2} = 0, N'_{4,2} = 1/2.
    const BasisAt d = basis_at(U, 2, 8, 2.5, 2);
    EXPECT_DOUBLE_EQ(d.values[1][0], -0.5);
    EXPECT_NEAR(d.values[1][1], 0.0, 1e-15);
    EXPECT_DOUBLE_EQ(d.values[1][2], 0.5);
    EXPECT_DOUBLE_EQ(d.values[2][0], 1.0);
    EXPECT_DOUBLE_EQ(d.values[2][1], -2.0);
    EXPECT_DOUBLE_EQ(d.values[2][2], 1.0);
}

TEST(Basis, PartitionOfUnityAndNonNegativityEverywhere) {
    RandomGeometry g(7);
    for (int trial = 0; trial < 200; ++trial) {
        const int p = g.integer(1, 9), n = g.integer(p + 1, p + 12);
        const Knots U = g.knots(n, p, trial % 2 == 0, p);
        const Interval dom = domain(U, p, n);
        std::vector<double> ts{dom.lo, dom.hi};
        for (int k = p; k <= n; ++k) ts.push_back(U[k]); // every knot in the domain
        for (int k = 0; k < 20; ++k) ts.push_back(g.uniform(dom.lo, dom.hi));
        for (double t : ts) {
            const auto N = all_basis(U, p, n, t, std::min(3, p));
            double sum = 0;
            for (double v : N[0]) {
                EXPECT_GE(v, -1e-15);
                sum += v;
            }
            EXPECT_NEAR(sum, 1.0, 1e-13) << "p=" << p << " t=" << t;
            for (size_t k = 1; k < N.size(); ++k) { // derivatives of a constant sum vanish
                const double dsum = std::accumulate(N[k].begin(), N[k].end(), 0.0);
                const double scale =
                    std::accumulate(N[k].begin(), N[k].end(), 0.0,
                                    [](double a, double b) { return a + std::abs(b); });
                EXPECT_NEAR(dsum, 0.0, 1e-11 * (1 + scale));
            }
        }
    }
}

TEST(Basis, DerivativesMatchFiniteDifferences) {
    RandomGeometry g(11);
    for (int trial = 0; trial < 100; ++trial) {
        const int p = g.integer(1, 6), n = g.integer(p + 1, p + 8);
        const Knots U = g.knots(n, p, true);
        const Interval dom = domain(U, p, n);
        const double t = g.uniform(dom.lo, dom.hi);
        const double h = 1e-6 * (dom.hi - dom.lo);
        if (t - h < dom.lo || t + h > dom.hi) continue;
        // Skip samples too close to a knot (the derivative jumps there).
        bool near_knot = false;
        for (double k : U) near_knot |= std::abs(k - t) < 2 * h;
        if (near_knot) continue;
        const auto N = all_basis(U, p, n, t, 1);
        const auto Np = all_basis(U, p, n, t + h, 0), Nm = all_basis(U, p, n, t - h, 0);
        for (int i = 0; i < n; ++i)
            EXPECT_NEAR(N[1][i], (Np[0][i] - Nm[0][i]) / (2 * h), 1e-5 * (1 + std::abs(N[1][i])));
    }
}

TEST(Basis, DerivativesAboveDegreeAreZero) {
    const Knots U{0, 0, 1, 1};
    const auto N = all_basis(U, 1, 2, 0.3, 3);
    EXPECT_EQ(N[2][0], 0.0);
    EXPECT_EQ(N[3][1], 0.0);
    EXPECT_DOUBLE_EQ(N[1][0], -1.0);
}

TEST(Basis, RationalBasisSumsToOneWithNegativeWeights) {
    const Knots U{0, 0, 0, 0.5, 1, 1, 1};
    const std::vector<double> w{1, -0.5, 2, 1};
    for (double t : {0.0, 0.1, 0.5, 0.77, 1.0}) {
        auto R = rational_basis(U, 2, w, t, 2);
        ASSERT_TRUE(R.has_value());
        EXPECT_NEAR(std::accumulate((*R)[0].begin(), (*R)[0].end(), 0.0), 1.0, 1e-13);
        EXPECT_NEAR(std::accumulate((*R)[1].begin(), (*R)[1].end(), 0.0), 0.0, 1e-11);
    }
}

TEST(Basis, RationalBasisAbsentWhereDenominatorVanishes) {
    // w = (1, -1): W(t) = (1 - t) - t vanishes at t = 0.5 exactly.
    auto R = rational_basis({0, 0, 1, 1}, 1, {1, -1}, 0.5, 0);
    EXPECT_FALSE(R.has_value());
    EXPECT_TRUE(rational_basis({0, 0, 1, 1}, 1, {1, -1}, 0.25, 0).has_value());
}

TEST(Basis, RationalBasisMatchesReferenceExample) {
    // Shared example 0036: degree 2, U = 0..6, weights (1, 2, 0.5, 1) at t = 2.
    auto R = rational_basis({0, 1, 2, 3, 4, 5, 6}, 2, {1, 2, 0.5, 1}, 2.0, 2);
    ASSERT_TRUE(R);
    EXPECT_NEAR((*R)[0][0], 1.0 / 3, 1e-15);
    EXPECT_NEAR((*R)[0][1], 2.0 / 3, 1e-15);
    EXPECT_NEAR((*R)[1][0], -0.8888888888888888, 1e-14);
    EXPECT_NEAR((*R)[2][0], 2.4074074074074074, 1e-13);
    EXPECT_NEAR((*R)[2][1], -2.740740740740741, 1e-13);
    EXPECT_NEAR((*R)[2][2], 1.0 / 3, 1e-14);
}

TEST(Basis, RationalBasisIjOfSurface) {
    RandomGeometry g(3);
    const Surface s = g.surface(3, 2, 6, 5, true);
    const Interval du = domain(s.knots_u, 3, 6), dv = domain(s.knots_v, 2, 5);
    const double u = 0.5 * (du.lo + du.hi), v = 0.3 * dv.lo + 0.7 * dv.hi;
    double sum = 0;
    for (int i = 0; i < s.n_u; ++i)
        for (int j = 0; j < s.n_v; ++j) sum += *rational_basis_ij(s, i, j, u, v);
    EXPECT_NEAR(sum, 1.0, 1e-13);
}
