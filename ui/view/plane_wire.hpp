// What a coordinate plane of the four-view layout draws of an object besides its control net
// (pure): a surface's boundary and knot isocurves, a curve sampled with its knots, a triangular
// patch's boundary. Polylines in 3D (the canvas projects them); a polyline breaks where the
// object does not exist (a zero denominator).
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "core/doc/document.hpp"

namespace isoparm::ui {

using Polyline3 = std::vector<glm::dvec3>;

// `samples` points along each isocurve or edge (at least 2); a curve gets that many per knot
// span. Nothing for implicit surfaces.
std::vector<Polyline3> object_wire(const doc::Object& o, int samples = 48);

} // namespace isoparm::ui
