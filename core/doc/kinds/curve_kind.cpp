// The curve kind's facts: JSON members (plane, knot mode), validation, control points, export
// forms.
#include "core/doc/kinds/curve_kind.hpp"

#include <nlohmann/json.hpp>

#include "core/doc/kinds/kind_common.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/refine_within_limits.hpp"
#include "core/geom/reshape.hpp"
#include "core/geom/validate.hpp"
#include "core/json/fields.hpp"
#include "core/json/shapes.hpp"

namespace isoparm::doc {

using geom::ErrorCode;
using geom::make_error;
using nlohmann::json;

namespace {

// An optional member named by E's table ("plane": "xz").
template <class E>
geom::Status read_named(const json& j, const std::string& at, const char* member, E& out) {
    const auto it = j.find(member);
    if (it == j.end()) return geom::Ok{};
    const std::string path = at + "/" + member;
    auto text = json_io::read_string(*it, path, member);
    if (!text) return text.error();
    const std::optional<E> named = geom::parse_name<E>(*text);
    if (!named)
        return json_io::schema_error(std::string(member) + " must be " + geom::names_list<E>() +
                                         ", got '" + *text + "'",
                                     path);
    out = *named;
    return geom::Ok{};
}

} // namespace

geom::Expected<CurveObject> read_kind(std::type_identity<CurveObject>, const json& j,
                                      const std::string& at) {
    CurveObject c;
    if (auto st = read_named(j, at, "plane", c.plane); !st) return st.error();
    if (auto st = read_named(j, at, "knot_mode", c.knot_mode); !st) return st.error();
    auto g = json_io::curve_from_json(j.at("curve"));
    if (!g) return g.error().under(at + "/curve");
    c.curve = std::move(g).value();
    // The designer edits a closed curve's polygon and closes it again: a curve that is not
    // closed that way would lose its last p points at the first edit.
    if (c.knot_mode == CurveKnotMode::closed && !geom::is_closed_periodic(c.curve))
        return json_io::schema_error("knot_mode closed needs the curve closed as the curve "
                                     "designer closes it: knots (k - p) / n and the last p control "
                                     "points equal to the first p",
                                     at + "/knot_mode");
    return c;
}

void kind_to_json(const CurveObject& c, json& out) {
    out["plane"] = geom::name_of(c.plane);
    // Custom (the default) is omitted, so older scenes save back unchanged.
    if (c.knot_mode != CurveKnotMode::custom) out["knot_mode"] = geom::name_of(c.knot_mode);
    out["curve"] = json_io::curve_to_json(c.curve);
}

geom::Expected<std::pair<int, int>>
selected_point_from_json(const CurveObject& c, const json& point, const std::string& at) {
    if (!point.is_array() || point.size() != 1)
        return json_io::schema_error("a curve's selected point is [i]", at);
    auto v =
        json_io::read_integer(point[0], at + "/0", "a control point index", 0, c.curve.count() - 1);
    if (!v) return v.error();
    return std::pair{static_cast<int>(*v), -1};
}

geom::Status validate(const CurveObject& c) {
    const geom::Curve& g = c.curve;
    if (g.weights.size() != g.points.size())
        return make_error(
            ErrorCode::weights,
            "a curve needs one weight per control point: " + std::to_string(g.points.size()) +
                " points, " + std::to_string(g.weights.size()) + " weights",
            "/weights");
    if (auto st = geom::check_net_size(g, "/points"); !st) return st;
    if (auto st = detail::finite_points(
            g.points, [](std::size_t k) { return "/points/" + std::to_string(k); });
        !st)
        return st;
    return geom::validate_curve(g);
}

ISOPARM_NET_FACTS(CurveObject, curve)
bool is_rational(const CurveObject& c) {
    return geom::is_rational(c.curve.type);
}

bool has_control_point(const CurveObject& c, int i, int j) {
    return i >= 0 && i < c.curve.count() && j < 0;
}

geom::Expected<std::size_t> point_index(const CurveObject& c, int i, int j) {
    const geom::Curve& g = c.curve;
    if (i < 0 || i >= g.count()) return detail::index_out_of_range("i", i, g.count(), "/i");
    if (j != -1 && j != 0)
        return make_error(ErrorCode::schema,
                          "a curve's control points have one index; j must be -1 (or 0), got " +
                              std::to_string(j),
                          "/j");
    return static_cast<std::size_t>(i);
}

std::string point_label(const CurveObject&, PointName name, int i, int j) {
    if (name == PointName::indexed) return detail::indexed_label('P', i, j);
    return detail::point_label(name == PointName::weight ? 'w' : 'P', i, -1);
}

std::string unit_weights_rule(const CurveObject& c) {
    return std::string(geom::spline_type_name(c.curve.type)) +
           " curve has unit weights; make it rational (nurbs or rational_bezier)";
}

std::optional<Box> bounds(const CurveObject& c) {
    return detail::box_of(c.curve.points);
}

void translate(CurveObject& c, const glm::dvec3& d) {
    for (glm::dvec3& p : control_points(c)) p += d;
}

ExactForm exact_form(const CurveObject& c) {
    return c.curve;
}

geom::Expected<MeshForm> mesh_form(const CurveObject&, int) {
    return MeshForm{NoForm{"a curve has no mesh (export IGES, STEP or OBJ free-form)"}};
}

double mesh_vertices(const CurveObject&, int) {
    return 0; // no mesh (mesh_form)
}

std::size_t heap_bytes(const CurveObject& c) {
    const geom::Curve& g = c.curve;
    return (g.knots.size() + g.weights.size()) * sizeof(double) +
           g.points.size() * sizeof(glm::dvec3);
}

bool same_bits(const CurveObject& a, const CurveObject& b) {
    return a.plane == b.plane && a.knot_mode == b.knot_mode &&
           detail::same_curve_bits(a.curve, b.curve);
}

} // namespace isoparm::doc
