// Multiresolution edits (Finkelstein & Salesin 1994, sec. 4): change the sweep at a coarse
// level keeping the detail, or change the detail keeping the sweep. Each answers the whole
// new curve or surface at its finest level; the knots, degree and type stay.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// The coarse control points at `level` (0 .. J; J gives the curve's own points).
// Refusals: multires_level's, "/level" out of range.
Expected<std::vector<glm::dvec3>> multires_coarse_points(const Curve& c, int level);
// Coarse point i at `level` moves to `position`; every detail coefficient stays ("/i").
Expected<Curve> multires_move_coarse_point(const Curve& c, int level, int i,
                                           const glm::dvec3& position);
// Every detail coefficient finer than `level` times `factor` (0 smooths the curve to its
// level-`level` sweep, 2 doubles its character); the coarse points stay ("/detail_scale"
// when not finite).
Expected<Curve> multires_scale_detail(const Curve& c, int level, double factor);

// Surfaces: levels per direction, the coarse net row-major (i along u).
struct CoarseNet {
    int n_u = 0, n_v = 0;
    std::vector<glm::dvec3> points;
};
Expected<CoarseNet> multires_coarse_net(const Surface& s, int level_u, int level_v);
Expected<Surface> multires_move_coarse_point(const Surface& s, int level_u, int level_v, int i,
                                             int j, const glm::dvec3& position);
Expected<Surface> multires_scale_detail(const Surface& s, int level_u, int level_v, double factor);

} // namespace isoparm::geom
