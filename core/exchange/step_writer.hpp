// STEP AP214 output of exact geometry (ISO 10303-21 clear text, FILE_SCHEMA
// AUTOMOTIVE_DESIGN): B_SPLINE_SURFACE_WITH_KNOTS and B_SPLINE_CURVE_WITH_KNOTS, the rational
// ones as the complex instance with RATIONAL_B_SPLINE_SURFACE / _CURVE (ISO 10303-42 4.4).
//
// Each surface becomes an ADVANCED_FACE bounded by its four boundary curves, in an OPEN_SHELL
// of a SHELL_BASED_SURFACE_MODEL (MANIFOLD_SURFACE_SHAPE_REPRESENTATION), under one PRODUCT,
// so that CAD readers make a face of it rather than loose geometry. Curves go into a
// GEOMETRIC_CURVE_SET (GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION). Units are
// millimetres, like the IGES writer's.
#pragma once

#include <string>
#include <vector>

#include "core/exchange/iges_writer.hpp"

namespace isoparm::exchange {

// The face's edge loop runs counter-clockwise in (u, v), so the face's normal is S_u x S_v:
// (u0,v0) -> (u1,v0) -> (u1,v1) -> (u0,v1). A side that collapses to a point (a pole) has no
// edge; two opposite sides that coincide (a closed surface: a full revolution, a torus) are one
// seam edge used twice in the loop, once in each sense (the way ISO 10303-42 topology bounds a
// periodic face). Weights must be positive (check_positive_weights; errors as iges_text's).
geom::Expected<std::string> step_text(const std::vector<ExactShape>& shapes,
                                      const std::string& name);

} // namespace isoparm::exchange
