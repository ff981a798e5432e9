// The parts of building a recipe that are not a construction from curves (internal to
// core/doc; build_construction calls them): the isocurve of a surface, and the refinements
// recorded after a construction.
#pragma once

#include "core/doc/curve_constructions.hpp"

namespace isoparm::doc::detail {

// The curve S(t, .) (iso_dir u) or S(., t) (iso_dir v) of the request's one surface, t at
// iso_t in [0, 1] over the surface's domain, as a 3D curve object named "isocurve <surface>
// u = t". Errors: "/curves" (not one input), "/curves/0" (no such object, not a surface, or a
// contracted control point at infinity), "/param" (iso_t outside [0, 1] or not finite).
geom::Expected<ConstructionResult> build_isocurve(const Document& doc,
                                                  const ConstructionRequest& request);

// Repeats the recorded refinements on the built object, in order; a refinement that no longer
// applies (a knot outside the new domain, a multiplicity above the degree) is its error at
// "/refinements/k".
geom::Status apply_refinements(ConstructionResult& built,
                               const std::vector<RecipeRefinement>& refinements);

} // namespace isoparm::doc::detail
