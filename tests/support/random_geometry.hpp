// Random valid curves and surfaces for property tests (seeded: failures reproduce).
#pragma once

#include <algorithm>
#include <random>

#include "core/geom/knots.hpp"
#include "core/geom/types.hpp"

namespace isoparm::testing {

struct RandomGeometry {
    std::mt19937_64 rng;
    explicit RandomGeometry(unsigned seed) : rng(seed) {}

    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
    int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); }

    // A valid knot vector for n points of degree p on [a, b]: clamped or not, with random
    // interior knots, some repeated up to multiplicity max_mult (<= p).
    geom::Knots knots(int n, int p, bool clamped, int max_mult = 1) {
        geom::Knots U;
        const double a = uniform(-2, 0), b = a + uniform(0.5, 3);
        const int total = n + p + 1;
        if (clamped) {
            U.assign(p + 1, a);
            std::vector<double> inner;
            while (static_cast<int>(inner.size()) < n - p - 1) {
                const double t = uniform(a, b);
                const int m =
                    std::min(integer(1, max_mult), n - p - 1 - static_cast<int>(inner.size()));
                for (int k = 0; k < m; ++k) inner.push_back(t);
            }
            std::sort(inner.begin(), inner.end());
            U.insert(U.end(), inner.begin(), inner.end());
            U.insert(U.end(), p + 1, b);
        } else {
            double t = a;
            for (int k = 0; k < total; ++k) {
                U.push_back(t);
                t += uniform(0.1, 1.0);
            }
        }
        return U;
    }

    geom::Curve curve(int p, int n, bool rational, bool clamped = true, int max_mult = 1) {
        geom::Curve c;
        c.type = rational ? geom::SplineType::nurbs : geom::SplineType::bspline;
        c.degree = p;
        c.knots = knots(n, p, clamped, max_mult);
        for (int i = 0; i < n; ++i) {
            c.points.push_back({uniform(-5, 5), uniform(-5, 5), uniform(-5, 5)});
            c.weights.push_back(rational ? uniform(0.2, 4.0) : 1.0);
        }
        return c;
    }

    geom::Surface surface(int p, int q, int nu, int nv, bool rational, bool clamped = true,
                          int max_mult = 1) {
        geom::Surface s;
        s.type = rational ? geom::SplineType::nurbs : geom::SplineType::bspline;
        s.degree_u = p;
        s.degree_v = q;
        s.n_u = nu;
        s.n_v = nv;
        s.knots_u = knots(nu, p, clamped, max_mult);
        s.knots_v = knots(nv, q, clamped, max_mult);
        for (int k = 0; k < nu * nv; ++k) {
            s.points.push_back({uniform(-5, 5), uniform(-5, 5), uniform(-5, 5)});
            s.weights.push_back(rational ? uniform(0.2, 4.0) : 1.0);
        }
        return s;
    }
};

} // namespace isoparm::testing
