// Recipes <-> JSON, one table of which parameters each operation takes.
#include "core/scene/recipe_json.hpp"

#include <algorithm>
#include <climits>
#include <string_view>
#include <vector>

#include "core/geom/validate.hpp"
#include "core/json/fields.hpp"
#include "core/scene/scene_io.hpp"

namespace isoparm::scene {

using namespace isoparm::doc;
using namespace isoparm::json_io;
using geom::Expected;
using nlohmann::json;

namespace {

// The parameters each operation takes, in Construction's order.
const std::initializer_list<std::string_view> operation_parameters[] = {
    {},                            // ruled
    {"angle"},                     // revolve
    {"scale"},                     // swing
    {},                            // sweep
    {"sections"},                  // oriented_sweep
    {"degree", "parametrization"}, // skin
    {},                            // coons
    {"gordon_u_count"},            // gordon
    {"direction", "param"},        // isocurve
};
static_assert(std::size(operation_parameters) == std::size(construction_names));

const std::string_view all_parameters[] = {
    "angle",           "scale",          "sections",  "degree",
    "parametrization", "gordon_u_count", "direction", "param"};

json refinement_to_json(const RecipeRefinement& r) {
    json j = json::object();
    const bool insert = r.kind == RecipeRefinement::Kind::insert_knot;
    j["refinement"] = insert ? "insert_knot" : "elevate_degree";
    j["direction"] = geom::name_of(r.dir);
    if (insert) j["knot"] = r.t;
    j["times"] = r.times;
    return j;
}

Expected<RecipeRefinement> refinement_from_json(const json& j, const std::string& at) {
    if (auto st = expect_object(j, at, "a refinement"); !st) return st.error();
    const json* kind = find_member(j, "refinement");
    if (!kind) return missing_member(at, "refinement");
    auto name = read_string(*kind, member_path(at, "refinement"), "refinement");
    if (!name) return name.error();
    RecipeRefinement r;
    if (*name == "insert_knot")
        r.kind = RecipeRefinement::Kind::insert_knot;
    else if (*name == "elevate_degree")
        r.kind = RecipeRefinement::Kind::elevate_degree;
    else
        return schema_error("refinement must be insert_knot or elevate_degree, got '" + *name + "'",
                            member_path(at, "refinement"));
    const bool insert = r.kind == RecipeRefinement::Kind::insert_knot;
    if (auto st = insert ? check_members(j, at, "an insert_knot refinement",
                                         {"refinement", "direction", "knot", "times"})
                         : check_members(j, at, "an elevate_degree refinement",
                                         {"refinement", "direction", "times"});
        !st)
        return st.error();
    const json* dir = find_member(j, "direction");
    if (!dir) return missing_member(at, "direction");
    const auto d = enum_value<geom::Dir>(*dir);
    if (!d) return schema_error("direction must be u or v", member_path(at, "direction"));
    r.dir = *d;
    if (insert) {
        const json* knot = find_member(j, "knot");
        if (!knot) return missing_member(at, "knot");
        auto t = read_finite(*knot, member_path(at, "knot"), "knot");
        if (!t) return t.error();
        r.t = *t;
    }
    if (const json* times = find_member(j, "times")) {
        auto n = read_integer(*times, member_path(at, "times"), "times", 1, INT_MAX);
        if (!n) return n.error();
        r.times = static_cast<int>(*n);
    }
    return r;
}

} // namespace

json recipe_to_json(const Recipe& r) {
    json j = json::object();
    j["operation"] = geom::name_of(r.kind);
    j["inputs"] = r.curves;
    switch (r.kind) {
    case Construction::revolve:
        j["angle"] = r.angle;
        break;
    case Construction::swing:
        j["scale"] = r.scale;
        break;
    case Construction::oriented_sweep:
        j["sections"] = r.sections;
        break;
    case Construction::skin:
        j["degree"] = r.skin_degree;
        j["parametrization"] = geom::name_of(r.parametrization);
        break;
    case Construction::gordon:
        j["gordon_u_count"] = r.gordon_u_count;
        break;
    case Construction::isocurve:
        j["direction"] = geom::name_of(r.iso_dir);
        j["param"] = r.iso_t;
        break;
    default:
        break;
    }
    if (!r.refinements.empty()) {
        json list = json::array();
        for (const RecipeRefinement& f : r.refinements) list.push_back(refinement_to_json(f));
        j["refinements"] = std::move(list);
    }
    return j;
}

Expected<Recipe> recipe_from_json(const json& j, const std::string& at) {
    if (auto st = expect_object(j, at, "a construction"); !st) return st.error();
    const json* op = find_member(j, "operation");
    if (!op) return missing_member(at, "operation");
    const std::string op_at = member_path(at, "operation");
    const auto kind = enum_value<Construction>(*op);
    if (!kind) {
        std::string names;
        for (const auto& e : construction_names)
            names += std::string(names.empty() ? "" : ", ") + e.name;
        return schema_error("operation must be one of " + names + ", got " +
                                (op->is_string() ? "'" + op->get<std::string>() + "'"
                                                 : std::string(type_name(*op))),
                            op_at);
    }
    Recipe r;
    r.kind = *kind;
    const auto& takes = operation_parameters[static_cast<std::size_t>(*kind)];
    // A parameter of another operation is named as such (a changed operation left it behind).
    for (std::string_view p : all_parameters)
        if (find_member(j, p) && std::find(takes.begin(), takes.end(), p) == takes.end())
            return schema_error(std::string(p) + " is not a parameter of " + geom::name_of(*kind) +
                                    " (it takes " +
                                    (takes.size() == 0 ? std::string("none")
                                                       : [&] {
                                                             std::string s;
                                                             for (auto t : takes)
                                                                 s += (s.empty() ? "" : ", ") + std::string(t);
                                                             return s;
                                                         }()) +
                                    ")",
                                member_path(at, p));
    std::vector<std::string_view> allowed{"operation", "inputs", "refinements"};
    allowed.insert(allowed.end(), takes.begin(), takes.end());
    if (auto st = check_members(j, at, "a construction", allowed); !st) return st.error();

    const json* inputs = find_member(j, "inputs");
    if (!inputs) return missing_member(at, "inputs");
    const std::string in_at = member_path(at, "inputs");
    if (!inputs->is_array())
        return schema_error(
            std::string("inputs is an array of object ids, got ") + type_name(*inputs), in_at);
    if (inputs->size() > 2 * static_cast<std::size_t>(geom::max_points_per_direction))
        return make_error(geom::ErrorCode::limit,
                          "a construction reads at most " +
                              std::to_string(2 * geom::max_points_per_direction) + " objects",
                          in_at);
    for (std::size_t k = 0; k < inputs->size(); ++k) {
        auto id = read_integer((*inputs)[k], in_at + "/" + std::to_string(k), "an object id", 1,
                               static_cast<std::int64_t>(max_object_id));
        if (!id) return id.error();
        r.curves.push_back(static_cast<std::uint64_t>(*id));
    }
    auto number = [&](std::string_view name, double& out) -> geom::Status {
        const json* v = find_member(j, name);
        if (!v) return geom::Ok{};
        auto x = read_finite(*v, member_path(at, name), name);
        if (!x) return x.error();
        out = *x;
        return geom::Ok{};
    };
    auto integer = [&](std::string_view name, int& out, int lo) -> geom::Status {
        const json* v = find_member(j, name);
        if (!v) return geom::Ok{};
        auto x = read_integer(*v, member_path(at, name), name, lo, INT_MAX);
        if (!x) return x.error();
        out = static_cast<int>(*x);
        return geom::Ok{};
    };
    if (auto st = number("angle", r.angle); !st) return st.error();
    if (auto st = number("scale", r.scale); !st) return st.error();
    if (auto st = integer("sections", r.sections, 1); !st) return st.error();
    if (auto st = integer("degree", r.skin_degree, 0); !st) return st.error();
    if (auto st = integer("gordon_u_count", r.gordon_u_count, 0); !st) return st.error();
    if (auto st = number("param", r.iso_t); !st) return st.error();
    if (const json* p = find_member(j, "parametrization")) {
        const auto m = enum_value<geom::Parametrization>(*p);
        if (!m)
            return schema_error("parametrization must be chord, centripetal or uniform",
                                member_path(at, "parametrization"));
        r.parametrization = *m;
    }
    if (const json* d = find_member(j, "direction")) {
        const auto dir = enum_value<geom::Dir>(*d);
        if (!dir) return schema_error("direction must be u or v", member_path(at, "direction"));
        r.iso_dir = *dir;
    }
    if (const json* list = find_member(j, "refinements")) {
        const std::string list_at = member_path(at, "refinements");
        if (!list->is_array())
            return schema_error(std::string("refinements is an array, got ") + type_name(*list),
                                list_at);
        for (std::size_t k = 0; k < list->size(); ++k) {
            auto f = refinement_from_json((*list)[k], list_at + "/" + std::to_string(k));
            if (!f) return f.error();
            r.refinements.push_back(*f);
        }
    }
    return r;
}

} // namespace isoparm::scene
