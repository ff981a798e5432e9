// Differential geometry at a point from exact derivatives (never from mesh differences):
// Gaussian, mean and principal curvatures of a surface, and a curve's Frenet frame.
#pragma once

#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include "core/geom/evaluate.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// Curvatures with respect to the unit normal n = (S_u x S_v) / |S_u x S_v|: a sphere whose
// normals point outwards has mean = k1 = k2 = -1/r. k1 >= k2; d1, d2 are unit principal
// directions in 3D (d2 = n x d1; at an umbilic d1 follows S_u).
struct SurfaceCurvature {
    double gaussian = 0, mean = 0, k1 = 0, k2 = 0;
    glm::dvec3 d1{0.0}, d2{0.0};
};
// nullopt where the point does not exist or the normal degenerates (normal_from_derivatives).
std::optional<SurfaceCurvature> surface_curvature(const Surface& s, double u, double v);
// The same from derivatives up to order 2 (D[a][b], a + b <= 2).
std::optional<SurfaceCurvature> curvature_from_derivatives(const SurfaceDerivatives& d);

// A surface's curvature shown as false colour (the analysis display modes), at every vertex of
// a tessellation grid (u-major, uniform parameters as tessellate lays them out), for vertices
// first .. first + count - 1; NaN where it is undefined (no point, or a degenerate normal: a
// pole), which the display draws as such.
enum class CurvatureKind { gaussian, mean, k_max, k_min };
std::vector<double> curvature_grid(const Surface& s, int samples_u, int samples_v,
                                   CurvatureKind kind, std::size_t first = 0,
                                   std::size_t count = static_cast<std::size_t>(-1));

// The Frenet frame of a curve at t. `curvature` (>= 0) and `tangent` exist where C' != 0;
// `torsion`, `normal` and `binormal` where C' x C'' != 0 as well (a straight piece has
// curvature 0 and no normal).
struct CurveCurvature {
    std::optional<double> curvature, torsion;
    std::optional<glm::dvec3> tangent, normal, binormal;
};
// nullopt where the point does not exist (a zero denominator).
std::optional<CurveCurvature> curve_curvature(const Curve& c, double t);

} // namespace isoparm::geom
