// Exercises that check themselves (docs/lessons.md): a starting scene, a task, hints and
// checks over the student's document. The Exercise panel's Check and `isoparm check` grade
// with the same function.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/doc/document.hpp"
#include "core/geom/status.hpp"

namespace isoparm::scene {

inline constexpr const char* exercise_format_name = "isoparm-exercise";
inline constexpr int exercise_format_version = 1;

enum class CheckKind {
    objects,            // how many objects (of a kind)
    type,               // an object's spline type
    degree,             // an object's degree along a direction (or both)
    control_points,     // how many control points along a direction (or in all)
    knot,               // a knot value with at least some multiplicity
    weight,             // one control point's weight in a range
    weights,            // every weight of the object(s) in a range
    no_negative_weight, // no weight below zero anywhere
    position,           // a control point at a position
    point_on_surface,   // points lie on a surface, within a tolerance
    interpolates,       // a curve passes through points, within a tolerance
    border,             // every shared border of the patch groups holds C0 / G1 / C1
    near_shape,         // the object stays within a distance of a target shape, both ways
};
inline constexpr geom::EnumName<CheckKind> check_kind_names[] = {
    {CheckKind::objects, "objects"},
    {CheckKind::type, "type"},
    {CheckKind::degree, "degree"},
    {CheckKind::control_points, "control_points"},
    {CheckKind::knot, "knot"},
    {CheckKind::weight, "weight"},
    {CheckKind::weights, "weights"},
    {CheckKind::no_negative_weight, "no_negative_weight"},
    {CheckKind::position, "position"},
    {CheckKind::point_on_surface, "point_on_surface"},
    {CheckKind::interpolates, "interpolates"},
    {CheckKind::border, "border"},
    {CheckKind::near_shape, "near_shape"},
};
static_assert(geom::in_declaration_order(check_kind_names));
constexpr std::span<const geom::EnumName<CheckKind>> enum_names(CheckKind) {
    return check_kind_names;
}

// What a border must hold (measured on the surfaces: doc::measure_border).
enum class BorderJoin { c0, g1, c1 };

struct Check {
    CheckKind kind = CheckKind::objects;
    std::string path;   // "/checks/3", for messages about the exercise file
    std::string object; // the object's name; "" any object that fits
    std::string label;  // what the check is about, in words (generated when not written)
    std::string hint;   // shown when this is the first check that fails
    std::optional<doc::ObjectKind> object_kind; // objects: count only these
    std::optional<geom::SplineType> type;
    std::optional<geom::Dir> direction;     // nullopt: both (degree, control_points) / u (knot)
    std::optional<double> equals, min, max; // counts, degrees, weights
    int i = -1, j = -1;                     // weight, position
    std::vector<glm::dvec3> points;         // position (one), point_on_surface, interpolates
    double value = 0;                       // knot
    int multiplicity = 1;                   // knot: at least this many
    BorderJoin join = BorderJoin::c0;
    std::optional<std::uint64_t> group; // border: one group ("" all)
    int min_borders = 1;                // border: at least this many shared borders
    double tolerance = 1e-6;            // lengths, relative to nothing: model units
    double angle_tolerance = 0.5;       // border G1: degrees
    std::optional<doc::Object> target;  // near_shape
    double distance = 0;                // near_shape
    int samples = 16;                   // near_shape: samples per direction
};

struct Exercise {
    std::string title, summary;
    std::string task;               // what the student is asked to do (several lines)
    std::vector<std::string> hints; // general hints, in order
    doc::Document start;
    std::string scene_name; // the starting scene's file, "(inline)"
    std::vector<Check> checks;
};

// Reads an exercise strictly (every member and check checked with its JSON Pointer): the
// starting scene ("scene": a path relative to `dir`, or inline) and the targets of
// near_shape checks ("target": an object of the starting scene by name, or {"scene": path,
// "object": name}).
geom::Expected<Exercise> exercise_from_json(const nlohmann::json& j, const std::string& dir);
geom::Expected<Exercise> load_exercise(const std::string& path);

struct CheckResult {
    std::string label; // what was checked
    bool passed = false;
    std::string message; // why it failed, with the values found ("" when it passed)
    std::string hint;    // the check's hint
};

struct Grade {
    std::vector<CheckResult> checks;
    bool passed() const;
    std::size_t passed_count() const;
    // The first check that failed, or null.
    const CheckResult* first_failure() const;
};

// Every check of the exercise on the student's document, in order.
Grade grade(const Exercise& exercise, const doc::Document& submission);

} // namespace isoparm::scene
