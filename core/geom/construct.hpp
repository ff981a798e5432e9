// Cross-section design: compatible curves, ruled, revolved, swung, swept and skinned surfaces.
#pragma once

#include <optional>
#include <vector>

#include "core/geom/interpolate.hpp"
#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// Inputs are valid curves (validate_curve); results are valid surfaces and curves. Error paths
// are relative to the protocol request of the same name ("/curves/1", "/angle", "/profile",
// "/trajectory/points/3", "/degree"), so the protocol passes them through unchanged. Results
// larger than the size caps (4096 points per direction, 1,000,000 per surface) are `limit`.

// The curves mapped to the domain [0, 1] (an affine change of the knots), clamped, raised to
// the largest degree (A5.9) and refined to one merged knot vector (each interior knot at its
// largest multiplicity over the curves, knot refinement A5.4): same degree, knots and count; each
// curve's shape unchanged. Fewer than 2 curves is `schema` ("/curves"); a result that would need a
// control point at infinity is `weights` ("/curves/k").
Expected<std::vector<Curve>> make_compatible(const std::vector<Curve>& curves);

// Piegl & Tiller 10.2, the ruled surface: S(u, 0) = C0(u), S(u, 1) = C1(u), degree 1 in v
// with knots v = [0, 0, 1, 1]; u is [0, 1] (curves made compatible first). Each v-isocurve is
// the straight segment from C0(u) to C1(u): for non-rational curves (or equal weight sums)
// S(u, v) = (1 - v) C0(u) + v C1(u) exactly; for rational ones the segment is traversed at a
// rational speed (the homogeneous tensor product).
Expected<Surface> ruled(const Curve& c0, const Curve& c1);

// Piegl & Tiller A8.1 MakeRevolvedSurf about the z-axis: S(u, v) = Rz(phi(v)) C(u), u the
// curve's own domain, v in [0, 1], phi from 0 to `degrees` counter-clockwise seen from +z,
// exactly (rational quadratic arcs). phi(v) is exact at v = 0, 1 and at the arc knots k/arcs,
// monotone between (a rational quadratic arc is not traversed at constant angular speed).
// `degrees` outside (0, 360] is `schema` ("/angle"). Points on the axis give poles.
Expected<Surface> revolve(const Curve& profile, double degrees);

// Piegl & Tiller 10.4, the swung surface: S(u, v) = (s Px(u) Tx(v), s Px(u) Ty(v), Pz(u)),
// exact (control points (s Px_i Tx_j, s Px_i Ty_j, Pz_i), weights w_i w_j). The profile must lie
// in the xz-plane (every control point y = 0) and the trajectory in the xy-plane (z = 0):
// `geometry` at the first offending control point ("/profile/points/3"). u is the profile's
// domain, v the trajectory's. A non-finite scale is `schema` ("/scale").
Expected<Surface> swing(const Curve& profile, const Curve& trajectory, double scale = 1.0);

// The translational sweep: S(u, v) = P(u) + T(v) - T(v_start), exact: control points
// P_i + T_j - T(v_start) with weights w_i w_j, i.e. the homogeneous tensor product
// w_i w_j (P_i + T_j - T0). u is the profile's domain, v the trajectory's.
Expected<Surface> sweep(const Curve& profile, const Curve& trajectory);

// Piegl & Tiller 10.3, the skinned surface through compatible sections: S(u, v_k) = C_k(u).
// The curves are made compatible (u in [0, 1]); parameters v_k by convention 15 (per
// control-point index the chord / centripetal lengths across the sections, normalized, then
// averaged; uniform k/K), knots v by averaging (eq. 9.8), and the i-th control points of all
// sections interpolated (A9.1) in homogeneous space for rational curves. Errors: fewer than 2
// curves (`schema`, "/curves"); degree < 1 or > count - 1 (`schema`, "/degree"); coincident
// sections: a zero total for some control-point index (`geometry`, "/curves") or two
// consecutive sections at equal parameters (`geometry`, "/curves/k"); interpolated weights
// that would put a control point at infinity (`weights`).
struct Skinned {
    Surface surface;
    std::vector<double> params; // v_k, first 0, last 1
};
constexpr int default_skin_degree(int curve_count) {
    return curve_count - 1 < 3 ? curve_count - 1 : 3;
}
Expected<Skinned> skin(const std::vector<Curve>& curves, int degree,
                       Parametrization mode = Parametrization::chord);
// The same at given parameters v_k (strictly increasing, one per curve; the Gordon surface
// needs its network's own), and on curves already compatible (make_compatible's output).
Expected<Skinned> skin_through(const std::vector<Curve>& curves, int degree,
                               const std::vector<double>& params);
Expected<Skinned> skin_compatible(const std::vector<Curve>& compatible, int degree,
                                  const std::vector<double>& params);

// Beyond the protocol: the oriented sweep. The profile moves along the trajectory and turns
// with it, following the rotation-minimizing frame (double reflection, Wang, Juttler, Zheng and
// Liu 2008): the ideal surface is S*(u, t) = T(t) + R(t) (P(u) - T(a)) with R(t) the rotation
// carrying the frame at the trajectory start a to the frame at t, so a profile drawn
// perpendicular to the trajectory at its start stays perpendicular. It is not a NURBS surface,
// so it is approximated by skinning `sections` + 1 placed copies of the profile at equal
// arc-length steps along the trajectory (uniform skin parameters, so v is proportional to arc
// length) and `max_deviation` reports max |S(u, v) - S*(u, t(v))| over a sampled grid (an
// upper bound on the distance to the ideal surface at those samples). Errors: sections < 1 or
// degree outside 0..min(3, sections)
// (`schema`, "/sections", "/degree"), a trajectory with no tangent anywhere (`geometry`).
struct OrientedSweep {
    Skinned skinned;
    int sections = 0;
    double max_deviation = 0;
    double deviation_u = 0, deviation_v = 0; // where it occurs (the surface's parameters)
};
struct OrientedSweepOptions {
    int sections = 16;  // copies - 1
    int degree = 0;     // v-degree of the skin, 1..min(3, sections); 0: min(3, sections)
    int samples_u = 32; // deviation samples along u
    int substeps = 16;  // frame steps and deviation samples per section
};
Expected<OrientedSweep> oriented_sweep(const Curve& profile, const Curve& trajectory,
                                       const OrientedSweepOptions& options = {});

} // namespace isoparm::geom
