// Parametrization (P&T 9.2.1), knot averaging (eq. 9.8) and global interpolation (A9.1).
#include "core/geom/interpolate.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/banded_lu.hpp"
#include "core/geom/basis.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::geom {

Expected<std::vector<double>> point_params(const std::vector<glm::dvec3>& points,
                                           Parametrization mode) {
    const int K = static_cast<int>(points.size()) - 1;
    assert(K >= 1);
    std::vector<double> t(K + 1, 0.0);
    if (mode == Parametrization::uniform) {
        for (int k = 1; k < K; ++k) t[k] = static_cast<double>(k) / K;
        t[K] = 1.0;
        return t;
    }
    std::vector<double> d(K + 1, 0.0);
    double total = 0.0;
    for (int k = 1; k <= K; ++k) {
        d[k] = glm::distance(points[k], points[k - 1]);
        if (mode == Parametrization::centripetal) d[k] = std::sqrt(d[k]);
        total += d[k];
    }
    if (!(total > 0.0))
        return make_error(ErrorCode::geometry,
                          "all points coincide, so they cannot be parametrized", "/points");
    for (int k = 1; k <= K; ++k) {
        if (d[k] == 0.0) {
            return make_error(ErrorCode::geometry,
                              "point " + std::to_string(k) + " coincides with point " +
                                  std::to_string(k - 1) + ", which gives two equal parameters",
                              "/points/" + std::to_string(k));
        }
    }
    for (int k = 1; k < K; ++k) t[k] = t[k - 1] + d[k] / total;
    t[K] = 1.0;
    return t;
}

Knots averaged_knots(const std::vector<double>& params, int p) {
    const int n = static_cast<int>(params.size());
    assert(p >= 1 && p <= n - 1);
    Knots U(static_cast<size_t>(n) + p + 1);
    for (int k = 0; k <= p; ++k) {
        U[k] = params.front();
        U[n + k] = params.back();
    }
    for (int j = 1; j <= n - p - 1; ++j) {
        double s = 0.0;
        for (int i = j; i <= j + p - 1; ++i) s += params[i];
        U[j + p] = s / p;
    }
    return U;
}

Expected<Knots> knots_for_points(const std::vector<glm::dvec3>& points, int p, KnotMode mode) {
    const int n = static_cast<int>(points.size());
    assert(p >= 1 && n >= p + 1);
    if (mode == KnotMode::clamped_uniform) return clamped_uniform_knots(n, p);
    auto t = point_params(points, mode == KnotMode::chord ? Parametrization::chord
                                                          : Parametrization::centripetal);
    if (!t) return t.error();
    return averaged_knots(*t, p);
}

bool solve_collocation(const Knots& U, int p, const std::vector<double>& params,
                       std::vector<double>& data, int columns) {
    const int n = static_cast<int>(params.size());
    assert(static_cast<int>(U.size()) == n + p + 1);
    assert(static_cast<int>(data.size()) == n * columns);
    // Row k holds N_{s-p..s}(t_k): find the band first, then fill it.
    std::vector<int> first(n);
    std::vector<double> N(static_cast<size_t>(n) * (p + 1));
    int kl = 0, ku = 0;
    for (int k = 0; k < n; ++k) {
        const int s = find_span(U, p, n, params[k]);
        basis_funs(s, params[k], p, U, &N[static_cast<size_t>(k) * (p + 1)]);
        first[k] = s - p;
        kl = std::max(kl, k - first[k]);
        ku = std::max(ku, s - k);
    }
    BandedLU lu(n, kl, ku);
    for (int k = 0; k < n; ++k)
        for (int r = 0; r <= p; ++r) {
            const int j = first[k] + r;
            if (j - k <= ku && k - j <= kl) lu.set(k, j, N[static_cast<size_t>(k) * (p + 1) + r]);
        }
    if (!lu.factor()) return false;
    std::vector<double> column(n);
    for (int c = 0; c < columns; ++c) {
        for (int k = 0; k < n; ++k) column[k] = data[static_cast<size_t>(k) * columns + c];
        lu.solve(column.data());
        for (int k = 0; k < n; ++k) data[static_cast<size_t>(k) * columns + c] = column[k];
    }
    return true;
}

Expected<Interpolated> interpolate_curve(const std::vector<glm::dvec3>& points, int degree,
                                         Parametrization mode) {
    const int n = static_cast<int>(points.size());
    if (n < 2)
        return make_error(ErrorCode::schema,
                          "interpolation needs at least 2 points, got " + std::to_string(n),
                          "/points");
    if (degree < 1 || degree > n - 1) {
        return make_error(ErrorCode::degree,
                          "the degree must lie between 1 and the point count - 1 = " +
                              std::to_string(n - 1) + ", got " + std::to_string(degree),
                          "/degree");
    }
    auto t = point_params(points, mode);
    if (!t) return t.error();
    Interpolated out;
    out.params = std::move(t).value();
    Curve& c = out.curve;
    c.type = SplineType::bspline;
    c.degree = degree;
    c.knots = averaged_knots(out.params, degree);
    std::vector<double> data(static_cast<size_t>(n) * 3);
    for (int k = 0; k < n; ++k)
        for (int a = 0; a < 3; ++a) data[static_cast<size_t>(k) * 3 + a] = points[k][a];
    if (!solve_collocation(c.knots, degree, out.params, data, 3))
        return make_error(ErrorCode::geometry, "the interpolation system is singular", "/points");
    c.points.resize(n);
    c.weights.assign(n, 1.0);
    for (int k = 0; k < n; ++k)
        c.points[k] = {data[static_cast<size_t>(k) * 3], data[static_cast<size_t>(k) * 3 + 1],
                       data[static_cast<size_t>(k) * 3 + 2]};
    return out;
}

} // namespace isoparm::geom
