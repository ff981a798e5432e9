// The triangle kind: a triangular Bezier patch (the paper's future work; Farin ch. 17), its
// control point b_ijk addressed as (i, j), k = n - i - j (the selection uses the same pair),
// and every fact the document asks of it (kind_facts.hpp).
#pragma once

#include <array>

#include "core/doc/kinds/kind_facts.hpp"
#include "core/geom/triangle.hpp"

namespace isoparm::doc {

struct TriangleObject {
    geom::TrianglePatch patch;

    static constexpr ObjectKind kind = ObjectKind::triangle;
    static constexpr std::array<std::string_view, 1> shape_members{"triangle"};
    static constexpr bool in_patch_groups = false;
    static constexpr bool constructed = false;
};

geom::Expected<TriangleObject> read_kind(std::type_identity<TriangleObject>,
                                         const nlohmann::json& j, const std::string& at);
void kind_to_json(const TriangleObject& t, nlohmann::json& out);
geom::Expected<std::pair<int, int>> selected_point_from_json(const TriangleObject& t,
                                                             const nlohmann::json& point,
                                                             const std::string& at);
geom::Status validate(const TriangleObject& t);
std::span<glm::dvec3> control_points(TriangleObject& t);
std::span<const glm::dvec3> control_points(const TriangleObject& t);
std::span<double> control_weights(TriangleObject& t);
std::span<const double> control_weights(const TriangleObject& t);
bool is_rational(const TriangleObject& t);
bool has_control_point(const TriangleObject& t, int i, int j);
geom::Expected<std::size_t> point_index(const TriangleObject& t, int i, int j);
std::string point_label(const TriangleObject& t, PointName name, int i, int j);
std::string unit_weights_rule(const TriangleObject& t);
std::optional<Box> bounds(const TriangleObject& t);
void translate(TriangleObject& t, const glm::dvec3& d);
ExactForm exact_form(const TriangleObject& t);
geom::Expected<MeshForm> mesh_form(const TriangleObject& t, int samples);
double mesh_vertices(const TriangleObject& t, int samples);
std::size_t heap_bytes(const TriangleObject& t);
bool same_bits(const TriangleObject& a, const TriangleObject& b);

static_assert(KindFacts<TriangleObject>);

} // namespace isoparm::doc
