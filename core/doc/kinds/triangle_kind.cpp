// The triangle kind's facts: JSON members, validation, control points b_ijk, export forms.
#include "core/doc/kinds/triangle_kind.hpp"

#include <nlohmann/json.hpp>

#include "core/doc/kinds/kind_common.hpp"
#include "core/json/fields.hpp"
#include "core/json/shapes.hpp"

namespace isoparm::doc {

using geom::ErrorCode;
using geom::make_error;
using nlohmann::json;

geom::Expected<TriangleObject> read_kind(std::type_identity<TriangleObject>, const json& j,
                                         const std::string& at) {
    return detail::read_geometry<TriangleObject>(
        j, at, "triangle", [](const json& v) { return json_io::triangle_from_json(v); });
}

void kind_to_json(const TriangleObject& t, json& out) {
    out["triangle"] = json_io::triangle_to_json(t.patch);
}

geom::Expected<std::pair<int, int>>
selected_point_from_json(const TriangleObject& t, const json& point, const std::string& at) {
    const int n = t.patch.degree;
    auto ij = detail::point_pair_from_json(
        point, at, "a triangle's selected point is [i, j] (b_ijk, k = n - i - j)", n, n);
    if (!ij) return ij;
    const int idx[2] = {ij->first, ij->second};
    if (idx[0] + idx[1] > n)
        return json_io::schema_error(
            "a degree " + std::to_string(n) +
                " triangle's point [i, j] needs i + j <= " + std::to_string(n) + ", got [" +
                std::to_string(idx[0]) + ", " + std::to_string(idx[1]) + "]",
            at + "/1");
    return std::pair{idx[0], idx[1]};
}

geom::Status validate(const TriangleObject& t) {
    // Non-rational triangles keep unit weights, as the type tag says of surfaces.
    if (!t.patch.rational)
        for (std::size_t k = 0; k < t.patch.weights.size(); ++k)
            if (t.patch.weights[k] != 1.0)
                return make_error(ErrorCode::weights,
                                  "a triangle_bezier has unit weights; weight " +
                                      std::to_string(k) + " is " +
                                      geom::format_number(t.patch.weights[k]),
                                  "/weights/" + std::to_string(k));
    return geom::validate_triangle(t.patch);
}

ISOPARM_NET_FACTS(TriangleObject, patch)
bool is_rational(const TriangleObject& t) {
    return t.patch.rational;
}

bool has_control_point(const TriangleObject& t, int i, int j) {
    return i >= 0 && j >= 0 && i + j <= t.patch.degree;
}

geom::Expected<std::size_t> point_index(const TriangleObject& t, int i, int j) {
    const int n = t.patch.degree;
    if (i < 0 || i > n) return detail::index_out_of_range("i", i, n + 1, "/i");
    if (j < 0 || j > n - i)
        return make_error(ErrorCode::schema,
                          "control point b_ijk of a degree " + std::to_string(n) +
                              " triangle needs 0 <= j <= n - i = " + std::to_string(n - i) +
                              ", got j = " + std::to_string(j),
                          "/j");
    return static_cast<std::size_t>(geom::TrianglePatch::index(n, i, j));
}

std::string point_label(const TriangleObject& t, PointName name, int i, int j) {
    if (name == PointName::indexed)
        return "b" + std::to_string(i) + "," + std::to_string(j) + "," +
               std::to_string(t.patch.degree - i - j);
    return detail::triangle_point_label(name == PointName::weight ? 'w' : 'b', t.patch.degree, i,
                                        j);
}

std::string unit_weights_rule(const TriangleObject&) {
    return "triangle_bezier has unit weights; make it rational (rational_triangle_bezier)";
}

std::optional<Box> bounds(const TriangleObject& t) {
    return detail::box_of(t.patch.points);
}

void translate(TriangleObject& t, const glm::dvec3& d) {
    for (glm::dvec3& p : control_points(t)) p += d;
}

ExactForm exact_form(const TriangleObject&) {
    return NoForm{"IGES, STEP and OBJ free-form have no triangular Bezier patch (export a mesh: "
                  "STL, PLY, glTF or OBJ mesh)"};
}

// `samples` points along each edge: (samples - 1)^2 triangles.
geom::Expected<MeshForm> mesh_form(const TriangleObject& t, int samples) {
    return MeshForm{geom::tessellate_triangle(t.patch, samples - 1)};
}

// samples points along each edge: samples (samples + 1) / 2 in the triangle.
double mesh_vertices(const TriangleObject&, int samples) {
    return double(samples) * (samples + 1) / 2;
}

std::size_t heap_bytes(const TriangleObject& t) {
    return t.patch.weights.size() * sizeof(double) + t.patch.points.size() * sizeof(glm::dvec3);
}

bool same_bits(const TriangleObject& a, const TriangleObject& b) {
    const geom::TrianglePatch& t = a.patch;
    const geom::TrianglePatch& u = b.patch;
    return t.rational == u.rational && t.degree == u.degree &&
           detail::bit_equal(t.points, u.points) && detail::bit_equal(t.weights, u.weights);
}

} // namespace isoparm::doc
