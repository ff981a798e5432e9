// Curve design from points: parametrizations, averaged knots and global interpolation (A9.1).
#pragma once

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

// Solves the collocation system sum_j N_j(t_k) X_j = D_k (k, j = 0..n-1) for `columns`
// right-hand sides: data[k * columns + c] in, solution in the same layout out. Banded LU with
// partial pivoting. False when the system is singular.
bool solve_collocation(const Knots& U, int p, const std::vector<double>& params,
                       std::vector<double>& data, int columns);

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
