// Refinement-like shape edits: the shared rule of commands_refine.cpp and commands_reshape.cpp.
#include "core/doc/refinement_edit.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/doc/commands_common.hpp"
#include "core/doc/commands_triangle.hpp"
#include "core/doc/shape_edit.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::doc::detail {

using geom::Dir;
using geom::ErrorCode;
using geom::make_error;

Line line_of(const Shape& shape, Dir dir) {
    if (const geom::Surface* s = surface_of(shape))
        return {&s->knots(dir), s->degree(dir), s->count(dir)};
    const geom::Curve& c = *curve_of(shape); // refinable: a surface or a curve
    return {&c.knots, c.degree, c.count()};
}

// The Greville abscissa of control point i, (U[i+1] + ... + U[i+p]) / p: the parameter a
// control point "belongs to" (Piegl & Tiller, sec. 9.3 and Farin). It is unchanged for the
// control points that knot insertion and splitting keep, so the nearest Greville abscissa
// finds "the same control point" in a new net. Summed as a running mean so that huge knots
// cannot overflow.
double greville(const Line& L, int i) {
    return geom::greville_abscissa(*L.U, L.p, i);
}

int nearest_greville(const Line& L, double g) {
    int best = 0;
    double best_d = std::abs(greville(L, 0) - g);
    for (int i = 1; i < L.n; ++i) {
        const double d = std::abs(greville(L, i) - g);
        if (d < best_d) best = i, best_d = d; // ties keep the lower index
    }
    return best;
}

int clamp_index(int i, int n) {
    return std::clamp(i, 0, std::max(n - 1, 0));
}

// The selection's index along dir if it is a control point of object id, else null.
int* selected_index(Selection& sel, std::uint64_t id, bool curve, Dir dir) {
    if (sel.object != id || !sel.has_point()) return nullptr;
    if (curve || dir == Dir::u) return &sel.i;
    return sel.j >= 0 ? &sel.j : nullptr;
}

bool is_curve(const Shape& shape) {
    return curve_of(shape) != nullptr;
}

// Shared checks of the refinement commands: the object is a surface or a curve (the kinds
// with knots), and a curve is refined along its only direction.
geom::Status check_refinable(const Object& obj, Dir dir, const char* what) {
    if (!obj.surface() && !obj.curve())
        return kind_refusal(obj, std::string(what) + " needs a curve or a surface");
    if (obj.curve() && dir != Dir::u)
        return make_error(ErrorCode::schema, "a curve has only one direction (u)", "/direction");
    return geom::Ok{};
}

geom::Expected<Object*> refinable(Document& doc, std::uint64_t id, Dir dir, const char* what) {
    auto found = find_object(doc, id);
    if (!found) return found.error();
    if (auto st = check_refinable(**found, dir, what); !st) return st.error();
    return *found;
}

const char* dir_name(Dir d) {
    return d == Dir::u ? "u" : "v";
}

// A triangle's selected control point in the refined net: the one nearest in the domain.
Selection same_triangle_point(Selection sel, std::uint64_t id, const Shape& from, const Shape& to) {
    if (sel.object != id || !sel.has_point()) return sel;
    const int n = triangle_of(from)->degree, m = triangle_of(to)->degree;
    std::tie(sel.i, sel.j) = nearest_control_point(m, control_point_domain(n, sel.i, sel.j));
    return sel;
}

std::unique_ptr<Command> refinement_command(std::uint64_t id, CommandSpec spec, Refinement r) {
    ShapeEditRule rule;
    rule.make = [r](const Object& obj) -> geom::Expected<Shape> {
        if (const geom::TrianglePatch* t = obj.triangle(); t && r.triangle) {
            auto refined = r.triangle(*t);
            if (!refined) return refined.error();
            return Shape{TriangleObject{std::move(refined).value()}};
        }
        if (auto st = check_refinable(obj, r.dir, r.what); !st) return st.error();
        if (const geom::Surface* s = obj.surface()) {
            auto refined = r.surface(*s);
            if (!refined) return refined.error();
            // The trim stays: refinement keeps the domain (validate_shape refuses an edit whose
            // new domain the loops leave).
            return Shape{SurfaceObject{std::move(refined).value(), *trim_of(obj.shape)}};
        }
        const CurveObject& c = *obj.curve_object();
        auto refined = r.curve(c.curve);
        if (!refined) return refined.error();
        // The refined knots are the curve's own now (knot mode custom): no rule gives them.
        // A curve closed by close_object stays closed under the designer's edits.
        return Shape{CurveObject{std::move(refined).value(), c.plane, r.curve_mode}};
    };
    // A (rational) Bezier has no interior knots: one inserted makes it a B-spline (NURBS).
    // The label says so, so that the change of kind is never silent.
    rule.label = [r](const Shape& before, const Shape& after) {
        const std::string change = type_change_text(before, after);
        return r.label(before, after) + (change.empty() ? "" : " (" + change + ")");
    };
    rule.forward = [id, r](const Selection& sel, const Shape& from, const Shape& to) {
        Selection out = sel;
        if (triangle_of(from)) return same_triangle_point(out, id, from, to);
        if (int* idx = selected_index(out, id, is_curve(from), r.dir))
            *idx = r.forward(line_of(from, r.dir), line_of(to, r.dir), *idx);
        return out;
    };
    rule.backward = [id, r](const Selection& sel, const Shape& from, const Shape& to) {
        Selection out = sel;
        if (triangle_of(from)) return same_triangle_point(out, id, from, to);
        if (int* idx = selected_index(out, id, is_curve(from), r.dir))
            *idx = r.backward(line_of(to, r.dir), line_of(from, r.dir), *idx);
        return out;
    };
    return shape_edit(id, std::move(spec), std::move(rule));
}

} // namespace isoparm::doc::detail
