// The surface kind: a tensor-product Bezier, rational Bezier, B-spline or NURBS surface, and
// every fact the document asks of it (kind_facts.hpp).
#pragma once

#include <array>

#include "core/doc/kinds/kind_facts.hpp"

namespace isoparm::doc {

struct SurfaceObject {
    geom::Surface surface;

    static constexpr ObjectKind kind = ObjectKind::surface;
    static constexpr std::array<std::string_view, 1> shape_members{"surface"};
    static constexpr bool in_patch_groups = true; // split surfaces share a domain
    static constexpr bool constructed = true; // a recipe builds surfaces
};

geom::Expected<SurfaceObject> read_kind(std::type_identity<SurfaceObject>, const nlohmann::json& j,
                                        const std::string& at);
void kind_to_json(const SurfaceObject& s, nlohmann::json& out);
geom::Expected<std::pair<int, int>> selected_point_from_json(const SurfaceObject& s,
                                                             const nlohmann::json& point,
                                                             const std::string& at);
geom::Status validate(const SurfaceObject& s);
std::span<glm::dvec3> control_points(SurfaceObject& s);
std::span<const glm::dvec3> control_points(const SurfaceObject& s);
std::span<double> control_weights(SurfaceObject& s);
std::span<const double> control_weights(const SurfaceObject& s);
bool is_rational(const SurfaceObject& s);
bool has_control_point(const SurfaceObject& s, int i, int j);
geom::Expected<std::size_t> point_index(const SurfaceObject& s, int i, int j);
std::string point_label(const SurfaceObject& s, PointName name, int i, int j);
std::string unit_weights_rule(const SurfaceObject& s);
std::optional<Box> bounds(const SurfaceObject& s);
void translate(SurfaceObject& s, const glm::dvec3& d);
ExactForm exact_form(const SurfaceObject& s);
geom::Expected<MeshForm> mesh_form(const SurfaceObject& s, int samples);
double mesh_vertices(const SurfaceObject& s, int samples);
std::size_t heap_bytes(const SurfaceObject& s);
bool same_bits(const SurfaceObject& a, const SurfaceObject& b);

static_assert(KindFacts<SurfaceObject>);

} // namespace isoparm::doc
