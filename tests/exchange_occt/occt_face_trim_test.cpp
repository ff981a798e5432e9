// A face's wires as trim loops (core/exchange_occt/occt_trim.hpp face_trim) on faces built here
// with BRepBuilderAPI, so that each case runs without the real files of ../shared/cad.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepLib.hxx>
#include <Geom2d_Circle.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <cmath>
#include <gp_Ax2d.hxx>

#include "core/exchange_occt/occt_trim.hpp"
#include "core/geom/trim/trim_area.hpp"

using namespace isoparm;

namespace {

// A bicubic Bezier patch over [0, 1] x [0, 1], 10 by 10, with a bump in the middle.
Handle(Geom_BSplineSurface) bumped_patch() {
    TColgp_Array2OfPnt poles(1, 4, 1, 4);
    for (int i = 1; i <= 4; ++i)
        for (int j = 1; j <= 4; ++j) {
            const bool inner = (i == 2 || i == 3) && (j == 2 || j == 3);
            poles(i, j) = gp_Pnt(10.0 * (i - 1) / 3, 10.0 * (j - 1) / 3, inner ? 2.0 : 0.0);
        }
    TColStd_Array1OfReal knots(1, 2);
    knots(1) = 0;
    knots(2) = 1;
    TColStd_Array1OfInteger mults(1, 2);
    mults.Init(4);
    return new Geom_BSplineSurface(poles, knots, knots, mults, mults, 3, 3);
}

// The same patch as isoparm's NURBS surface (the same poles and knots, so OCCT's parameters).
geom::Surface as_isoparm(const Handle(Geom_BSplineSurface) & s) {
    geom::Surface out;
    out.type = geom::SplineType::bspline;
    out.degree_u = out.degree_v = 3;
    out.n_u = out.n_v = 4;
    out.knots_u = out.knots_v = {0, 0, 0, 0, 1, 1, 1, 1};
    out.points.resize(16);
    out.weights.assign(16, 1.0);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const gp_Pnt& p = s->Pole(i + 1, j + 1);
            out.point(i, j) = {p.X(), p.Y(), p.Z()};
        }
    return out;
}

// The patch's whole domain with a hole: a circle of radius 0.25 about (0.5, 0.5) in (u, v),
// written as a p-curve only (its 3D curve built from it).
TopoDS_Face patch_with_round_hole(const Handle(Geom_BSplineSurface) & s) {
    TopoDS_Face face = BRepBuilderAPI_MakeFace(s, 0, 1, 0, 1, 1e-7).Face();
    Handle(Geom2d_Circle) circle =
        new Geom2d_Circle(gp_Ax2d(gp_Pnt2d(0.5, 0.5), gp_Dir2d(1, 0)), 0.25);
    TopoDS_Edge edge = BRepBuilderAPI_MakeEdge(circle, s, 0, 2 * M_PI).Edge();
    BRepLib::BuildCurves3d(edge);
    TopoDS_Wire hole = BRepBuilderAPI_MakeWire(edge).Wire();
    hole.Reverse();
    return BRepBuilderAPI_MakeFace(face, hole).Face();
}

// A box that ends a rounding past the surface's domain (as Geom_BSplineSurface::Segment leaves a
// face's box and its segmented surface's end knot an ulp or so apart: bug22869_Spring.igs face
// 0) is the domain: the parameters are OCCT's, and the circle's p-curve comes in exactly as
// Geom2dConvert writes it (rational quadratic arcs), not as cubic fits of a map from one to the
// other (which followed one of Spring's edges not at all).
TEST(OcctFaceTrim, ABoxARoundingPastTheDomainKeepsOcctsParameters) {
    const Handle(Geom_BSplineSurface) s = bumped_patch();
    const geom::Surface converted = as_isoparm(s);
    const TopoDS_Face face = patch_with_round_hole(s);
    for (const double past : {0.0, 1e-15, 4e-13}) {
        const exchange_occt::FaceBox box{0, 1 + past, -past, 1, 0, 0};
        const auto trim = exchange_occt::face_trim(face, s, box, converted);
        ASSERT_TRUE(std::holds_alternative<geom::Trim>(trim))
            << "past " << past << ": " << std::get<std::string>(trim);
        const geom::Trim& t = std::get<geom::Trim>(trim);
        ASSERT_EQ(t.holes.size(), 1u) << "past " << past;
        for (const geom::Curve& c : t.holes[0].curves) {
            EXPECT_EQ(c.type, geom::SplineType::nurbs) << "past " << past;
            EXPECT_EQ(c.degree, 2) << "past " << past;
        }
        // The hole is the circle's exact conversion: its area in (u, v) is pi r^2 (the loops'
        // own area, not the surface's, so the bump does not enter).
        geom::Trim hole_only;
        hole_only.outer = geom::reversed(t.holes[0]);
        geom::Surface flat = converted;
        for (glm::dvec3& p : flat.points) p.z = 0;
        EXPECT_NEAR(geom::trimmed_area(flat, hole_only), 100 * M_PI * 0.0625, 1e-9)
            << "past " << past;
    }
}

} // namespace
