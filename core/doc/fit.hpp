// The Fit panel's work: a curve through (or near) data points, or a surface through a grid,
// with how far the result is from every point. The document is not changed: the caller adds
// the object with add_object (one undo step).
#pragma once

#include <string>
#include <vector>

#include "core/doc/document.hpp"
#include "core/geom/interpolate.hpp"

namespace isoparm::doc {

enum class FitMethod { interpolate, approximate };
inline constexpr geom::EnumName<FitMethod> fit_method_names[] = {
    {FitMethod::interpolate, "interpolate", "Interpolate"},
    {FitMethod::approximate, "approximate", "Least squares"},
};
static_assert(geom::in_declaration_order(fit_method_names));
constexpr std::span<const geom::EnumName<FitMethod>> enum_names(FitMethod) {
    return fit_method_names;
}

struct FitSettings {
    FitMethod method = FitMethod::interpolate;
    int degree = 3;
    int count = 6; // approximation: control points, degree + 1 .. number of points
    geom::Parametrization parametrization = geom::Parametrization::chord;
    int degree_v = 3; // a grid: the degree across the rows
    int count_v = 6;  // a grid's least squares: control points along v (count is along u)
};

// The result and its distance to each data point: |C(t_k) - Q_k| (a grid: |S(u_k, v_l) - Q_kl|
// in row-major order), with the largest and the root mean square.
struct Fit {
    Object object;                     // id 0; a curve in `plane` (knot mode custom) or a surface
    std::vector<double> params;        // t_k (a grid: u_k of the rows, then v_l)
    std::vector<glm::dvec3> on_result; // C(t_k) for each point (whisker ends)
    std::vector<double> errors;
    double max_error = 0, rms_error = 0;
};

// Curves: interpolation (A9.1) or least squares with fixed ends (9.4.1, `count` control
// points); errors of the geometry keep their paths ("/points/3", "/degree", "/count").
geom::Expected<Fit> fit_curve(const std::vector<glm::dvec3>& points, const FitSettings& settings,
                              const std::string& name, CurvePlane plane);
// A grid of rows x columns points (row-major) interpolated by A9.4 with degrees
// (settings.degree, settings.degree_v), or fitted by least squares (P&T 9.4.3) with
// (count, count_v) control points; errors keep the geometry's paths ("/count/0", "/grid/3").
geom::Expected<Fit> fit_grid(const std::vector<glm::dvec3>& grid, int rows, int columns,
                             const FitSettings& settings, const std::string& name);

} // namespace isoparm::doc
