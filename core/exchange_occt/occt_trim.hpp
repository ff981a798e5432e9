// A face's wires as trim loops in the (u, v) domain of the NURBS surface the face converted to:
// the p-curves of its edges (or their 3D curves projected, where a file has no p-curve), mapped
// from OCCT's surface parameters to the NURBS surface's where the conversion changed them.
#pragma once

#include <Geom_Surface.hxx>
#include <TopoDS_Face.hxx>
#include <string>
#include <variant>

#include "core/geom/trim/trim.hpp"
#include "core/geom/types.hpp"

namespace isoparm::exchange_occt {

// The box the face converted over (OCCT's parameters) and, for periodic directions, the period.
struct FaceBox {
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    double u_period = 0, v_period = 0; // 0: not periodic
};

// The trim of `face` on `converted` (the NURBS form of `original` over `box`), or why there is
// none. Where the conversion kept OCCT's parameters (B-splines, planes) the p-curves convert
// exactly (Geom2dConvert); elsewhere (the angle of a cylinder, cone, sphere, torus or
// revolution becomes a rational parameter) each point of a p-curve is mapped by inverting the
// NURBS surface (one-dimensional maps u -> u', v -> v' where the conversion is separable, as
// OCCT's are; Newton on the surface otherwise), lines of constant u or v stay lines, and other
// curves are fitted within 1e-9 of the domain's size. Curve ends are joined where they differ by
// less than 1e-4 of the domain, or by less than 1e-2 of it where their points in space are within
// the file's own tolerance there (BRep_Tool::Tolerance of the vertex and the edges; two lines
// then meet where they cross, other curves halfway); loops are oriented (the outer one,
// BRepTools::OuterWire, counter-clockwise, holes clockwise); the result passes geom::validate_trim.
std::variant<geom::Trim, std::string> face_trim(const TopoDS_Face& face,
                                                const Handle(Geom_Surface) & original,
                                                const FaceBox& box, const geom::Surface& converted);

// Whether a trim is the domain's own boundary: no holes and an outer loop of curves each with its
// control points on one side of the domain (a face with its natural bounds, as OCCT reads an
// untrimmed surface). Such a face comes in as its surface alone, so an untrimmed surface exported
// and read back stays untrimmed.
bool is_whole_domain(const geom::Trim& trim, const geom::ParamRect& domain);

} // namespace isoparm::exchange_occt
