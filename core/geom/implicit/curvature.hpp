// Curvature of an implicit surface f(x, y, z) = 0 at a point on it, from f's gradient and
// Hessian (Goldman, "Curvature formulas for implicit curves and surfaces", CAGD 22, 2005):
// K = g^T adj(H) g / |g|^4 and mean = (g^T H g - |g|^2 trace H) / (2 |g|^3), g = grad f.
#pragma once

#include <optional>

#include <glm/vec3.hpp>

#include "core/geom/curvature.hpp"
#include "core/geom/implicit/expression.hpp"

namespace isoparm::geom::implicit {

// With respect to the unit normal n = grad f / |grad f| (where f grows), the convention of
// geom::SurfaceCurvature: a sphere f = |p|^2 - r^2 has mean = k1 = k2 = -1/r, K = 1/r^2. The
// gradient is exact (forward-mode dual numbers); the Hessian is the central difference of that
// exact gradient with a step of cbrt(eps) times the point's size, accurate to about 1e-10
// relative. nullopt where the gradient vanishes (a singular point: no normal) or a value is not
// finite.
std::optional<SurfaceCurvature> implicit_curvature(const Program& f, const glm::dvec3& p,
                                                   const double* params = nullptr);

// The kind the analysis display shows; NaN where undefined (as geom::curvature_grid).
double implicit_curvature_value(const Program& f, const glm::dvec3& p, CurvatureKind kind,
                                const double* params = nullptr);

} // namespace isoparm::geom::implicit
