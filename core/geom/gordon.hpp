// The Gordon surface through a network of curves (Gordon 1969; Piegl & Tiller 10.5): the
// boolean sum of two skins minus the tensor-product interpolant of the intersections.
#pragma once

#include <vector>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// u_curves[k] is the curve of constant v = v_k, v_curves[l] the curve of constant u = u_l.
// Each family is made compatible on [0, 1]; the network's intersections Q_kl are found
// (closest points, Newton from a sampled start) and must exist (within 1e-6 of the network's
// size) and lie at common parameters:
// every v-curve meets all u-curves at one u = u_l, every u-curve meets all v-curves at one
// v = v_k (within 1e-6 of the domain), the compatibility a Gordon surface needs. Then
// S = P_u + P_v - T: the skin of the u-curves at the v_k, the skin of the v-curves at the u_l,
// minus the tensor-product interpolant of Q_kl, each of degree min(3, count - 1) across its
// curves; S interpolates every curve of the network.
struct Gordon {
    Surface surface;
    std::vector<double> u_params; // u_l, for v_curves in the given order
    std::vector<double> v_params; // v_k, for u_curves in the given order
};
// Errors: fewer than 2 curves in a family (`schema`, "/u_curves", "/v_curves"); a rational
// curve with unequal weights (`weights` at the curve); a pair that does not meet, parameters
// that disagree, or two curves at one parameter (`geometry`, at the v-curve or u-curve).
Expected<Gordon> gordon(const std::vector<Curve>& u_curves, const std::vector<Curve>& v_curves);

} // namespace isoparm::geom
