// Face wires to trim loops: p-curves converted or mapped into the NURBS surface's parameters.
#include "core/exchange_occt/occt_trim.hpp"

#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dConvert.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom2d_Line.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_Curve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <optional>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/refine.hpp"
#include "core/geom/trim/fit_samples.hpp"
#include "core/geom/trim/trim_flatten.hpp"
#include "core/geom/trim/trim_validate.hpp"

namespace isoparm::exchange_occt {

namespace {

using geom::ParamRect;

// Curve ends closer than this fraction of the domain are joined; loops farther open fail.
constexpr double join_fraction = 1e-4;
// Mapped curves are fitted within this fraction of the domain.
constexpr double fit_fraction = 1e-9;

glm::dvec3 occt_point(const Handle(Geom_Surface) & s, double u, double v) {
    const gp_Pnt p = s->Value(u, v);
    return {p.X(), p.Y(), p.Z()};
}

// Where the maps are checked, as fractions of the box: not quarters, since a circle converted
// in two or four equal arcs agrees with its angle parameter exactly at the quarters (its knots)
// and nowhere between.
constexpr int sample_count = 7;
constexpr double samples[sample_count] = {0, 0.137, 0.291, 0.458, 0.619, 0.853, 1};

// From OCCT's parameters of the face's surface to the converted NURBS surface's.
class Mapper {
public:
    Mapper(const Handle(Geom_Surface) & original, const FaceBox& box, const geom::Surface& s)
        : original_(original), box_(box), s_(s), d_(geom::domain(s)) {
        glm::dvec3 lo(INFINITY), hi(-INFINITY);
        for (const glm::dvec3& p : s.points) lo = glm::min(lo, p), hi = glm::max(hi, p);
        size_ = std::max(glm::length(hi - lo), 1e-300);
        identity_ = true;
        for (int i = 0; i < sample_count && identity_; ++i)
            for (int j = 0; j < sample_count && identity_; ++j) {
                const double u = box.u0 + (box.u1 - box.u0) * samples[i];
                const double v = box.v0 + (box.v1 - box.v0) * samples[j];
                const auto at = on_domain(u, v);
                const auto p = at ? geom::surface_point(s, at->x, at->y) : std::nullopt;
                identity_ = p && glm::length(*p - occt_point(original, u, v)) <= 1e-9 * size_;
            }
        if (identity_) return;
        // One-dimensional maps through the middle of the box, checked on the same grid.
        const double um = 0.5 * (box.u0 + box.u1), vm = 0.5 * (box.v0 + box.v1);
        const glm::dvec2 mid = newton({um, vm}, occt_point(original, um, vm), guess({um, vm}));
        u_ref_ = mid.x;
        v_ref_ = mid.y;
        separable_ = true;
        for (int i = 0; i < sample_count && separable_; ++i)
            for (int j = 0; j < sample_count && separable_; ++j) {
                const double u = box.u0 + (box.u1 - box.u0) * samples[i];
                const double v = box.v0 + (box.v1 - box.v0) * samples[j];
                const glm::dvec2 m{map_u(u), map_v(v)};
                const auto p = geom::surface_point(s, m.x, m.y);
                separable_ = p && glm::length(*p - occt_point(original, u, v)) <= 1e-8 * size_;
            }
    }

    bool identity() const { return identity_; }
    double size() const { return size_; }

    glm::dvec2 map(glm::dvec2 uv) const {
        if (identity_) return uv;
        const glm::dvec2 first{map_u(uv.x), map_v(uv.y)};
        if (separable_) return first;
        return newton(uv, occt_point(original_, uv.x, uv.y), first);
    }

    // The NURBS parameters of a 3D point near the surface (a p-curve's projection).
    glm::dvec2 project(const glm::dvec3& p) const {
        glm::dvec2 best{d_.u.lo, d_.v.lo};
        double best_d = INFINITY;
        for (int i = 0; i <= 32; ++i)
            for (int j = 0; j <= 32; ++j) {
                const glm::dvec2 t{d_.u.lo + (d_.u.hi - d_.u.lo) * i / 32,
                                   d_.v.lo + (d_.v.hi - d_.v.lo) * j / 32};
                const auto q = geom::surface_point(s_, t.x, t.y);
                if (q && glm::length(*q - p) < best_d) best_d = glm::length(*q - p), best = t;
            }
        return solve(p, best);
    }

private:
    // (u, v) in the domain, where it is there up to rounding (1e-9 of the domain's width: the
    // box's ends and the domain's differ by a rounding where a B-spline was segmented to the box,
    // as Geom_BSplineSurface::Segment computes its end knots: bug22869_Spring.igs face 0's box
    // ends at u = 0.00097572377793087028, its segmented surface at ...78442, and that corner of
    // the box, "outside", made its parameters look not OCCT's: its p-curves then went through
    // maps and fits, and one edge was not followed).
    std::optional<glm::dvec2> on_domain(double u, double v) const {
        const double tu = 1e-9 * (d_.u.hi - d_.u.lo), tv = 1e-9 * (d_.v.hi - d_.v.lo);
        if (!(u >= d_.u.lo - tu && u <= d_.u.hi + tu && v >= d_.v.lo - tv && v <= d_.v.hi + tv))
            return std::nullopt;
        return glm::dvec2(std::clamp(u, d_.u.lo, d_.u.hi), std::clamp(v, d_.v.lo, d_.v.hi));
    }

    // The NURBS parameters proportional to OCCT's over the box: the first guess.
    glm::dvec2 guess(glm::dvec2 uv) const {
        return {d_.u.lo + (uv.x - box_.u0) / (box_.u1 - box_.u0) * (d_.u.hi - d_.u.lo),
                d_.v.lo + (uv.y - box_.v0) / (box_.v1 - box_.v0) * (d_.v.hi - d_.v.lo)};
    }

    glm::dvec2 newton(glm::dvec2, const glm::dvec3& target, glm::dvec2 start) const {
        return solve(target, start);
    }

    // Gauss-Newton on S(u', v') = target, damped and kept in the domain.
    glm::dvec2 solve(const glm::dvec3& target, glm::dvec2 t) const {
        t = {std::clamp(t.x, d_.u.lo, d_.u.hi), std::clamp(t.y, d_.v.lo, d_.v.hi)};
        for (int it = 0; it < 50; ++it) {
            const auto der = geom::surface_derivatives(s_, t.x, t.y, 1);
            if (!der) break;
            const glm::dvec3 r = der->D[0][0] - target, su = der->D[1][0], sv = der->D[0][1];
            const double a = glm::dot(su, su), b = glm::dot(su, sv), c = glm::dot(sv, sv);
            const double gu = glm::dot(su, r), gv = glm::dot(sv, r);
            const double det = a * c - b * b;
            glm::dvec2 step;
            if (det > 1e-24 * (a * c + 1e-300)) {
                step = {-(c * gu - b * gv) / det, -(a * gv - b * gu) / det};
            } else if (a >= c && a > 0) { // degenerate in v (a pole): move along u only
                step = {-gu / a, 0};
            } else if (c > 0) {
                step = {0, -gv / c};
            } else {
                break;
            }
            const glm::dvec2 next{std::clamp(t.x + step.x, d_.u.lo, d_.u.hi),
                                  std::clamp(t.y + step.y, d_.v.lo, d_.v.hi)};
            if (glm::length(next - t) <= 1e-15 * (d_.u.hi - d_.u.lo + d_.v.hi - d_.v.lo)) break;
            t = next;
        }
        return t;
    }

    // One parameter along an isocurve of the NURBS surface through the reference line, by
    // Newton's method kept inside a bracket (the distance's derivative changes sign once).
    double solve_1d(geom::Dir dir, const glm::dvec3& target, double start) const {
        const geom::Interval I = dir == geom::Dir::u ? d_.u : d_.v;
        double lo = I.lo, hi = I.hi, t = std::clamp(start, lo, hi);
        for (int it = 0; it < 100; ++it) {
            const double u = dir == geom::Dir::u ? t : u_ref_, v = dir == geom::Dir::u ? v_ref_ : t;
            const auto der = geom::surface_derivatives(s_, u, v, 2);
            if (!der) break;
            const glm::dvec3 r = der->D[0][0] - target;
            const glm::dvec3 d1 = dir == geom::Dir::u ? der->D[1][0] : der->D[0][1];
            const glm::dvec3 d2 = dir == geom::Dir::u ? der->D[2][0] : der->D[0][2];
            const double g1 = glm::dot(d1, r), g2 = glm::dot(d2, r) + glm::dot(d1, d1);
            if (g1 > 0)
                hi = t;
            else
                lo = t;
            double next = g2 > 0 ? t - g1 / g2 : 0.5 * (lo + hi);
            if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
            if (std::abs(next - t) <= 1e-15 * (I.hi - I.lo) || g1 == 0) break;
            t = next;
        }
        return t;
    }

    // The box's ends are the NURBS domain's ends (the conversion spans the box, in the same
    // direction). Inverting the surface cannot tell them apart where the box is a whole period:
    // both are the seam, and a p-curve on the seam at u1 would land on u0 (its loop then
    // encloses nothing or crosses itself).
    static std::optional<double> at_end(double t, double t0, double t1, geom::Interval d) {
        const double tol = 1e-9 * (t1 - t0);
        if (std::abs(t - t0) <= tol) return d.lo;
        if (std::abs(t - t1) <= tol) return d.hi;
        return std::nullopt;
    }

    double map_u(double u) const {
        if (const auto end = at_end(u, box_.u0, box_.u1, d_.u)) return *end;
        const double vm = 0.5 * (box_.v0 + box_.v1);
        return solve_1d(geom::Dir::u, occt_point(original_, u, vm), guess({u, vm}).x);
    }
    double map_v(double v) const {
        if (const auto end = at_end(v, box_.v0, box_.v1, d_.v)) return *end;
        const double um = 0.5 * (box_.u0 + box_.u1);
        return solve_1d(geom::Dir::v, occt_point(original_, um, v), guess({um, v}).y);
    }

    Handle(Geom_Surface) original_;
    FaceBox box_;
    const geom::Surface& s_;
    ParamRect d_;
    double size_ = 1, u_ref_ = 0, v_ref_ = 0;
    bool identity_ = false, separable_ = false;
};

geom::Curve to_curve_2d(Handle(Geom2d_BSplineCurve) c, glm::dvec2 shift) {
    if (c->IsPeriodic()) c->SetNotPeriodic();
    geom::Curve out;
    out.type = c->IsRational() ? geom::SplineType::nurbs : geom::SplineType::bspline;
    out.degree = c->Degree();
    TColStd_Array1OfReal k(1, c->NbPoles() + c->Degree() + 1);
    c->KnotSequence(k);
    for (Standard_Integer i = k.Lower(); i <= k.Upper(); ++i) out.knots.push_back(k(i));
    for (int i = 1; i <= c->NbPoles(); ++i) {
        const gp_Pnt2d& p = c->Pole(i);
        out.points.push_back({p.X() + shift.x, p.Y() + shift.y, 0.0});
        out.weights.push_back(out.type == geom::SplineType::nurbs ? c->Weight(i) : 1.0);
    }
    if (!geom::is_clamped(out.knots, out.degree, out.count()))
        if (auto clamped = geom::clamp(out); clamped) out = std::move(*clamped);
    return out;
}

// The whole periods that bring t into [lo, hi] (a p-curve may sit one period over).
double period_shift(double t, double lo, double hi, double period) {
    if (period <= 0) return 0;
    const double tol = 1e-9 * period;
    double shift = 0;
    for (int k = 0; k < 8 && t + shift < lo - tol; ++k) shift += period;
    for (int k = 0; k < 8 && t + shift > hi + tol; ++k) shift -= period;
    return shift;
}

struct EdgeCurve {
    std::vector<geom::Curve> curves; // the edge in order (a mapped edge may be several pieces)
    std::string why;                 // when it failed
};

// The distinct interior knots of a knot vector.
std::vector<double> interior_knots(const geom::Knots& k) {
    std::vector<double> out;
    for (double t : k)
        if (t > k.front() && t < k.back() && (out.empty() || t != out.back())) out.push_back(t);
    return out;
}

// Where a mapped p-curve has a kink: the parameters t in (f, l) at which its image crosses a
// knot line of the converted surface (the map from OCCT's parameters to the NURBS surface's is
// only piecewise smooth there: each rational arc of a converted circle has a map of its own)
// and the p-curve's own knots of continuity below C2. A cubic fit of uniform samples cannot
// follow a kink, so each smooth piece is fitted on its own.
std::vector<double> kinks(const std::function<glm::dvec2(double)>& mapped, double f, double l,
                          const geom::Surface& s, const Handle(Geom2d_Curve) & basis) {
    std::vector<double> out;
    if (auto b = Handle(Geom2d_BSplineCurve)::DownCast(basis); !b.IsNull())
        for (int i = 1; i <= b->NbKnots(); ++i)
            if (b->Multiplicity(i) >= std::max(1, b->Degree() - 1) && b->Knot(i) > f &&
                b->Knot(i) < l)
                out.push_back(b->Knot(i));
    const std::vector<double> lines[2] = {interior_knots(s.knots_u), interior_knots(s.knots_v)};
    constexpr int samples = 256;
    glm::dvec2 prev = mapped(f);
    double t_prev = f;
    for (int k = 1; k <= samples; ++k) {
        const double t = f + (l - f) * k / samples;
        const glm::dvec2 q = mapped(t);
        for (int axis = 0; axis < 2; ++axis)
            for (double knot : lines[axis]) {
                const double a = prev[axis] - knot, b = q[axis] - knot;
                if (!(a * b < 0)) continue;
                // Bisection for the crossing (the map is monotone within a sample step).
                double lo = t_prev, hi = t;
                for (int it = 0; it < 60; ++it) {
                    const double m = 0.5 * (lo + hi);
                    if ((mapped(m)[axis] - knot) * a > 0)
                        lo = m;
                    else
                        hi = m;
                }
                out.push_back(0.5 * (lo + hi));
            }
        prev = q;
        t_prev = t;
    }
    std::sort(out.begin(), out.end());
    // Pieces shorter than 1e-9 of the edge are merged into their neighbour.
    std::vector<double> kept;
    for (double t : out)
        if (t - (kept.empty() ? f : kept.back()) > 1e-9 * (l - f) && l - t > 1e-9 * (l - f))
            kept.push_back(t);
    return kept;
}

// Pieces of a mapped curve are fitted with at most this many samples each; a piece that does
// not come within the tolerance is halved (down to `max_depth` halvings), which isolates a kink
// the search in kinks() missed (a cubic fit converges only slowly across one).
constexpr int piece_samples = 256;
constexpr int max_depth = 40;

// Fits [a, b] into `out`, halving it where one fit is not within the tolerance; false where
// even the smallest pieces are not.
bool fit_adaptive(const std::function<glm::dvec2(double)>& mapped, double a, double b, int pieces,
                  double tolerance, int depth, std::vector<geom::Curve>& out) {
    geom::SampleFit fit =
        geom::fit_samples_limited([&](double t) { return glm::dvec3(mapped(t), 0.0); }, {a, b},
                                  pieces, tolerance, piece_samples);
    if (!fit.within && depth < max_depth) {
        const double m = 0.5 * (a + b);
        return fit_adaptive(mapped, a, m, std::max(1, pieces / 2), tolerance, depth + 1, out) &&
               fit_adaptive(mapped, m, b, std::max(1, pieces / 2), tolerance, depth + 1, out);
    }
    if (!out.empty()) fit.curve.points.front() = out.back().points.back();
    out.push_back(std::move(fit.curve));
    return fit.within;
}

// The mapped function fitted piece by piece between its kinks; consecutive pieces share their
// end points exactly. Empty where it cannot be followed within the tolerance.
std::vector<geom::Curve> fit_pieces(const std::function<glm::dvec2(double)>& mapped, double f,
                                    double l, const std::vector<double>& breaks, int pieces,
                                    double tolerance) {
    std::vector<double> ends{f};
    ends.insert(ends.end(), breaks.begin(), breaks.end());
    ends.push_back(l);
    std::vector<geom::Curve> out;
    const int per_piece = std::max(1, pieces / static_cast<int>(ends.size() - 1));
    for (std::size_t k = 0; k + 1 < ends.size(); ++k)
        if (!fit_adaptive(mapped, ends[k], ends[k + 1], per_piece, tolerance, 0, out)) return {};
    return out;
}

// Where a B-spline p-curve is a line of constant u or v written as a spline (its poles on one
// line of constant u or v, running one way along it, so the curve does too): the direction of
// that line, else a null direction.
std::optional<gp_Dir2d> iso_line_of(const Handle(Geom2d_Curve) & basis, const FaceBox& box) {
    const auto b = Handle(Geom2d_BSplineCurve)::DownCast(basis);
    if (b.IsNull() || b->NbPoles() < 2) return std::nullopt;
    for (int axis = 0; axis < 2; ++axis) {
        const double width = axis == 0 ? box.u1 - box.u0 : box.v1 - box.v0;
        const auto coord = [&](int i, int a) { return a == 0 ? b->Pole(i).X() : b->Pole(i).Y(); };
        bool flat = true, up = true, down = true;
        for (int i = 2; i <= b->NbPoles(); ++i) {
            flat = flat && std::abs(coord(i, axis) - coord(1, axis)) <= 1e-12 * width;
            up = up && coord(i, 1 - axis) >= coord(i - 1, 1 - axis);
            down = down && coord(i, 1 - axis) <= coord(i - 1, 1 - axis);
        }
        if (flat && (up || down) && coord(1, 1 - axis) != coord(b->NbPoles(), 1 - axis))
            return axis == 0 ? gp_Dir2d(0, up ? 1 : -1) : gp_Dir2d(up ? 1 : -1, 0);
    }
    return std::nullopt;
}
bool iso_spline(const Handle(Geom2d_Curve) & basis, const FaceBox& box) {
    return iso_line_of(basis, box).has_value();
}

EdgeCurve edge_curve(const TopoDS_Edge& edge, const TopoDS_Face& face, const FaceBox& box,
                     const Mapper& map, const geom::Surface& surface) {
    const ParamRect domain = geom::domain(surface);
    Standard_Real f = 0, l = 0;
    Handle(Geom2d_Curve) c2d = BRep_Tool::CurveOnSurface(edge, face, f, l);
    const double scale = geom::domain_scale(domain);
    const double tolerance = fit_fraction * scale;
    EdgeCurve out;
    if (!(f < l)) {
        out.why = "an edge with an empty parameter range";
        return out;
    }
    if (c2d.IsNull()) {
        // No p-curve: the edge's 3D curve projected onto the surface point by point.
        TopLoc_Location loc;
        Standard_Real a = 0, b = 0;
        Handle(Geom_Curve) c3d = BRep_Tool::Curve(edge, loc, a, b);
        if (c3d.IsNull() || !(a < b)) {
            out.why = "an edge with neither a p-curve nor a 3D curve";
            return out;
        }
        const gp_Trsf trsf = loc.Transformation();
        const std::function<glm::dvec2(double)> projected = [&](double t) {
            gp_Pnt p = c3d->Value(t);
            p.Transform(trsf);
            return map.project({p.X(), p.Y(), p.Z()});
        };
        out.curves = fit_pieces(
            projected, a, b, kinks(projected, a, b, surface, Handle(Geom2d_Curve)()), 8, tolerance);
    } else {
        // Unwrap trimmed curves to see a line.
        Handle(Geom2d_Curve) basis = c2d;
        for (int depth = 0; depth < 16; ++depth) {
            auto t = Handle(Geom2d_TrimmedCurve)::DownCast(basis);
            if (t.IsNull()) break;
            basis = t->BasisCurve();
        }
        const gp_Pnt2d pm = c2d->Value(0.5 * (f + l));
        const glm::dvec2 shift{period_shift(pm.X(), box.u0, box.u1, box.u_period),
                               period_shift(pm.Y(), box.v0, box.v1, box.v_period)};
        auto at = [&](double t) {
            const gp_Pnt2d p = c2d->Value(t);
            return glm::dvec2(p.X(), p.Y()) + shift;
        };
        const auto line = Handle(Geom2d_Line)::DownCast(basis);
        bool converted = false;
        if (map.identity()) {
            try {
                Handle(Geom2d_BSplineCurve) b =
                    Geom2dConvert::CurveToBSplineCurve(new Geom2d_TrimmedCurve(c2d, f, l));
                if (!b.IsNull()) {
                    out.curves.push_back(to_curve_2d(b, shift));
                    converted = true;
                }
            } catch (const Standard_Failure&) {
            }
        }
        if (!converted && (!line.IsNull() || iso_spline(basis, box))) {
            const gp_Dir2d dir = !line.IsNull() ? line->Direction() : *iso_line_of(basis, box);
            // Lines of constant u or v map to lines (the maps are one-dimensional), and every
            // line maps to itself where the parameters are kept.
            if (map.identity() || std::abs(dir.X()) < 1e-12 || std::abs(dir.Y()) < 1e-12) {
                const glm::dvec2 a = map.map(at(f)), b = map.map(at(l));
                glm::dvec2 a2 = a, b2 = b;
                if (std::abs(dir.X()) < 1e-12) b2.x = a2.x; // exactly constant u
                if (std::abs(dir.Y()) < 1e-12) b2.y = a2.y;
                out.curves.push_back(geom::trim_line(a2, b2));
                converted = true;
            }
        }
        if (!converted) {
            int pieces = 8;
            if (auto b = Handle(Geom2d_BSplineCurve)::DownCast(basis); !b.IsNull())
                pieces = std::max(pieces, b->NbKnots());
            const std::function<glm::dvec2(double)> mapped = [&](double t) {
                return map.map(at(t));
            };
            out.curves =
                fit_pieces(mapped, f, l, kinks(mapped, f, l, surface, basis), pieces, tolerance);
        }
    }
    if (out.curves.empty() && out.why.empty())
        out.why =
            "an edge that no fit follows within " + geom::format_short(tolerance, 3) + " in (u, v)";
    if (edge.Orientation() == TopAbs_REVERSED) {
        std::reverse(out.curves.begin(), out.curves.end());
        for (geom::Curve& c : out.curves) c = geom::reversed(c);
    }
    return out;
}

// Moves a clamped curve's first (or last) point, the end of the curve, to p.
void move_end(geom::Curve& c, bool last, glm::dvec2 p) {
    glm::dvec3& q = last ? c.points.back() : c.points.front();
    q.x = p.x;
    q.y = p.y;
}

// The file's own tolerance where two edges of a wire meet (BRep_Tool::Tolerance of the vertex
// between them and of both edges): the distance in space within which OCCT, and the system that
// wrote the file, take the p-curves' ends as one point.
double junction_tolerance(const TopoDS_Edge& before, const TopoDS_Edge& after) {
    double t = std::max(BRep_Tool::Tolerance(before), BRep_Tool::Tolerance(after));
    const TopoDS_Vertex a = TopExp::LastVertex(before, Standard_True);
    const TopoDS_Vertex b = TopExp::FirstVertex(after, Standard_True);
    if (!a.IsNull()) t = std::max(t, BRep_Tool::Tolerance(a));
    if (!b.IsNull()) t = std::max(t, BRep_Tool::Tolerance(b));
    return t;
}

glm::dvec2 clamped(glm::dvec2 p, const ParamRect& d) {
    return {std::clamp(p.x, d.u.lo, d.u.hi), std::clamp(p.y, d.v.lo, d.v.hi)};
}

// The distance in space between the surface's points at two parameters (clamped to the domain).
double distance_on_surface(const geom::Surface& s, glm::dvec2 a, glm::dvec2 b) {
    const ParamRect d = geom::domain(s);
    const auto p = geom::surface_point(s, clamped(a, d).x, clamped(a, d).y);
    const auto q = geom::surface_point(s, clamped(b, d).x, clamped(b, d).y);
    return p && q ? glm::length(*p - *q) : INFINITY;
}

bool is_line(const geom::Curve& c) {
    return c.degree == 1 && c.points.size() == 2;
}

// Where two curves whose ends do not quite meet are joined. Two lines meet where they cross
// when that is near both ends (a writer's lines that overshoot or stop short of their corner,
// as a rectangle's sides in catiav5_Ventilator.stp do by 0.024, keep the rectangle); any other
// pair meets halfway between the ends.
glm::dvec2 junction_point(const geom::Curve& before, const geom::Curve& after, double limit) {
    const glm::dvec2 a = geom::curve_end(before).value_or(glm::dvec2(NAN));
    const glm::dvec2 b = geom::curve_start(after).value_or(glm::dvec2(NAN));
    const glm::dvec2 mid = 0.5 * (a + b);
    if (a == b || !is_line(before) || !is_line(after)) return mid;
    const glm::dvec2 p = geom::uv(before.points.front()), d = a - p;
    const glm::dvec2 q = b, e = geom::uv(after.points.back()) - b;
    const double cross = d.x * e.y - d.y * e.x;
    // Nearly parallel lines (within 1e-3 radians) meet halfway.
    if (!(std::abs(cross) > 1e-3 * glm::length(d) * glm::length(e))) return mid;
    const double s = ((q.x - p.x) * e.y - (q.y - p.y) * e.x) / cross;
    const glm::dvec2 x = p + s * d;
    return glm::length(x - a) <= limit && glm::length(x - b) <= limit ? x : mid;
}

// Ends farther apart than this fraction of the domain are never joined, whatever the distance
// in space: across a seam or a pole the ends of an open wire meet in space but not in (u, v).
constexpr double join_fraction_limit = 1e-2;

std::variant<geom::TrimLoop, std::string> wire_loop(const TopoDS_Wire& wire,
                                                    const TopoDS_Face& face, const FaceBox& box,
                                                    const Mapper& map,
                                                    const geom::Surface& surface) {
    const ParamRect domain = geom::domain(surface);
    geom::TrimLoop loop;
    // For each curve, the file's tolerance at its start where an edge starts there (0 between
    // the pieces of one edge, which share their ends exactly).
    std::vector<double> start_tolerance;
    std::vector<TopoDS_Edge> edges;
    for (BRepTools_WireExplorer e(wire, face); e.More(); e.Next()) {
        EdgeCurve c = edge_curve(e.Current(), face, box, map, surface);
        if (!c.why.empty()) return c.why;
        edges.push_back(e.Current());
        for (std::size_t k = 0; k < c.curves.size(); ++k) {
            loop.curves.push_back(std::move(c.curves[k]));
            start_tolerance.push_back(k == 0 ? -1.0 : 0.0); // -1: an edge starts here
        }
    }
    if (loop.curves.empty()) return std::string("a wire without edges");
    for (std::size_t k = 0, edge = 0; k < start_tolerance.size(); ++k)
        if (start_tolerance[k] < 0) {
            const TopoDS_Edge& after = edges[edge];
            const TopoDS_Edge& before = edges[(edge + edges.size() - 1) % edges.size()];
            start_tolerance[k] = junction_tolerance(before, after);
            ++edge;
        }
    // Join the ends: each junction to the middle of the two ends that meet there. Ends meet
    // where they are within 1e-4 of the domain in (u, v), or where the surface's points there are
    // within twice the file's tolerance in space (what "closed" means in that file: BRepCheck
    // takes each p-curve's end within the tolerance of the vertex, so the two are within twice
    // it of each other).
    const double join = join_fraction * geom::domain_scale(domain);
    const double join_limit = join_fraction_limit * geom::domain_scale(domain);
    const std::size_t n = loop.curves.size();
    for (std::size_t k = 0; k < n; ++k) {
        geom::Curve& before = loop.curves[(k + n - 1) % n];
        geom::Curve& after = loop.curves[k];
        const glm::dvec2 a = geom::curve_end(before).value_or(glm::dvec2(NAN));
        const glm::dvec2 b = geom::curve_start(after).value_or(glm::dvec2(NAN));
        const double gap = glm::length(a - b);
        const bool closes =
            gap <= join ||
            (gap <= join_limit && distance_on_surface(surface, a, b) <= 2 * start_tolerance[k]);
        if (!closes)
            return "its wire is open by " + geom::format_short(gap, 3) + " in (u, v), " +
                   geom::format_short(distance_on_surface(surface, a, b), 3) +
                   " in space (at most " + geom::format_short(join, 3) +
                   " is joined, or the file's tolerance " +
                   geom::format_short(2 * start_tolerance[k], 3) + " in space)";
        const glm::dvec2 m = junction_point(before, after, join_limit);
        move_end(before, true, m);
        move_end(after, false, m);
    }
    // Points a hair outside the domain (the file's rounding) onto its edge.
    for (geom::Curve& c : loop.curves)
        for (glm::dvec3& p : c.points) {
            if (p.x < domain.u.lo && p.x > domain.u.lo - join) p.x = domain.u.lo;
            if (p.x > domain.u.hi && p.x < domain.u.hi + join) p.x = domain.u.hi;
            if (p.y < domain.v.lo && p.y > domain.v.lo - join) p.y = domain.v.lo;
            if (p.y > domain.v.hi && p.y < domain.v.hi + join) p.y = domain.v.hi;
        }
    return loop;
}

} // namespace

std::variant<geom::Trim, std::string> face_trim(const TopoDS_Face& face,
                                                const Handle(Geom_Surface) & original,
                                                const FaceBox& box,
                                                const geom::Surface& converted) {
    const ParamRect domain = geom::domain(converted);
    const Mapper map(original, box, converted);
    const TopoDS_Wire outer = BRepTools::OuterWire(face);
    geom::Trim trim;
    geom::FlattenRule rule;
    rule.tolerance = 1e-6 * geom::domain_scale(domain);
    int wires = 0;
    for (TopExp_Explorer e(face, TopAbs_WIRE); e.More(); e.Next(), ++wires) {
        const TopoDS_Wire wire = TopoDS::Wire(e.Current());
        auto loop = wire_loop(wire, face, box, map, converted);
        if (auto* why = std::get_if<std::string>(&loop)) return *why;
        geom::TrimLoop l = std::move(std::get<geom::TrimLoop>(loop));
        const double area = geom::twice_signed_area(geom::flatten_loop(l, rule).points);
        const bool is_outer = wire.IsSame(outer) && !trim.outer;
        if ((is_outer && area < 0) || (!is_outer && area > 0)) l = geom::reversed(l);
        if (is_outer)
            trim.outer = std::move(l);
        else
            trim.holes.push_back(std::move(l));
    }
    if (wires == 0) return std::string("a face without wires");
    if (geom::Status st = geom::validate_trim(trim, domain); !st) return st.error().message;
    return trim;
}

bool is_whole_domain(const geom::Trim& trim, const ParamRect& domain) {
    if (!trim.outer || !trim.holes.empty()) return false;
    const double tol = 1e-12 * geom::domain_scale(domain);
    const auto on = [&](double a, double b) { return std::abs(a - b) <= tol; };
    for (const geom::Curve& c : trim.outer->curves) {
        bool u_lo = true, u_hi = true, v_lo = true, v_hi = true;
        for (const glm::dvec3& p : c.points) {
            u_lo = u_lo && on(p.x, domain.u.lo);
            u_hi = u_hi && on(p.x, domain.u.hi);
            v_lo = v_lo && on(p.y, domain.v.lo);
            v_hi = v_hi && on(p.y, domain.v.hi);
        }
        if (!(u_lo || u_hi || v_lo || v_hi)) return false;
    }
    // Curves along the sides only (each inside the hull of its control points, all on one side),
    // counter-clockwise (face_trim orients the outer loop): the whole rectangle.
    return true;
}

} // namespace isoparm::exchange_occt
