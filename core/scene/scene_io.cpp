// Scenes <-> JSON values (docs/scene-format.md): strict reading with JSON Pointer errors.
#include "core/scene/scene_io.hpp"

#include "core/geom/reshape.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <set>

#include "core/doc/associative.hpp"
#include "core/doc/commands_common.hpp"
#include "core/doc/patches.hpp"
#include "core/geom/reshape.hpp"
#include "core/json/fields.hpp"
#include "core/json/out_of_memory.hpp"
#include "core/json/reader.hpp"
#include "core/json/shapes.hpp"
#include "core/scene/recipe_json.hpp"

namespace isoparm::scene {

using namespace isoparm::doc;
using namespace isoparm::json_io;

using geom::Error;
using geom::ErrorCode;
using geom::Expected;
using geom::make_error;
using nlohmann::json;

namespace {

// The colours in file order, with their names (shared by writing and reading).
template <class C> auto color_fields(C& colors) {
    using R = std::conditional_t<std::is_const_v<C>, const Rgba*, Rgba*>;
    return std::array<std::pair<const char*, R>, 8>{{
        {"background", &colors.background},
        {"surface", &colors.surface},
        {"selected_surface", &colors.selected_surface},
        {"control_net", &colors.control_net},
        {"control_points", &colors.control_points},
        {"selected_point", &colors.selected_point},
        {"knot_curves", &colors.knot_curves},
        {"indicator", &colors.indicator},
    }};
}

template <class D> auto display_flags(D& d) {
    using B = std::conditional_t<std::is_const_v<D>, const bool*, bool*>;
    return std::array<std::pair<const char*, B>, 6>{{
        {"control_points", &d.control_points},
        {"control_net", &d.control_net},
        {"point_ids", &d.point_ids},
        {"knot_curves", &d.knot_curves},
        {"indicator_point", &d.indicator_point},
        {"deboor", &d.deboor},
    }};
}

template <class D> auto object_display_flags(D& d) {
    using B = std::conditional_t<std::is_const_v<D>, const bool*, bool*>;
    return std::array<std::pair<const char*, B>, 4>{{
        {"control_points", &d.control_points},
        {"control_net", &d.control_net},
        {"point_ids", &d.point_ids},
        {"knot_curves", &d.knot_curves},
    }};
}

constexpr int max_density = 256;
constexpr std::size_t max_objects = 100000;

// A colour channel is a float; it is written as the shortest decimal that reads back as that
// float ("0.13", not 0.12999999523162842), held in a double.
double channel_to_double(float f) {
    char buf[32];
    const auto res = std::to_chars(buf, buf + sizeof buf, f);
    *res.ptr = '\0';
    return std::strtod(buf, nullptr);
}

json color_to_json(const Rgba& c) {
    return json::array({channel_to_double(c.r), channel_to_double(c.g), channel_to_double(c.b),
                        channel_to_double(c.a)});
}

// ---------------------------------------------------------------------------------------
// Reading helpers (the shared ones are in core/json/fields.hpp): every error carries the
// absolute path into the scene.

Expected<Rgba> read_color(const json& v, const std::string& at) {
    if (!v.is_array() || (v.size() != 3 && v.size() != 4))
        return schema_error("a colour is [r, g, b] or [r, g, b, a] with channels in [0, 1]", at);
    float ch[4] = {0, 0, 0, 1};
    for (std::size_t k = 0; k < v.size(); ++k) {
        const std::string p = at + "/" + std::to_string(k);
        auto x = read_finite(v[k], p, "a colour channel");
        if (!x) return x.error();
        if (*x < 0 || *x > 1)
            return schema_error(
                "colour channels are between 0 and 1, got " + geom::format_number(*x), p);
        ch[k] = static_cast<float>(*x);
    }
    return Rgba{ch[0], ch[1], ch[2], ch[3]};
}

// ---------------------------------------------------------------------------------------
// Objects.

// A name of E's table ("style": "shaded"); anything else is refused with the table's names.
template <class E> Expected<E> read_named(const json& v, const std::string& at, const char* what) {
    auto s = read_string(v, at, what);
    if (!s) return s.error();
    const std::optional<E> named = geom::parse_name<E>(*s);
    if (!named)
        return schema_error(
            std::string(what) + " must be " + geom::names_list<E>() + ", got '" + *s + "'", at);
    return *named;
}

// The kind a scene object or a command's shape names ("/kind" under at).
Expected<ObjectKind> read_kind_name(const json& j, const std::string& at) {
    const auto kind_it = j.find("kind");
    if (kind_it == j.end()) return missing_member(at, "kind");
    return read_named<ObjectKind>(*kind_it, at + "/kind", "kind");
}

// The members a scene object (`object`) or a command's shape of this kind may have, and how
// messages name it ("a surface object", "an implicit shape").
struct KindMembers {
    std::vector<std::string_view> allowed;
    std::string what;
};
KindMembers kind_members(ObjectKind kind, bool object) {
    return with_kind_type(kind, [&]<class K>(std::type_identity<K>) {
        KindMembers m;
        m.allowed = object ? std::vector<std::string_view>{"id", "name", "kind", "visible"}
                           : std::vector<std::string_view>{"kind"};
        if (object && K::in_patch_groups) m.allowed.push_back("patch_group");
        m.allowed.insert(m.allowed.end(), K::shape_members.begin(), K::shape_members.end());
        if (object && K::constructed) m.allowed.push_back("construction");
        m.what = kind_file_noun(kind) + (object ? " object" : " shape");
        return m;
    });
}

// The geometry members of a shape of this kind, after the caller checked the members.
Expected<Shape> read_shape(const json& j, const std::string& at, ObjectKind kind) {
    const char* member = geom::name_of(kind); // the geometry's member is named as the kind
    const std::string gat = at + "/" + member;
    if (j.find(member) == j.end())
        return schema_error(std::string("missing member '") + member + "' (the " +
                                geom::name_of(kind) + " object's geometry)",
                            gat);
    auto shape = with_kind_type(kind, [&]<class K>(std::type_identity<K> tag) -> Expected<Shape> {
        auto k = read_kind(tag, j, at);
        if (!k) return k.error();
        return Shape{std::move(k).value()};
    });
    if (!shape) return shape.error();
    // The document's own rules (size caps, finite points, the implicit's box and parameters).
    // A surface's trim is a member beside its geometry, not inside it.
    if (auto st = detail::validate_shape(*shape); !st)
        return st.error().under(st.error().path.starts_with("/trim") ? at : gat);
    return shape;
}

} // namespace

Expected<Object> object_from_json(const json& j, const std::string& at) {
    if (auto st = expect_object(j, at, "an object"); !st) return st.error();
    auto kind = read_kind_name(j, at);
    if (!kind) return kind.error();
    const KindMembers members = kind_members(*kind, true);
    if (auto st = check_members(j, at, members.what, members.allowed); !st) return st.error();

    Object o;
    if (const auto id = j.find("id"); id != j.end()) {
        auto v = read_integer(*id, at + "/id", "an object id", 1,
                              static_cast<std::int64_t>(max_object_id));
        if (!v) return v.error();
        o.id = static_cast<std::uint64_t>(*v);
    }
    const auto name_it = j.find("name");
    if (name_it == j.end()) return missing_member(at, "name");
    auto name = read_string(*name_it, at + "/name", "name");
    if (!name) return name.error();
    o.name = *name;
    if (auto st = detail::validate_name(o.name); !st) return st.error().under(at);
    if (const auto vis = j.find("visible"); vis != j.end()) {
        auto v = read_bool(*vis, at + "/visible");
        if (!v) return v.error();
        o.visible = *v;
    }
    if (const auto group = j.find("patch_group"); group != j.end()) {
        auto v = read_integer(*group, at + "/patch_group", "a patch group id", 1,
                              static_cast<std::int64_t>(max_object_id));
        if (!v) return v.error();
        o.patch_group = static_cast<std::uint64_t>(*v);
    }
    auto shape = read_shape(j, at, *kind);
    if (!shape) return shape.error();
    o.shape = std::move(shape).value();
    // Its links to the other objects are checked with the whole scene (check_constructions).
    if (const auto recipe = j.find("construction"); recipe != j.end()) {
        auto r = recipe_from_json(*recipe, at + "/construction");
        if (!r) return r.error();
        o.construction = std::move(r).value();
    }
    return o;
}

Expected<Shape> shape_from_json(const json& j, const std::string& at) {
    if (auto st = expect_object(j, at, "a shape"); !st) return st.error();
    auto kind = read_kind_name(j, at);
    if (!kind) return kind.error();
    const KindMembers members = kind_members(*kind, false);
    if (auto st = check_members(j, at, members.what, members.allowed); !st) return st.error();
    return read_shape(j, at, *kind);
}

json shape_to_json(const Shape& shape) {
    json j = json::object();
    j["kind"] = geom::name_of(kind_of(shape));
    std::visit([&](const auto& k) { kind_to_json(k, j); }, shape);
    return j;
}

json object_to_json(const Object& o) {
    json j = json::object();
    if (o.id != 0) j["id"] = o.id; // 0: not in a document yet (a command's new object)
    j["name"] = o.name;
    j["visible"] = o.visible;
    if (o.patch_group != 0) j["patch_group"] = o.patch_group;
    const json shape = shape_to_json(o.shape);
    for (const auto& [key, value] : shape.items()) j[key] = value;
    if (o.construction) j["construction"] = recipe_to_json(*o.construction);
    return j;
}

json display_to_json(const DisplaySettings& d) {
    json display = json::object();
    display["style"] = geom::name_of(d.style);
    for (const auto& [name, flag] : display_flags(d)) display[name] = *flag;
    display["density"] = d.density;
    // Written only when set, so scenes without analysis read as before.
    if (d.analysis != AnalysisMode::off) display["analysis"] = geom::name_of(d.analysis);
    if (d.analysis_fixed) display["analysis_range"] = {d.analysis_lo, d.analysis_hi};
    if (d.stripes != DisplaySettings{}.stripes) display["stripes"] = d.stripes;
    if (d.zebra_angle != 0) display["zebra_angle"] = d.zebra_angle;
    return display;
}

json colors_to_json(const Colors& colors) {
    json j = json::object();
    for (const auto& [name, c] : color_fields(colors)) j[name] = color_to_json(*c);
    return j;
}

Expected<Colors> colors_from_json(const json& j, const std::string& at, Colors colors) {
    if (auto st = expect_object(j, at, "colors"); !st) return st.error();
    std::vector<std::string_view> allowed;
    for (auto& [name, c] : color_fields(colors)) allowed.push_back(name);
    if (auto st = check_members(j, at, "colors", allowed); !st) return st.error();
    for (auto& [name, c] : color_fields(colors)) {
        const auto v = j.find(name);
        if (v == j.end()) continue;
        auto colour = read_color(*v, member_path(at, name));
        if (!colour) return colour.error();
        *c = *colour;
    }
    return colors;
}

namespace {} // namespace

Expected<DisplaySettings> display_from_json(const json& j, const std::string& at,
                                            DisplaySettings d) {
    if (auto st = expect_object(j, at, "display"); !st) return st.error();
    std::vector<std::string_view> allowed{"style"};
    for (auto& [name, flag] : display_flags(d)) allowed.push_back(name);
    for (const char* name : {"density", "analysis", "analysis_range", "stripes", "zebra_angle"})
        allowed.push_back(name);
    if (auto st = check_members(j, at, "display", allowed); !st) return st.error();
    for (const auto& item : j.items()) {
        const std::string mat = member_path(at, item.key());
        if (item.key() == "style") {
            auto style = read_named<DisplayStyle>(item.value(), mat, "style");
            if (!style) return style.error();
            d.style = *style;
            continue;
        }
        if (item.key() == "density") {
            auto n = read_integer(item.value(), mat, "density", 1, max_density);
            if (!n) return n.error();
            d.density = static_cast<int>(*n);
            continue;
        }
        if (item.key() == "analysis") {
            auto mode = read_named<AnalysisMode>(item.value(), mat, "analysis");
            if (!mode) return mode.error();
            d.analysis = *mode;
            continue;
        }
        if (item.key() == "analysis_range") {
            const json& r = item.value();
            if (!r.is_array() || r.size() != 2 || !r[0].is_number() || !r[1].is_number())
                return schema_error("analysis_range is [low, high], two numbers", mat);
            const double lo = r[0].get<double>(), hi = r[1].get<double>();
            if (!(std::isfinite(lo) && std::isfinite(hi) && lo < hi))
                return schema_error("analysis_range needs finite low < high, got [" +
                                        geom::format_number(lo) + ", " + geom::format_number(hi) +
                                        "]",
                                    mat);
            d.analysis_fixed = true;
            d.analysis_lo = lo;
            d.analysis_hi = hi;
            continue;
        }
        if (item.key() == "stripes") {
            auto n = read_integer(item.value(), mat, "stripes", 2, 64);
            if (!n) return n.error();
            d.stripes = static_cast<int>(*n);
            continue;
        }
        if (item.key() == "zebra_angle") {
            if (!item.value().is_number() || !std::isfinite(item.value().get<double>()))
                return schema_error("zebra_angle is a number of degrees", mat);
            d.zebra_angle = item.value().get<double>();
            continue;
        }
        for (auto& [name, flag] : display_flags(d)) {
            if (item.key() != name) continue;
            auto v = read_bool(item.value(), mat);
            if (!v) return v.error();
            *flag = *v;
        }
    }
    return d;
}

json selection_to_json(const Selection& s) {
    if (s.object == 0) return nullptr;
    json j = {{"object", s.object}};
    if (s.has_point()) j["point"] = s.j >= 0 ? json::array({s.i, s.j}) : json::array({s.i});
    return j;
}

Expected<Selection> selection_from_json(const json& j, const std::string& at, const Document& doc) {
    Selection sel;
    if (j.is_null()) return sel;
    if (auto st = expect_object(j, at, "selection (or null)"); !st) return st.error();
    if (auto st = check_members(j, at, "selection", {"object", "point"}); !st) return st.error();
    const auto obj = j.find("object");
    if (obj == j.end()) return missing_member(at, "object");
    auto id = read_integer(*obj, at + "/object", "the selected object's id", 1,
                           static_cast<std::int64_t>(max_object_id));
    if (!id) return id.error();
    const Object* o = doc.find(static_cast<std::uint64_t>(*id));
    if (!o)
        return schema_error("the selection names object " + std::to_string(*id) +
                                ", but no object has that id",
                            at + "/object");
    sel.object = o->id;
    const auto point = j.find("point");
    if (point == j.end()) return sel;
    auto idx = std::visit(
        [&](const auto& k) { return selected_point_from_json(k, *point, at + "/point"); },
        o->shape);
    if (!idx) return idx.error();
    std::tie(sel.i, sel.j) = *idx;
    return sel;
}

Expected<glm::dvec2> indicator_from_json(const json& j, const std::string& at) {
    if (!j.is_array() || j.size() != 2)
        return schema_error("indicator is [u, v], each in [0, 1]", at);
    glm::dvec2 uv{0.5, 0.5};
    for (int a = 0; a < 2; ++a) {
        const std::string aat = at + "/" + std::to_string(a);
        auto x = read_finite(j[static_cast<std::size_t>(a)], aat, "an indicator coordinate");
        if (!x) return x.error();
        if (*x < 0 || *x > 1)
            return schema_error("indicator coordinates are in [0, 1] (over the domain), got " +
                                    geom::format_number(*x),
                                aat);
        uv[a] = *x;
    }
    return uv;
}

Expected<geom::Barycentric> barycentric_from_json(const json& j, const std::string& at) {
    auto read = triangle_param_from_json(j, at);
    if (!read) return read.error();
    const geom::Barycentric rst = *read;
    for (std::size_t a = 0; a < 3; ++a)
        if (rst[a] < 0)
            return schema_error("barycentric coordinates are >= 0, got " +
                                    geom::format_number(rst[a]),
                                at + "/" + std::to_string(a));
    if (!(std::abs(rst[0] + rst[1] + rst[2] - 1) <= 1e-12))
        return schema_error("barycentric coordinates sum to 1, these sum to " +
                                geom::format_number(rst[0] + rst[1] + rst[2]),
                            at);
    return rst;
}

Expected<Continuity> continuity_from_json(const json& j, const std::string& at) {
    auto name = read_string(j, at, "continuity");
    if (!name) return name.error();
    const std::optional<Continuity> continuity = geom::parse_name<Continuity>(*name);
    if (!continuity)
        return schema_error(
            "continuity must be " + geom::names_list<Continuity>() + ", got '" + *name + "'", at);
    return *continuity;
}

namespace {} // namespace

json without_display(const json& object) {
    json rest = object;
    rest.erase("display");
    return rest;
}

json object_display_to_json(const ObjectDisplay& d) {
    json j = json::object();
    for (const auto& [name, flag] : object_display_flags(d)) j[name] = *flag;
    return j;
}

Expected<ObjectDisplay> object_display_from_json(const json& j, const std::string& at,
                                                 ObjectDisplay d) {
    if (auto st = expect_object(j, at, "display"); !st) return st.error();
    std::vector<std::string_view> allowed;
    for (auto& [name, flag] : object_display_flags(d)) allowed.push_back(name);
    if (auto st = check_members(j, at, "an object's display", allowed); !st) return st.error();
    for (auto& [name, flag] : object_display_flags(d))
        if (const auto it = j.find(name); it != j.end()) {
            auto v = read_bool(*it, member_path(at, name));
            if (!v) return v.error();
            *flag = *v;
        }
    return d;
}

json scene_to_json(const Document& doc) {
    json objects = json::array();
    bool own_display = false;
    for (const Object& o : doc.objects) {
        json oj = object_to_json(o);
        // An object's own display toggles (format version 2); the others take the scene's.
        if (const auto d = doc.view.object_display.find(o.id); d != doc.view.object_display.end()) {
            oj["display"] = object_display_to_json(d->second);
            own_display = true;
        }
        objects.push_back(std::move(oj));
    }
    json colors = colors_to_json(doc.colors);

    json display = display_to_json(doc.view.display);

    // A selection of an object that is gone is not written.
    const json selection =
        doc.find(doc.view.selection.object) ? selection_to_json(doc.view.selection) : json();

    json scene = json::object();
    scene["format"] = scene_format_name;
    // Version 2 only where it is needed (an object's own display toggles or a construction),
    // version 3 where a surface is trimmed, so other scenes save as version 1 and read in older
    // builds as before.
    const bool constructions =
        std::any_of(doc.objects.begin(), doc.objects.end(),
                    [](const Object& o) { return o.construction.has_value(); });
    const bool trims = std::any_of(doc.objects.begin(), doc.objects.end(), is_trimmed);
    scene["version"] = trims ? 3 : own_display || constructions ? 2 : 1;
    scene["objects"] = std::move(objects);
    scene["colors"] = std::move(colors);
    scene["display"] = std::move(display);
    scene["selection"] = std::move(selection);
    scene["indicator"] = json::array({doc.view.indicator.x, doc.view.indicator.y});
    // The triangle indicator only where there is a triangle, so other scenes save as before.
    if (std::any_of(doc.objects.begin(), doc.objects.end(),
                    [](const Object& o) { return o.triangle() != nullptr; }))
        scene["barycentric"] = json::array(
            {doc.view.barycentric[0], doc.view.barycentric[1], doc.view.barycentric[2]});
    if (doc.continuity != Continuity::off) scene["continuity"] = geom::name_of(doc.continuity);
    // The id the next new object gets, where deleting the newest objects left it above the
    // largest id (so that a script replayed on this scene makes the same ids).
    std::uint64_t largest = 0;
    for (const Object& o : doc.objects) largest = std::max(largest, o.id);
    if (doc.next_id > largest + 1) scene["next_id"] = doc.next_id;
    return scene;
}

namespace {

// The scene's format version, after its format: checked first, since a newer file may well have
// members this version lacks.
Expected<std::int64_t> scene_version(const json& j) {
    const auto format = j.find("format");
    if (format == j.end())
        return schema_error("missing member 'format' (an isoparm scene has \"format\": \"" +
                                std::string(scene_format_name) + "\")",
                            "/format");
    if (!format->is_string() || format->get<std::string>() != scene_format_name)
        return schema_error("not an isoparm scene: format must be \"" +
                                std::string(scene_format_name) + "\", got " +
                                (format->is_string() ? "\"" + format->get<std::string>() + "\""
                                                     : std::string(type_name(*format))),
                            "/format");
    const auto version = j.find("version");
    if (version == j.end()) return missing_member("", "version");
    const auto v = integer_value(*version);
    if (!v) return schema_error("version must be an integer, got " + version->dump(), "/version");
    if (*v > scene_format_version)
        return schema_error("this scene has format version " + std::to_string(*v) +
                                ", newer than this isoparm reads (" +
                                std::to_string(scene_format_version) +
                                "); update isoparm to open it",
                            "/version");
    if (*v < 1)
        return schema_error("version must be at least 1, got " + std::to_string(*v), "/version");
    return *v;
}

// An object's own display toggles, read after the scene's (object index, its JSON).
using OwnDisplays = std::vector<std::pair<std::size_t, const json*>>;

// The objects, with fresh ids for those written without one, and next_id.
geom::Status read_scene_objects(const json& j, std::int64_t version, Document& doc,
                                OwnDisplays& own_displays) {
    const auto objects = j.find("objects");
    if (objects == j.end()) return missing_member("", "objects");
    if (!objects->is_array())
        return schema_error(std::string("objects must be an array, got ") + type_name(*objects),
                            "/objects");
    if (objects->size() > max_objects)
        return make_error(ErrorCode::limit,
                          "a scene may hold at most " + std::to_string(max_objects) +
                              " objects, got " + std::to_string(objects->size()),
                          "/objects");
    std::set<std::uint64_t> ids;
    for (std::size_t k = 0; k < objects->size(); ++k) {
        const std::string at = "/objects/" + std::to_string(k);
        const json& oj = (*objects)[k];
        // An object's own display is view state, not geometry: read apart (version 2).
        const bool own = oj.is_object() && oj.contains("display");
        if (own && version < 2)
            return schema_error("an object's display needs format version 2, this scene says "
                                "version " +
                                    std::to_string(version),
                                at + "/display");
        if (version < 3 && oj.is_object() && oj.contains("trim"))
            return schema_error("a surface's trim needs format version 3, this scene says "
                                "version " +
                                    std::to_string(version),
                                at + "/trim");
        if (own) own_displays.emplace_back(k, &oj.at("display"));
        auto o = own ? object_from_json(without_display(oj), at) : object_from_json(oj, at);
        if (!o) return o.error();
        if (o->id != 0 && !ids.insert(o->id).second)
            return schema_error("object id " + std::to_string(o->id) + " is used twice",
                                at + "/id");
        doc.objects.push_back(std::move(o).value());
    }
    // Objects written without an id get fresh ones after the largest given.
    std::uint64_t next = ids.empty() ? 1 : *ids.rbegin() + 1;
    for (Object& o : doc.objects)
        if (o.id == 0) o.id = next++;
    doc.next_id = next;
    if (const auto n = j.find("next_id"); n != j.end()) {
        auto v = read_integer(*n, "/next_id", "next_id", static_cast<std::int64_t>(next),
                              static_cast<std::int64_t>(max_object_id));
        if (!v) return v.error();
        doc.next_id = static_cast<std::uint64_t>(*v);
    }
    return geom::Ok{};
}

// Colours, display settings (the scene's, then each object's own), selection and continuity.
geom::Status read_scene_settings(const json& j, Document& doc, const OwnDisplays& own_displays) {
    if (const auto c = j.find("colors"); c != j.end()) {
        auto colors = colors_from_json(*c, "/colors", doc.colors);
        if (!colors) return colors.error();
        doc.colors = *colors;
    }
    if (const auto d = j.find("display"); d != j.end()) {
        auto display = display_from_json(*d, "/display", doc.view.display);
        if (!display) return display.error();
        doc.view.display = *display;
    }
    for (const auto& [k, dj] : own_displays) {
        auto d = object_display_from_json(*dj, "/objects/" + std::to_string(k) + "/display",
                                          defaults_of(doc.view.display));
        if (!d) return d.error();
        doc.view.object_display[doc.objects[k].id] = *d;
    }
    if (const auto s = j.find("selection"); s != j.end()) {
        auto selection = selection_from_json(*s, "/selection", doc);
        if (!selection) return selection.error();
        doc.view.selection = *selection;
    }
    if (const auto c = j.find("continuity"); c != j.end()) {
        auto continuity = continuity_from_json(*c, "/continuity");
        if (!continuity) return continuity.error();
        doc.continuity = *continuity;
    }
    return geom::Ok{};
}

// Each recipe's inputs exist, are of the kind it reads, and no recipe reads itself.
geom::Status check_scene_constructions(const Document& doc, std::int64_t version) {
    if (version < 2)
        for (std::size_t k = 0; k < doc.objects.size(); ++k)
            if (doc.objects[k].construction)
                return schema_error("construction needs scene format version 2 (this scene says " +
                                        std::to_string(version) + ")",
                                    "/objects/" + std::to_string(k) + "/construction");
    for (std::size_t k = 0; k < doc.objects.size(); ++k) {
        const Object& o = doc.objects[k];
        if (!o.construction) continue;
        if (auto st = check_recipe_links(doc, o.id, o, *o.construction); !st)
            return st.error().under("/objects/" + std::to_string(k));
    }
    return geom::Ok{};
}

} // namespace

Expected<Document> scene_from_json(const json& j) {
    if (!j.is_object())
        return schema_error(std::string("a scene is a JSON object, got ") + type_name(j), "");
    const auto v = scene_version(j);
    if (!v) return v.error();
    if (auto st = check_members(j, "", "a scene",
                                {"format", "version", "objects", "colors", "display", "selection",
                                 "indicator", "barycentric", "continuity", "next_id"});
        !st)
        return st.error();

    Document doc;
    OwnDisplays own_displays;
    if (auto st = read_scene_objects(j, *v, doc, own_displays); !st) return st.error();
    if (auto st = read_scene_settings(j, doc, own_displays); !st) return st.error();
    if (auto e = check_patch_groups(doc)) return *e;
    if (auto st = check_scene_constructions(doc, *v); !st) return st.error();
    if (const auto ind = j.find("indicator"); ind != j.end()) {
        auto uv = indicator_from_json(*ind, "/indicator");
        if (!uv) return uv.error();
        doc.view.indicator = *uv;
    }
    if (const auto bary = j.find("barycentric"); bary != j.end()) {
        auto rst = barycentric_from_json(*bary, "/barycentric");
        if (!rst) return rst.error();
        doc.view.barycentric = *rst;
    }
    return doc;
}

Expected<Document> scene_from_text(std::string_view text) {
    auto read = read_json(text);
    if (!read) return read.error();
    // Duplicate keys and excessive nesting are found while reading; the first one wins.
    if (!read->problems.empty()) return read->problems.front();
    // Freed without allocating, also while unwinding from std::bad_alloc (out_of_memory.hpp).
    const ReleaseJsonOnExit release(read->value);
    return scene_from_json(read->value);
}

} // namespace isoparm::scene
