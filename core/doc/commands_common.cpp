// Helpers shared by the command implementations: lookup, validation, labels, sizes.
#include "core/doc/commands_common.hpp"

#include <cmath>
#include <set>

#include "core/geom/implicit/expression.hpp"
#include "core/geom/refine_within_limits.hpp"
#include "core/geom/validate.hpp"

namespace isoparm::doc::detail {

using geom::ErrorCode;
using geom::make_error;

geom::Expected<Object*> find_object(Document& doc, std::uint64_t id) {
    if (Object* o = doc.find(id)) return o;
    return make_error(ErrorCode::schema, "there is no object with id " + std::to_string(id), "/id");
}

geom::Expected<const Object*> find_object(const Document& doc, std::uint64_t id) {
    if (const Object* o = doc.find(id)) return o;
    return make_error(ErrorCode::schema, "there is no object with id " + std::to_string(id), "/id");
}

const char* kind_name(const Shape& shape) {
    return doc::kind_name(kind_of(shape));
}

namespace {

bool is_identifier(const std::string& s) {
    if (s.empty() || s.size() > 64) return false;
    auto alpha = [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
    };
    auto digit = [](char c) { return c >= '0' && c <= '9'; };
    if (!alpha(s[0])) return false;
    for (char c : s)
        if (!alpha(c) && !digit(c)) return false;
    return true;
}

geom::Status validate_implicit(const ImplicitObject& f) {
    if (f.expression.find_first_not_of(" \t\r\n") == std::string::npos)
        return make_error(ErrorCode::parse, "the implicit surface needs an expression in x, y, z",
                          "/expression");
    if (f.expression.size() > 65536)
        return make_error(ErrorCode::limit,
                          "an expression may have at most 65536 characters, got " +
                              std::to_string(f.expression.size()),
                          "/expression");
    if (f.parameter_names.size() != f.parameter_values.size())
        return make_error(
            ErrorCode::schema,
            "every parameter needs a value: " + std::to_string(f.parameter_names.size()) +
                " names, " + std::to_string(f.parameter_values.size()) + " values",
            "/parameters");
    std::set<std::string> seen;
    static const std::set<std::string> reserved = {"x",   "y",   "z",   "sin",  "cos",
                                                   "tan", "exp", "log", "sqrt", "abs"};
    for (std::size_t k = 0; k < f.parameter_names.size(); ++k) {
        const std::string& name = f.parameter_names[k];
        const std::string at = "/parameters/" + std::to_string(k);
        if (!is_identifier(name))
            return make_error(ErrorCode::schema,
                              "parameter name '" + name +
                                  "' must be a letter or '_' followed by letters, digits or '_' "
                                  "(at most 64)",
                              at + "/name");
        if (reserved.count(name))
            return make_error(ErrorCode::schema,
                              "'" + name +
                                  "' is a variable or function and cannot name a parameter",
                              at + "/name");
        if (!seen.insert(name).second)
            return make_error(ErrorCode::schema, "parameter '" + name + "' is named twice",
                              at + "/name");
        if (!std::isfinite(f.parameter_values[k]))
            return make_error(ErrorCode::schema,
                              "parameter '" + name + "' must be a finite number, got " +
                                  geom::format_number(f.parameter_values[k]),
                              at + "/value");
    }
    // The expression must compile with these parameters (column-precise `parse` errors).
    if (auto program = geom::implicit::compile(f.expression, f.parameter_names); !program) {
        geom::Error e = program.error();
        e.path = e.path.empty() ? "/expression" : e.path + "/name";
        e.has_path = true;
        return e;
    }
    for (int a = 0; a < 3; ++a) {
        const char* axis = a == 0 ? "x" : a == 1 ? "y" : "z";
        if (!std::isfinite(f.lo[a]))
            return make_error(ErrorCode::schema,
                              std::string("the box's lower ") + axis +
                                  " must be a finite number, got " + geom::format_number(f.lo[a]),
                              "/bounds/0/" + std::to_string(a));
        if (!std::isfinite(f.hi[a]))
            return make_error(ErrorCode::schema,
                              std::string("the box's upper ") + axis +
                                  " must be a finite number, got " + geom::format_number(f.hi[a]),
                              "/bounds/1/" + std::to_string(a));
        if (!(f.lo[a] < f.hi[a]))
            return make_error(ErrorCode::schema,
                              std::string("the box must have lower ") + axis + " < upper " + axis +
                                  ", got " + geom::format_number(f.lo[a]) + " and " +
                                  geom::format_number(f.hi[a]),
                              "/bounds/1/" + std::to_string(a));
    }
    if (!std::isfinite(f.cell) || !(f.cell > 0))
        return make_error(
            ErrorCode::schema,
            "the cell size must be a positive number, got " + geom::format_number(f.cell), "/cell");
    return geom::Ok{};
}

} // namespace

geom::Status check_size(const Shape& shape, const std::string& path) {
    if (const geom::Surface* s = surface_of(shape)) return geom::check_net_size(*s, path);
    if (const geom::Curve* c = curve_of(shape)) return geom::check_net_size(*c, path);
    return geom::Ok{};
}

namespace {

// Every coordinate finite (`schema`); point_path(k) is the JSON Pointer of point k, to which
// the coordinate's index is appended.
template <typename PointPath>
geom::Status finite_points(const std::vector<glm::dvec3>& points, PointPath point_path) {
    for (std::size_t k = 0; k < points.size(); ++k)
        for (int a = 0; a < 3; ++a)
            if (!std::isfinite(points[k][a]))
                return make_error(ErrorCode::schema,
                                  "control point coordinates must be finite numbers, got " +
                                      geom::format_number(points[k][a]),
                                  point_path(k) + "/" + std::to_string(a));
    return geom::Ok{};
}

} // namespace

geom::Status validate_shape(const Shape& shape) {
    if (auto* s = std::get_if<SurfaceObject>(&shape)) {
        const geom::Surface& g = s->surface;
        // Shape consistency first, so validate_surface only ever sees coherent arrays.
        if (g.n_u < 0 || g.n_v < 0 ||
            g.points.size() != static_cast<std::size_t>(g.n_u) * static_cast<std::size_t>(g.n_v))
            return make_error(ErrorCode::schema,
                              "a surface of " + std::to_string(g.n_u) + " x " +
                                  std::to_string(g.n_v) + " control points needs as many points",
                              "/points");
        if (g.weights.size() != g.points.size())
            return make_error(
                ErrorCode::weights,
                "a surface needs one weight per control point: " + std::to_string(g.points.size()) +
                    " points, " + std::to_string(g.weights.size()) + " weights",
                "/weights");
        if (auto st = check_size(shape, "/points"); !st) return st;
        if (auto st = finite_points(g.points,
                                    [&](std::size_t k) {
                                        return "/points/" + std::to_string(k / g.n_v) + "/" +
                                               std::to_string(k % g.n_v);
                                    });
            !st)
            return st;
        return geom::validate_surface(g);
    }
    if (auto* c = std::get_if<CurveObject>(&shape)) {
        const geom::Curve& g = c->curve;
        if (g.weights.size() != g.points.size())
            return make_error(
                ErrorCode::weights,
                "a curve needs one weight per control point: " + std::to_string(g.points.size()) +
                    " points, " + std::to_string(g.weights.size()) + " weights",
                "/weights");
        if (auto st = check_size(shape, "/points"); !st) return st;
        if (auto st = finite_points(g.points,
                                    [](std::size_t k) { return "/points/" + std::to_string(k); });
            !st)
            return st;
        return geom::validate_curve(g);
    }
    if (const geom::TrianglePatch* t = triangle_of(shape)) {
        // Non-rational triangles keep unit weights, as the type tag says of surfaces.
        if (!t->rational)
            for (std::size_t k = 0; k < t->weights.size(); ++k)
                if (t->weights[k] != 1.0)
                    return make_error(ErrorCode::weights,
                                      "a triangle_bezier has unit weights; weight " +
                                          std::to_string(k) + " is " +
                                          geom::format_number(t->weights[k]),
                                      "/weights/" + std::to_string(k));
        return geom::validate_triangle(*t);
    }
    return validate_implicit(std::get<ImplicitObject>(shape));
}

geom::Status validate_name(const std::string& name) {
    if (name.empty()) return make_error(ErrorCode::schema, "an object needs a name", "/name");
    for (unsigned char ch : name)
        if (ch < 0x20 || ch == 0x7f)
            return make_error(ErrorCode::schema,
                              "an object name may not contain control characters", "/name");
    return geom::Ok{};
}

std::string point_label(char letter, int i, int j) {
    std::string s(1, letter);
    if (j < 0) return s + std::to_string(i);
    if (i < 10 && j < 10) return s + std::to_string(i) + std::to_string(j);
    return s + std::to_string(i) + "," + std::to_string(j);
}

std::string triangle_point_label(char letter, int n, int i, int j) {
    const int k = n - i - j;
    std::string s(1, letter);
    if (n < 10) return s + std::to_string(i) + std::to_string(j) + std::to_string(k);
    return s + std::to_string(i) + "," + std::to_string(j) + "," + std::to_string(k);
}

std::size_t shape_bytes(const Shape& shape) {
    std::size_t bytes = sizeof(Shape);
    if (auto* s = std::get_if<SurfaceObject>(&shape)) {
        const geom::Surface& g = s->surface;
        bytes += (g.knots_u.size() + g.knots_v.size() + g.weights.size()) * sizeof(double) +
                 g.points.size() * sizeof(glm::dvec3);
    } else if (auto* c = std::get_if<CurveObject>(&shape)) {
        const geom::Curve& g = c->curve;
        bytes += (g.knots.size() + g.weights.size()) * sizeof(double) +
                 g.points.size() * sizeof(glm::dvec3);
    } else if (const geom::TrianglePatch* t = triangle_of(shape)) {
        bytes += t->weights.size() * sizeof(double) + t->points.size() * sizeof(glm::dvec3);
    } else {
        const auto& f = std::get<ImplicitObject>(shape);
        bytes += f.expression.size() + f.parameter_values.size() * sizeof(double);
        for (const auto& n : f.parameter_names) bytes += sizeof(std::string) + n.size();
    }
    return bytes;
}

} // namespace isoparm::doc::detail
