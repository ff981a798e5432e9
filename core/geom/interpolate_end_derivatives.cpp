// Global interpolation with end derivatives specified (Piegl & Tiller 9.2.2, eq. 9.21-9.22).
#include <vector>

#include "core/geom/basis.hpp"
#include "core/geom/fitting.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::geom {

namespace {

// Eq. 9.22: K + 3 control points of degree p on [0, 1]; interior knots
// u_(j+p+1) = (1/p) sum_(i=j)^(j+p-1) t_i for j = 0..K-p+1. For p >= 2 every average lies
// strictly inside (0, 1) and they increase, so no knot repeats more than p times.
Knots end_derivative_knots(const std::vector<double>& t, int p) {
    const int K = static_cast<int>(t.size()) - 1;
    const int count = K + 3;
    Knots U(static_cast<size_t>(count) + p + 1);
    for (int k = 0; k <= p; ++k) {
        U[k] = 0.0;
        U[count + k] = 1.0;
    }
    for (int j = 0; j <= K - p + 1; ++j) {
        double s = 0.0;
        for (int i = j; i <= j + p - 1; ++i) s += t[i];
        U[j + p + 1] = s / p;
    }
    return U;
}

// The row sum_j N'_j(t) X_j: the first derivative of the curve at t.
BandedRow derivative_row(const Knots& U, int p, int count, double t) {
    const int s = find_span(U, p, count, t);
    std::vector<double> ders(static_cast<size_t>(2) * (p + 1));
    ders_basis_funs(s, t, p, 1, U, ders.data());
    return {s - p, std::vector<double>(ders.begin() + (p + 1), ders.end())};
}

} // namespace

Expected<Interpolated> interpolate_curve_with_end_derivatives(const std::vector<glm::dvec3>& points,
                                                              int degree, Parametrization mode,
                                                              const glm::dvec3& start,
                                                              const glm::dvec3& end) {
    const int points_count = static_cast<int>(points.size());
    if (Status s = check_fit_points(points_count, "interpolation"); !s) return s.error();
    const int count = points_count + 2, p = degree;
    if (Status s = check_fit_degree(p, 2, count - 1,
                                    "with end derivatives the degree must lie between 2 (a "
                                    "degree-1 curve's end derivatives are its first and last "
                                    "legs) and the control point count - 1");
        !s)
        return s.error();
    auto t = point_params(points, mode);
    if (!t) return t.error();
    Interpolated out;
    out.params = std::move(t).value();
    const std::vector<double>& params = out.params;
    Curve& c = out.curve;
    c.type = SplineType::bspline;
    c.degree = p;
    c.knots = end_derivative_knots(params, p);

    // Eq. 9.21: P_0 = Q_0, C'(0) = D_0, C(t_k) = Q_k (k = 1..K-1), C'(1) = D_K, P_(K+2) = Q_K,
    // in this order so that the matrix stays banded.
    const int K = points_count - 1;
    std::vector<BandedRow> rows;
    rows.reserve(count);
    std::vector<glm::dvec3> rhs;
    rhs.reserve(count);
    rows.push_back({0, {1.0}});
    rhs.push_back(points[0]);
    rows.push_back(derivative_row(c.knots, p, count, 0.0));
    rhs.push_back(start);
    const std::vector<double> inner(params.begin() + 1, params.end() - 1);
    std::vector<BandedRow> inner_rows = collocation_rows(c.knots, p, inner);
    for (int k = 1; k < K; ++k) {
        rows.push_back(std::move(inner_rows[k - 1]));
        rhs.push_back(points[k]);
    }
    rows.push_back(derivative_row(c.knots, p, count, 1.0));
    rhs.push_back(end);
    rows.push_back({count - 1, {1.0}});
    rhs.push_back(points[K]);

    std::vector<double> data = points_as_rows(rhs);
    if (!solve_banded_rows(rows, data, 3))
        return make_error(ErrorCode::geometry, "the interpolation system is singular", "/points");
    c.points = rows_as_points(data);
    c.weights.assign(count, 1.0);
    return out;
}

} // namespace isoparm::geom
