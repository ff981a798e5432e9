// Curve and surface evaluation with derivatives (up to order 3) and unit normals.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/geom/types.hpp"

namespace isoparm::geom {

constexpr int max_derivative_order = 3;

// C^(k)(t), k = 0..d (Piegl & Tiller A3.2 on homogeneous points, then A4.2 for the
// rational quotient). nullopt where the denominator sum N_i w_i is exactly zero.
// Precondition: valid curve, t in its domain.
std::optional<std::vector<glm::dvec3>> curve_derivatives(const Curve& c, double t, int d);
std::optional<glm::dvec3> curve_point(const Curve& c, double t);

// D[a][b] = d^(a+b) S / du^a dv^b for a + b <= d (A3.6 on homogeneous points, then A4.4).
struct SurfaceDerivatives {
    std::array<std::array<glm::dvec3, max_derivative_order + 1>, max_derivative_order + 1> D{};
};
std::optional<SurfaceDerivatives> surface_derivatives(const Surface& s, double u, double v, int d);
std::optional<glm::dvec3> surface_point(const Surface& s, double u, double v);

// (S_u x S_v) / |S_u x S_v|; nullopt where the point does not exist or the cross product
// degenerates (|S_u x S_v| below 1e-10 max(|S_u|, |S_v|)^2). The protocol's `evaluate`.
std::optional<glm::dvec3> surface_normal(const Surface& s, double u, double v);

// A normal a renderer can always use: the strict normal where it exists; at a degenerate
// point (a collapsed edge, a pole) the limit approached from inside the domain, from the
// first-order expansion of S_u x S_v; failing that a nearby evaluation; else +z.
glm::dvec3 surface_normal_or_limit(const Surface& s, double u, double v);

// The normal of given first/second derivatives: strict or the limit toward (du, dv).
std::optional<glm::dvec3> normal_from_derivatives(const SurfaceDerivatives& d);
std::optional<glm::dvec3> limit_normal_from_derivatives(const SurfaceDerivatives& d, double du,
                                                        double dv);

} // namespace isoparm::geom
