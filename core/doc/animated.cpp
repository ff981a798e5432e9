// Animated parameters on the document: checks, previews taken back bit for bit, and the
// command that keeps a value.
#include "core/doc/animated.hpp"

#include <algorithm>
#include <cmath>

#include "core/doc/commands.hpp"
#include "core/doc/commands_common.hpp"
#include "core/doc/point_set.hpp"

namespace isoparm::doc {

using geom::ErrorCode;
using geom::make_error;

namespace {

struct KnotRun {
    geom::Knots* U = nullptr;
    int first = 0, count = 0;
    double lo = 0, hi = 0; // the neighbours' values
};

// The run of equal knots holding index k of the object's knot vector along dir, and the
// values it may take; the ends of a clamped vector do not move.
geom::Expected<KnotRun> knot_run(Shape& shape, const std::string& name, geom::Dir dir, int k) {
    geom::Knots* U = nullptr;
    if (geom::Surface* s = surface_of(shape))
        U = dir == geom::Dir::u ? &s->knots_u : &s->knots_v;
    else if (geom::Curve* c = curve_of(shape))
        U = &c->knots;
    if (!U) return make_error(ErrorCode::schema, "'" + name + "' has no knots", "/object");
    const int m = static_cast<int>(U->size());
    if (k < 0 || k >= m)
        return make_error(
            ErrorCode::schema,
            "knot index " + std::to_string(k) + " is outside 0.." + std::to_string(m - 1), "/k");
    KnotRun r{U, k, 1};
    while (r.first > 0 && (*U)[r.first - 1] == (*U)[k]) --r.first;
    int last = k;
    while (last + 1 < m && (*U)[last + 1] == (*U)[k]) ++last;
    r.count = last - r.first + 1;
    if (r.first == 0 || last == m - 1)
        return make_error(ErrorCode::schema,
                          "knot " + std::to_string(k) +
                              " is at an end of the knot vector; only "
                              "the knots between the ends move",
                          "/k");
    r.lo = (*U)[r.first - 1];
    r.hi = (*U)[last + 1];
    return r;
}

void set_run(KnotRun& r, double v) {
    for (int q = r.first; q < r.first + r.count; ++q) (*r.U)[q] = v;
}

// The weight of control point (i, j), and of the point a closed curve repeats it as.
geom::Status set_weight_in(Shape& shape, int i, int j, double w) {
    if (geom::Surface* s = surface_of(shape)) {
        s->weight(i, j) = w;
    } else if (CurveObject* c = curve_object_of(shape)) {
        c->curve.weights[static_cast<std::size_t>(i)] = w;
        if (c->knot_mode == CurveKnotMode::closed) {
            const int p = c->curve.degree, n = c->curve.count() - p;
            if (i < p) c->curve.weights[static_cast<std::size_t>(i + n)] = w;
            if (i >= n) c->curve.weights[static_cast<std::size_t>(i - n)] = w;
        }
    } else if (geom::TrianglePatch* t = triangle_of(shape)) {
        t->weights[static_cast<std::size_t>(geom::TrianglePatch::index(t->degree, i, j))] = w;
    }
    return geom::Ok{};
}

bool rational(const Shape& shape) {
    if (const geom::Surface* s = surface_of(shape)) return geom::is_rational(s->type);
    if (const geom::Curve* c = curve_of(shape)) return geom::is_rational(c->type);
    if (const geom::TrianglePatch* t = triangle_of(shape)) return t->rational;
    return false;
}

int parameter_index(const ImplicitObject& f, const std::string& name) {
    for (std::size_t k = 0; k < f.parameter_names.size(); ++k)
        if (f.parameter_names[k] == name) return static_cast<int>(k);
    return -1;
}

} // namespace

geom::Status check_target(const Document& doc, const AnimationTarget& t) {
    for (auto [v, path] : {std::pair{t.from, "/from"}, std::pair{t.to, "/to"}})
        if (!std::isfinite(v))
            return make_error(ErrorCode::schema, "an animation needs finite values", path);
    const bool needs_object = t.kind == AnimatedKind::weight || t.kind == AnimatedKind::knot ||
                              t.kind == AnimatedKind::implicit_parameter;
    if (!needs_object) {
        if (t.kind == AnimatedKind::deboor_step && (t.from < -1 || t.to < -1))
            return make_error(ErrorCode::schema, "de Boor steps start at 0 (-1: all)", "/from");
        for (double c :
             {t.uv_from.x, t.uv_from.y, t.uv_to.x, t.uv_to.y, t.centre.x, t.centre.y, t.radius})
            if (!std::isfinite(c))
                return make_error(ErrorCode::schema, "the indicator's path needs finite values",
                                  t.kind == AnimatedKind::indicator_circle ? "/centre" : "/from");
        return geom::Ok{};
    }
    const Object* o = doc.find(t.object);
    if (!o)
        return make_error(ErrorCode::schema,
                          "there is no object with id " + std::to_string(t.object), "/object");
    switch (t.kind) {
    case AnimatedKind::weight:
        if (!has_control_point(o->shape, t.i, t.j))
            return make_error(ErrorCode::schema,
                              "'" + o->name + "' has no control point [" + std::to_string(t.i) +
                                  (o->curve() ? "" : ", " + std::to_string(t.j)) + "]",
                              "/point");
        if (!rational(o->shape))
            return make_error(ErrorCode::weights,
                              "'" + o->name +
                                  "' is not rational: its weights are all 1. Convert it "
                                  "to NURBS (or rational Bezier) to animate a weight",
                              "/object");
        return geom::Ok{};
    case AnimatedKind::knot: {
        Shape copy = o->shape;
        if (o->curve() && t.dir != geom::Dir::u)
            return make_error(ErrorCode::schema, "a curve has only one direction (u)",
                              "/direction");
        auto run = knot_run(copy, o->name, t.dir, t.k);
        if (!run) return run.error();
        for (auto [v, path] : {std::pair{t.from, "/from"}, std::pair{t.to, "/to"}}) {
            if (v < run->lo || v > run->hi)
                return make_error(ErrorCode::knots,
                                  "knot " + std::to_string(t.k) + " moves between its neighbours " +
                                      geom::format_number(run->lo) + " and " +
                                      geom::format_number(run->hi) + ", not to " +
                                      geom::format_number(v),
                                  path);
            set_run(*run, v);
            if (auto st = detail::validate_shape(copy); !st)
                return make_error(st.error().code, st.error().message, path);
        }
        return geom::Ok{};
    }
    case AnimatedKind::implicit_parameter: {
        const ImplicitObject* f = o->implicit();
        if (!f)
            return make_error(ErrorCode::schema, "'" + o->name + "' is not an implicit surface",
                              "/object");
        if (parameter_index(*f, t.parameter) < 0)
            return make_error(ErrorCode::schema,
                              "'" + o->name + "' has no parameter '" + t.parameter + "'",
                              "/parameter");
        return geom::Ok{};
    }
    default:
        return geom::Ok{};
    }
}

geom::Expected<PreviewUndo> show_preview(Document& doc, const AnimationTarget& t, double value,
                                         glm::dvec2 uv) {
    PreviewUndo undo;
    if (t.kind == AnimatedKind::indicator_line || t.kind == AnimatedKind::indicator_circle) {
        undo.indicator = doc.view.indicator;
        doc.view.indicator = uv;
        return undo;
    }
    if (t.kind == AnimatedKind::deboor_step) return undo;
    Object* o = doc.find(t.object);
    if (!o) return make_error(ErrorCode::schema, "the animated object is gone", "/object");
    undo.object = t.object;
    undo.shape = o->shape;
    switch (t.kind) {
    case AnimatedKind::weight:
        set_weight_in(o->shape, t.i, t.j, value);
        break;
    case AnimatedKind::knot: {
        auto run = knot_run(o->shape, o->name, t.dir, t.k);
        if (run) set_run(*run, value);
        break;
    }
    case AnimatedKind::implicit_parameter: {
        ImplicitObject& f = *o->implicit();
        const int k = parameter_index(f, t.parameter);
        if (k >= 0) f.parameter_values[static_cast<std::size_t>(k)] = value;
        break;
    }
    default:
        break;
    }
    auto rebuilt = rebuild_dependants(doc, {t.object});
    if (!rebuilt) {
        o->shape = std::move(*undo.shape);
        return rebuilt.error();
    }
    undo.dependants = std::move(rebuilt).value();
    return undo;
}

void restore_preview(Document& doc, PreviewUndo& undo) {
    restore_shapes(doc, undo.dependants);
    if (undo.object && undo.shape)
        if (Object* o = doc.find(*undo.object)) o->shape = std::move(*undo.shape);
    if (undo.indicator) doc.view.indicator = *undo.indicator;
    undo = PreviewUndo{};
}

std::unique_ptr<Command> keep_value(const Document& doc, const AnimationTarget& t, double value) {
    const Object* o = doc.find(t.object);
    switch (t.kind) {
    case AnimatedKind::weight:
        return set_weight(t.object, t.i, t.j, value);
    case AnimatedKind::knot: {
        if (!o) return nullptr;
        Shape copy = o->shape;
        auto run = knot_run(copy, o->name, t.dir, t.k);
        if (!run) return nullptr;
        return move_knot_run(t.object, t.dir, run->first, run->count, value);
    }
    case AnimatedKind::implicit_parameter: {
        if (!o || !o->implicit()) return nullptr;
        ImplicitObject f = *o->implicit();
        const int k = parameter_index(f, t.parameter);
        if (k < 0) return nullptr;
        f.parameter_values[static_cast<std::size_t>(k)] = value;
        return edit_shape(t.object, f, "Set " + t.parameter + " = " + geom::format_number(value));
    }
    default:
        return nullptr;
    }
}

// ---------------------------------------------------------------------------------------
// Values along the range.

double value_at(const AnimationTarget& t, double s) {
    if (s <= 0) return t.from;
    if (s >= 1) return t.to;
    return t.from + s * (t.to - t.from);
}

int step_at(const AnimationTarget& t, double s) {
    const int a = static_cast<int>(std::lround(t.from)), b = static_cast<int>(std::lround(t.to));
    if (s >= 1) return b;
    if (s <= 0) return a;
    // Each of the b - a + 1 steps gets an equal share of the phase.
    const int k = static_cast<int>(std::floor(s * (std::abs(b - a) + 1)));
    return a <= b ? std::min(a + k, b) : std::max(a - k, b);
}

glm::dvec2 indicator_at(const AnimationTarget& t, double s) {
    s = std::clamp(s, 0.0, 1.0);
    glm::dvec2 p;
    if (t.kind == AnimatedKind::indicator_circle) {
        const double a = 2 * std::acos(-1.0) * s;
        p = t.centre + t.radius * glm::dvec2(std::cos(a), std::sin(a));
    } else {
        p = s >= 1 ? t.uv_to : t.uv_from + s * (t.uv_to - t.uv_from);
    }
    return glm::clamp(p, glm::dvec2(0), glm::dvec2(1));
}

std::string describe(const AnimationTarget& t) {
    auto num = [](double x) { return geom::format_short(x); };
    switch (t.kind) {
    case AnimatedKind::weight: {
        const std::string idx = t.j < 0 ? std::to_string(t.i)
                                : (t.i < 10 && t.j < 10)
                                    ? std::to_string(t.i) + std::to_string(t.j)
                                    : std::to_string(t.i) + "," + std::to_string(t.j);
        return "w" + idx + " from " + num(t.from) + " to " + num(t.to);
    }
    case AnimatedKind::knot:
        return std::string("knot ") + geom::name_of(t.dir) + std::to_string(t.k) + " from " +
               num(t.from) + " to " + num(t.to);
    case AnimatedKind::indicator_line:
        return "(u, v) from (" + num(t.uv_from.x) + ", " + num(t.uv_from.y) + ") to (" +
               num(t.uv_to.x) + ", " + num(t.uv_to.y) + ")";
    case AnimatedKind::indicator_circle:
        return "(u, v) around (" + num(t.centre.x) + ", " + num(t.centre.y) + "), radius " +
               num(t.radius);
    case AnimatedKind::deboor_step:
        return "de Boor step " + std::to_string(step_at(t, 0)) + " to " +
               std::to_string(step_at(t, 1));
    case AnimatedKind::implicit_parameter:
        return t.parameter + " from " + num(t.from) + " to " + num(t.to);
    }
    return {};
}

} // namespace isoparm::doc
