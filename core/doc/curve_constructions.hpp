// The Construct menu's work: chosen curves of the document in, a new surface object out.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/doc/document.hpp"
#include "core/doc/recipe.hpp"
#include "core/geom/construct.hpp"

namespace isoparm::doc {

struct ConstructionResult {
    Object object;    // the new surface or curve (id 0: add_object assigns one), without its recipe
    std::string note; // for the user: the oriented sweep's deviation, the skin's parameters
};

// Runs the construction on the document's curves (core/geom/construct.hpp). The document is
// not changed: the caller adds the object with add_object. Errors name the curve and the
// reason in the message; the path points into the request: "/curves" (wrong count),
// "/curves/k" (no such curve, not a curve, or the geometry's complaint about that curve:
// "/curves/1/points/3"; a Coons corner that does not meet, a Gordon pair that does not
// intersect), "/angle", "/scale", "/degree", "/sections", "/gordon_u_count".
geom::Expected<ConstructionResult> build_construction(const Document& doc,
                                                      const ConstructionRequest& request);

} // namespace isoparm::doc
