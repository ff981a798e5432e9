// The implicit kind: a surface f(x, y, z) = 0 from an expression, polygonized in a box, and
// every fact the document asks of it (kind_facts.hpp). It has no control points.
#pragma once

#include <array>
#include <vector>

#include "core/doc/kinds/kind_facts.hpp"

namespace isoparm::doc {

struct ImplicitObject {
    std::string expression;
    std::vector<std::string> parameter_names;
    std::vector<double> parameter_values;
    glm::dvec3 lo{-1, -1, -1}, hi{1, 1, 1};
    double cell = 0.05;

    static constexpr ObjectKind kind = ObjectKind::implicit;
    static constexpr std::array<std::string_view, 1> shape_members{"implicit"};
    static constexpr bool in_patch_groups = false;
    static constexpr bool constructed = false;
};

geom::Expected<ImplicitObject> read_kind(std::type_identity<ImplicitObject>,
                                         const nlohmann::json& j, const std::string& at);
void kind_to_json(const ImplicitObject& f, nlohmann::json& out);
geom::Expected<std::pair<int, int>> selected_point_from_json(const ImplicitObject& f,
                                                             const nlohmann::json& point,
                                                             const std::string& at);
geom::Status validate(const ImplicitObject& f);
std::span<glm::dvec3> control_points(ImplicitObject& f);
std::span<const glm::dvec3> control_points(const ImplicitObject& f);
std::span<double> control_weights(ImplicitObject& f);
std::span<const double> control_weights(const ImplicitObject& f);
bool is_rational(const ImplicitObject& f);
bool has_control_point(const ImplicitObject& f, int i, int j);
geom::Expected<std::size_t> point_index(const ImplicitObject& f, int i, int j);
std::string point_label(const ImplicitObject& f, PointName name, int i, int j);
std::string unit_weights_rule(const ImplicitObject& f);
std::optional<Box> bounds(const ImplicitObject& f);
// Moved with its formula (in absolute coordinates: moving its box alone would cut the field):
// its box moves by d and x, y, z become (x - d.x), ... (translated).
void translate(ImplicitObject& f, const glm::dvec3& d);
ExactForm exact_form(const ImplicitObject& f);
geom::Expected<MeshForm> mesh_form(const ImplicitObject& f, int samples);
double mesh_vertices(const ImplicitObject& f, int samples);
std::size_t heap_bytes(const ImplicitObject& f);
bool same_bits(const ImplicitObject& a, const ImplicitObject& b);

static_assert(KindFacts<ImplicitObject>);

// An implicit surface moved by d: its box moved and every x, y, z of its expression replaced
// by (x - d.x), (y - d.y), (z - d.z) (a zero component leaves its coordinate as it is).
ImplicitObject translated(const ImplicitObject& f, const glm::dvec3& d);

} // namespace isoparm::doc
