#include "core/exchange_occt/occt_step_diagnosis.hpp"

#include <Geom_BSplineSurface.hxx>
#include <StepGeom_BSplineCurveWithKnots.hxx>
#include <StepGeom_BSplineCurveWithKnotsAndRationalBSplineCurve.hxx>
#include <StepGeom_BSplineSurfaceWithKnots.hxx>
#include <StepGeom_BSplineSurfaceWithKnotsAndRationalBSplineSurface.hxx>
#include <StepGeom_CartesianPoint.hxx>
#include <StepGeom_HArray1OfCartesianPoint.hxx>
#include <StepGeom_HArray2OfCartesianPoint.hxx>
#include <TColStd_HArray1OfInteger.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColStd_HArray2OfReal.hxx>

#include "core/geom/status.hpp"

namespace isoparm::exchange_occt {

namespace {

std::string check_point(const Handle(StepGeom_CartesianPoint) & p, const std::string& which) {
    if (p.IsNull()) return "control point " + which + " is missing (a dangling reference)";
    if (p->NbCoordinates() != 3)
        return "control point " + which + " has " + std::to_string(p->NbCoordinates()) +
               " coordinates, not 3";
    return "";
}

std::string check_degree(int degree, const char* dir) {
    const int most = Geom_BSplineSurface::MaxDegree();
    if (degree < 1)
        return std::string("its ") + dir + "degree " + std::to_string(degree) + " is below 1";
    if (degree > most)
        return std::string("its ") + dir + "degree " + std::to_string(degree) + " is above " +
               std::to_string(most) + ", the most OpenCASCADE takes";
    return "";
}

// The knot vector in STEP's form: distinct knots with multiplicities.
std::string check_knots(const Handle(TColStd_HArray1OfInteger) & mult,
                        const Handle(TColStd_HArray1OfReal) & knots, int poles, int degree,
                        const char* dir) {
    const std::string d = dir;
    if (mult.IsNull() || knots.IsNull()) return "its " + d + "knots are missing";
    if (mult->Length() != knots->Length())
        return "it has " + std::to_string(knots->Length()) + " " + d + "knots and " +
               std::to_string(mult->Length()) + " multiplicities";
    long sum = 0;
    for (int k = mult->Lower(); k <= mult->Upper(); ++k) {
        const int m = mult->Value(k);
        if (m < 1 || m > degree + 1)
            return "its " + d + "knot multiplicity " + std::to_string(m) + " is not 1.." +
                   std::to_string(degree + 1);
        sum += m;
    }
    if (sum != poles + degree + 1)
        return "its " + d + "knot multiplicities add up to " + std::to_string(sum) + "; " +
               std::to_string(poles) + " control points of degree " + std::to_string(degree) +
               " need " + std::to_string(poles + degree + 1);
    for (int k = knots->Lower() + 1; k <= knots->Upper(); ++k)
        if (!(knots->Value(k) > knots->Value(k - 1)))
            return "its " + d + "knots do not increase (" +
                   geom::format_number(knots->Value(k - 1)) + " then " +
                   geom::format_number(knots->Value(k)) + ")";
    return "";
}

std::string check_weight(double w, const std::string& which) {
    if (!(w > 0))
        return "weight " + which + " is " + geom::format_number(w) +
               " (OpenCASCADE takes weights above 0 only)";
    return "";
}

std::string surface_problem(const Handle(StepGeom_BSplineSurface) & s,
                            const Handle(TColStd_HArray1OfInteger) & um,
                            const Handle(TColStd_HArray1OfReal) & uk,
                            const Handle(TColStd_HArray1OfInteger) & vm,
                            const Handle(TColStd_HArray1OfReal) & vk,
                            const Handle(TColStd_HArray2OfReal) & weights) {
    if (auto p = check_degree(s->UDegree(), "u "); !p.empty()) return p;
    if (auto p = check_degree(s->VDegree(), "v "); !p.empty()) return p;
    const Handle(StepGeom_HArray2OfCartesianPoint) points = s->ControlPointsList();
    if (points.IsNull()) return "its control points are missing";
    for (int i = points->LowerRow(); i <= points->UpperRow(); ++i)
        for (int j = points->LowerCol(); j <= points->UpperCol(); ++j)
            if (auto p = check_point(points->Value(i, j), "(" + std::to_string(i - 1) + ", " +
                                                              std::to_string(j - 1) + ")");
                !p.empty())
                return p;
    if (!um.IsNull() || !uk.IsNull()) {
        if (auto p = check_knots(um, uk, points->ColLength(), s->UDegree(), "u "); !p.empty())
            return p;
        if (auto p = check_knots(vm, vk, points->RowLength(), s->VDegree(), "v "); !p.empty())
            return p;
    }
    if (!weights.IsNull()) {
        if (weights->ColLength() != points->ColLength() ||
            weights->RowLength() != points->RowLength())
            return "it has " + std::to_string(weights->ColLength()) + " x " +
                   std::to_string(weights->RowLength()) + " weights for " +
                   std::to_string(points->ColLength()) + " x " +
                   std::to_string(points->RowLength()) + " control points";
        for (int i = weights->LowerRow(); i <= weights->UpperRow(); ++i)
            for (int j = weights->LowerCol(); j <= weights->UpperCol(); ++j)
                if (auto p = check_weight(weights->Value(i, j), "(" + std::to_string(i - 1) + ", " +
                                                                    std::to_string(j - 1) + ")");
                    !p.empty())
                    return p;
    }
    return "";
}

std::string curve_problem(const Handle(StepGeom_BSplineCurve) & c,
                          const Handle(TColStd_HArray1OfInteger) & mult,
                          const Handle(TColStd_HArray1OfReal) & knots,
                          const Handle(TColStd_HArray1OfReal) & weights) {
    if (auto p = check_degree(c->Degree(), ""); !p.empty()) return p;
    const Handle(StepGeom_HArray1OfCartesianPoint) points = c->ControlPointsList();
    if (points.IsNull()) return "its control points are missing";
    for (int i = points->Lower(); i <= points->Upper(); ++i)
        if (auto p = check_point(points->Value(i), std::to_string(i - 1)); !p.empty()) return p;
    if (!mult.IsNull() || !knots.IsNull())
        if (auto p = check_knots(mult, knots, points->Length(), c->Degree(), ""); !p.empty())
            return p;
    if (!weights.IsNull()) {
        if (weights->Length() != points->Length())
            return "it has " + std::to_string(weights->Length()) + " weights for " +
                   std::to_string(points->Length()) + " control points";
        for (int i = weights->Lower(); i <= weights->Upper(); ++i)
            if (auto p = check_weight(weights->Value(i), std::to_string(i - 1)); !p.empty())
                return p;
    }
    return "";
}

} // namespace

std::string diagnose_step_bspline(const Handle(Standard_Transient) & entity) {
    if (auto s =
            Handle(StepGeom_BSplineSurfaceWithKnotsAndRationalBSplineSurface)::DownCast(entity);
        !s.IsNull())
        return surface_problem(s, s->UMultiplicities(), s->UKnots(), s->VMultiplicities(),
                               s->VKnots(), s->WeightsData());
    if (auto s = Handle(StepGeom_BSplineSurfaceWithKnots)::DownCast(entity); !s.IsNull())
        return surface_problem(s, s->UMultiplicities(), s->UKnots(), s->VMultiplicities(),
                               s->VKnots(), Handle(TColStd_HArray2OfReal)());
    if (auto c = Handle(StepGeom_BSplineCurveWithKnotsAndRationalBSplineCurve)::DownCast(entity);
        !c.IsNull())
        return curve_problem(c, c->KnotMultiplicities(), c->Knots(), c->WeightsData());
    if (auto c = Handle(StepGeom_BSplineCurveWithKnots)::DownCast(entity); !c.IsNull())
        return curve_problem(c, c->KnotMultiplicities(), c->Knots(),
                             Handle(TColStd_HArray1OfReal)());
    return "";
}

} // namespace isoparm::exchange_occt
