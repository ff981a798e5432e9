#include "core/exchange_occt/occt_convert.hpp"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <BndLib_Add2dCurve.hxx>
#include <Bnd_Box2d.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Line.hxx>
#include <Geom_OffsetCurve.hxx>
#include <Geom_OffsetSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Precision.hxx>
#include <ShapeFix_Wire.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <cmath>
#include <variant>
#include <vector>

#include "core/exchange_occt/occt_trim.hpp"
#include "core/geom/extend.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/status.hpp"

namespace isoparm::exchange_occt {

namespace {

std::vector<double> knot_sequence(const TColStd_Array1OfReal& a) {
    std::vector<double> out;
    out.reserve(static_cast<std::size_t>(a.Length()));
    for (Standard_Integer k = a.Lower(); k <= a.Upper(); ++k) out.push_back(a(k));
    return out;
}

// How many knots of the flat sequence equal the one at index k.
int multiplicity_at(const TColStd_Array1OfReal& knots, Standard_Integer k) {
    int m = 0;
    for (Standard_Integer i = knots.Lower(); i <= knots.Upper(); ++i) m += knots(i) == knots(k);
    return m;
}

// OCCT's readers turn a closed B-spline into its periodic form (poles shared around the seam),
// and SetNotPeriodic unrolls that into unclamped knots running past the domain. Where the seam
// knot has multiplicity >= p the file's spline passed through a control point there: it was a
// clamped closed spline (a revolution, a circle), so it is clamped again to its domain (the
// same poles and knots as the file's, up to rounding). Smooth periodic splines keep the
// unrolled form, which is the file's unclamped one.
void unroll_surface(Handle(Geom_BSplineSurface) & s) {
    const bool u = s->IsUPeriodic(), v = s->IsVPeriodic();
    if (u) s->SetUNotPeriodic();
    if (v) s->SetVNotPeriodic();
    if (!u && !v) return;
    TColStd_Array1OfReal ku(1, s->NbUPoles() + s->UDegree() + 1);
    TColStd_Array1OfReal kv(1, s->NbVPoles() + s->VDegree() + 1);
    s->UKnotSequence(ku);
    s->VKnotSequence(kv);
    const int p = s->UDegree(), q = s->VDegree();
    const bool clamp_u = u && multiplicity_at(ku, 1 + p) >= p && ku(1) != ku(1 + p);
    const bool clamp_v = v && multiplicity_at(kv, 1 + q) >= q && kv(1) != kv(1 + q);
    if (!clamp_u && !clamp_v) return;
    const double u0 = ku(1 + p), u1 = ku(s->NbUPoles() + 1);
    const double v0 = kv(1 + q), v1 = kv(s->NbVPoles() + 1);
    s->Segment(u0, u1, v0, v1);
}

void unroll_curve(Handle(Geom_BSplineCurve) & c) {
    if (!c->IsPeriodic()) return;
    c->SetNotPeriodic();
    TColStd_Array1OfReal k(1, c->NbPoles() + c->Degree() + 1);
    c->KnotSequence(k);
    const int p = c->Degree();
    if (multiplicity_at(k, 1 + p) >= p && k(1) != k(1 + p))
        c->Segment(k(1 + p), k(c->NbPoles() + 1));
}

geom::Surface to_surface(Handle(Geom_BSplineSurface) s) {
    unroll_surface(s);
    geom::Surface out;
    out.type =
        s->IsURational() || s->IsVRational() ? geom::SplineType::nurbs : geom::SplineType::bspline;
    out.degree_u = s->UDegree();
    out.degree_v = s->VDegree();
    out.n_u = s->NbUPoles();
    out.n_v = s->NbVPoles();
    TColStd_Array1OfReal ku(1, out.n_u + out.degree_u + 1), kv(1, out.n_v + out.degree_v + 1);
    s->UKnotSequence(ku);
    s->VKnotSequence(kv);
    out.knots_u = knot_sequence(ku);
    out.knots_v = knot_sequence(kv);
    out.points.resize(static_cast<std::size_t>(out.n_u) * out.n_v);
    out.weights.resize(out.points.size());
    const bool rational = out.type == geom::SplineType::nurbs;
    for (int i = 0; i < out.n_u; ++i)
        for (int j = 0; j < out.n_v; ++j) {
            const gp_Pnt& p = s->Pole(i + 1, j + 1);
            out.point(i, j) = {p.X(), p.Y(), p.Z()};
            out.weight(i, j) = rational ? s->Weight(i + 1, j + 1) : 1.0;
        }
    return out;
}

geom::Curve to_curve(Handle(Geom_BSplineCurve) c) {
    unroll_curve(c);
    geom::Curve out;
    out.type = c->IsRational() ? geom::SplineType::nurbs : geom::SplineType::bspline;
    out.degree = c->Degree();
    TColStd_Array1OfReal k(1, c->NbPoles() + c->Degree() + 1);
    c->KnotSequence(k);
    out.knots = knot_sequence(k);
    out.points.reserve(static_cast<std::size_t>(c->NbPoles()));
    out.weights.reserve(static_cast<std::size_t>(c->NbPoles()));
    for (int i = 1; i <= c->NbPoles(); ++i) {
        const gp_Pnt& p = c->Pole(i);
        out.points.push_back({p.X(), p.Y(), p.Z()});
        out.weights.push_back(out.type == geom::SplineType::nurbs ? c->Weight(i) : 1.0);
    }
    return out;
}

// Rounding, relative to the range: a box this close to the surface's range is its range.
double rounding(double a, double b) {
    return 1e-9 * std::max(1.0, std::abs(b - a));
}

std::string interval_text(double lo, double hi) {
    return "[" + geom::format_number(lo) + ", " + geom::format_number(hi) + "]";
}

// One direction of a face's box fitted to its surface's (or an edge's range to its curve's).
struct Range {
    double lo = 0, hi = 0;
    bool cut = false; // narrower than what the geometry spans: the geometry is segmented
};
using Fitted = std::variant<Range, std::string>;

struct ParamReach {
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    bool found = false;
};

Fitted fit_range(double lo, double hi, double first, double last, bool periodic, double period,
                 const char* what) {
    const double huge = Precision::Infinite() / 2;
    if (!(lo < hi))
        return std::string("its ") + what + " range " + interval_text(lo, hi) + " is empty";
    if (periodic) {
        if (lo <= -huge || hi >= huge) return Range{first, first + period, false};
        // A face is at most one period wide; wider is rounding (or nonsense) and means one turn.
        if (hi - lo >= period - rounding(0, period)) return Range{lo, lo + period, false};
        return Range{lo, hi, true};
    }
    lo = std::max(lo, first);
    hi = std::min(hi, last);
    if (lo <= -huge || hi >= huge)
        return std::string("it is unbounded in ") + what +
               " (no edges close it on an infinite surface or curve)";
    if (!(lo < hi))
        return std::string("its ") + what + " range lies outside its geometry's range " +
               interval_text(first, last);
    const double tol = rounding(first, last);
    return Range{lo, hi, lo > first + tol || hi < last - tol};
}

// Where the face's p-curves reach in its surface's parameters: the box of their control points
// (which holds each curve), unlike BRepTools::UVBounds, which cuts it to the surface's range.
ParamReach pcurve_reach(const TopoDS_Face& face) {
    Bnd_Box2d box;
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
        Standard_Real f = 0, l = 0;
        const Handle(Geom2d_Curve) c =
            BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Current()), face, f, l);
        if (!c.IsNull() && f < l) BndLib_Add2dCurve::Add(c, f, l, 0.0, box);
    }
    ParamReach r;
    if (box.IsVoid()) return r;
    box.Get(r.u0, r.v0, r.u1, r.v1);
    r.found = true;
    return r;
}

// A B-spline face whose p-curves leave its surface's range (by more than rounding, in a
// direction that is not periodic): the face's edges run on the surface continued past its range
// (OCCT's Geom_BSplineSurface evaluates there by continuing its end pieces). The surface is
// extended the same way (geom::extend_domain: unchanged on its range, exactly that continuation
// outside) to hold the loops, so the trim follows the file's edges, and the note says so.
// hammer.iges has four planes (bilinear patches) with circles 1e-5 to 2e-5 outside their range,
// 0.037 to 0.115 in space against the file's tolerances of 3e-6 to 8e-6; trj7_k1-al-214.stp two
// bicubic faces with an edge wandering 3.1e-4 past u = 0 (OCCT's area integral cuts those at
// the range: occt_trimmed_area_test.cpp has the figures).
std::string extend_to_pcurves(const TopoDS_Face& face, bool u_periodic, bool v_periodic,
                              geom::Surface& surface, FaceBox& box) {
    const ParamReach reach = pcurve_reach(face);
    if (!reach.found) return "";
    const geom::ParamRect d = geom::domain(surface);
    geom::ParamRect to = d;
    if (!u_periodic && reach.u0 < d.u.lo - rounding(d.u.lo, d.u.hi)) to.u.lo = reach.u0;
    if (!u_periodic && reach.u1 > d.u.hi + rounding(d.u.lo, d.u.hi)) to.u.hi = reach.u1;
    if (!v_periodic && reach.v0 < d.v.lo - rounding(d.v.lo, d.v.hi)) to.v.lo = reach.v0;
    if (!v_periodic && reach.v1 > d.v.hi + rounding(d.v.lo, d.v.hi)) to.v.hi = reach.v1;
    if (to.u.lo == d.u.lo && to.u.hi == d.u.hi && to.v.lo == d.v.lo && to.v.hi == d.v.hi) return "";
    geom::Expected<geom::Surface> extended = geom::extend_domain(surface, to);
    if (!extended) return "";
    surface = std::move(extended).value();
    box.u0 = to.u.lo;
    box.u1 = to.u.hi;
    box.v0 = to.v.lo;
    box.v1 = to.v.hi;
    return "its surface was extended from " + interval_text(d.u.lo, d.u.hi) + " x " +
           interval_text(d.v.lo, d.v.hi) + " to " + interval_text(to.u.lo, to.u.hi) + " x " +
           interval_text(to.v.lo, to.v.hi) +
           " to hold its trim loops (its end pieces continued, as OCCT evaluates them)";
}

// The face with its wires mended by OCCT's ShapeFix_Wire (self-intersecting edges, edges that
// cross, adjacent or not; precision the largest tolerance of its edges), or nothing where that
// changes nothing. bug32596_abc_0_13.step's faces 4, 13, 65 (edge tolerances up to 0.0099 on a
// domain 0.0086 wide in u) and bug22869_Spring.igs's faces 0 and 5 (up to 0.079) have p-curves
// that cross; mended, their loops are valid and their areas within 1e-4 of OCCT's area of the
// face as the file has it (faces 4, 13, 65: 3.4e-5, 3.8e-5, 2.0e-6; Spring face 0: 8.2e-7).
struct Mended {
    TopoDS_Face face;
    std::string what;
};
std::optional<Mended> fixed_wires(const TopoDS_Face& original) {
    // A deep copy: ShapeFix changes edges in place, and the file's edges are shared with the
    // neighbouring faces (which must come in as the file has them).
    const TopoDS_Face face = TopoDS::Face(BRepBuilderAPI_Copy(original).Shape());
    double precision = 0;
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next())
        precision = std::max(precision, BRep_Tool::Tolerance(TopoDS::Edge(e.Current())));
    TopoDS_Face out = TopoDS::Face(face.EmptyCopied());
    BRep_Builder builder;
    bool changed = false;
    for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
        ShapeFix_Wire fix(TopoDS::Wire(w.Current()), face, precision);
        fix.FixSelfIntersectingEdgeMode() = 1;
        fix.FixIntersectingEdgesMode() = 1;
        fix.FixNonAdjacentIntersectingEdgesMode() = 1;
        fix.ModifyTopologyMode() = Standard_True; // may cut edges and move vertices
        fix.ModifyGeometryMode() = Standard_True; // may replace p-curves
        changed = fix.Perform() || changed;
        builder.Add(out, fix.Wire());
    }
    if (!changed) return std::nullopt;
    return Mended{out, "its wires' crossing p-curves were mended by OCCT's ShapeFix_Wire (at the "
                       "largest edge tolerance, " +
                           geom::format_short(precision, 3) + ")"};
}

// The surface an offset surface is, exactly, where OCCT or the basis's form gives one: OCCT's own
// equivalent (Geom_OffsetSurface::Surface: a plane, cylinder, cone, sphere or torus basis, trimmed
// or not, becomes the same kind with the offset radius), or, for a straight line revolved about
// an axis in its plane (a cylinder, cone or plane written as a revolution, as bug23171_tube_surf
// has), the revolution of that line moved by the offset along its normal: the normal is the same
// all along a line in the meridian plane, so the offset of each meridian is the moved line, with
// the same parameters. Either is accepted only where it agrees with the offset surface on a
// grid over the face's box (within 1e-9 of the box's size): a skew line (a hyperboloid) fails.
Handle(Geom_Surface)
    exact_offset(const Handle(Geom_OffsetSurface) & o, double u0, double u1, double v0, double v1) {
    Handle(Geom_Surface) eq = o->Surface();
    if (eq.IsNull()) {
        Handle(Geom_Surface) basis = o->BasisSurface();
        for (int depth = 0; depth < 64; ++depth) {
            auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(basis);
            if (t.IsNull()) break;
            basis = t->BasisSurface();
        }
        const auto rev = Handle(Geom_SurfaceOfRevolution)::DownCast(basis);
        if (rev.IsNull()) return {};
        Handle(Geom_Curve) meridian = rev->BasisCurve();
        for (int depth = 0; depth < 64; ++depth) {
            auto t = Handle(Geom_TrimmedCurve)::DownCast(meridian);
            if (t.IsNull()) break;
            meridian = t->BasisCurve();
        }
        const auto line = Handle(Geom_Line)::DownCast(meridian);
        if (line.IsNull()) return {};
        // At u = 0 the revolution is its meridian: the offset's points there are the moved line.
        const gp_Pnt start = o->Value(0, 0);
        const gp_Pnt on_line = line->Value(0);
        Handle(Geom_Line) moved =
            new Geom_Line(line->Position().Translated(gp_Vec(on_line, start)));
        eq = new Geom_SurfaceOfRevolution(moved, rev->Axis());
    }
    const double huge = Precision::Infinite() / 2;
    if (!(u0 > -huge && u1 < huge && v0 > -huge && v1 < huge)) return {};
    double size = 0;
    const gp_Pnt corner = o->Value(u0, v0);
    for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 8; ++j)
            size = std::max(
                size, o->Value(u0 + (u1 - u0) * i / 8, v0 + (v1 - v0) * j / 8).Distance(corner));
    for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 8; ++j) {
            const double u = u0 + (u1 - u0) * i / 8, v = v0 + (v1 - v0) * j / 8;
            if (o->Value(u, v).Distance(eq->Value(u, v)) > 1e-9 * std::max(size, 1e-300)) return {};
        }
    return eq;
}

Converted face_geometry(const TopoDS_Face& face) {
    Handle(Geom_Surface) s = BRep_Tool::Surface(face);
    if (s.IsNull()) return {std::nullopt, "a face without a surface"};
    Standard_Real u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    for (int depth = 0; depth < 64; ++depth) {
        auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s);
        if (t.IsNull()) break;
        s = t->BasisSurface();
    }
    std::string kind = s->DynamicType()->Name();
    if (const auto offset = Handle(Geom_OffsetSurface)::DownCast(s); !offset.IsNull()) {
        const Handle(Geom_Surface) exact = exact_offset(offset, u0, u1, v0, v1);
        if (exact.IsNull())
            return {std::nullopt, kind + ": an offset surface has no exact NURBS form (only an "
                                         "offset of a plane, cylinder, cone, sphere, torus or "
                                         "revolved line is converted)"};
        s = exact;
        kind += " (as a " + std::string(s->DynamicType()->Name()) + ")";
    }
    Standard_Real a0, a1, b0, b1;
    s->Bounds(a0, a1, b0, b1);
    const bool up = s->IsUPeriodic(), vp = s->IsVPeriodic();
    const Fitted fu = fit_range(u0, u1, a0, a1, up, up ? s->UPeriod() : 0, "u");
    if (const auto* why = std::get_if<std::string>(&fu)) return {std::nullopt, kind + ": " + *why};
    const Fitted fv = fit_range(v0, v1, b0, b1, vp, vp ? s->VPeriod() : 0, "v");
    if (const auto* why = std::get_if<std::string>(&fv)) return {std::nullopt, kind + ": " + *why};
    const Range u = std::get<Range>(fu), v = std::get<Range>(fv);

    Handle(Geom_BSplineSurface) b;
    if (auto bs = Handle(Geom_BSplineSurface)::DownCast(s); !bs.IsNull()) {
        b = Handle(Geom_BSplineSurface)::DownCast(bs->Copy());
        // A periodic B-spline is cut while still periodic: the piece may cross the seam.
        if (u.cut || v.cut)
            b->Segment(u.cut ? u.lo : a0, u.cut ? u.hi : a1, v.cut ? v.lo : b0, v.cut ? v.hi : b1);
    } else {
        Handle(Geom_RectangularTrimmedSurface) box =
            new Geom_RectangularTrimmedSurface(s, u.lo, u.hi, v.lo, v.hi);
        b = GeomConvert::SurfaceToBSplineSurface(box);
    }
    if (b.IsNull()) return {std::nullopt, kind + ": OCCT cannot convert it to a B-spline surface"};
    geom::Surface surface = to_surface(b);
    const FaceBox box{u.lo, u.hi, v.lo, v.hi, up ? s->UPeriod() : 0.0, vp ? s->VPeriod() : 0.0};
    // The face's loops on the surface (extended where its p-curves leave a B-spline's range:
    // only there are the parameters OCCT's own, not a conversion's over the box).
    struct Attempt {
        geom::Surface surface;
        std::variant<geom::Trim, std::string> trim;
        std::string extended;
    };
    const auto attempt = [&](const TopoDS_Face& f) {
        Attempt a{surface, {}, ""};
        FaceBox b = box;
        if (!Handle(Geom_BSplineSurface)::DownCast(s).IsNull())
            a.extended = extend_to_pcurves(f, up, vp, a.surface, b);
        a.trim = face_trim(f, s, b, a.surface);
        return a;
    };
    Attempt a = attempt(face);
    std::string fixed;
    if (std::holds_alternative<std::string>(a.trim)) {
        // p-curves that cross within a loose file tolerance: the wires as OCCT's own ShapeFix
        // mends them (occt_trim.hpp fixed_wires), kept only where that gives valid loops.
        const auto mended = fixed_wires(face);
        if (mended) {
            Attempt b = attempt(mended->face);
            if (std::holds_alternative<geom::Trim>(b.trim)) {
                a = std::move(b);
                fixed = mended->what;
            }
        }
    }
    if (auto* why = std::get_if<std::string>(&a.trim))
        return {std::move(a.surface), "", kind + ": its trim loops were left out (" + *why + ")"};
    if (is_whole_domain(std::get<geom::Trim>(a.trim), geom::domain(a.surface)) && fixed.empty())
        return {std::move(a.surface), "", ""};
    std::string note = a.extended;
    if (!fixed.empty()) note += (note.empty() ? "" : "; ") + fixed;
    return {geom::TrimmedSurface{std::move(a.surface), std::move(std::get<geom::Trim>(a.trim))}, "",
            note.empty() ? "" : kind + ": " + note};
}

Converted edge_geometry(const TopoDS_Edge& edge) {
    Standard_Real first = 0, last = 0;
    Handle(Geom_Curve) c = BRep_Tool::Curve(edge, first, last);
    if (c.IsNull()) return {std::nullopt, "an edge without a 3D curve"};
    for (int depth = 0; depth < 64; ++depth) {
        auto t = Handle(Geom_TrimmedCurve)::DownCast(c);
        if (t.IsNull()) break;
        c = t->BasisCurve();
    }
    const std::string kind = c->DynamicType()->Name();
    if (!Handle(Geom_OffsetCurve)::DownCast(c).IsNull())
        return {std::nullopt, kind + ": an offset curve has no exact NURBS form"};
    const bool periodic = c->IsPeriodic();
    const Fitted fitted = fit_range(first, last, c->FirstParameter(), c->LastParameter(), periodic,
                                    periodic ? c->Period() : 0, "parameter");
    if (const auto* why = std::get_if<std::string>(&fitted))
        return {std::nullopt, kind + ": " + *why};
    const Range r = std::get<Range>(fitted);
    Handle(Geom_BSplineCurve) b;
    if (auto bc = Handle(Geom_BSplineCurve)::DownCast(c); !bc.IsNull()) {
        b = Handle(Geom_BSplineCurve)::DownCast(bc->Copy());
        if (r.cut) b->Segment(r.lo, r.hi);
    } else {
        b = GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(c, r.lo, r.hi));
    }
    if (b.IsNull()) return {std::nullopt, kind + ": OCCT cannot convert it to a B-spline curve"};
    return {to_curve(b), ""};
}

// OCCT reports what it refuses by exceptions (Standard_Failure); each stays with its item.
template <class F> Converted guarded(F&& convert) {
    try {
        return convert();
    } catch (const Standard_Failure& e) {
        return {std::nullopt, std::string("OCCT failed converting it: ") + e.DynamicType()->Name() +
                                  " " + e.GetMessageString()};
    }
}

} // namespace

Converted convert_face(const TopoDS_Face& face) {
    return guarded([&] { return face_geometry(face); });
}

Converted convert_edge(const TopoDS_Edge& edge) {
    return guarded([&] { return edge_geometry(edge); });
}

} // namespace isoparm::exchange_occt
