// Least-squares curve approximation with fixed end points (Piegl & Tiller 9.4.1).
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <vector>

#include "core/geom/basis.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/fitting.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::geom {

namespace {

// Eq. 9.68-9.69: n + 1 control points of degree p for the parameters t_0..t_m:
// d = (m + 1) / (n - p + 1), and for j = 1..n-p with i = int(j d), alpha = j d - i,
// u_(p+j) = (1 - alpha) t_(i-1) + alpha t_i. Every knot span then holds at least one t_k.
Knots least_squares_knots(const std::vector<double>& t, int p, int count) {
    const int m = static_cast<int>(t.size()) - 1, n = count - 1;
    Knots U(static_cast<size_t>(count) + p + 1);
    for (int k = 0; k <= p; ++k) {
        U[k] = 0.0;
        U[count + k] = 1.0;
    }
    const double d = static_cast<double>(m + 1) / (n - p + 1);
    for (int j = 1; j <= n - p; ++j) {
        const int i = static_cast<int>(j * d);
        const double alpha = j * d - i;
        U[p + j] = (1.0 - alpha) * t[i - 1] + alpha * t[i];
    }
    return U;
}

// Eq. 9.63-9.67: the normal equations (N^T N) P = R for the interior control points P_1..P_(n-1)
// with R_k = Q_k - N_0(t_k) Q_0 - N_n(t_k) Q_m for the interior points k = 1..m-1. N^T N has
// p diagonals on each side of the main one. Returns the interior points, or nothing when the
// system is singular.
std::optional<std::vector<glm::dvec3>> interior_points(const std::vector<glm::dvec3>& Q,
                                                       const std::vector<double>& t, const Knots& U,
                                                       int p, int count) {
    const int m = static_cast<int>(Q.size()) - 1, n = count - 1, unknowns = n - 1;
    if (unknowns == 0) return std::vector<glm::dvec3>{};
    const int width = 2 * p + 1; // row i of N^T N holds columns i - p .. i + p
    std::vector<double> normal(static_cast<size_t>(unknowns) * width, 0.0);
    std::vector<glm::dvec3> rhs(unknowns, glm::dvec3(0.0));
    std::vector<double> N(p + 1);
    for (int k = 1; k < m; ++k) {
        const int s = find_span(U, p, count, t[k]);
        basis_funs(s, t[k], p, U, N.data());
        glm::dvec3 R = Q[k];
        for (int r = 0; r <= p; ++r) {
            if (s - p + r == 0) R -= N[r] * Q[0];
            if (s - p + r == n) R -= N[r] * Q[m];
        }
        for (int r1 = 0; r1 <= p; ++r1) {
            const int i = s - p + r1 - 1; // unknown index of P_(s-p+r1)
            if (i < 0 || i >= unknowns) continue;
            rhs[i] += N[r1] * R;
            for (int r2 = 0; r2 <= p; ++r2) {
                const int j = s - p + r2 - 1;
                if (j < 0 || j >= unknowns) continue;
                normal[static_cast<size_t>(i) * width + (j - i + p)] += N[r1] * N[r2];
            }
        }
    }
    std::vector<BandedRow> rows(unknowns);
    for (int i = 0; i < unknowns; ++i) {
        const int first = std::max(0, i - p), last = std::min(unknowns - 1, i + p);
        rows[i].first = first;
        for (int j = first; j <= last; ++j)
            rows[i].values.push_back(normal[static_cast<size_t>(i) * width + (j - i + p)]);
    }
    std::vector<double> data = points_as_rows(rhs);
    if (!solve_banded_rows(rows, data, 3)) return std::nullopt;
    return rows_as_points(data);
}

} // namespace

Expected<Approximated> approximate_curve(const std::vector<glm::dvec3>& points, int degree,
                                         int count, Parametrization mode) {
    const int total = static_cast<int>(points.size());
    if (Status s = check_fit_points(total, "approximation"); !s) return s.error();
    if (Status s = check_fit_degree(degree, 1, total - 1,
                                    "the degree must lie between 1 and the point count - 1");
        !s)
        return s.error();
    if (count < degree + 1) {
        return make_error(ErrorCode::degree,
                          "a degree-" + std::to_string(degree) + " curve needs at least " +
                              std::to_string(degree + 1) + " control points, got count " +
                              std::to_string(count),
                          "/count");
    }
    if (count > total) {
        return make_error(ErrorCode::schema,
                          "count (the control points) must not exceed the number of points " +
                              std::to_string(total) + ", got " + std::to_string(count),
                          "/count");
    }
    auto t = point_params(points, mode);
    if (!t) return t.error();
    Approximated out;
    out.params = std::move(t).value();
    Curve& c = out.curve;
    c.type = SplineType::bspline;
    c.degree = degree;
    c.knots = least_squares_knots(out.params, degree, count);
    auto interior = interior_points(points, out.params, c.knots, degree, count);
    if (!interior) {
        return make_error(ErrorCode::geometry,
                          "the least-squares system is singular (a knot span holds no data "
                          "parameter)",
                          "/points");
    }
    c.points.reserve(count);
    c.points.push_back(points.front());
    c.points.insert(c.points.end(), interior->begin(), interior->end());
    c.points.push_back(points.back());
    c.weights.assign(count, 1.0);

    double sum = 0.0;
    for (int k = 0; k < total; ++k) {
        const double e = glm::distance(*curve_point(c, out.params[k]), points[k]);
        out.max_error = std::max(out.max_error, e);
        sum += e * e;
    }
    out.rms_error = std::sqrt(sum / total);
    return out;
}

} // namespace isoparm::geom
