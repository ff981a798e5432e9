// What every kind of object answers: the list a new kind's file must fill in (the concept
// KindFacts below), and the types those answers use.
//
// One kind, one place: each kind of object (surface, curve, implicit surface, triangular
// patch) is a struct in its own file under core/doc/kinds/, beside the free functions that
// answer for it (found by argument-dependent lookup). The document's kind-dependent code
// dispatches with std::visit over doc::Shape to those functions, so a kind that lacks one does
// not build. Code that serves only some kinds asks for them by name (Object::surface(),
// curve(), ..., an allow-list) and refuses the others with refuse_kind(), which names the
// object's real kind. Its view side (drawing, picking, meshes) is ui/view/kinds/.
#pragma once

#include <concepts>
#include <cstddef>
#include <glm/vec3.hpp>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

#include "core/geom/enum_names.hpp"
#include "core/geom/status.hpp"
#include "core/geom/tessellate.hpp"
#include "core/geom/trim/trim.hpp"
#include "core/geom/types.hpp"

namespace isoparm::doc {

// What kind of object a shape is. doc::Shape lists its alternatives in this order.
enum class ObjectKind { surface, curve, implicit, triangle };
// Scene files write "kind": "implicit"; messages and panels say "implicit surface".
inline constexpr geom::EnumName<ObjectKind> object_kind_names[] = {
    {ObjectKind::surface, "surface"},
    {ObjectKind::curve, "curve"},
    {ObjectKind::implicit, "implicit", "implicit surface"},
    {ObjectKind::triangle, "triangle", "triangular patch"},
};
static_assert(geom::in_declaration_order(object_kind_names));
constexpr std::span<const geom::EnumName<ObjectKind>> enum_names(ObjectKind) {
    return object_kind_names;
}
// "surface", "curve", "implicit surface": how messages and panels name the kind (label_of).
inline const char* kind_name(ObjectKind kind) {
    return geom::label_of(kind);
}
// "a surface", "an implicit surface", "a triangular patch": the kind in a sentence.
std::string kind_noun(ObjectKind kind);
// "a triangle", "an implicit": the kind as files name it, in a sentence ("a triangle object").
std::string kind_file_noun(ObjectKind kind);

// The box around an object (its control points, or an implicit surface's bounds).
struct Box {
    glm::dvec3 lo{0}, hi{0};
};

// How an object goes into an exchange file: its exact geometry (IGES, STEP, OBJ free-form) or
// a mesh (STL, PLY, glTF, OBJ mesh), or why it has no such form (`why` ends the sentence
// "'Hat' (id 3): ...").
struct NoForm {
    std::string why;
};
using ExactForm = std::variant<NoForm, geom::Curve, geom::Surface, geom::TrimmedSurface>;
using MeshForm = std::variant<NoForm, geom::Mesh>;

// A control point, or its weight, as labels name it ("P23" and "w23"); indexed: with its
// indices apart, as scripts' expectations name it ("P2,3", "b1,0,2").
enum class PointName { position, weight, indexed };

// The overload set of a std::visit written in place: visit(overloaded{[](const A&) {...},
// [](const B&) {...}}, shape). List every kind (no `auto` catch-all), so that a new kind
// stops the build there.
template <class... F> struct overloaded : F... { using F::operator()...; };
template <class... F> overloaded(F...) -> overloaded<F...>;

// Every fact a kind K answers. `K::kind` is its ObjectKind; `K::shape_members` the members of
// its JSON form beside "kind" (one is its geometry, named as the kind: "surface": {...});
// `K::in_patch_groups` whether its objects may carry "patch_group" (subpatches);
// `K::constructed` whether a recipe builds objects of the kind (they may carry "construction").
template <class K>
concept KindFacts = requires(K& k, const K& c, int i, int j, PointName name, int samples,
                             const nlohmann::json& json, nlohmann::json& out, const std::string& at,
                             const glm::dvec3& d) {
    { K::kind } -> std::convertible_to<ObjectKind>;
    { K::shape_members } -> std::convertible_to<std::span<const std::string_view>>;
    { K::in_patch_groups } -> std::convertible_to<bool>;
    { K::constructed } -> std::convertible_to<bool>;
    // JSON: the kind's members (json: the object or shape holding them, at: its path) in
    // both directions, and a selected control point ("point": [i, j] or [i]).
    { read_kind(std::type_identity<K>{}, json, at) } -> std::same_as<geom::Expected<K>>;
    { kind_to_json(c, out) } -> std::same_as<void>; // out: the JSON object to write into
    { selected_point_from_json(c, json, at) } -> std::same_as<geom::Expected<std::pair<int, int>>>;
    // The document's own rules (geometry, size caps, finite numbers); paths under the shape.
    { validate(c) } -> std::same_as<geom::Status>;
    // Control points and their weights (none for a kind without them), and how they are named.
    { control_points(k) } -> std::same_as<std::span<glm::dvec3>>;
    { control_points(c) } -> std::same_as<std::span<const glm::dvec3>>;
    { control_weights(k) } -> std::same_as<std::span<double>>;
    { control_weights(c) } -> std::same_as<std::span<const double>>;
    { is_rational(c) } -> std::same_as<bool>;
    { has_control_point(c, i, j) } -> std::same_as<bool>;
    // The index of control point (i, j) in control_points(), or why there is none
    // (`schema` at "/i" or "/j").
    { point_index(c, i, j) } -> std::same_as<geom::Expected<std::size_t>>;
    // "P23", "P4", "b210" (the point), "w23", "w4", "w210" (its weight), "P2,3", "b2,1,0"
    // (indexed).
    { point_label(c, name, i, j) } -> std::same_as<std::string>;
    // Why a weight other than 1 is refused here (a non-rational object keeps unit weights).
    { unit_weights_rule(c) } -> std::same_as<std::string>;
    { bounds(c) } -> std::same_as<std::optional<Box>>;
    // The object moved by d (a new object placed beside the scene).
    { translate(k, d) } -> std::same_as<void>;
    { exact_form(c) } -> std::same_as<ExactForm>;
    // samples: points along each edge of a surface's tessellation.
    { mesh_form(c, samples) } -> std::same_as<geom::Expected<MeshForm>>;
    // The vertices its mesh form takes at `samples`, known before tessellating (an export's
    // memory budget); 0 for a kind without a mesh or with its own budget.
    { mesh_vertices(c, samples) } -> std::same_as<double>;
    // Approximate heap bytes, for the history's memory bound; and bit-for-bit equality.
    { heap_bytes(c) } -> std::same_as<std::size_t>;
    { same_bits(c, c) } -> std::same_as<bool>;
};

// Declares the facts KindFacts asks of kind K, each defined in K's own file
// (kinds/<kind>_kind.cpp): a kind's header says ISOPARM_KIND_FACTS(K); after its struct, and a
// fact left undefined there fails the link, one left out of the concept fails the build.
#define ISOPARM_KIND_FACTS(K)                                                                      \
    geom::Expected<K> read_kind(std::type_identity<K>, const nlohmann::json& j,                    \
                                const std::string& at);                                            \
    void kind_to_json(const K& k, nlohmann::json& out);                                            \
    geom::Expected<std::pair<int, int>> selected_point_from_json(                                  \
        const K& k, const nlohmann::json& point, const std::string& at);                           \
    geom::Status validate(const K& k);                                                             \
    std::span<glm::dvec3> control_points(K& k);                                                    \
    std::span<const glm::dvec3> control_points(const K& k);                                        \
    std::span<double> control_weights(K& k);                                                       \
    std::span<const double> control_weights(const K& k);                                           \
    bool is_rational(const K& k);                                                                  \
    bool has_control_point(const K& k, int i, int j);                                              \
    geom::Expected<std::size_t> point_index(const K& k, int i, int j);                             \
    std::string point_label(const K& k, PointName name, int i, int j);                             \
    std::string unit_weights_rule(const K& k);                                                     \
    std::optional<Box> bounds(const K& k);                                                         \
    void translate(K& k, const glm::dvec3& d);                                                     \
    ExactForm exact_form(const K& k);                                                              \
    geom::Expected<MeshForm> mesh_form(const K& k, int samples);                                   \
    double mesh_vertices(const K& k, int samples);                                                 \
    std::size_t heap_bytes(const K& k);                                                            \
    bool same_bits(const K& a, const K& b);                                                        \
    static_assert(KindFacts<K>)

} // namespace isoparm::doc
