// Why OCCT refused a STEP B-spline, in terms a person can act on: OCCT's transfer only says
// "Surface has not been created". Checked against ISO 10303-42 (b_spline_surface_with_knots:
// sum of multiplicities = poles + degree + 1, increasing knots) and OCCT's own bounds (degree
// at most 25, weights above 0, points in 3D).
#pragma once

#include <Standard_Handle.hxx>
#include <Standard_Transient.hxx>
#include <string>

namespace isoparm::exchange_occt {

// "its u degree 30 is above 25, the most OpenCASCADE takes", "control point (1, 2) (#20) has 2
// coordinates, not 3"; "" when the entity is no B-spline or nothing in it is wrong.
std::string diagnose_step_bspline(const Handle(Standard_Transient) & entity);

} // namespace isoparm::exchange_occt
