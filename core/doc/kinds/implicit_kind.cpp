// The implicit kind's facts: JSON members (expression, parameters, bounds, cell), validation,
// the polygonized mesh as its export form.
#include "core/doc/kinds/implicit_kind.hpp"

#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "core/doc/kinds/kind_common.hpp"
#include "core/geom/implicit/expression.hpp"
#include "core/geom/implicit/polygonize.hpp"
#include "core/json/fields.hpp"

namespace isoparm::doc {

using geom::ErrorCode;
using geom::make_error;
using json_io::check_members;
using json_io::expect_object;
using json_io::missing_member;
using json_io::read_finite;
using json_io::read_string;
using json_io::schema_error;
using nlohmann::json;

namespace {

geom::Expected<glm::dvec3> read_vec3(const json& v, const std::string& at, const char* what) {
    if (!v.is_array() || v.size() != 3)
        return schema_error(std::string(what) + " must be [x, y, z]", at);
    glm::dvec3 p(0.0);
    for (int a = 0; a < 3; ++a) {
        auto x = read_finite(v[a], at + "/" + std::to_string(a), "a coordinate");
        if (!x) return x.error();
        p[a] = *x;
    }
    return p;
}

geom::Status read_parameters(const json& params, const std::string& pat, ImplicitObject& f) {
    if (!params.is_array())
        return schema_error("parameters is an array of {\"name\": ..., \"value\": ...}", pat);
    for (std::size_t k = 0; k < params.size(); ++k) {
        const json& p = params[k];
        const std::string kat = pat + "/" + std::to_string(k);
        if (auto st = expect_object(p, kat, "a parameter"); !st) return st.error();
        if (auto st = check_members(p, kat, "a parameter", {"name", "value"}); !st)
            return st.error();
        if (!p.contains("name")) return missing_member(kat, "name");
        if (!p.contains("value")) return missing_member(kat, "value");
        auto name = read_string(p["name"], kat + "/name", "a parameter name");
        if (!name) return name.error();
        auto value = read_finite(p["value"], kat + "/value", "a parameter value");
        if (!value) return value.error();
        f.parameter_names.push_back(*name);
        f.parameter_values.push_back(*value);
    }
    return geom::Ok{};
}

geom::Expected<ImplicitObject> implicit_from_json(const json& j, const std::string& at) {
    if (auto st = expect_object(j, at, "an implicit surface"); !st) return st.error();
    if (auto st = check_members(j, at, "an implicit surface",
                                {"expression", "parameters", "bounds", "cell"});
        !st)
        return st.error();
    ImplicitObject f;
    const auto expr = j.find("expression");
    if (expr == j.end()) return missing_member(at, "expression");
    auto text = read_string(*expr, at + "/expression", "the expression");
    if (!text) return text.error();
    f.expression = *text;
    if (const auto params = j.find("parameters"); params != j.end())
        if (auto st = read_parameters(*params, at + "/parameters", f); !st) return st.error();
    if (const auto bounds = j.find("bounds"); bounds != j.end()) {
        if (!bounds->is_array() || bounds->size() != 2)
            return schema_error("bounds is [[xmin, ymin, zmin], [xmax, ymax, zmax]]",
                                at + "/bounds");
        auto lo = read_vec3((*bounds)[0], at + "/bounds/0", "the lower corner");
        if (!lo) return lo.error();
        auto hi = read_vec3((*bounds)[1], at + "/bounds/1", "the upper corner");
        if (!hi) return hi.error();
        f.lo = *lo;
        f.hi = *hi;
    }
    if (const auto cell = j.find("cell"); cell != j.end()) {
        auto c = read_finite(*cell, at + "/cell", "the cell size");
        if (!c) return c.error();
        f.cell = *c;
    }
    return f;
}

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

geom::Status validate_parameters(const ImplicitObject& f) {
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
    return geom::Ok{};
}

geom::Status validate_box(const ImplicitObject& f) {
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

geom::Expected<ImplicitObject> read_kind(std::type_identity<ImplicitObject>, const json& j,
                                         const std::string& at) {
    return implicit_from_json(j.at("implicit"), at + "/implicit");
}

void kind_to_json(const ImplicitObject& f, json& out) {
    json params = json::array();
    const std::size_t count = std::min(f.parameter_names.size(), f.parameter_values.size());
    for (std::size_t k = 0; k < count; ++k)
        params.push_back({{"name", f.parameter_names[k]}, {"value", f.parameter_values[k]}});
    out["implicit"] = {{"expression", f.expression},
                       {"parameters", std::move(params)},
                       {"bounds", json::array({json::array({f.lo.x, f.lo.y, f.lo.z}),
                                               json::array({f.hi.x, f.hi.y, f.hi.z})})},
                       {"cell", f.cell}};
}

geom::Expected<std::pair<int, int>> selected_point_from_json(const ImplicitObject&, const json&,
                                                             const std::string& at) {
    return schema_error("an implicit surface has no control points to select", at);
}

geom::Status validate(const ImplicitObject& f) {
    if (f.expression.find_first_not_of(" \t\r\n") == std::string::npos)
        return make_error(ErrorCode::parse, "the implicit surface needs an expression in x, y, z",
                          "/expression");
    if (f.expression.size() > 65536)
        return make_error(ErrorCode::limit,
                          "an expression may have at most 65536 characters, got " +
                              std::to_string(f.expression.size()),
                          "/expression");
    if (auto st = validate_parameters(f); !st) return st;
    // The expression must compile with these parameters (column-precise `parse` errors).
    if (auto program = geom::implicit::compile(f.expression, f.parameter_names); !program) {
        geom::Error e = program.error();
        e.path = e.path.empty() ? "/expression" : e.path + "/name";
        e.has_path = true;
        return e;
    }
    return validate_box(f);
}

// No control points: the expression is the shape.
std::span<glm::dvec3> control_points(ImplicitObject&) {
    return {};
}
std::span<const glm::dvec3> control_points(const ImplicitObject&) {
    return {};
}
std::span<double> control_weights(ImplicitObject&) {
    return {};
}
std::span<const double> control_weights(const ImplicitObject&) {
    return {};
}
bool is_rational(const ImplicitObject&) {
    return false;
}
bool has_control_point(const ImplicitObject&, int, int) {
    return false;
}
geom::Expected<std::size_t> point_index(const ImplicitObject&, int, int) {
    return make_error(ErrorCode::schema, "an implicit surface has no control points", "/id");
}
std::string point_label(const ImplicitObject&, PointName name, int i, int j) {
    if (name == PointName::indexed) return detail::indexed_label('P', i, j);
    return detail::point_label(name == PointName::weight ? 'w' : 'P', i, j);
}
std::string unit_weights_rule(const ImplicitObject&) {
    return "an implicit surface has no weights";
}

std::optional<Box> bounds(const ImplicitObject& f) {
    return Box{f.lo, f.hi};
}

void translate(ImplicitObject& f, const glm::dvec3& d) {
    f = translated(f, d);
}

ImplicitObject translated(const ImplicitObject& f, const glm::dvec3& d) {
    ImplicitObject out = f;
    out.lo += d;
    out.hi += d;
    // Identifiers are whole words: "exp" keeps its x, a parameter "xa" is not x.
    const std::string& e = f.expression;
    std::string r;
    std::size_t k = 0;
    auto ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    while (k < e.size()) {
        if (!ident(e[k])) {
            r += e[k++];
            continue;
        }
        std::size_t end = k;
        while (end < e.size() && ident(e[end])) ++end;
        const std::string word = e.substr(k, end - k);
        const bool number = std::isdigit(static_cast<unsigned char>(word[0])) != 0;
        const int axis = word == "x" ? 0 : word == "y" ? 1 : word == "z" ? 2 : -1;
        if (!number && axis >= 0 && d[axis] != 0)
            r += "(" + word + (d[axis] > 0 ? " - " : " + ") +
                 geom::format_number(std::abs(d[axis])) + ")";
        else
            r += word;
        // A number's exponent (1e-3) is one token with its sign: copy it as it is.
        k = end;
        if (number && k < e.size() && (e[k] == '-' || e[k] == '+') &&
            (r.back() == 'e' || r.back() == 'E'))
            r += e[k++];
    }
    out.expression = r;
    return out;
}

ExactForm exact_form(const ImplicitObject&) {
    return NoForm{"an implicit surface has no exact form (export a mesh: STL, PLY, glTF or OBJ "
                  "mesh)"};
}

// Its polygonizer's own cell, whatever the samples.
geom::Expected<MeshForm> mesh_form(const ImplicitObject& f, int) {
    auto program = geom::implicit::compile(f.expression, f.parameter_names);
    if (!program) return program.error();
    geom::implicit::PolygonizeOptions options;
    options.lo = f.lo;
    options.hi = f.hi;
    options.cell = f.cell;
    options.parameters = f.parameter_values;
    auto mesh = geom::implicit::polygonize(*program, options);
    if (!mesh) return mesh.error();
    if (mesh->triangles.empty())
        return MeshForm{NoForm{"the implicit surface was not found in its box"}};
    return MeshForm{std::move(mesh).value()};
}

double mesh_vertices(const ImplicitObject&, int) {
    return 0; // its polygonizer keeps its own budget (cells, triangles)
}

std::size_t heap_bytes(const ImplicitObject& f) {
    std::size_t bytes = f.expression.size() + f.parameter_values.size() * sizeof(double);
    for (const auto& n : f.parameter_names) bytes += sizeof(std::string) + n.size();
    return bytes;
}

bool same_bits(const ImplicitObject& a, const ImplicitObject& b) {
    return a.expression == b.expression && a.parameter_names == b.parameter_names &&
           detail::bit_equal(a.parameter_values, b.parameter_values) &&
           detail::bit_equal(a.lo, b.lo) && detail::bit_equal(a.hi, b.hi) &&
           detail::bit_equal(a.cell, b.cell);
}

} // namespace isoparm::doc
