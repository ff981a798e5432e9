// The curve designer's commands: one curve edit class (old and new CurveObject) behind each.
#include "core/doc/commands_curve.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <charconv>
#include <cmath>
#include <functional>
#include <optional>

#include "core/doc/commands_common.hpp"
#include "core/doc/shape_edit.hpp"
#include "core/geom/construct.hpp"
#include "core/geom/interpolate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/primitives.hpp"
#include "core/geom/reshape.hpp"
#include "core/geom/validate.hpp"

namespace isoparm::doc {

using geom::ErrorCode;
using geom::make_error;

const char* knot_mode_label(CurveKnotMode mode) {
    return geom::label_of(mode);
}

const char* curve_plane_label(CurvePlane plane) {
    return geom::label_of(plane);
}

geom::Expected<geom::Knots> knots_for_mode(const geom::Curve& curve, CurveKnotMode mode) {
    const int n = curve.count(), p = curve.degree;
    if (mode == CurveKnotMode::custom) return curve.knots;
    if (mode == CurveKnotMode::closed) return geom::close_periodic(curve).knots;
    if (p < 1 || n < p + 1)
        return make_error(ErrorCode::degree,
                          "a degree-" + std::to_string(p) + " curve needs at least " +
                              std::to_string(p + 1) + " control points, got " + std::to_string(n),
                          "/degree");
    const geom::KnotMode m = mode == CurveKnotMode::clamped_uniform
                                 ? geom::KnotMode::clamped_uniform
                             : mode == CurveKnotMode::chord ? geom::KnotMode::chord
                                                            : geom::KnotMode::centripetal;
    return geom::knots_for_points(curve.points, p, m);
}

namespace {

std::string vec_text(const glm::dvec3& p) {
    return "(" + geom::format_number(p.x) + ", " + geom::format_number(p.y) + ", " +
           geom::format_number(p.z) + ")";
}

// The refusal of a count or degree change under custom knots.
geom::Error custom_refusal(const Object& obj, const std::string& what) {
    return make_error(ErrorCode::knots,
                      "curve '" + obj.name + "' has custom knots, so " + what +
                          " has no rule for its new knot vector: choose the knot mode clamped "
                          "uniform, chord length or centripetal first (knot insertion and "
                          "degree elevation keep custom knots and the shape)",
                      "/knot_mode");
}

// The curve designer's polygon: a closed curve's points less the p it repeats at its end
// (every other mode: the curve's own points). Edits change the polygon, then refresh_knots
// closes it again.
CurveObject unwrapped(const CurveObject& c) {
    if (c.knot_mode != CurveKnotMode::closed) return c;
    CurveObject out = c;
    const auto n = static_cast<std::size_t>(std::max(c.curve.count() - c.curve.degree, 1));
    out.curve.points.resize(n);
    out.curve.weights.resize(n);
    return out;
}

// A closed curve's repeated point is the same point of the polygon.
int polygon_index(const CurveObject& c, int i) {
    if (c.knot_mode != CurveKnotMode::closed) return i;
    return i % std::max(c.curve.count() - c.curve.degree, 1);
}

// Recomputes the knots of c after its points or degree changed (a closed curve's polygon in
// c is closed again); a degenerate polygon is a `geometry` error at `path` naming the curve.
geom::Status refresh_knots(const Object& obj, CurveObject& c, const std::string& path) {
    geom::Curve& g = c.curve;
    if (c.knot_mode == CurveKnotMode::closed) {
        // A closed curve of degree p wraps p of its points: it needs at least p + 1.
        if (g.degree < 1 || g.count() < g.degree + 1)
            return make_error(ErrorCode::degree,
                              "closed curve '" + obj.name + "' of degree " +
                                  std::to_string(g.degree) + " needs at least " +
                                  std::to_string(g.degree + 1) + " control points, got " +
                                  std::to_string(g.count()),
                              path);
        g = geom::close_periodic(g);
        return geom::Ok{};
    }
    if (geom::is_bezier(g.type)) { // the Bezier rule: one span, degree = count - 1
        const double a = g.knots.empty() ? 0.0 : g.knots.front();
        const double b = g.knots.empty() ? 1.0 : g.knots.back();
        g.degree = g.count() - 1;
        g.knots = geom::bezier_knots(g.degree, a, b);
        return geom::Ok{};
    }
    auto k = knots_for_mode(g, c.knot_mode);
    if (!k) {
        geom::Error e = k.error();
        e.message = "curve '" + obj.name + "' with " + knot_mode_label(c.knot_mode) +
                    " knots: " + e.message + " (move the point apart or choose clamped uniform)";
        e.path = path;
        return e;
    }
    g.knots = std::move(k).value();
    return geom::Ok{};
}

// The new CurveObject an edit makes from the current one (the object is there for messages).
using CurveEdit = std::function<geom::Expected<CurveObject>(const Object&, const CurveObject&)>;
// The selection after the edit, from the one before.
using SelectionMap = std::function<Selection(const Selection&, const CurveObject& after)>;

// A curve designer's edit: a shape edit (shape_edit.hpp) of a curve object. `select` moves
// the selection into the new curve; a point index past its end goes to its last point.
std::unique_ptr<Command> curve_edit(std::uint64_t id, CommandSpec spec, std::string label,
                                    CurveEdit edit, std::string merge_key = {},
                                    SelectionMap select = {}) {
    detail::ShapeEditRule rule;
    rule.make = [edit = std::move(edit)](const Object& obj) -> geom::Expected<Shape> {
        const CurveObject* c = obj.curve_object();
        if (!c) return kind_refusal(obj, "the curve designer edits curves");
        auto r = edit(obj, *c);
        if (!r) return r.error();
        return Shape{std::move(r).value()};
    };
    rule.label = [label = std::move(label)](const Shape&, const Shape&) { return label; };
    rule.forward = [id, select = std::move(select)](const Selection& sel, const Shape&,
                                                    const Shape& to) {
        const CurveObject& after = *curve_object_of(to);
        Selection out = select ? select(sel, after) : sel;
        if (out.object == id && out.i >= after.curve.count()) out.i = after.curve.count() - 1;
        return out;
    };
    rule.merge_key = std::move(merge_key);
    rule.shape_path = "/curve";
    return detail::shape_edit(id, std::move(spec), std::move(rule));
}

geom::Status check_index(int i, int count, const char* what) {
    if (i < 0 || i > count)
        return make_error(ErrorCode::schema,
                          std::string(what) + " " + std::to_string(i) + " is outside 0.." +
                              std::to_string(count),
                          "/i");
    return geom::Ok{};
}

geom::Status check_finite(const glm::dvec3& p) {
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(p[a]))
            return make_error(ErrorCode::schema,
                              "a control point needs finite coordinates, got " + vec_text(p),
                              "/position/" + std::to_string(a));
    return geom::Ok{};
}

// The axes (first, second, normal) of a plane as coordinate indices.
std::array<int, 3> plane_axes_of(CurvePlane plane) {
    switch (plane) {
    case CurvePlane::xz:
        return {0, 2, 1};
    case CurvePlane::yz:
        return {1, 2, 0};
    default:
        return {0, 1, 2};
    }
}

geom::Expected<Object> curve_object(std::string name, CurvePlane plane,
                                    geom::Expected<geom::Curve> curve, CurveKnotMode mode) {
    if (!curve) return curve.error();
    Object o;
    o.name = std::move(name);
    o.shape = CurveObject{std::move(curve).value(), plane, mode};
    if (auto st = detail::validate_name(o.name); !st) return st.error();
    if (auto st = detail::validate_shape(o.shape); !st) return st.error().under("/curve");
    return o;
}

geom::Expected<geom::Plane> primitive_plane(CurvePlane plane) {
    switch (plane) {
    case CurvePlane::xy:
        return geom::Plane::xy;
    case CurvePlane::xz:
        return geom::Plane::xz;
    case CurvePlane::yz:
        return geom::Plane::yz;
    case CurvePlane::free3d:
        break;
    }
    return make_error(ErrorCode::schema,
                      "an arc or circle is drawn in a plane: choose xy, xz or yz, not 3D",
                      "/plane");
}

} // namespace

geom::Expected<Object> new_curve_object(std::string name, CurvePlane plane,
                                        std::vector<glm::dvec3> points, int degree,
                                        CurveKnotMode mode, bool rational) {
    const int n = static_cast<int>(points.size());
    if (n < 2)
        return make_error(ErrorCode::schema,
                          "a curve needs at least 2 control points, got " + std::to_string(n),
                          "/points");
    if (degree < 1 || degree > n - 1)
        return make_error(ErrorCode::degree,
                          "the degree must be 1.." + std::to_string(n - 1) + " for " +
                              std::to_string(n) + " control points, got " + std::to_string(degree),
                          "/degree");
    if (mode == CurveKnotMode::custom)
        return make_error(ErrorCode::knots,
                          "a new curve has no custom knots yet: choose clamped uniform, chord "
                          "length or centripetal",
                          "/knot_mode");
    for (std::size_t k = 0; k < points.size(); ++k)
        if (auto st = check_finite(points[k]); !st)
            return st.error().under("/points/" + std::to_string(k));
    geom::Curve c;
    c.type = rational ? geom::SplineType::nurbs : geom::SplineType::bspline;
    c.degree = degree;
    c.points = std::move(points);
    c.weights.assign(c.points.size(), 1.0);
    if (mode == CurveKnotMode::closed) {
        if (n < degree + 1)
            return make_error(ErrorCode::degree,
                              "a closed curve of degree " + std::to_string(degree) +
                                  " needs at least " + std::to_string(degree + 1) +
                                  " control points, got " + std::to_string(n),
                              "/degree");
        return curve_object(std::move(name), plane, geom::close_periodic(c), mode);
    }
    auto knots = knots_for_mode(c, mode);
    if (!knots) return knots.error();
    c.knots = std::move(knots).value();
    return curve_object(std::move(name), plane, std::move(c), mode);
}

geom::Expected<Object> line_object(std::string name, CurvePlane plane, const glm::dvec3& p0,
                                   const glm::dvec3& p1) {
    if (auto st = check_finite(p0); !st) return st.error().under("/p0");
    if (auto st = check_finite(p1); !st) return st.error().under("/p1");
    if (p0 == p1)
        return make_error(ErrorCode::geometry,
                          "a line needs two different end points, got " + vec_text(p0) + " twice",
                          "/p1");
    return curve_object(std::move(name), plane, geom::line_segment(p0, p1), CurveKnotMode::custom);
}

geom::Expected<Object> arc_object(std::string name, CurvePlane plane, const glm::dvec3& centre,
                                  double radius, double start_degrees, double end_degrees) {
    auto pl = primitive_plane(plane);
    if (!pl) return pl.error();
    if (auto st = check_finite(centre); !st) return st.error().under("/centre");
    return curve_object(std::move(name), plane,
                        geom::circular_arc(centre, radius, start_degrees, end_degrees, *pl),
                        CurveKnotMode::custom);
}

geom::Expected<Object> circle_object(std::string name, CurvePlane plane, const glm::dvec3& centre,
                                     double radius) {
    auto pl = primitive_plane(plane);
    if (!pl) return pl.error();
    if (auto st = check_finite(centre); !st) return st.error().under("/centre");
    return curve_object(std::move(name), plane, geom::full_circle(centre, radius, *pl),
                        CurveKnotMode::custom);
}

// ---------------------------------------------------------------------------------------

std::unique_ptr<Command> insert_curve_point(std::uint64_t id, int i, glm::dvec3 position) {
    auto edit = [i, position](const Object& obj,
                              const CurveObject& whole) -> geom::Expected<CurveObject> {
        const CurveObject c = unwrapped(whole);
        const int n = c.curve.count();
        if (auto st = check_index(i, n, "the new point's index"); !st) return st.error();
        if (auto st = check_finite(position); !st) return st.error();
        if (n + 1 > geom::max_points_per_direction)
            return make_error(ErrorCode::limit,
                              "curve '" + obj.name + "' has " + std::to_string(n) +
                                  " control points; at most " +
                                  std::to_string(geom::max_points_per_direction) + " are allowed",
                              "/i");
        if (!geom::is_bezier(c.curve.type) && c.knot_mode == CurveKnotMode::custom)
            return custom_refusal(obj, "inserting a control point");
        CurveObject out = c;
        out.curve.points.insert(out.curve.points.begin() + i, position);
        out.curve.weights.insert(out.curve.weights.begin() + i, 1.0);
        if (auto st = refresh_knots(obj, out, "/position"); !st) return st.error();
        return out;
    };
    auto select = [id, i](const Selection&, const CurveObject&) { return Selection{id, i, -1}; };
    return curve_edit(id, InsertCurvePointSpec{id, i, position}, "Insert P" + std::to_string(i),
                      edit, "", select);
}

std::unique_ptr<Command> delete_curve_point(std::uint64_t id, int i) {
    auto edit = [i](const Object& obj, const CurveObject& whole) -> geom::Expected<CurveObject> {
        if (i < 0 || i >= whole.curve.count())
            return make_error(ErrorCode::schema,
                              "control point index " + std::to_string(i) + " is outside 0.." +
                                  std::to_string(whole.curve.count() - 1),
                              "/i");
        const CurveObject c = unwrapped(whole);
        const int n = c.curve.count();
        const bool bezier = geom::is_bezier(c.curve.type);
        const int need = bezier ? 2 : std::max(2, c.curve.degree + 1);
        if (n - 1 < need)
            return make_error(ErrorCode::degree,
                              "deleting P" + std::to_string(i) + " would leave curve '" + obj.name +
                                  "' " + std::to_string(n - 1) + " control points; " +
                                  (bezier ? std::string("a curve needs 2")
                                          : "its degree " + std::to_string(c.curve.degree) +
                                                " needs " + std::to_string(need) +
                                                " (lower the degree first)"),
                              "/i");
        if (!bezier && c.knot_mode == CurveKnotMode::custom)
            return custom_refusal(obj, "deleting a control point");
        CurveObject out = c;
        const int at = polygon_index(whole, i);
        out.curve.points.erase(out.curve.points.begin() + at);
        out.curve.weights.erase(out.curve.weights.begin() + at);
        if (auto st = refresh_knots(obj, out, "/i"); !st) return st.error();
        return out;
    };
    auto select = [id, i](const Selection& s, const CurveObject& after) {
        Selection out = s;
        if (s.object != id || !s.has_point()) return out;
        if (s.i > i) --out.i;
        out.i = std::min(out.i, after.curve.count() - 1);
        return out;
    };
    return curve_edit(id, DeleteCurvePointSpec{id, i}, "Delete P" + std::to_string(i), edit, "",
                      select);
}

std::unique_ptr<Command> move_curve_point(std::uint64_t id, int i, glm::dvec3 position) {
    auto edit = [i, position](const Object& obj,
                              const CurveObject& c) -> geom::Expected<CurveObject> {
        const int n = c.curve.count();
        if (i < 0 || i >= n)
            return make_error(ErrorCode::schema,
                              "control point index " + std::to_string(i) + " is outside 0.." +
                                  std::to_string(n - 1),
                              "/i");
        if (auto st = check_finite(position); !st) return st.error();
        if (c.knot_mode == CurveKnotMode::closed) {
            // The polygon's point moves, and its repeat with it.
            CurveObject out = unwrapped(c);
            out.curve.points[static_cast<std::size_t>(polygon_index(c, i))] = position;
            if (auto st = refresh_knots(obj, out, "/position"); !st) return st.error();
            return out;
        }
        CurveObject out = c;
        out.curve.points[static_cast<std::size_t>(i)] = position;
        // Only the polygon-dependent modes follow a drag: clamped uniform knots do not depend
        // on the points, and custom knots are the user's.
        if (!geom::is_bezier(c.curve.type) &&
            (c.knot_mode == CurveKnotMode::chord || c.knot_mode == CurveKnotMode::centripetal))
            if (auto st = refresh_knots(obj, out, "/position"); !st) return st.error();
        return out;
    };
    return curve_edit(id, MoveCurvePointSpec{id, i, position}, "Move P" + std::to_string(i), edit,
                      "move " + std::to_string(i));
}

std::unique_ptr<Command> set_curve_degree(std::uint64_t id, int degree) {
    auto edit = [degree](const Object& obj,
                         const CurveObject& whole) -> geom::Expected<CurveObject> {
        const CurveObject c = unwrapped(whole);
        const int n = c.curve.count();
        if (geom::is_bezier(c.curve.type)) {
            if (degree == c.curve.degree) return whole;
            return make_error(
                ErrorCode::degree,
                "curve '" + obj.name + "' is a " + geom::spline_type_name(c.curve.type) +
                    " curve: its degree is " + std::to_string(c.curve.degree) +
                    " (its point count - 1), so it cannot be set to " + std::to_string(degree) +
                    "; use degree elevation, or make it a B-spline",
                "/degree");
        }
        if (degree < 1 || degree > n - 1)
            return make_error(ErrorCode::degree,
                              "curve '" + obj.name + "' has " + std::to_string(n) +
                                  " control points, so its degree must be 1.." +
                                  std::to_string(n - 1) + ", got " + std::to_string(degree),
                              "/degree");
        if (c.knot_mode == CurveKnotMode::custom) return custom_refusal(obj, "changing the degree");
        CurveObject out = c;
        out.curve.degree = degree;
        if (auto st = refresh_knots(obj, out, "/degree"); !st) return st.error();
        return out;
    };
    return curve_edit(id, SetCurveDegreeSpec{id, degree}, "Set degree " + std::to_string(degree),
                      edit);
}

std::unique_ptr<Command> set_curve_knot_mode(std::uint64_t id, CurveKnotMode mode) {
    auto edit = [mode](const Object& obj, const CurveObject& whole) -> geom::Expected<CurveObject> {
        // Custom keeps the curve as it is (a closed one stays closed, its knots now the user's);
        // every other mode starts from the polygon.
        if (mode == CurveKnotMode::custom) {
            CurveObject out = whole;
            out.knot_mode = mode;
            return out;
        }
        const CurveObject c = unwrapped(whole);
        CurveObject out = c;
        out.knot_mode = mode;
        if (mode == CurveKnotMode::closed) {
            if (auto st = refresh_knots(obj, out, "/knot_mode"); !st) return st.error();
            return out;
        }
        {
            auto k = knots_for_mode(c.curve, mode);
            if (!k) {
                geom::Error e = k.error();
                e.message = "curve '" + obj.name + "' cannot take " + knot_mode_label(mode) +
                            " knots: " + e.message;
                e.path = "/knot_mode";
                return e;
            }
            out.curve.knots = std::move(k).value();
        }
        return out;
    };
    return curve_edit(id, SetCurveKnotModeSpec{id, mode},
                      std::string("Knots: ") + knot_mode_label(mode), edit);
}

std::unique_ptr<Command> set_curve_plane(std::uint64_t id, CurvePlane plane, bool carry_points) {
    auto edit = [plane, carry_points](const Object&,
                                      const CurveObject& c) -> geom::Expected<CurveObject> {
        CurveObject out = c;
        out.plane = plane;
        if (carry_points && c.plane != CurvePlane::free3d && plane != CurvePlane::free3d) {
            const auto from = plane_axes_of(c.plane), to = plane_axes_of(plane);
            for (glm::dvec3& p : out.curve.points) {
                glm::dvec3 q{0};
                for (int a = 0; a < 3; ++a) q[to[a]] = p[from[a]];
                p = q;
            }
        }
        return out;
    };
    return curve_edit(id, SetCurvePlaneSpec{id, plane, carry_points},
                      std::string("Plane ") + curve_plane_label(plane), edit);
}

// ---------------------------------------------------------------------------------------

namespace {

class MakeCompatible final : public Command {
public:
    explicit MakeCompatible(std::vector<std::uint64_t> ids) : ids_(std::move(ids)) {}

    geom::Status apply(Document& doc) override {
        if (ids_.size() < 2)
            return make_error(ErrorCode::schema,
                              "make compatible takes at least 2 curves, got " +
                                  std::to_string(ids_.size()),
                              "/ids");
        std::vector<geom::Curve> curves;
        std::vector<const Object*> objects;
        for (std::size_t k = 0; k < ids_.size(); ++k) {
            const std::string at = "/ids/" + std::to_string(k);
            const Object* o = doc.find(ids_[k]);
            if (!o)
                return make_error(ErrorCode::schema,
                                  "there is no object with id " + std::to_string(ids_[k]), at);
            if (std::find(ids_.begin(), ids_.begin() + static_cast<long>(k), ids_[k]) !=
                ids_.begin() + static_cast<long>(k))
                return make_error(ErrorCode::schema, "curve '" + o->name + "' is chosen twice", at);
            const auto* c = std::get_if<CurveObject>(&o->shape);
            if (!c)
                return make_error(ErrorCode::schema,
                                  "'" + o->name + "' is " + kind_noun(o->kind()) + ", not a curve",
                                  at);
            curves.push_back(c->curve);
            objects.push_back(o);
        }
        auto r = geom::make_compatible(curves);
        if (!r) {
            geom::Error e = r.error();
            const std::string prefix = "/curves/";
            if (e.path.compare(0, prefix.size(), prefix) == 0) {
                const std::size_t end = e.path.find('/', prefix.size());
                const std::string digits = e.path.substr(prefix.size(), end - prefix.size());
                std::size_t k = objects.size();
                std::from_chars(digits.data(), digits.data() + digits.size(), k);
                if (k < objects.size())
                    e.message = "curve '" + objects[k]->name + "': " + e.message;
                e.path = "/ids/" + e.path.substr(prefix.size());
            }
            return e;
        }
        // All checked: now change the document.
        old_.clear();
        for (std::size_t k = 0; k < ids_.size(); ++k) {
            Object* o = doc.find(ids_[k]);
            auto& c = std::get<CurveObject>(o->shape);
            old_.push_back(c);
            c.curve = (*r)[k];
            c.knot_mode = CurveKnotMode::custom;
        }
        sel_before_ = doc.view.selection;
        for (std::size_t k = 0; k < ids_.size(); ++k)
            if (doc.view.selection.object == ids_[k] && doc.view.selection.has_point())
                doc.view.selection.i = std::min(doc.view.selection.i, (*r)[k].count() - 1);
        sel_after_ = doc.view.selection;
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        for (std::size_t k = 0; k < ids_.size(); ++k) {
            Object* o = doc.find(ids_[k]);
            assert(o);
            o->shape = old_[k];
        }
        if (doc.view.selection == sel_after_) doc.view.selection = sel_before_;
    }

    std::string label() const override {
        return "Make " + std::to_string(ids_.size()) + " curves compatible";
    }
    std::size_t memory_bytes() const override {
        std::size_t bytes = sizeof(*this);
        for (const CurveObject& c : old_) bytes += 2 * detail::shape_bytes(c);
        return bytes;
    }
    std::optional<CommandSpec> spec() const override { return MakeCompatibleSpec{ids_}; }

private:
    std::vector<std::uint64_t> ids_;
    std::vector<CurveObject> old_;
    Selection sel_before_, sel_after_;
};

} // namespace

std::unique_ptr<Command> make_curves_compatible(std::vector<std::uint64_t> ids) {
    return std::make_unique<MakeCompatible>(std::move(ids));
}

} // namespace isoparm::doc
