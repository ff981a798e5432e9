// The surface kind's facts: JSON members (the surface and its trim), validation, control
// points, export forms.
#include "core/doc/kinds/surface_kind.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/doc/kinds/kind_common.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/refine_within_limits.hpp"
#include "core/geom/trim/trim_validate.hpp"
#include "core/geom/trim/trimmed_tessellator.hpp"
#include "core/geom/validate.hpp"
#include "core/json/fields.hpp"
#include "core/json/shapes.hpp"
#include "core/json/trim_json.hpp"

namespace isoparm::doc {

using geom::ErrorCode;
using geom::make_error;
using nlohmann::json;

geom::Expected<SurfaceObject> read_kind(std::type_identity<SurfaceObject>, const json& j,
                                        const std::string& at) {
    auto s = detail::read_geometry<SurfaceObject>(
        j, at, "surface", [](const json& v) { return json_io::surface_from_json(v); });
    if (!s) return s;
    // Whether the loops fit the domain is validate's (the document's rules, on every path in).
    if (const auto t = j.find("trim"); t != j.end()) {
        auto trim = json_io::trim_from_json(*t);
        if (!trim) return trim.error().under(at + "/trim");
        s->trim = std::move(trim).value();
    }
    return s;
}

void kind_to_json(const SurfaceObject& s, json& out) {
    out["surface"] = json_io::surface_to_json(s.surface);
    if (!s.trim.empty()) out["trim"] = json_io::trim_to_json(s.trim);
}

geom::Expected<std::pair<int, int>>
selected_point_from_json(const SurfaceObject& s, const json& point, const std::string& at) {
    return detail::point_pair_from_json(point, at, "a surface's selected point is [i, j]",
                                        s.surface.n_u - 1, s.surface.n_v - 1);
}

geom::Status validate(const SurfaceObject& s) {
    const geom::Surface& g = s.surface;
    // Shape consistency first, so validate_surface only ever sees coherent arrays.
    if (g.n_u < 0 || g.n_v < 0 ||
        g.points.size() != static_cast<std::size_t>(g.n_u) * static_cast<std::size_t>(g.n_v))
        return make_error(ErrorCode::schema,
                          "a surface of " + std::to_string(g.n_u) + " x " + std::to_string(g.n_v) +
                              " control points needs as many points",
                          "/points");
    if (g.weights.size() != g.points.size())
        return make_error(
            ErrorCode::weights,
            "a surface needs one weight per control point: " + std::to_string(g.points.size()) +
                " points, " + std::to_string(g.weights.size()) + " weights",
            "/weights");
    if (auto st = geom::check_net_size(g, "/points"); !st) return st;
    if (auto st = detail::finite_points(g.points,
                                        [&](std::size_t k) {
                                            return "/points/" + std::to_string(k / g.n_v) + "/" +
                                                   std::to_string(k % g.n_v);
                                        });
        !st)
        return st;
    if (auto st = geom::validate_surface(g); !st) return st;
    if (s.trim.empty()) return geom::Ok{};
    geom::Status st = geom::validate_trim(s.trim, geom::domain(g));
    if (!st) return st.error().under("/trim");
    return st;
}

ISOPARM_NET_FACTS(SurfaceObject, surface)
bool is_rational(const SurfaceObject& s) {
    return geom::is_rational(s.surface.type);
}

bool has_control_point(const SurfaceObject& s, int i, int j) {
    return i >= 0 && i < s.surface.n_u && j >= 0 && j < s.surface.n_v;
}

geom::Expected<std::size_t> point_index(const SurfaceObject& s, int i, int j) {
    const geom::Surface& g = s.surface;
    if (i < 0 || i >= g.n_u) return detail::index_out_of_range("i", i, g.n_u, "/i");
    if (j < 0 || j >= g.n_v) return detail::index_out_of_range("j", j, g.n_v, "/j");
    return static_cast<std::size_t>(g.index(i, j));
}

std::string point_label(const SurfaceObject&, PointName name, int i, int j) {
    if (name == PointName::indexed) return detail::indexed_label('P', i, j);
    return detail::point_label(name == PointName::weight ? 'w' : 'P', i, j);
}

std::string unit_weights_rule(const SurfaceObject& s) {
    return std::string(geom::spline_type_name(s.surface.type)) +
           " surface has unit weights; make it rational (nurbs or rational_bezier)";
}

std::optional<Box> bounds(const SurfaceObject& s) {
    return detail::box_of(s.surface.points);
}

void translate(SurfaceObject& s, const glm::dvec3& d) {
    for (glm::dvec3& p : control_points(s)) p += d;
}

// A trimmed surface goes out as a trimmed face (IGES 144, STEP ADVANCED_FACE with its bounds).
ExactForm exact_form(const SurfaceObject& s) {
    if (!s.trim.empty()) return geom::TrimmedSurface{s.surface, s.trim};
    return s.surface;
}

geom::Expected<MeshForm> mesh_form(const SurfaceObject& s, int samples) {
    if (!s.trim.empty())
        return MeshForm{geom::tessellate_trimmed(s.surface, s.trim, samples, samples)};
    return MeshForm{geom::tessellate(s.surface, samples, samples)};
}

// A samples x samples grid (a trim keeps part of it and adds its loops' points).
double mesh_vertices(const SurfaceObject&, int samples) {
    return double(samples) * samples;
}

namespace {

std::size_t curve_bytes(const geom::Curve& c) {
    return (c.knots.size() + c.weights.size()) * sizeof(double) +
           c.points.size() * sizeof(glm::dvec3) + sizeof(geom::Curve);
}

std::size_t trim_bytes(const geom::Trim& t) {
    std::size_t bytes = 0;
    for (int k = 0; k < t.loop_count(); ++k)
        for (const geom::Curve& c : t.loop(k).curves) bytes += curve_bytes(c);
    return bytes + t.holes.size() * sizeof(geom::TrimLoop);
}

bool same_loop_bits(const geom::TrimLoop& a, const geom::TrimLoop& b) {
    return std::equal(a.curves.begin(), a.curves.end(), b.curves.begin(), b.curves.end(),
                      detail::same_curve_bits);
}

bool same_trim_bits(const geom::Trim& a, const geom::Trim& b) {
    if (a.outer.has_value() != b.outer.has_value()) return false;
    if (a.outer && !same_loop_bits(*a.outer, *b.outer)) return false;
    return std::equal(a.holes.begin(), a.holes.end(), b.holes.begin(), b.holes.end(),
                      same_loop_bits);
}

} // namespace

std::size_t heap_bytes(const SurfaceObject& s) {
    const geom::Surface& g = s.surface;
    return (g.knots_u.size() + g.knots_v.size() + g.weights.size()) * sizeof(double) +
           g.points.size() * sizeof(glm::dvec3) + trim_bytes(s.trim);
}

bool same_bits(const SurfaceObject& x, const SurfaceObject& y) {
    const geom::Surface& a = x.surface;
    const geom::Surface& b = y.surface;
    return a.type == b.type && a.degree_u == b.degree_u && a.degree_v == b.degree_v &&
           a.n_u == b.n_u && a.n_v == b.n_v && detail::bit_equal(a.knots_u, b.knots_u) &&
           detail::bit_equal(a.knots_v, b.knots_v) && detail::bit_equal(a.points, b.points) &&
           detail::bit_equal(a.weights, b.weights) && same_trim_bits(x.trim, y.trim);
}

} // namespace isoparm::doc
