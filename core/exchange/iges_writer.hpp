// IGES 5.3 output of exact geometry: entity 126 (rational B-spline curve), 128 (rational
// B-spline surface) and, for a trimmed surface, 144 (trimmed parametric surface) with a 142
// (curve on a parametric surface) per loop, each a 102 (composite curve) of 126 pieces in
// (u, v) and in model space, with complete Start, Global, Directory Entry, Parameter Data and
// Terminate sections in 80-column records.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "core/geom/status.hpp"
#include "core/geom/trim/trim.hpp"
#include "core/geom/types.hpp"

namespace isoparm::exchange {

// A curve, a surface over its whole domain, or a trimmed surface (IGES 144 / STEP advanced face
// with its loops).
using ExactShape = std::variant<geom::Curve, geom::Surface, geom::TrimmedSurface>;

// Every weight must be > 0 (CAD readers reject others): `weights` at the first offending one
// ("/weights/3", "/weights/1/2"), with the object's index prefixed when there are several
// ("/objects/2/weights/3"). `name` goes into the Start and Global sections (file name, product).
geom::Expected<std::string> iges_text(const std::vector<ExactShape>& shapes,
                                      const std::string& name);

// The positive-weight rule shared by the exact writers (IGES, STEP).
geom::Status check_positive_weights(const ExactShape& shape);

// The surface of a surface or a trimmed surface (nullptr for a curve); any shape's control
// points.
const geom::Surface* surface_of(const ExactShape& shape);
const std::vector<glm::dvec3>& control_points_of(const ExactShape& shape);

// How closely the exact writers' model-space edge curves follow a trimmed surface (S(C(t)),
// geom::curve_on_surface): 1e-9 of the largest coordinate of the shapes (at least 1e-12).
double edge_curve_tolerance(const std::vector<ExactShape>& shapes);

} // namespace isoparm::exchange
