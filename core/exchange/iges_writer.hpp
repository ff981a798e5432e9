// IGES 5.3 output of exact geometry: entity 126 (rational B-spline curve) and 128 (rational
// B-spline surface), with complete Start, Global, Directory Entry, Parameter Data and Terminate
// sections in 80-column records.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::exchange {

using ExactShape = std::variant<geom::Curve, geom::Surface>;

// Every weight must be > 0 (CAD readers reject others): `weights` at the first offending one
// ("/weights/3", "/weights/1/2"), with the object's index prefixed when there are several
// ("/objects/2/weights/3"). `name` goes into the Start and Global sections (file name, product).
geom::Expected<std::string> iges_text(const std::vector<ExactShape>& shapes,
                                      const std::string& name);

// The positive-weight rule shared by the exact writers (IGES, STEP).
geom::Status check_positive_weights(const ExactShape& shape);

} // namespace isoparm::exchange
