// IGES and STEP files read through OpenCASCADE (OCCT), the one part of isoparm that links it:
// built only where CMake finds OCCT (core/CMakeLists.txt), installed into core/exchange's
// read_cad at start-up (app/main.cpp). Everything else reaches it through cad_reader.hpp.
#pragma once

#include <string_view>

#include "core/exchange/cad_reader.hpp"

namespace isoparm::exchange_occt {

// OCCT's readers (IGESControl_Reader, STEPControl_Reader) build a shape; its faces and the
// edges outside every face become surfaces and curves, in the order of the entities they came
// from in the file. B-spline geometry comes over as it is (OCCT's periodic form unrolled to
// clamped knots); planes, cylinders, cones, spheres, tori, surfaces of revolution and of
// extrusion, Bezier surfaces and lines, circles, conics are converted to NURBS by GeomConvert
// over the face's (u, v) box or the edge's parameter range; a trimmed face comes in as its
// underlying surface cut to the face's (u, v) box. What OCCT cannot convert (offset surfaces
// and curves) and entities that gave no shape are listed in `skipped` with their kind.
geom::Expected<exchange::ImportResult> read(std::string_view text, exchange::CadFormat format);

// install_cad_reader(read).
void install();

} // namespace isoparm::exchange_occt
