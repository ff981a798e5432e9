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
// Several point sets at the same parameters (the columns of a grid) share N^T N: one
// factorisation solves them all, the right-hand sides side by side.
std::optional<std::vector<std::vector<glm::dvec3>>>
interior_points_of_sets(const std::vector<std::vector<glm::dvec3>>& sets,
                        const std::vector<double>& t, const Knots& U, int p, int count) {
    const int m = static_cast<int>(t.size()) - 1, n = count - 1, unknowns = n - 1;
    const std::size_t S = sets.size();
    if (unknowns == 0) return std::vector<std::vector<glm::dvec3>>(S);
    const int width = 2 * p + 1; // row i of N^T N holds columns i - p .. i + p
    std::vector<double> normal(static_cast<size_t>(unknowns) * width, 0.0);
    // rhs[i * S + set]: the right-hand side of unknown i for each set.
    std::vector<glm::dvec3> rhs(static_cast<size_t>(unknowns) * S, glm::dvec3(0.0));
    std::vector<double> N(p + 1);
    std::vector<glm::dvec3> R(S);
    for (int k = 1; k < m; ++k) {
        const int s = find_span(U, p, count, t[k]);
        basis_funs(s, t[k], p, U, N.data());
        for (std::size_t q = 0; q < S; ++q) {
            const std::vector<glm::dvec3>& Q = sets[q];
            R[q] = Q[k];
            for (int r = 0; r <= p; ++r) {
                if (s - p + r == 0) R[q] -= N[r] * Q[0];
                if (s - p + r == n) R[q] -= N[r] * Q[m];
            }
        }
        for (int r1 = 0; r1 <= p; ++r1) {
            const int i = s - p + r1 - 1; // unknown index of P_(s-p+r1)
            if (i < 0 || i >= unknowns) continue;
            for (std::size_t q = 0; q < S; ++q) rhs[static_cast<size_t>(i) * S + q] += N[r1] * R[q];
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
    if (!solve_banded_rows(rows, data, static_cast<int>(3 * S))) return std::nullopt;
    const std::vector<glm::dvec3> solved = rows_as_points(data);
    std::vector<std::vector<glm::dvec3>> out(S);
    for (int i = 0; i < unknowns; ++i)
        for (std::size_t q = 0; q < S; ++q)
            out[q].push_back(solved[static_cast<size_t>(i) * S + q]);
    return out;
}

std::optional<std::vector<glm::dvec3>> interior_points(const std::vector<glm::dvec3>& Q,
                                                       const std::vector<double>& t, const Knots& U,
                                                       int p, int count) {
    auto sets = interior_points_of_sets({Q}, t, U, p, count);
    if (!sets) return std::nullopt;
    return std::move(sets->front());
}

// The count of control points along one direction: p + 1 .. the data points along it.
Status check_count(int count, int p, int points, int axis, const char* dir) {
    if (count < p + 1)
        return make_error(ErrorCode::degree,
                          std::string("a degree-") + std::to_string(p) + " fit in " + dir +
                              " needs at least " + std::to_string(p + 1) + " control points, got " +
                              std::to_string(count),
                          "/count" + pointer_step(axis));
    if (count > points)
        return make_error(ErrorCode::schema,
                          std::string("the control points in ") + dir +
                              " must not exceed the grid's " + std::to_string(points) +
                              " points along it, got " + std::to_string(count),
                          "/count" + pointer_step(axis));
    return Ok{};
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

Expected<ApproximatedSurface> approximate_surface(const std::vector<glm::dvec3>& grid, int rows,
                                                  int columns, int p, int q, int count_u,
                                                  int count_v, Parametrization mode) {
    auto params = grid_params(grid, rows, columns, p, q, mode);
    if (!params) return params.error();
    if (Status s = check_count(count_u, p, rows, 0, "u"); !s) return s.error();
    if (Status s = check_count(count_v, q, columns, 1, "v"); !s) return s.error();
    ApproximatedSurface out;
    out.u_params = std::move(params->u);
    out.v_params = std::move(params->v);
    Surface& S = out.surface;
    S.type = SplineType::bspline;
    S.degree_u = p;
    S.degree_v = q;
    S.n_u = count_u;
    S.n_v = count_v;
    S.knots_u = least_squares_knots(out.u_params, p, count_u);
    S.knots_v = least_squares_knots(out.v_params, q, count_v);
    const auto singular = [] {
        return make_error(ErrorCode::geometry,
                          "the least-squares system is singular (a knot span holds no data "
                          "parameter)",
                          "/grid");
    };
    // Stage 1: each column l (the points Q_kl along u) to count_u points R_il.
    std::vector<std::vector<glm::dvec3>> columns_data(static_cast<size_t>(columns));
    for (int l = 0; l < columns; ++l)
        for (int k = 0; k < rows; ++k)
            columns_data[l].push_back(grid[static_cast<size_t>(k) * columns + l]);
    auto inner_u = interior_points_of_sets(columns_data, out.u_params, S.knots_u, p, count_u);
    if (!inner_u) return singular();
    // R as rows i = 0..count_u - 1 of `columns` points each (fixed ends: the grid's first and
    // last rows).
    std::vector<std::vector<glm::dvec3>> R(static_cast<size_t>(count_u));
    for (int l = 0; l < columns; ++l) {
        R.front().push_back(columns_data[l].front());
        for (int i = 1; i < count_u - 1; ++i) R[i].push_back((*inner_u)[l][i - 1]);
        R.back().push_back(columns_data[l].back());
    }
    // Stage 2: each row of R along v to count_v points.
    auto inner_v = interior_points_of_sets(R, out.v_params, S.knots_v, q, count_v);
    if (!inner_v) return singular();
    S.points.resize(static_cast<size_t>(count_u) * count_v);
    S.weights.assign(S.points.size(), 1.0);
    for (int i = 0; i < count_u; ++i) {
        S.point(i, 0) = R[i].front();
        for (int j = 1; j < count_v - 1; ++j) S.point(i, j) = (*inner_v)[i][j - 1];
        S.point(i, count_v - 1) = R[i].back();
    }
    double sum = 0.0;
    for (int k = 0; k < rows; ++k)
        for (int l = 0; l < columns; ++l) {
            const double e = glm::distance(*surface_point(S, out.u_params[k], out.v_params[l]),
                                           grid[static_cast<size_t>(k) * columns + l]);
            out.max_error = std::max(out.max_error, e);
            sum += e * e;
        }
    out.rms_error = std::sqrt(sum / (static_cast<double>(rows) * columns));
    return out;
}

} // namespace isoparm::geom
