// Fitting curves and surfaces to data points: interpolation with end derivatives (P&T 9.2.2),
// surface interpolation through a grid (A9.4) and least-squares approximation (9.4.1). Plain
// curve interpolation (A9.1) and the parametrizations are in interpolate.hpp.
#pragma once

#include <vector>

#include "core/geom/interpolate.hpp"
#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// Error paths are those of the protocol's requests ("/points/3", "/grid/2", "/degree",
// "/count"), so the protocol passes them through unchanged.

// Piegl & Tiller 9.2.2: the degree-p B-spline through the K + 1 points (at the mode's
// parameters t_k) whose derivatives at the ends are C'(0) = start and C'(1) = end: K + 3 control
// points, knots by eq. 9.22 (averages of p consecutive parameters, one more interior knot than
// A9.1), the two derivative rows added to the collocation system. The degree runs from 2 (a
// degree-1 curve's end derivatives are fixed by its first and last legs) to K + 2, the count of
// control points - 1 (`degree`, "/degree"); fewer than 2 points is `schema` ("/points");
// degenerate points as point_params (`geometry`).
Expected<Interpolated> interpolate_curve_with_end_derivatives(const std::vector<glm::dvec3>& points,
                                                              int degree, Parametrization mode,
                                                              const glm::dvec3& start,
                                                              const glm::dvec3& end);

// Piegl & Tiller A9.4 GlobalSurfInterp: the (p, q) B-spline surface with S(u_k, v_l) =
// grid[k * columns + l] (k along u: `rows` rows of `columns` points). The u_k are the mode's
// parameters of each column averaged over the columns (eq. 9.16-9.18), the v_l likewise over
// the rows; a column (row) whose points all coincide is left out of its average as A9.4 does.
// Knots by averaging (eq. 9.8); the columns are interpolated first (A9.1 for every column at
// once), then the rows of the result. Errors: fewer than 2 rows or columns (`schema`, "/grid"
// or "/grid/0"); p or q outside 1..rows - 1, 1..columns - 1 (`degree`, "/degree/0", "/degree/1");
// all points coincide (`geometry`, "/grid"); row k equal to row k - 1 (`geometry`, "/grid/k");
// column l equal to column l - 1 (`geometry`, "/grid/0/l", its first point); when every row
// (column) is the same, k = 1 (l = 1).
// The checks and parameters A9.4 and surface least squares share: the grid's shape, the
// degrees (errors as interpolate_surface's below) and the averaged parameters u_k, v_l.
struct GridParams {
    std::vector<double> u, v;
};
Expected<GridParams> grid_params(const std::vector<glm::dvec3>& grid, int rows, int columns, int p,
                                 int q, Parametrization mode);

struct InterpolatedSurface {
    Surface surface;
    std::vector<double> u_params, v_params;
};
Expected<InterpolatedSurface> interpolate_surface(const std::vector<glm::dvec3>& grid, int rows,
                                                  int columns, int p, int q, Parametrization mode);

// Piegl & Tiller 9.4.1, least squares with fixed ends: `count` control points of degree p for
// the m + 1 points at the mode's parameters; P_0 = Q_0 and P_n = Q_m exactly, knots by eq. 9.69
// (every span holds a parameter, so the normal equations are positive definite), the interior
// control points from the normal equations (eq. 9.66, banded, 2p + 1 wide). max_error and
// rms_error are the largest and the root-mean-square distance |C(t_k) - Q_k| over all points.
// Errors: fewer than 2 points (`schema`, "/points"); degree outside 1..m (`degree`, "/degree");
// count below p + 1 (`degree`, "/count") or above m + 1 (`schema`, "/count"); degenerate points
// as point_params (`geometry`); a singular system (`geometry`, "/points").
struct Approximated {
    Curve curve;
    std::vector<double> params;
    double max_error = 0;
    double rms_error = 0;
};
Expected<Approximated> approximate_curve(const std::vector<glm::dvec3>& points, int degree,
                                         int count, Parametrization mode);

// Least-squares surface approximation of a grid (Piegl & Tiller 9.4.3): the parameters of
// interpolate_surface (grid_params), knots by eq. 9.69 in each direction, every column of the
// grid fitted with fixed ends by 9.4.1 at the u_k (count_u points each; one factorisation for
// all columns), then every row of the result at the v_l (count_v points). The four corners are
// kept exactly; counts equal to the grid's interpolate it. max_error and rms_error are over all
// grid points, |S(u_k, v_l) - Q_kl|. Errors: as grid_params; count_u outside p + 1 .. rows
// (`degree` below, `schema` above, "/count/0"), count_v likewise ("/count/1"); a singular
// system (`geometry`, "/grid").
struct ApproximatedSurface {
    Surface surface;
    std::vector<double> u_params, v_params;
    double max_error = 0;
    double rms_error = 0;
};
Expected<ApproximatedSurface> approximate_surface(const std::vector<glm::dvec3>& grid, int rows,
                                                  int columns, int p, int q, int count_u,
                                                  int count_v, Parametrization mode);

} // namespace isoparm::geom
