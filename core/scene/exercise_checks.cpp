// Grading: each check of an exercise on a student's document, with what it found.
#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>

#include "core/doc/border_measure.hpp"
#include "core/doc/patches.hpp"
#include "core/geom/closest_point.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/scene/exercise.hpp"
#include "core/scene/exercise_text.hpp"

namespace isoparm::scene {

namespace {

std::string num(double x) {
    return short_number(x);
}

std::string quoted(const doc::Object& o) {
    return "'" + o.name + "'";
}

// What a check looks at: the named object, or every object of the kinds it takes.
struct Candidates {
    std::vector<const doc::Object*> objects;
    std::string missing; // why there is none ("no object named 'vase'", "no curve in the scene")
};

Candidates candidates(const Check& c, const doc::Document& d, bool surfaces, bool curves,
                      bool triangles = false) {
    Candidates out;
    auto fits = [&](const doc::Object& o) {
        return (surfaces && o.surface()) || (curves && o.curve()) || (triangles && o.triangle());
    };
    const std::string kinds = surfaces && curves ? "surface or curve"
                              : surfaces         ? "surface"
                                                 : "curve";
    if (!c.object.empty()) {
        for (const doc::Object& o : d.objects)
            if (o.name == c.object) {
                if (fits(o))
                    out.objects.push_back(&o);
                else
                    out.missing =
                        quoted(o) + " is a " + doc::kind_name(o.kind()) + ", not a " + kinds;
                return out;
            }
        out.missing = "there is no object named '" + c.object + "'";
        return out;
    }
    for (const doc::Object& o : d.objects)
        if (fits(o)) out.objects.push_back(&o);
    if (out.objects.empty()) out.missing = "there is no " + kinds + " in the scene";
    return out;
}

// Passes when some candidate passes; the message is the first candidate's reason.
CheckResult any_of(const Check& c, const Candidates& cands,
                   const std::function<std::string(const doc::Object&)>& problem) {
    CheckResult r{c.label, false, {}, c.hint};
    if (cands.objects.empty()) {
        r.message = cands.missing;
        return r;
    }
    std::string first;
    for (const doc::Object* o : cands.objects) {
        std::string why = problem(*o);
        if (why.empty()) {
            r.passed = true;
            return r;
        }
        if (first.empty()) first = std::move(why);
    }
    r.message = cands.objects.size() > 1 ? first + " (and no other object fits)" : first;
    return r;
}

// Passes when every candidate passes (weights): the first offender is the message.
CheckResult all_of(const Check& c, const Candidates& cands,
                   const std::function<std::string(const doc::Object&)>& problem) {
    CheckResult r{c.label, true, {}, c.hint};
    if (cands.objects.empty() && !c.object.empty()) {
        r.passed = false;
        r.message = cands.missing;
        return r;
    }
    for (const doc::Object* o : cands.objects) {
        std::string why = problem(*o);
        if (!why.empty()) {
            r.passed = false;
            r.message = std::move(why);
            return r;
        }
    }
    return r;
}

int degree_of(const doc::Object& o, geom::Dir d) {
    if (const geom::Surface* s = o.surface()) return s->degree(d);
    return o.curve()->degree;
}

int count_of(const doc::Object& o, geom::Dir d) {
    if (const geom::Surface* s = o.surface()) return s->count(d);
    return o.curve()->count();
}

const geom::Knots& knots_of(const doc::Object& o, geom::Dir d) {
    if (const geom::Surface* s = o.surface()) return s->knots(d);
    return o.curve()->knots;
}

// Directions a check looks at on this object: a curve has one.
std::vector<geom::Dir> directions(const Check& c, const doc::Object& o) {
    if (o.curve()) return {geom::Dir::u};
    if (c.direction) return {*c.direction};
    return {geom::Dir::u, geom::Dir::v};
}

std::string point_label(const doc::Object& o, int i, int j) {
    return "P" + std::to_string(i) + (o.surface() ? "," + std::to_string(j) : std::string());
}

// The control point (i, j) of a surface or (i) of a curve: its index, or -1.
long point_index(const doc::Object& o, int i, int j) {
    if (const geom::Surface* s = o.surface())
        return (i >= 0 && i < s->n_u && j >= 0 && j < s->n_v) ? s->index(i, j) : -1;
    return (i >= 0 && i < o.curve()->count() && j < 0) ? i : -1;
}

std::span<const double> weights_of(const doc::Object& o) {
    if (const geom::Surface* s = o.surface()) return s->weights;
    if (const geom::Curve* cv = o.curve()) return cv->weights;
    if (const geom::TrianglePatch* t = o.triangle()) return t->weights;
    return {};
}

std::string weight_problem(const doc::Object& o, const std::optional<double>& min,
                           const std::optional<double>& max) {
    const std::span<const double> w = weights_of(o);
    for (std::size_t k = 0; k < w.size(); ++k) {
        if (in_range(w[k], std::nullopt, min, max)) continue;
        std::string which;
        if (const geom::Surface* s = o.surface())
            which = point_label(o, static_cast<int>(k) / s->n_v, static_cast<int>(k) % s->n_v);
        else
            which = "control point " + std::to_string(k);
        return "the weight of " + which + " of " + quoted(o) + " is " + num(w[k]) +
               "; weights must be " + range_text(std::nullopt, min, max);
    }
    return {};
}

// Uniform samples of a surface's or a curve's domain (points that exist only).
std::vector<glm::dvec3> samples_of(const doc::Object& o, int n) {
    std::vector<glm::dvec3> out;
    if (const geom::Surface* s = o.surface()) {
        const geom::ParamRect d = geom::domain(*s);
        for (int a = 0; a <= n; ++a)
            for (int b = 0; b <= n; ++b) {
                const double u = a == n ? d.u.hi : d.u.lo + (d.u.hi - d.u.lo) * a / n;
                const double v = b == n ? d.v.hi : d.v.lo + (d.v.hi - d.v.lo) * b / n;
                if (auto p = geom::surface_point(*s, u, v)) out.push_back(*p);
            }
    } else if (const geom::Curve* cv = o.curve()) {
        const geom::Interval d = geom::domain(*cv);
        const int m = n * n;
        for (int a = 0; a <= m; ++a)
            if (auto p = geom::curve_point(*cv, a == m ? d.hi : d.lo + (d.hi - d.lo) * a / m))
                out.push_back(*p);
    }
    return out;
}

// The farthest any sample of `from` lies from `onto` (infinity when nothing can be measured).
double one_sided(const doc::Object& from, const doc::Object& onto, int n) {
    const std::vector<glm::dvec3> pts = samples_of(from, n);
    if (pts.empty()) return INFINITY;
    double worst = 0;
    if (const geom::Surface* s = onto.surface()) {
        const geom::SurfaceProjector proj(*s);
        for (const glm::dvec3& p : pts) {
            const auto f = proj.closest(p);
            worst = std::max(worst, f ? f->distance : INFINITY);
        }
    } else {
        const geom::CurveProjector proj(*onto.curve());
        for (const glm::dvec3& p : pts) {
            const auto f = proj.closest(p);
            worst = std::max(worst, f ? f->distance : INFINITY);
        }
    }
    return worst;
}

double distance_to(const doc::Object& o, const glm::dvec3& p) {
    if (const geom::Surface* s = o.surface()) {
        const auto f = geom::closest_point(*s, p);
        return f ? f->distance : INFINITY;
    }
    const auto f = geom::closest_point(*o.curve(), p);
    return f ? f->distance : INFINITY;
}

CheckResult check_border(const Check& c, const doc::Document& d) {
    CheckResult r{c.label, false, {}, c.hint};
    std::vector<std::uint64_t> groups;
    for (const doc::Object& o : d.objects)
        if (o.patch_group != 0 && (!c.group || o.patch_group == *c.group) &&
            std::find(groups.begin(), groups.end(), o.patch_group) == groups.end())
            groups.push_back(o.patch_group);
    int count = 0;
    for (std::uint64_t g : groups)
        for (const doc::SharedBorder& b : doc::shared_borders(d, g)) {
            ++count;
            const doc::BorderMeasure m = doc::measure_border(d, b);
            const doc::Object* low = d.find(b.low);
            const doc::Object* high = d.find(b.high);
            const std::string which = "the border between '" + (low ? low->name : "?") + "' and '" +
                                      (high ? high->name : "?") + "'";
            if (m.sampled == 0) {
                r.message = which + " could not be measured (no point on one side)";
                return r;
            }
            if (m.gap > c.tolerance) {
                r.message = which + " is open: a gap of " + num(m.gap) + " (at most " +
                            num(c.tolerance) + " for C0)";
                return r;
            }
            if (c.join == BorderJoin::g1 && m.angle_degrees > c.angle_tolerance) {
                r.message = which + " has a crease: the normals differ by " + num(m.angle_degrees) +
                            " degrees (at most " + num(c.angle_tolerance) + " for G1)";
                return r;
            }
            if (c.join == BorderJoin::c1 && m.derivative > c.tolerance) {
                r.message = which + " is not C1: the derivatives across it differ by " +
                            num(m.derivative) + " (at most " + num(c.tolerance) + ")";
                return r;
            }
        }
    if (count < c.min_borders) {
        r.message = count == 0 ? std::string("there is no border between patches (split the "
                                             "surface into subpatches first)")
                               : "there are " + std::to_string(count) +
                                     " borders between patches; the task needs at least " +
                                     std::to_string(c.min_borders);
        return r;
    }
    r.passed = true;
    return r;
}

// How many objects (of a kind) the scene holds.
CheckResult check_objects(const Check& c, const doc::Document& d) {
    std::size_t n = 0;
    for (const doc::Object& o : d.objects) n += !c.object_kind || o.kind() == *c.object_kind;
    CheckResult r{c.label, in_range(static_cast<double>(n), c.equals, c.min, c.max), {}, c.hint};
    if (!r.passed)
        r.message = "the scene holds " + std::to_string(n) + " " +
                    (c.object_kind ? doc::kind_name(*c.object_kind) + std::string("s")
                                   : std::string("objects")) +
                    "; the task asks for " + range_text(c.equals, c.min, c.max);
    return r;
}

// A degree or a control point count, in each direction the check names.
CheckResult check_degree_or_count(const Check& c, const doc::Document& d) {
    using K = CheckKind;
    return any_of(c, candidates(c, d, true, true), [&](const doc::Object& o) -> std::string {
        for (geom::Dir dir : directions(c, o)) {
            const int x = c.kind == K::degree ? degree_of(o, dir) : count_of(o, dir);
            if (in_range(x, c.equals, c.min, c.max)) continue;
            const std::string in = o.surface() ? std::string(" in ") + geom::name_of(dir) : "";
            return c.kind == K::degree
                       ? quoted(o) + " has degree " + std::to_string(x) + in +
                             "; the task asks for " + range_text(c.equals, c.min, c.max)
                       : quoted(o) + " has " + std::to_string(x) + " control points" + in +
                             "; the task asks for " + range_text(c.equals, c.min, c.max);
        }
        return {};
    });
}

// A knot value at least `multiplicity` times.
CheckResult check_knot(const Check& c, const doc::Document& d) {
    return any_of(c, candidates(c, d, true, true), [&](const doc::Object& o) -> std::string {
        const geom::Dir dir = o.curve() ? geom::Dir::u : c.direction.value_or(geom::Dir::u);
        const geom::Knots& U = knots_of(o, dir);
        const auto m = std::count_if(
            U.begin(), U.end(), [&](double t) { return std::abs(t - c.value) <= c.tolerance; });
        if (m >= c.multiplicity) return {};
        const std::string in = o.surface() ? std::string(" in ") + geom::name_of(dir) : "";
        return m == 0 ? quoted(o) + " has no knot " + num(c.value) + in
                      : quoted(o) + " has the knot " + num(c.value) + in + " " + std::to_string(m) +
                            (m == 1 ? " time" : " times") + "; the task asks for " +
                            std::to_string(c.multiplicity);
    });
}

// Each point on some surface (a split surface's patches together): the union.
CheckResult check_points_on_surface(const Check& c, const doc::Document& d) {
    const Candidates cands = candidates(c, d, true, false);
    CheckResult r{c.label, false, {}, c.hint};
    if (cands.objects.empty()) {
        r.message = cands.missing;
        return r;
    }
    for (const glm::dvec3& p : c.points) {
        double best = INFINITY;
        const doc::Object* nearest = nullptr;
        for (const doc::Object* o : cands.objects) {
            const double dist = distance_to(*o, p);
            if (dist < best) {
                best = dist;
                nearest = o;
            }
        }
        if (best > c.tolerance) {
            r.message = point_text(p) + " is " + num(best) + " from " +
                        (nearest ? quoted(*nearest) : std::string("the surface")) + " (at most " +
                        num(c.tolerance) + ")";
            return r;
        }
    }
    r.passed = true;
    return r;
}

// Near the target shape both ways (a one-sided Hausdorff distance each way).
CheckResult check_near_shape(const Check& c, const doc::Document& d) {
    const bool curve = c.target->curve() != nullptr;
    return any_of(c, candidates(c, d, !curve, curve), [&](const doc::Object& o) -> std::string {
        const double there = one_sided(o, *c.target, c.samples);
        const double back = there > c.distance ? there : one_sided(*c.target, o, c.samples);
        const double worst = std::max(there, back);
        if (worst <= c.distance) return {};
        if (!std::isfinite(worst)) return quoted(o) + " could not be measured (no point)";
        return quoted(o) + " is " + num(worst) + " away from the shape '" + c.target->name +
               "' at its farthest (at most " + num(c.distance) + ")";
    });
}

CheckResult run_check(const Check& c, const doc::Document& d) {
    using K = CheckKind;
    switch (c.kind) {
    case K::objects:
        return check_objects(c, d);
    case K::type:
        return any_of(c, candidates(c, d, true, true), [&](const doc::Object& o) -> std::string {
            const geom::SplineType t = o.surface() ? o.surface()->type : o.curve()->type;
            if (t == *c.type) return {};
            return quoted(o) + " is a " + geom::label_of(t) + ", not a " + geom::label_of(*c.type);
        });
    case K::degree:
    case K::control_points:
        return check_degree_or_count(c, d);
    case K::knot:
        return check_knot(c, d);
    case K::weight:
        return any_of(c, candidates(c, d, true, true), [&](const doc::Object& o) -> std::string {
            const long k = point_index(o, c.i, c.j);
            if (k < 0) return quoted(o) + " has no control point " + point_label(o, c.i, c.j);
            const double w = weights_of(o)[static_cast<std::size_t>(k)];
            if (in_range(w, c.equals, c.min, c.max, c.tolerance)) return {};
            return "the weight of " + point_label(o, c.i, c.j) + " of " + quoted(o) + " is " +
                   num(w) + "; the task asks for " + range_text(c.equals, c.min, c.max);
        });
    case K::weights:
        return all_of(c, candidates(c, d, true, true, true),
                      [&](const doc::Object& o) { return weight_problem(o, c.min, c.max); });
    case K::no_negative_weight:
        return all_of(c, candidates(c, d, true, true, true),
                      [&](const doc::Object& o) { return weight_problem(o, 0.0, std::nullopt); });
    case K::position:
        return any_of(c, candidates(c, d, true, true), [&](const doc::Object& o) -> std::string {
            const long k = point_index(o, c.i, c.j);
            if (k < 0) return quoted(o) + " has no control point " + point_label(o, c.i, c.j);
            const glm::dvec3 p = o.surface() ? o.surface()->points[static_cast<std::size_t>(k)]
                                             : o.curve()->points[static_cast<std::size_t>(k)];
            const double gap = glm::length(p - c.points.front());
            if (gap <= c.tolerance) return {};
            return point_label(o, c.i, c.j) + " of " + quoted(o) + " is at " + point_text(p) +
                   ", " + num(gap) + " from " + point_text(c.points.front());
        });
    case K::point_on_surface:
        return check_points_on_surface(c, d);
    case K::interpolates:
        return any_of(c, candidates(c, d, false, true), [&](const doc::Object& o) -> std::string {
            for (const glm::dvec3& p : c.points) {
                const double dist = distance_to(o, p);
                if (dist > c.tolerance)
                    return quoted(o) + " passes " + num(dist) + " from " + point_text(p) +
                           " (at most " + num(c.tolerance) + ")";
            }
            return {};
        });
    case K::border:
        return check_border(c, d);
    case K::near_shape:
        return check_near_shape(c, d);
    }
    return {c.label, false, "unknown check", c.hint};
}

} // namespace

bool Grade::passed() const {
    return std::all_of(checks.begin(), checks.end(), [](const CheckResult& c) { return c.passed; });
}

std::size_t Grade::passed_count() const {
    return static_cast<std::size_t>(
        std::count_if(checks.begin(), checks.end(), [](const CheckResult& c) { return c.passed; }));
}

const CheckResult* Grade::first_failure() const {
    for (const CheckResult& c : checks)
        if (!c.passed) return &c;
    return nullptr;
}

Grade grade(const Exercise& exercise, const doc::Document& submission) {
    Grade g;
    for (const Check& c : exercise.checks) g.checks.push_back(run_check(c, submission));
    return g;
}

} // namespace isoparm::scene
