// One face or one free edge of an OpenCASCADE shape as an isoparm NURBS surface or curve, each
// converted on its own: a failure is that item's reason, never the file's. Used by the reader
// that runs in the sandbox's child (occt_read.cpp).
#pragma once

#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <optional>
#include <string>

#include "core/exchange/iges_writer.hpp"

namespace isoparm::exchange_occt {

// A converted item, or why it was not (then `shape` is empty). A face comes in as its
// underlying surface over the face's (u, v) box with its wires as trim loops
// (occt_trim.hpp); where the loops cannot be made, the surface alone, and `note` says why.
struct Converted {
    std::optional<exchange::ExactShape> shape;
    std::string skip_reason;
    // Why a face came without its trim loops, or what was changed to keep them (its surface
    // extended to hold them); empty: the face as the file has it.
    std::string note = {};
};

// The box (BRepTools::UVBounds) is fitted to the surface first: cut to the surface's range
// where a direction is not periodic (writers round a box a hair outside it), at most one period
// wide where it is (a full turn 4e-13 over 2 pi is a full turn); a periodic B-spline's box may
// cross its seam, and the piece comes out whole and unrolled. B-splines keep their exact knots
// where the box is their whole range; planes, cylinders, cones, spheres, tori, surfaces of
// revolution and extrusion and Bezier surfaces go through GeomConvert over the box. Offset
// surfaces have no exact NURBS form. OCCT's exceptions become the reason.
Converted convert_face(const TopoDS_Face& face);
// The same for an edge's 3D curve over the edge's parameter range.
Converted convert_edge(const TopoDS_Edge& edge);

} // namespace isoparm::exchange_occt
