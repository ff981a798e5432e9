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

NetParams averaged_net_params(int K, int lines,
                              const std::function<glm::dvec3(int k, int l)>& point,
                              Parametrization mode, bool skip_degenerate_lines) {
    NetParams out;
    std::vector<double>& t = out.params;
    t.assign(K + 1, 0.0);
    if (mode == Parametrization::uniform) {
        for (int k = 1; k < K; ++k) t[k] = static_cast<double>(k) / K;
        t[K] = 1.0;
        return out;
    }
    std::vector<double> d(K + 1);
    int used = 0;
    for (int l = 0; l < lines; ++l) {
        double total = 0.0;
        for (int k = 1; k <= K; ++k) {
            d[k] = glm::distance(point(k, l), point(k - 1, l));
            if (mode == Parametrization::centripetal) d[k] = std::sqrt(d[k]);
            total += d[k];
        }
        if (!(total > 0.0)) {
            if (skip_degenerate_lines) continue;
            out.degenerate_line = l;
            return out;
        }
        ++used;
        double acc = 0.0;
        for (int k = 1; k < K; ++k) {
            acc += d[k];
            t[k] += acc / total;
        }
    }
    if (used == 0) {
        out.all_degenerate = true;
        return out;
    }
    for (int k = 1; k < K; ++k) t[k] /= used;
    t[K] = 1.0;
    for (int k = 1; k <= K; ++k) {
        if (!(t[k] > t[k - 1])) {
            out.coincident = k;
            return out;
        }
    }
    return out;
}

bool solve_banded_rows(const std::vector<BandedRow>& rows, std::vector<double>& data, int columns) {
    const int n = static_cast<int>(rows.size());
    assert(static_cast<int>(data.size()) == n * columns);
    int kl = 0, ku = 0;
    for (int k = 0; k < n; ++k) {
        const int last = rows[k].first + static_cast<int>(rows[k].values.size()) - 1;
        kl = std::max(kl, k - rows[k].first);
        ku = std::max(ku, last - k);
    }
    BandedLU lu(n, kl, ku);
    for (int k = 0; k < n; ++k)
        for (size_t r = 0; r < rows[k].values.size(); ++r)
            lu.set(k, rows[k].first + static_cast<int>(r), rows[k].values[r]);
    if (!lu.factor()) return false;
    std::vector<double> column(n);
    for (int c = 0; c < columns; ++c) {
        for (int k = 0; k < n; ++k) column[k] = data[static_cast<size_t>(k) * columns + c];
        lu.solve(column.data());
        for (int k = 0; k < n; ++k) data[static_cast<size_t>(k) * columns + c] = column[k];
    }
    return true;
}

std::vector<BandedRow> collocation_rows(const Knots& U, int p, const std::vector<double>& params) {
    const int n = static_cast<int>(U.size()) - p - 1;
    std::vector<BandedRow> rows(params.size());
    for (size_t k = 0; k < params.size(); ++k) {
        const int s = find_span(U, p, n, params[k]);
        rows[k].first = s - p;
        rows[k].values.resize(p + 1);
        basis_funs(s, params[k], p, U, rows[k].values.data());
    }
    return rows;
}

std::vector<double> points_as_rows(const std::vector<glm::dvec3>& points) {
    std::vector<double> data(points.size() * 3);
    for (size_t k = 0; k < points.size(); ++k)
        for (int a = 0; a < 3; ++a) data[k * 3 + a] = points[k][a];
    return data;
}

std::vector<glm::dvec3> rows_as_points(const std::vector<double>& data) {
    std::vector<glm::dvec3> points(data.size() / 3);
    for (size_t k = 0; k < points.size(); ++k)
        points[k] = {data[k * 3], data[k * 3 + 1], data[k * 3 + 2]};
    return points;
}

bool solve_collocation(const Knots& U, int p, const std::vector<double>& params,
                       std::vector<double>& data, int columns) {
    assert(U.size() == params.size() + p + 1);
    return solve_banded_rows(collocation_rows(U, p, params), data, columns);
}

Status check_fit_points(int count, const std::string& fit) {
    if (count >= 2) return Ok{};
    return make_error(ErrorCode::schema,
                      fit + " needs at least 2 points, got " + std::to_string(count), "/points");
}

Status check_fit_degree(int degree, int lo, int hi, const std::string& rule) {
    if (degree >= lo && degree <= hi) return Ok{};
    return make_error(ErrorCode::degree,
                      rule + " = " + std::to_string(hi) + ", got " + std::to_string(degree),
                      "/degree");
}

Expected<Interpolated> interpolate_curve(const std::vector<glm::dvec3>& points, int degree,
                                         Parametrization mode) {
    const int n = static_cast<int>(points.size());
    if (Status s = check_fit_points(n, "interpolation"); !s) return s.error();
    if (Status s = check_fit_degree(degree, 1, n - 1,
                                    "the degree must lie between 1 and the point count - 1");
        !s)
        return s.error();
    auto t = point_params(points, mode);
    if (!t) return t.error();
    Interpolated out;
    out.params = std::move(t).value();
    Curve& c = out.curve;
    c.type = SplineType::bspline;
    c.degree = degree;
    c.knots = averaged_knots(out.params, degree);
    std::vector<double> data = points_as_rows(points);
    if (!solve_collocation(c.knots, degree, out.params, data, 3))
        return make_error(ErrorCode::geometry, "the interpolation system is singular", "/points");
    c.points = rows_as_points(data);
    c.weights.assign(n, 1.0);
    return out;
}

} // namespace isoparm::geom
