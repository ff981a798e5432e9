// Exercise checks in words.
#include "core/scene/exercise_text.hpp"

#include <cmath>
#include <cstdio>

namespace isoparm::scene {

namespace {

std::string num(double x) {
    return short_number(x);
}

const char* join_name(BorderJoin j) {
    return j == BorderJoin::c0 ? "C0" : j == BorderJoin::g1 ? "G1" : "C1";
}

std::string direction_text(const Check& c) {
    return c.direction ? std::string(" in ") + geom::name_of(*c.direction) : " in u and v";
}

std::string plural(const std::string& what, const std::optional<double>& equals,
                   const std::optional<double>& max) {
    const bool one = (equals && *equals == 1) || (!equals && max && *max == 1);
    return one ? what : what + "s";
}

} // namespace

std::string short_number(double x) {
    if (!std::isfinite(x)) return geom::format_number(x);
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", x == 0 ? 0.0 : x); // no "-0"
    return text;
}

std::string range_text(const std::optional<double>& equals, const std::optional<double>& min,
                       const std::optional<double>& max) {
    if (equals) return num(*equals);
    if (min && max) return "between " + num(*min) + " and " + num(*max);
    if (min) return "at least " + num(*min);
    if (max) return "at most " + num(*max);
    return "any";
}

bool in_range(double x, const std::optional<double>& equals, const std::optional<double>& min,
              const std::optional<double>& max, double tolerance) {
    if (equals && std::abs(x - *equals) > tolerance) return false;
    if (min && x < *min) return false;
    if (max && x > *max) return false;
    return true;
}

std::string point_text(const glm::dvec3& p) {
    return "(" + num(p.x) + ", " + num(p.y) + ", " + num(p.z) + ")";
}

std::string subject_text(const Check& c, const char* any) {
    return c.object.empty() ? std::string(any) : "'" + c.object + "'";
}

std::string describe_check(const Check& c) {
    const std::string range = range_text(c.equals, c.min, c.max);
    const std::string point =
        "P" + std::to_string(c.i) + (c.j >= 0 ? "," + std::to_string(c.j) : std::string());
    switch (c.kind) {
    case CheckKind::objects: {
        const std::string what = c.object_kind ? doc::kind_name(*c.object_kind) : "object";
        return "the scene holds " + range + " " + plural(what, c.equals, c.max);
    }
    case CheckKind::type:
        return subject_text(c, "a surface or curve") + " is a " + geom::label_of(*c.type);
    case CheckKind::degree:
        return subject_text(c, "a surface or curve") + " has degree " + range + direction_text(c);
    case CheckKind::control_points:
        return subject_text(c, "a surface or curve") + " has " + range + " control points" +
               (c.direction ? direction_text(c) : std::string(" in each direction"));
    case CheckKind::knot:
        return subject_text(c, "a surface or curve") + " has the knot " + num(c.value) +
               direction_text(c) +
               (c.multiplicity > 1 ? " at least " + std::to_string(c.multiplicity) + " times"
                                   : std::string());
    case CheckKind::weight:
        return "the weight of " + point + " of " + subject_text(c, "a surface or curve") + " is " +
               range;
    case CheckKind::weights:
        return "every weight of " + subject_text(c, "every object") + " is " + range;
    case CheckKind::no_negative_weight:
        return "no weight of " + subject_text(c, "any object") + " is negative";
    case CheckKind::position:
        return point + " of " + subject_text(c, "a surface or curve") + " is at " +
               point_text(c.points.front()) + " (within " + num(c.tolerance) + ")";
    case CheckKind::point_on_surface: {
        std::string pts;
        for (std::size_t k = 0; k < c.points.size(); ++k)
            pts += (k ? ", " : "") + point_text(c.points[k]);
        return pts + (c.points.size() == 1 ? " lies on " : " lie on ") +
               subject_text(c, "the surface") + " (within " + num(c.tolerance) + ")";
    }
    case CheckKind::interpolates:
        return subject_text(c, "a curve") + " passes through the " +
               std::to_string(c.points.size()) + " given points (within " + num(c.tolerance) + ")";
    case CheckKind::border:
        return "every border between patches is " + std::string(join_name(c.join)) +
               (c.min_borders > 1 ? " (at least " + std::to_string(c.min_borders) + " borders)"
                                  : std::string());
    case CheckKind::near_shape:
        return subject_text(c, c.target && c.target->curve() ? "a curve" : "a surface") +
               " stays within " + num(c.distance) + " of the shape '" +
               (c.target ? c.target->name : std::string()) + "'";
    }
    return {};
}

} // namespace isoparm::scene
