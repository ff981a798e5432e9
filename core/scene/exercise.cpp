// Exercise files: strict reading of the task, the starting scene and every check.
#include "core/scene/exercise.hpp"

#include <filesystem>

#include "core/json/fields.hpp"
#include "core/json/input_file.hpp"
#include "core/json/reader.hpp"
#include "core/json/shapes.hpp"
#include "core/scene/exercise_text.hpp"
#include "core/scene/scene_io.hpp"
#include "core/scene/starting_scene.hpp"

namespace isoparm::scene {

using namespace isoparm::json_io;
using geom::Error;
using geom::Expected;
using nlohmann::json;

namespace {

constexpr std::uintmax_t max_exercise_bytes = 16u << 20;
constexpr std::size_t max_checks = 1000;

// The members each kind of check takes besides check, object, label and hint.
std::vector<std::string_view> members_of(CheckKind k) {
    switch (k) {
    case CheckKind::objects:
        return {"kind", "count", "min", "max"};
    case CheckKind::type:
        return {"type"};
    case CheckKind::degree:
        return {"direction", "degree", "min", "max"};
    case CheckKind::control_points:
        return {"direction", "count", "min", "max"};
    case CheckKind::knot:
        return {"direction", "value", "multiplicity", "tolerance"};
    case CheckKind::weight:
        return {"point", "value", "min", "max", "tolerance"};
    case CheckKind::weights:
        return {"min", "max"};
    case CheckKind::no_negative_weight:
        return {};
    case CheckKind::position:
        return {"point", "position", "tolerance"};
    case CheckKind::point_on_surface:
    case CheckKind::interpolates:
        return {"points", "tolerance"};
    case CheckKind::border:
        return {"continuity", "group", "borders", "tolerance", "angle_tolerance"};
    case CheckKind::near_shape:
        return {"target", "distance", "samples"};
    }
    return {};
}

class CheckReader {
public:
    CheckReader(const json& j, std::string at) : j_(j), at_(std::move(at)) {}

    const json* find(std::string_view name) const { return find_member(j_, name); }
    std::string path(std::string_view name) const { return member_path(at_, name); }

    geom::Status number(std::string_view name, std::optional<double>& into) {
        if (const json* v = find(name)) {
            auto x = read_finite(*v, path(name), name);
            if (!x) return x.error();
            into = *x;
        }
        return geom::Ok{};
    }
    geom::Status positive(std::string_view name, double& into) {
        if (const json* v = find(name)) {
            auto x = read_finite(*v, path(name), name);
            if (!x) return x.error();
            if (*x < 0) return schema_error(std::string(name) + " is 0 or more", path(name));
            into = *x;
        }
        return geom::Ok{};
    }
    geom::Status integer(std::string_view name, int& into, int lo, int hi) {
        if (const json* v = find(name)) {
            auto n = read_integer(*v, path(name), name, lo, hi);
            if (!n) return n.error();
            into = static_cast<int>(*n);
        }
        return geom::Ok{};
    }
    geom::Status text(std::string_view name, std::string& into) {
        if (const json* v = find(name)) {
            auto t = read_string(*v, path(name), name);
            if (!t) return t.error();
            into = *t;
        }
        return geom::Ok{};
    }

private:
    const json& j_;
    std::string at_;
};

Expected<std::vector<glm::dvec3>> read_points(const json& v, const std::string& at) {
    if (!v.is_array() || v.empty())
        return schema_error("points is an array of at least one [x, y, z]", at);
    std::vector<glm::dvec3> out;
    for (std::size_t k = 0; k < v.size(); ++k) {
        auto p = read_point(v[k], at + "/" + std::to_string(k), "a point");
        if (!p) return p.error();
        out.push_back(*p);
    }
    return out;
}

// A near_shape target: an object of the starting scene by name, or one of another scene.
Expected<doc::Object> read_target(const json& v, const std::string& at, const Exercise& ex,
                                  const std::string& dir) {
    std::string name;
    const doc::Document* from = &ex.start;
    doc::Document other;
    std::string where = "the starting scene";
    if (v.is_string()) {
        name = v.get<std::string>();
    } else if (v.is_object()) {
        if (auto st = check_members(v, at, "a target", {"scene", "object"}); !st) return st.error();
        const json* scene = find_member(v, "scene");
        const json* object = find_member(v, "object");
        if (!object) return missing_member(at, "object");
        auto n = read_string(*object, member_path(at, "object"), "object");
        if (!n) return n.error();
        name = *n;
        if (scene) {
            auto rel = read_string(*scene, member_path(at, "scene"), "scene");
            if (!rel) return rel.error();
            const std::filesystem::path p(*rel);
            const std::string file =
                p.is_absolute() ? *rel : (std::filesystem::path(dir) / p).string();
            auto loaded = load_scene(file);
            if (!loaded) {
                Error e = loaded.error();
                e.message = "the target scene '" + file + "': " + e.message;
                e.path = member_path(at, "scene");
                e.has_path = true;
                return e;
            }
            other = std::move(loaded).value();
            from = &other;
            where = "'" + file + "'";
        }
    } else {
        return schema_error("target is an object's name in the starting scene, or {\"scene\": "
                            "path, \"object\": name}",
                            at);
    }
    for (const doc::Object& o : from->objects)
        if (o.name == name) {
            if (!o.surface() && !o.curve())
                return schema_error("the target '" + name + "' is a " + doc::kind_name(o.kind()) +
                                        ": near_shape compares surfaces or curves",
                                    at);
            return o;
        }
    return schema_error("no object named '" + name + "' in " + where, at);
}

// The values compared (min, max, the exact value) and what is looked at: the kind of object,
// the type, the direction, the control point.
geom::Status read_check_selectors(CheckReader& r, const std::string& at, Check& c) {
    if (auto st = r.number("min", c.min); !st) return st.error();
    if (auto st = r.number("max", c.max); !st) return st.error();
    for (const char* exact : {"count", "degree", "value"})
        if (c.kind != CheckKind::knot)
            if (auto st = r.number(exact, c.equals); !st) return st.error();
    if (const json* v = r.find("kind")) {
        c.object_kind = enum_value<doc::ObjectKind>(*v);
        if (!c.object_kind)
            return schema_error("kind is surface, curve, implicit or triangle", r.path("kind"));
    }
    if (const json* v = r.find("type")) {
        c.type = enum_value<geom::SplineType>(*v);
        if (!c.type)
            return schema_error("type is bezier, rational_bezier, bspline or nurbs",
                                r.path("type"));
    } else if (c.kind == CheckKind::type) {
        return missing_member(at, "type");
    }
    if (c.kind == CheckKind::knot) c.direction = geom::Dir::u; // a knot is in one direction
    if (const json* v = r.find("direction")) {
        if (v->is_string() && v->get<std::string>() == "both" && c.kind != CheckKind::knot) {
            c.direction.reset();
        } else if (auto d = enum_value<geom::Dir>(*v)) {
            c.direction = *d;
        } else {
            return schema_error("direction is \"u\", \"v\" or \"both\"", r.path("direction"));
        }
    }
    if (const json* v = r.find("point")) {
        if (!v->is_array() || v->empty() || v->size() > 2)
            return schema_error("point is [i, j] (a surface's) or [i] (a curve's)",
                                r.path("point"));
        for (std::size_t n = 0; n < v->size(); ++n) {
            auto x = read_integer((*v)[n], r.path("point") + "/" + std::to_string(n),
                                  "a control point index", 0, 1 << 20);
            if (!x) return x.error();
            (n == 0 ? c.i : c.j) = static_cast<int>(*x);
        }
    } else if (c.kind == CheckKind::weight || c.kind == CheckKind::position) {
        return missing_member(at, "point");
    }
    return geom::Ok{};
}

// The geometry the check compares with: a position, points, a knot, tolerances, a border's
// continuity and its patch group.
geom::Status read_check_geometry(CheckReader& r, const std::string& at, Check& c) {
    if (const json* v = r.find("position")) {
        auto p = read_point(*v, r.path("position"), "a position");
        if (!p) return p.error();
        c.points = {*p};
    } else if (c.kind == CheckKind::position) {
        return missing_member(at, "position");
    }
    if (const json* v = r.find("points")) {
        auto p = read_points(*v, r.path("points"));
        if (!p) return p.error();
        c.points = std::move(p).value();
    } else if (c.kind == CheckKind::point_on_surface || c.kind == CheckKind::interpolates) {
        return missing_member(at, "points");
    }
    if (c.kind == CheckKind::knot) {
        const json* v = r.find("value");
        if (!v) return missing_member(at, "value");
        auto x = read_finite(*v, r.path("value"), "value");
        if (!x) return x.error();
        c.value = *x;
        if (auto st = r.integer("multiplicity", c.multiplicity, 1, 64); !st) return st.error();
        c.tolerance = 1e-12; // knots are compared exactly unless the file says otherwise
    }
    if (c.kind == CheckKind::weight) c.tolerance = 1e-9;
    if (auto st = r.positive("tolerance", c.tolerance); !st) return st.error();
    if (auto st = r.positive("angle_tolerance", c.angle_tolerance); !st) return st.error();
    if (const json* v = r.find("continuity")) {
        const std::string s = v->is_string() ? v->get<std::string>() : "";
        if (s == "C0")
            c.join = BorderJoin::c0;
        else if (s == "G1")
            c.join = BorderJoin::g1;
        else if (s == "C1")
            c.join = BorderJoin::c1;
        else
            return schema_error("continuity is \"C0\", \"G1\" or \"C1\"", r.path("continuity"));
    } else if (c.kind == CheckKind::border) {
        return missing_member(at, "continuity");
    }
    if (const json* v = r.find("group")) {
        auto g = read_integer(*v, r.path("group"), "a patch group id", 1,
                              static_cast<std::int64_t>(max_object_id));
        if (!g) return g.error();
        c.group = static_cast<std::uint64_t>(*g);
    }
    if (auto st = r.integer("borders", c.min_borders, 0, 1 << 20); !st) return st.error();
    return geom::Ok{};
}

// near_shape's target (an object of the starting scene or of another scene) and distance.
geom::Status read_near_shape(CheckReader& r, const std::string& at, const Exercise& ex,
                             const std::string& dir, Check& c) {
    const json* t = r.find("target");
    if (!t) return missing_member(at, "target");
    auto target = read_target(*t, r.path("target"), ex, dir);
    if (!target) return target.error();
    c.target = std::move(target).value();
    const json* d = r.find("distance");
    if (!d) return missing_member(at, "distance");
    std::optional<double> dist;
    if (auto st = r.number("distance", dist); !st) return st.error();
    if (*dist < 0) return schema_error("distance is 0 or more", r.path("distance"));
    c.distance = *dist;
    if (auto st = r.integer("samples", c.samples, 2, 256); !st) return st.error();
    return geom::Ok{};
}

Expected<Check> read_check(const json& j, const std::string& at, const Exercise& ex,
                           const std::string& dir) {
    if (auto st = expect_object(j, at, "a check"); !st) return st.error();
    const json* kind = find_member(j, "check");
    if (!kind) return missing_member(at, "check");
    Check c;
    c.path = at;
    const auto k = enum_value<CheckKind>(*kind);
    if (!k) {
        std::string names;
        for (const auto& e : check_kind_names)
            names += std::string(names.empty() ? "" : ", ") + e.name;
        return schema_error("check is one of " + names + ", got " +
                                (kind->is_string() ? "'" + kind->get<std::string>() + "'"
                                                   : std::string(type_name(*kind))),
                            member_path(at, "check"));
    }
    c.kind = *k;
    std::vector<std::string_view> allowed{"check", "object", "label", "hint"};
    for (std::string_view m : members_of(c.kind)) allowed.push_back(m);
    if (auto st = check_members(j, at, std::string("check '") + geom::name_of(c.kind) + "'",
                                std::span<const std::string_view>(allowed));
        !st)
        return st.error();
    CheckReader r(j, at);
    for (auto [name, into] :
         {std::pair{"object", &c.object}, std::pair{"label", &c.label}, std::pair{"hint", &c.hint}})
        if (auto st = r.text(name, *into); !st) return st.error();
    if (c.kind == CheckKind::objects && r.find("object"))
        return schema_error("check 'objects' counts objects: it names a kind, not an object",
                            r.path("object"));
    if (auto st = read_check_selectors(r, at, c); !st) return st.error();
    if (auto st = read_check_geometry(r, at, c); !st) return st.error();
    if (c.kind == CheckKind::near_shape)
        if (auto st = read_near_shape(r, at, ex, dir, c); !st) return st.error();
    const bool counted = c.kind == CheckKind::objects || c.kind == CheckKind::degree ||
                         c.kind == CheckKind::control_points || c.kind == CheckKind::weight ||
                         c.kind == CheckKind::weights;
    if (counted && !c.equals && !c.min && !c.max)
        return schema_error("check '" + std::string(geom::name_of(c.kind)) +
                                "' needs a value to compare with (min, max or the exact value)",
                            at);
    if (c.min && c.max && *c.min > *c.max) return schema_error("min is above max", r.path("min"));
    if (c.label.empty()) c.label = describe_check(c);
    return c;
}

} // namespace

Expected<Exercise> exercise_from_json(const json& j, const std::string& dir) {
    if (auto st = expect_object(j, "", "an exercise"); !st) return st.error();
    if (auto st = check_members(
            j, "", "an exercise",
            {"format", "version", "title", "summary", "task", "hints", "scene", "checks"});
        !st)
        return st.error();
    const json* format = find_member(j, "format");
    if (!format) return missing_member("", "format");
    if (!format->is_string() || format->get<std::string>() != exercise_format_name)
        return schema_error(std::string("format must be \"") + exercise_format_name + "\"",
                            "/format");
    const json* version = find_member(j, "version");
    if (!version) return missing_member("", "version");
    if (auto v = read_integer(*version, "/version", "version", 1, exercise_format_version); !v)
        return v.error();
    Exercise ex;
    for (auto [name, into] : {std::pair{"title", &ex.title}, std::pair{"summary", &ex.summary},
                              std::pair{"task", &ex.task}})
        if (const json* m = find_member(j, name)) {
            auto t = read_string(*m, member_path("", name), name);
            if (!t) return t.error();
            *into = *t;
        }
    if (ex.task.empty()) return schema_error("an exercise states its task: add \"task\"", "/task");
    if (const json* hints = find_member(j, "hints")) {
        if (!hints->is_array()) return schema_error("hints is an array of texts", "/hints");
        for (std::size_t k = 0; k < hints->size(); ++k) {
            auto t = read_string((*hints)[k], "/hints/" + std::to_string(k), "a hint");
            if (!t) return t.error();
            ex.hints.push_back(*t);
        }
    }
    const json* scene = find_member(j, "scene");
    if (!scene) return missing_member("", "scene");
    auto start = read_starting_scene(*scene, dir, "the exercise");
    if (!start) return start.error();
    ex.start = std::move(start->document);
    ex.scene_name = std::move(start->name);
    const json* checks = find_member(j, "checks");
    if (!checks) return missing_member("", "checks");
    if (!checks->is_array() || checks->empty())
        return schema_error("checks is an array of at least one check", "/checks");
    if (checks->size() > max_checks)
        return schema_error("an exercise has at most " + std::to_string(max_checks) + " checks",
                            "/checks");
    for (std::size_t k = 0; k < checks->size(); ++k) {
        auto c = read_check((*checks)[k], "/checks/" + std::to_string(k), ex, dir);
        if (!c) return c.error();
        ex.checks.push_back(std::move(c).value());
    }
    return ex;
}

Expected<Exercise> load_exercise(const std::string& path) {
    auto text = read_input_file(path, max_exercise_bytes);
    if (!text) return text.error();
    auto read = read_json(*text);
    if (!read) {
        Error e = read.error();
        e.message = "'" + path + "' is not JSON: " + e.message;
        return e;
    }
    if (!read->problems.empty()) return read->problems.front();
    const std::string dir = std::filesystem::path(path).parent_path().string();
    return exercise_from_json(read->value, dir.empty() ? "." : dir);
}

} // namespace isoparm::scene
