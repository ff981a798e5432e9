// Knot insertion and degree elevation as users ask for them (the workstation's commands and the
// geom protocol alike): the refinement of refine.hpp inside the size caps of validate.hpp, so
// a request that would build an enormous net is refused with its count instead of attempted.
#pragma once

#include <string>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// `schema` at "/times" when times < 1; `limit` at "/times" when the result would exceed
// max_points_per_direction (or, for a surface, max_points_per_surface).
Expected<Curve> insert_knot_within_limits(const Curve& c, double t, int times);
Expected<Surface> insert_knot_within_limits(const Surface& s, Dir dir, double t, int times);
// Elevation is refused before anything is allocated when its size is known to be too large.
Expected<Curve> elevate_degree_within_limits(const Curve& c, int times);
Expected<Surface> elevate_degree_within_limits(const Surface& s, Dir dir, int times);

// `limit` at `path` when a net has more control points than the caps allow ("the result would
// have 5000 control points; at most 4096 are allowed").
Status check_net_size(const Curve& c, const std::string& path);
Status check_net_size(const Surface& s, const std::string& path);

} // namespace isoparm::geom
