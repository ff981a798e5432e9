// Commands <-> JSON. Each command's form (Form<Spec>) lists its members once, reads and writes
// them; reading refuses any other member, and the first error found is the answer.
#include "core/scene/command_json.hpp"

#include <climits>
#include <optional>
#include <string_view>

#include "core/json/fields.hpp"
#include "core/json/shapes.hpp"
#include "core/json/trim_json.hpp"
#include "core/scene/recipe_json.hpp"
#include "core/scene/scene_io.hpp"

namespace isoparm::scene {

using namespace isoparm::doc;
using namespace isoparm::json_io;
using geom::Expected;
using nlohmann::json;

namespace {

constexpr auto max_id = static_cast<std::int64_t>(max_object_id);

// Reads a command's members, keeping the first error: after one, every read answers a default
// and `error` holds the refusal.
class Members {
public:
    Members(const json& j, std::string at) : j_(j), at_(std::move(at)) {}

    std::uint64_t id(std::string_view name) {
        const json* v = need(name);
        if (!v) return 0;
        auto r = read_integer(*v, path(name), "an object id", 1, max_id);
        return r ? static_cast<std::uint64_t>(*r) : fail(r.error(), 0);
    }
    int integer(std::string_view name, std::optional<int> otherwise = std::nullopt) {
        const json* v = otherwise ? find(name) : need(name);
        if (!v) return otherwise.value_or(0);
        auto r = read_integer(*v, path(name), std::string(name), INT_MIN, INT_MAX);
        return r ? static_cast<int>(*r) : fail(r.error(), 0);
    }
    std::optional<int> optional_integer(std::string_view name) {
        if (!find(name)) return std::nullopt;
        return integer(name);
    }
    double number(std::string_view name) {
        const json* v = need(name);
        if (!v) return 0;
        auto r = read_finite(*v, path(name), name);
        return r ? *r : fail(r.error(), 0.0);
    }
    std::optional<double> optional_number(std::string_view name) {
        if (!find(name)) return std::nullopt;
        return number(name);
    }
    glm::dvec3 point(std::string_view name) {
        const json* v = need(name);
        if (!v) return glm::dvec3(0);
        auto r = read_point(*v, path(name), "a position");
        return r ? *r : fail(r.error(), glm::dvec3(0));
    }
    bool has(std::string_view name) { return find(name) != nullptr; }
    std::optional<glm::dvec3> optional_point(std::string_view name) {
        if (!find(name)) return std::nullopt;
        return point(name);
    }
    std::string text(std::string_view name, std::optional<std::string> otherwise = std::nullopt) {
        const json* v = otherwise ? find(name) : need(name);
        if (!v) return otherwise.value_or("");
        auto r = read_string(*v, path(name), name);
        return r ? *r : fail(r.error(), std::string());
    }
    bool flag(std::string_view name, std::optional<bool> otherwise = std::nullopt) {
        const json* v = otherwise ? find(name) : need(name);
        if (!v) return otherwise.value_or(false);
        auto r = read_bool(*v, path(name));
        return r ? *r : fail(r.error(), false);
    }
    // An enumeration by its table's names ("direction": "u" or "v").
    template <class E> E named(std::string_view name, std::string_view what) {
        const json* v = need(name);
        if (!v) return E{};
        if (auto e = enum_value<E>(*v)) return *e;
        std::string names;
        for (const auto& entry : enum_names(E{}))
            names += std::string(names.empty() ? "" : ", ") + entry.name;
        return fail(schema_error(std::string(what) + " must be one of " + names + ", got " +
                                     (v->is_string() ? "'" + v->get<std::string>() + "'"
                                                     : std::string(type_name(*v))),
                                 path(name)),
                    E{});
    }
    template <class T> T read(std::string_view name, auto reader) {
        const json* v = need(name);
        if (!v) return T{};
        Expected<T> r = reader(*v, path(name));
        return r ? std::move(r).value() : fail(r.error(), T{});
    }

    std::optional<geom::Error> error;

private:
    std::string path(std::string_view name) const { return member_path(at_, name); }
    const json* find(std::string_view name) { return error ? nullptr : find_member(j_, name); }
    const json* need(std::string_view name) {
        if (error) return nullptr;
        const json* v = find_member(j_, name);
        if (!v) error = missing_member(at_, name);
        return v;
    }
    template <class T> T fail(geom::Error e, T value) {
        if (!error) error = std::move(e);
        return value;
    }

    const json& j_;
    std::string at_;
};

json matrix_to_json(const glm::dmat4& m) {
    json rows = json::array();
    for (int r = 0; r < 4; ++r) rows.push_back({m[0][r], m[1][r], m[2][r], m[3][r]});
    return rows;
}

// Rows as people write them: [[m00, m01, m02, m03], ..., [0, 0, 0, 1]] (glm is column-major).
Expected<glm::dmat4> matrix_from_json(const json& v, const std::string& at) {
    if (!v.is_array() || v.size() != 4)
        return schema_error("a matrix is 4 rows of 4 numbers, got " + std::string(type_name(v)),
                            at);
    glm::dmat4 m(1.0);
    for (int r = 0; r < 4; ++r) {
        const json& row = v[static_cast<std::size_t>(r)];
        const std::string rat = at + "/" + std::to_string(r);
        if (!row.is_array() || row.size() != 4)
            return schema_error("a matrix row is 4 numbers", rat);
        for (int c = 0; c < 4; ++c) {
            auto x = read_finite(row[static_cast<std::size_t>(c)], rat + "/" + std::to_string(c),
                                 "a matrix entry");
            if (!x) return x.error();
            m[c][r] = *x;
        }
    }
    return m;
}

Expected<std::vector<Object>> objects_from_json(const json& v, const std::string& at) {
    if (!v.is_array()) return schema_error("objects is an array of objects", at);
    std::vector<Object> objects;
    for (std::size_t k = 0; k < v.size(); ++k) {
        auto o = object_from_json(v[k], at + "/" + std::to_string(k));
        if (!o) return o.error();
        objects.push_back(std::move(o).value());
    }
    return objects;
}

Expected<std::vector<std::uint64_t>> ids_from_json(const json& v, const std::string& at) {
    if (!v.is_array()) return schema_error("ids is an array of object ids", at);
    std::vector<std::uint64_t> ids;
    for (std::size_t k = 0; k < v.size(); ++k) {
        auto id = read_integer(v[k], at + "/" + std::to_string(k), "an object id", 1, max_id);
        if (!id) return id.error();
        ids.push_back(static_cast<std::uint64_t>(*id));
    }
    return ids;
}

json points_to_json(const std::vector<PointIndex>& points) {
    json out = json::array();
    for (PointIndex p : points)
        out.push_back(p.j < 0 ? json::array({p.i}) : json::array({p.i, p.j}));
    return out;
}

// [[i, j], ...] (surfaces, triangles) or [[i], ...] (curves).
Expected<std::vector<PointIndex>> points_from_json(const json& v, const std::string& at) {
    if (!v.is_array())
        return schema_error(std::string("points is an array of [i, j] or [i], got ") + type_name(v),
                            at);
    std::vector<PointIndex> out;
    for (std::size_t k = 0; k < v.size(); ++k) {
        const std::string pat = at + "/" + std::to_string(k);
        const json& p = v[k];
        if (!p.is_array() || p.empty() || p.size() > 2)
            return schema_error("a control point is [i, j] (a surface's or triangle's) or [i] (a "
                                "curve's)",
                                pat);
        PointIndex q;
        for (std::size_t c = 0; c < p.size(); ++c) {
            auto x = read_integer(p[c], pat + "/" + std::to_string(c), "a control point index", 0,
                                  INT_MAX);
            if (!x) return x.error();
            (c == 0 ? q.i : q.j) = static_cast<int>(*x);
        }
        out.push_back(q);
    }
    return out;
}

Expected<std::vector<glm::dvec3>> positions_from_json(const json& v, const std::string& at) {
    if (!v.is_array())
        return schema_error(std::string("positions is an array of [x, y, z], got ") + type_name(v),
                            at);
    std::vector<glm::dvec3> out;
    for (std::size_t k = 0; k < v.size(); ++k) {
        auto p = read_point(v[k], at + "/" + std::to_string(k), "a position");
        if (!p) return p.error();
        out.push_back(*p);
    }
    return out;
}

// Each command's JSON form in one place: its members (besides "command"), its reader and its
// writer. CommandSpec's alternatives are dispatched to these by type, so a command without its
// form does not build.
template <class Spec> struct Form;

// The object and the direction a command acts along ("id", "direction"), read first.
template <class Spec> Spec on_direction(Members& m) {
    Spec s;
    s.id = m.id("id");
    s.dir = m.named<geom::Dir>("direction", "direction");
    return s;
}

template <> struct Form<AddObjectSpec> {
    static constexpr std::string_view members[]{"object"};
    static AddObjectSpec read(Members& m) {
        return AddObjectSpec{m.read<Object>("object", object_from_json)};
    }
    static json write(const AddObjectSpec& s) { return {{"object", object_to_json(s.object)}}; }
};
template <> struct Form<AddObjectsSpec> {
    static constexpr std::string_view members[]{"objects", "label"};
    static AddObjectsSpec read(Members& m) {
        return AddObjectsSpec{m.read<std::vector<Object>>("objects", objects_from_json),
                              m.text("label", "")};
    }
    static json write(const AddObjectsSpec& s) {
        json objects = json::array();
        for (const Object& o : s.objects) objects.push_back(object_to_json(o));
        json j = {{"objects", std::move(objects)}};
        if (!s.label.empty()) j["label"] = s.label;
        return j;
    }
};
template <> struct Form<RemoveObjectSpec> {
    static constexpr std::string_view members[]{"id"};
    static RemoveObjectSpec read(Members& m) { return RemoveObjectSpec{m.id("id")}; }
    static json write(const RemoveObjectSpec& s) { return {{"id", s.id}}; }
};
template <> struct Form<RenameObjectSpec> {
    static constexpr std::string_view members[]{"id", "name"};
    static RenameObjectSpec read(Members& m) { return {m.id("id"), m.text("name")}; }
    static json write(const RenameObjectSpec& s) { return {{"id", s.id}, {"name", s.name}}; }
};
template <> struct Form<SetVisibleSpec> {
    static constexpr std::string_view members[]{"id", "visible"};
    static SetVisibleSpec read(Members& m) { return {m.id("id"), m.flag("visible")}; }
    static json write(const SetVisibleSpec& s) { return {{"id", s.id}, {"visible", s.visible}}; }
};
template <> struct Form<EditShapeSpec> {
    static constexpr std::string_view members[]{"id", "shape", "label", "merge_key"};
    static EditShapeSpec read(Members& m) {
        EditShapeSpec s;
        s.id = m.id("id");
        s.shape = m.read<Shape>("shape", shape_from_json);
        s.label = m.text("label", "Edit shape");
        s.merge_key = m.text("merge_key", "");
        return s;
    }
    static json write(const EditShapeSpec& s) {
        json j = {{"id", s.id}, {"shape", shape_to_json(s.shape)}, {"label", s.label}};
        if (!s.merge_key.empty()) j["merge_key"] = s.merge_key;
        return j;
    }
};
template <> struct Form<EditPointSpec> {
    static constexpr std::string_view members[]{"id", "i", "j", "position", "weight"};
    static EditPointSpec read(Members& m) {
        EditPointSpec s;
        s.id = m.id("id");
        s.i = m.integer("i");
        s.j = m.integer("j", -1);
        s.position = m.optional_point("position");
        s.weight = m.optional_number("weight");
        return s;
    }
    static json write(const EditPointSpec& s) {
        json j = {{"id", s.id}, {"i", s.i}};
        if (s.j >= 0) j["j"] = s.j;
        if (s.position) j["position"] = point_to_json(*s.position);
        if (s.weight) j["weight"] = *s.weight;
        return j;
    }
};
template <> struct Form<MoveKnotSpec> {
    static constexpr std::string_view members[]{"id", "direction", "k", "count", "value"};
    static MoveKnotSpec read(Members& m) {
        MoveKnotSpec s = on_direction<MoveKnotSpec>(m);
        s.k = m.integer("k");
        s.count = m.integer("count", 1);
        s.value = m.number("value");
        return s;
    }
    static json write(const MoveKnotSpec& s) {
        json j = {
            {"id", s.id}, {"direction", geom::name_of(s.dir)}, {"k", s.k}, {"value", s.value}};
        if (s.count != 1) j["count"] = s.count;
        return j;
    }
};
template <> struct Form<TransformSpec> {
    static constexpr std::string_view members[]{"id", "matrix", "label"};
    static TransformSpec read(Members& m) {
        return {m.id("id"), m.read<glm::dmat4>("matrix", matrix_from_json), m.text("label", "")};
    }
    static json write(const TransformSpec& s) {
        json j = {{"id", s.id}, {"matrix", matrix_to_json(s.matrix)}};
        if (!s.label.empty()) j["label"] = s.label;
        return j;
    }
};
template <> struct Form<InsertKnotSpec> {
    static constexpr std::string_view members[]{"id", "direction", "knot", "times"};
    static InsertKnotSpec read(Members& m) {
        InsertKnotSpec s = on_direction<InsertKnotSpec>(m);
        s.t = m.number("knot");
        s.times = m.integer("times", 1);
        return s;
    }
    static json write(const InsertKnotSpec& s) {
        return {
            {"id", s.id}, {"direction", geom::name_of(s.dir)}, {"knot", s.t}, {"times", s.times}};
    }
};
template <> struct Form<ElevateDegreeSpec> {
    static constexpr std::string_view members[]{"id", "direction", "times"};
    static ElevateDegreeSpec read(Members& m) {
        ElevateDegreeSpec s = on_direction<ElevateDegreeSpec>(m);
        s.times = m.integer("times", 1);
        return s;
    }
    static json write(const ElevateDegreeSpec& s) {
        return {{"id", s.id}, {"direction", geom::name_of(s.dir)}, {"times", s.times}};
    }
};
// Commands on one object along a direction with one number: split ("param") and
// reduce_degree ("tolerance").
template <class Spec, double Spec::*number, const std::string_view& name>
struct DirectionNumberForm {
    static constexpr std::string_view members[]{"id", "direction", name};
    static Spec read(Members& m) {
        Spec s = on_direction<Spec>(m);
        s.*number = m.number(name);
        return s;
    }
    static json write(const Spec& s) {
        return {{"id", s.id}, {"direction", geom::name_of(s.dir)}, {std::string(name), s.*number}};
    }
};
constexpr std::string_view param_member = "param", tolerance_member = "tolerance";
template <> struct Form<SplitSpec> : DirectionNumberForm<SplitSpec, &SplitSpec::t, param_member> {};
template <> struct Form<SplitTriangleSpec> {
    static constexpr std::string_view members[]{"id", "param"};
    static SplitTriangleSpec read(Members& m) {
        return {m.id("id"), m.read<geom::Barycentric>("param", triangle_param_from_json)};
    }
    static json write(const SplitTriangleSpec& s) {
        return {{"id", s.id}, {"param", {s.at[0], s.at[1], s.at[2]}}};
    }
};
template <> struct Form<ConformBordersSpec> {
    static constexpr std::string_view members[]{"group"};
    static ConformBordersSpec read(Members& m) { return ConformBordersSpec{m.id("group")}; }
    static json write(const ConformBordersSpec& s) { return {{"group", s.group}}; }
};
template <> struct Form<SetColorsSpec> {
    static constexpr std::string_view members[]{"colors"};
    static SetColorsSpec read(Members& m) {
        return SetColorsSpec{m.read<Colors>("colors", [](const json& v, const std::string& at) {
            return colors_from_json(v, at, Colors{});
        })};
    }
    static json write(const SetColorsSpec& s) { return {{"colors", colors_to_json(s.colors)}}; }
};
// insert_curve_point and move_curve_point: a curve's point i and a position.
template <class Spec> struct CurvePointForm {
    static constexpr std::string_view members[]{"id", "i", "position"};
    static Spec read(Members& m) { return {m.id("id"), m.integer("i"), m.point("position")}; }
    static json write(const Spec& s) {
        return {{"id", s.id}, {"i", s.i}, {"position", point_to_json(s.position)}};
    }
};
template <> struct Form<InsertCurvePointSpec> : CurvePointForm<InsertCurvePointSpec> {};
template <> struct Form<DeleteCurvePointSpec> {
    static constexpr std::string_view members[]{"id", "i"};
    static DeleteCurvePointSpec read(Members& m) { return {m.id("id"), m.integer("i")}; }
    static json write(const DeleteCurvePointSpec& s) { return {{"id", s.id}, {"i", s.i}}; }
};
template <> struct Form<MoveCurvePointSpec> : CurvePointForm<MoveCurvePointSpec> {};
template <> struct Form<SetCurveDegreeSpec> {
    static constexpr std::string_view members[]{"id", "degree"};
    static SetCurveDegreeSpec read(Members& m) { return {m.id("id"), m.integer("degree")}; }
    static json write(const SetCurveDegreeSpec& s) { return {{"id", s.id}, {"degree", s.degree}}; }
};
template <> struct Form<SetCurveKnotModeSpec> {
    static constexpr std::string_view members[]{"id", "knot_mode"};
    static SetCurveKnotModeSpec read(Members& m) {
        return {m.id("id"), m.named<CurveKnotMode>("knot_mode", "knot_mode")};
    }
    static json write(const SetCurveKnotModeSpec& s) {
        return {{"id", s.id}, {"knot_mode", geom::name_of(s.mode)}};
    }
};
template <> struct Form<SetCurvePlaneSpec> {
    static constexpr std::string_view members[]{"id", "plane", "carry_points"};
    static SetCurvePlaneSpec read(Members& m) {
        SetCurvePlaneSpec s;
        s.id = m.id("id");
        s.plane = m.named<CurvePlane>("plane", "plane");
        s.carry_points = m.flag("carry_points", false);
        return s;
    }
    static json write(const SetCurvePlaneSpec& s) {
        return {{"id", s.id}, {"plane", geom::name_of(s.plane)}, {"carry_points", s.carry_points}};
    }
};
template <> struct Form<MakeCompatibleSpec> {
    static constexpr std::string_view members[]{"ids"};
    static MakeCompatibleSpec read(Members& m) {
        return MakeCompatibleSpec{m.read<std::vector<std::uint64_t>>("ids", ids_from_json)};
    }
    static json write(const MakeCompatibleSpec& s) { return {{"ids", s.ids}}; }
};
template <> struct Form<RemoveKnotSpec> {
    static constexpr std::string_view members[]{"id", "direction", "knot", "times", "tolerance"};
    static RemoveKnotSpec read(Members& m) {
        RemoveKnotSpec s = on_direction<RemoveKnotSpec>(m);
        s.t = m.number("knot");
        s.times = m.integer("times", 1);
        s.tolerance = m.number("tolerance");
        return s;
    }
    static json write(const RemoveKnotSpec& s) {
        return {{"id", s.id},
                {"direction", geom::name_of(s.dir)},
                {"knot", s.t},
                {"times", s.times},
                {"tolerance", s.tolerance}};
    }
};
template <>
struct Form<ReduceDegreeSpec>
    : DirectionNumberForm<ReduceDegreeSpec, &ReduceDegreeSpec::tolerance, tolerance_member> {};
template <> struct Form<SplitKnotSpec> {
    static constexpr std::string_view members[]{"id", "direction", "knot", "delta"};
    static SplitKnotSpec read(Members& m) {
        SplitKnotSpec s = on_direction<SplitKnotSpec>(m);
        s.t = m.number("knot");
        s.delta = m.optional_number("delta");
        return s;
    }
    static json write(const SplitKnotSpec& s) {
        json j = {{"id", s.id}, {"direction", geom::name_of(s.dir)}, {"knot", s.t}};
        if (s.delta) j["delta"] = *s.delta;
        return j;
    }
};
template <> struct Form<CloseSpec> {
    static constexpr std::string_view members[]{"id", "direction"};
    static CloseSpec read(Members& m) {
        return {m.id("id"), m.named<geom::Dir>("direction", "direction")};
    }
    static json write(const CloseSpec& s) {
        return {{"id", s.id}, {"direction", geom::name_of(s.dir)}};
    }
};
template <> struct Form<ConvertSpec> {
    static constexpr std::string_view members[]{"id", "to", "reset_weights"};
    static ConvertSpec read(Members& m) {
        ConvertSpec s;
        s.id = m.id("id");
        s.to = m.named<geom::SplineType>("to", "to");
        s.reset_weights = m.flag("reset_weights", false);
        return s;
    }
    static json write(const ConvertSpec& s) {
        json j = {{"id", s.id}, {"to", geom::name_of(s.to)}};
        if (s.reset_weights) j["reset_weights"] = true;
        return j;
    }
};
template <> struct Form<MultiresEditSpec> {
    static constexpr std::string_view members[]{"id", "level",    "level_v",     "i",
                                                "j",  "position", "detail_scale"};
    static MultiresEditSpec read(Members& m) {
        MultiresEditSpec s;
        s.id = m.id("id");
        s.level = m.integer("level");
        s.level_v = m.optional_integer("level_v");
        s.i = m.integer("i", 0);
        s.j = m.integer("j", -1);
        s.position = m.optional_point("position");
        s.detail_scale = m.optional_number("detail_scale");
        return s;
    }
    static json write(const MultiresEditSpec& s) {
        json j = {{"id", s.id}, {"level", s.level}, {"i", s.i}};
        if (s.level_v) j["level_v"] = *s.level_v;
        if (s.j >= 0) j["j"] = s.j;
        if (s.position) j["position"] = point_to_json(*s.position);
        if (s.detail_scale) j["detail_scale"] = *s.detail_scale;
        return j;
    }
};

template <> struct Form<ConstructSpec> {
    static constexpr std::string_view members[]{"construction", "name"};
    static ConstructSpec read(Members& m) {
        return ConstructSpec{m.read<Recipe>("construction", recipe_from_json), m.text("name", "")};
    }
    static json write(const ConstructSpec& s) {
        json j = {{"construction", recipe_to_json(s.recipe)}};
        if (!s.name.empty()) j["name"] = s.name;
        return j;
    }
};
template <> struct Form<EditConstructionSpec> {
    static constexpr std::string_view members[]{"id", "construction"};
    static EditConstructionSpec read(Members& m) {
        EditConstructionSpec s;
        s.id = m.id("id");
        s.recipe = m.read<Recipe>("construction", recipe_from_json);
        return s;
    }
    static json write(const EditConstructionSpec& s) {
        return {{"id", s.id}, {"construction", recipe_to_json(s.recipe)}};
    }
};
template <> struct Form<DetachSpec> {
    static constexpr std::string_view members[]{"id"};
    static DetachSpec read(Members& m) { return DetachSpec{m.id("id")}; }
    static json write(const DetachSpec& s) { return {{"id", s.id}}; }
};
template <> struct Form<SetTrimSpec> {
    static constexpr std::string_view members[]{"id", "trim"};
    static SetTrimSpec read(Members& m) {
        SetTrimSpec s;
        s.id = m.id("id");
        s.trim = m.read<geom::Trim>(
            "trim", [](const json& v, const std::string& path) -> Expected<geom::Trim> {
                auto t = json_io::trim_from_json(v);
                if (!t) return t.error().under(path);
                return t;
            });
        return s;
    }
    static json write(const SetTrimSpec& s) {
        return {{"id", s.id}, {"trim", json_io::trim_to_json(s.trim)}};
    }
};
template <> struct Form<RemoveTrimSpec> {
    static constexpr std::string_view members[]{"id"};
    static RemoveTrimSpec read(Members& m) { return RemoveTrimSpec{m.id("id")}; }
    static json write(const RemoveTrimSpec& s) { return {{"id", s.id}}; }
};
template <> struct Form<MovePointsSpec> {
    static constexpr std::string_view members[]{"id", "points", "positions", "label"};
    static MovePointsSpec read(Members& m) {
        MovePointsSpec s;
        s.id = m.id("id");
        s.points = m.read<std::vector<PointIndex>>("points", points_from_json);
        s.positions = m.read<std::vector<glm::dvec3>>("positions", positions_from_json);
        s.label = m.text("label", "");
        return s;
    }
    static json write(const MovePointsSpec& s) {
        json positions = json::array();
        for (const glm::dvec3& p : s.positions) positions.push_back({p.x, p.y, p.z});
        json j = {{"id", s.id},
                  {"points", points_to_json(s.points)},
                  {"positions", std::move(positions)}};
        if (!s.label.empty()) j["label"] = s.label;
        return j;
    }
};
// "about": "centroid" or a point [x, y, z]; absent: the origin.
Expected<std::pair<Pivot, glm::dvec3>> pivot_from_json(const json& v, const std::string& at) {
    if (v.is_string()) {
        if (v.get<std::string>() == "centroid") return std::pair{Pivot::centroid, glm::dvec3(0)};
        return schema_error(
            "about is \"centroid\" or a point [x, y, z], got '" + v.get<std::string>() + "'", at);
    }
    auto p = read_point(v, at, "the pivot");
    if (!p) return p.error();
    return std::pair{Pivot::point, *p};
}
template <> struct Form<TransformPointsSpec> {
    static constexpr std::string_view members[]{"id", "points", "matrix", "about", "label"};
    static TransformPointsSpec read(Members& m) {
        TransformPointsSpec s;
        s.id = m.id("id");
        s.points = m.read<std::vector<PointIndex>>("points", points_from_json);
        s.matrix = m.read<glm::dmat4>("matrix", matrix_from_json);
        s.label = m.text("label", "");
        if (m.has("about")) {
            const auto about = m.read<std::pair<Pivot, glm::dvec3>>("about", pivot_from_json);
            s.about = about.first;
            s.pivot = about.second;
        }
        return s;
    }
    static json write(const TransformPointsSpec& s) {
        json j = {{"id", s.id},
                  {"points", points_to_json(s.points)},
                  {"matrix", matrix_to_json(s.matrix)}};
        switch (s.about) {
        case Pivot::origin:
            break;
        case Pivot::centroid:
            j["about"] = "centroid";
            break;
        case Pivot::point:
            j["about"] = {s.pivot.x, s.pivot.y, s.pivot.z};
            break;
        }
        if (!s.label.empty()) j["label"] = s.label;
        return j;
    }
};

// The command named `name`, read through its form: members checked, then read.
template <std::size_t I = 0>
Expected<CommandSpec> read_command(std::string_view name, const json& j, const std::string& at) {
    if constexpr (I == std::variant_size_v<CommandSpec>) {
        std::string names;
        for (const char* n : command_names) names += std::string(names.empty() ? "" : ", ") + n;
        return schema_error("unknown command '" + std::string(name) + "' (commands: " + names + ")",
                            member_path(at, "command"));
    } else {
        using Spec = std::variant_alternative_t<I, CommandSpec>;
        if (name != Spec::script_name) return read_command<I + 1>(name, j, at);
        std::vector<std::string_view> allowed{"command"};
        allowed.insert(allowed.end(), std::begin(Form<Spec>::members),
                       std::end(Form<Spec>::members));
        const std::string what = "command '" + std::string(name) + "'";
        if (auto st = check_members(j, at, what, allowed); !st) return st.error();
        Members m(j, at);
        CommandSpec spec = Form<Spec>::read(m);
        if (m.error) return *m.error;
        return spec;
    }
}

} // namespace

json command_to_json(const CommandSpec& spec) {
    json j =
        std::visit([](const auto& s) { return Form<std::decay_t<decltype(s)>>::write(s); }, spec);
    j["command"] = command_name(spec);
    return j;
}

Expected<CommandSpec> command_from_json(const json& j, const std::string& at) {
    if (auto st = expect_object(j, at, "a command"); !st) return st.error();
    const json* name = find_member(j, "command");
    if (!name) return missing_member(at, "command");
    auto text = read_string(*name, member_path(at, "command"), "command");
    if (!text) return text.error();
    return read_command(*text, j, at);
}

} // namespace isoparm::scene
