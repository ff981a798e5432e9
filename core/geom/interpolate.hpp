// Curve design from points: parametrizations, averaged knots and global interpolation (A9.1).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// How parameters follow the data (Piegl & Tiller 9.2.1): chord length (eq. 9.5), centripetal
// (eq. 9.6, square roots of the chord lengths) or uniform (eq. 9.4, k / K).
enum class Parametrization { chord, centripetal, uniform };
inline constexpr EnumName<Parametrization> parametrization_names[] = {
    {Parametrization::chord, "chord"},
    {Parametrization::centripetal, "centripetal"},
    {Parametrization::uniform, "uniform"},
};
static_assert(in_declaration_order(parametrization_names));
constexpr std::span<const EnumName<Parametrization>> enum_names(Parametrization) {
    return parametrization_names;
}
// The name (name_of), for callers that say it this way.
inline const char* parametrization_name(Parametrization m) {
    return name_of(m);
}

// Parameters t_0 = 0 < ... < t_K = 1 for K + 1 points. Errors (`geometry`): all points
// coincide (path "/points"), or two consecutive points coincide under chord/centripetal, which
// gives two equal parameters and a singular system (path "/points/k" for the second point).
Expected<std::vector<double>> point_params(const std::vector<glm::dvec3>& points,
                                           Parametrization mode);

// Piegl & Tiller eq. 9.8, knots by averaging: for n = params.size() values and degree p
// (1 <= p <= n - 1) the clamped vector 0^(p+1), (1/p) sum_{i=j}^{j+p-1} t_i for j = 1..n-p-1,
// 1^(p+1), on the params' own ends [t_0, t_{n-1}].
Knots averaged_knots(const std::vector<double>& params, int p);

// How the curve designer chooses a knot vector for n control points of degree p: clamped
// uniform, or averaged (eq. 9.8) from the chord / centripetal parameters of the control
// polygon itself, always on [0, 1]. Errors as point_params (a degenerate polygon).
enum class KnotMode { clamped_uniform, chord, centripetal };
Expected<Knots> knots_for_points(const std::vector<glm::dvec3>& points, int p, KnotMode mode);

// Parameters for a net of points, averaged over its lines (Piegl & Tiller A9.4 and eq.
// 9.16-9.18; 9.2.5 for skinning): `lines` lines of K + 1 points each, point(k, l) the k-th point
// of line l. Each line's chord (or centripetal) lengths are normalized to total 1 and the
// resulting parameters averaged over the lines; uniform gives k / K. A line whose lengths sum
// to zero either stops the computation (degenerate_line names it) or, with
// skip_degenerate_lines, is left out of the average as A9.4 does (all_degenerate when no line
// is left). coincident names the first k whose parameter equals the one before (no data can be
// interpolated there); it is not checked for uniform parameters, which never coincide.
struct NetParams {
    std::vector<double> params; // t_0 = 0 < ... < t_K = 1 when nothing below is set
    int degenerate_line = -1;
    bool all_degenerate = false;
    int coincident = -1;
};
NetParams averaged_net_params(int K, int lines,
                              const std::function<glm::dvec3(int k, int l)>& point,
                              Parametrization mode, bool skip_degenerate_lines);

// One row of a banded linear system: the coefficients of unknowns first, first + 1, ...
struct BandedRow {
    int first = 0;
    std::vector<double> values;
};

// Solves the square system whose k-th row is rows[k] for `columns` right-hand sides:
// data[k * columns + c] in, solution in the same layout out. Banded LU with partial pivoting
// (the band is read off the rows). False when the system is singular.
bool solve_banded_rows(const std::vector<BandedRow>& rows, std::vector<double>& data, int columns);

// The collocation rows N_{s-p..s}(t_k) of the degree-p basis on U at each parameter.
std::vector<BandedRow> collocation_rows(const Knots& U, int p, const std::vector<double>& params);

// Points as rows of 3 numbers (the data layout of the solvers below: data[k * 3 + axis]) and
// back.
std::vector<double> points_as_rows(const std::vector<glm::dvec3>& points);
std::vector<glm::dvec3> rows_as_points(const std::vector<double>& data);

// Solves the collocation system sum_j N_j(t_k) X_j = D_k (k, j = 0..n-1) for `columns`
// right-hand sides: data[k * columns + c] in, solution in the same layout out. Banded LU with
// partial pivoting. False when the system is singular.
bool solve_collocation(const Knots& U, int p, const std::vector<double>& params,
                       std::vector<double>& data, int columns);

// The checks every fit of a curve to points starts with: at least 2 points (`schema`,
// "/points"; `fit` names the fit, "interpolation needs at least 2 points, got 1") and a degree
// from lo to hi (`degree`, "/degree"; the message is `rule` = hi, "the degree must lie between
// 1 and the point count - 1 = 4, got 5").
Status check_fit_points(int count, const std::string& fit);
Status check_fit_degree(int degree, int lo, int hi, const std::string& rule);

// Piegl & Tiller A9.1 GlobalCurveInterp: the degree-p B-spline through the points at the
// given mode's parameters, knots by averaging; the curve passes through points[k] at
// params[k]. Errors: fewer than 2 points (`schema`, "/points"), degree < 1 or above
// count - 1 (`degree`, "/degree"), degenerate points as point_params.
struct Interpolated {
    Curve curve;
    std::vector<double> params;
};
Expected<Interpolated> interpolate_curve(const std::vector<glm::dvec3>& points, int degree,
                                         Parametrization mode);

} // namespace isoparm::geom
