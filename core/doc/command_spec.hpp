// Commands as data: every document edit as a plain value (its name and its arguments), from
// which the command is built (make_command) and which an applied command gives back
// (Command::spec). Scripts and recordings store exactly this; core/scene/command_json.hpp
// reads and writes it as JSON (docs/commands.md).
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/doc/document.hpp"
#include "core/doc/point_set.hpp"

namespace isoparm::doc {

class Command;

struct AddObjectSpec {
    Object object; // id 0: the document assigns one
};
struct RemoveObjectSpec {
    std::uint64_t id = 0;
};
struct RenameObjectSpec {
    std::uint64_t id = 0;
    std::string name;
};
struct SetVisibleSpec {
    std::uint64_t id = 0;
    bool visible = true;
};
// The object's shape becomes `shape` (same kind of object). Consecutive edits of one object
// with the same non-empty merge_key are one undo step (a drag of an implicit's parameter).
struct EditShapeSpec {
    std::uint64_t id = 0;
    Shape shape;
    std::string label;
    std::string merge_key;
};
// A control point's position, its weight, or both (curves: j = -1).
struct EditPointSpec {
    std::uint64_t id = 0;
    int i = 0, j = -1;
    std::optional<glm::dvec3> position;
    std::optional<double> weight;
};
// Knots k .. k + count - 1 (one run of equal knots) move to value.
struct MoveKnotSpec {
    std::uint64_t id = 0;
    geom::Dir dir = geom::Dir::u;
    int k = 0, count = 1;
    double value = 0;
};
struct TransformSpec {
    std::uint64_t id = 0;
    glm::dmat4 matrix{1.0};
    std::string label; // empty: "Transform <name>"
};
struct InsertKnotSpec {
    std::uint64_t id = 0;
    geom::Dir dir = geom::Dir::u;
    double t = 0;
    int times = 1;
};
struct ElevateDegreeSpec {
    std::uint64_t id = 0;
    geom::Dir dir = geom::Dir::u;
    int times = 1;
};
struct SplitSpec {
    std::uint64_t id = 0;
    geom::Dir dir = geom::Dir::u;
    double t = 0;
};
struct ConformBordersSpec {
    std::uint64_t group = 0;
};
struct SetColorsSpec {
    Colors colors;
};
struct InsertCurvePointSpec {
    std::uint64_t id = 0;
    int i = 0;
    glm::dvec3 position{0.0};
};
struct DeleteCurvePointSpec {
    std::uint64_t id = 0;
    int i = 0;
};
struct MoveCurvePointSpec {
    std::uint64_t id = 0;
    int i = 0;
    glm::dvec3 position{0.0};
};
struct SetCurveDegreeSpec {
    std::uint64_t id = 0;
    int degree = 1;
};
struct SetCurveKnotModeSpec {
    std::uint64_t id = 0;
    CurveKnotMode mode = CurveKnotMode::clamped_uniform;
};
struct SetCurvePlaneSpec {
    std::uint64_t id = 0;
    CurvePlane plane = CurvePlane::xy;
    bool carry_points = false;
};
struct MakeCompatibleSpec {
    std::vector<std::uint64_t> ids;
};
// The toolbox's shape changes (commands_reshape.cpp).
struct RemoveKnotSpec {
    std::uint64_t id = 0;
    geom::Dir dir = geom::Dir::u;
    double t = 0;
    int times = 1;
    double tolerance = 0;
};
struct ReduceDegreeSpec {
    std::uint64_t id = 0;
    geom::Dir dir = geom::Dir::u;
    double tolerance = 0;
};
struct SplitKnotSpec {
    std::uint64_t id = 0;
    geom::Dir dir = geom::Dir::u;
    double t = 0;
    std::optional<double> delta;
};
struct CloseSpec {
    std::uint64_t id = 0;
    geom::Dir dir = geom::Dir::u;
};
// Several new objects as one undo step (an import); label: the undo label, may be empty.
struct AddObjectsSpec {
    std::vector<Object> objects;
    std::string label;
};
struct ConvertSpec {
    std::uint64_t id = 0;
    geom::SplineType to = geom::SplineType::nurbs;
    bool reset_weights = false;
};
// A multiresolution edit (commands_multires.hpp): at coarse `level` (surfaces: `level` along
// u and `level_v` along v), coarse point i (j) moves to `position` keeping the detail, or the
// detail finer than the level is multiplied by `detail_scale` keeping the coarse points.
struct MultiresEditSpec {
    std::uint64_t id = 0;
    int level = 0;
    std::optional<int> level_v;
    int i = 0, j = -1;
    std::optional<glm::dvec3> position;
    std::optional<double> detail_scale;
};

// A triangular patch split into three at the barycentric point `at` (commands_triangle.hpp).
struct SplitTriangleSpec {
    std::uint64_t id = 0;
    geom::Barycentric at{};
};

// Constructions that stay linked to their inputs (commands_construction.hpp): a new object
// built by `recipe` (name: empty for the construction's own, "revolve profile"), an existing
// constructed object's recipe changed (its refinements kept), and a constructed object made
// free (its recipe dropped, its shape kept).
struct ConstructSpec {
    Recipe recipe;
    std::string name;
};
struct EditConstructionSpec {
    std::uint64_t id = 0;
    Recipe recipe;
};
struct DetachSpec {
    std::uint64_t id = 0;
};

// Many control points of one object at once (commands_points.hpp): moved to positions (a
// drag, a symmetric edit), or mapped by an affine matrix about a pivot (typed values).
struct MovePointsSpec {
    std::uint64_t id = 0;
    std::vector<PointIndex> points;
    std::vector<glm::dvec3> positions; // one per point
    std::string label;                 // empty: "Move 3 points"
};
enum class Pivot { origin, centroid, point };
struct TransformPointsSpec {
    std::uint64_t id = 0;
    std::vector<PointIndex> points;
    glm::dmat4 matrix{1.0};
    Pivot about =
        Pivot::origin; // the matrix acts about the origin, the points' centroid or `pivot`
    glm::dvec3 pivot{0};
    std::string label; // empty: "Transform 3 points"
};

// The order of the alternatives is the order of command_names below.
using CommandSpec =
    std::variant<AddObjectSpec, RemoveObjectSpec, RenameObjectSpec, SetVisibleSpec, EditShapeSpec,
                 EditPointSpec, MoveKnotSpec, TransformSpec, InsertKnotSpec, ElevateDegreeSpec,
                 SplitSpec, ConformBordersSpec, SetColorsSpec, InsertCurvePointSpec,
                 DeleteCurvePointSpec, MoveCurvePointSpec, SetCurveDegreeSpec, SetCurveKnotModeSpec,
                 SetCurvePlaneSpec, MakeCompatibleSpec, RemoveKnotSpec, ReduceDegreeSpec,
                 SplitKnotSpec, CloseSpec, ConvertSpec, AddObjectsSpec, MultiresEditSpec,
                 SplitTriangleSpec, ConstructSpec, EditConstructionSpec, DetachSpec, MovePointsSpec,
                 TransformPointsSpec>;

// The command's name as scripts spell it ("edit_point"), indexed like CommandSpec.
inline constexpr const char* command_names[] = {
    "add_object",
    "remove_object",
    "rename_object",
    "set_visible",
    "edit_shape",
    "edit_point",
    "move_knot",
    "transform",
    "insert_knot",
    "elevate_degree",
    "split",
    "conform_borders",
    "set_colors",
    "insert_curve_point",
    "delete_curve_point",
    "move_curve_point",
    "set_curve_degree",
    "set_curve_knot_mode",
    "set_curve_plane",
    "make_compatible",
    "remove_knot",
    "reduce_degree",
    "split_knot",
    "close",
    "convert",
    "add_objects",
    "multires_edit",
    "split_triangle",
    "construct",
    "edit_construction",
    "detach",
    "move_points",
    "transform_points",
};
static_assert(std::size(command_names) == std::variant_size_v<CommandSpec>);

inline const char* command_name(const CommandSpec& spec) {
    return command_names[spec.index()];
}

// The command the spec describes (not applied yet: History::execute applies it).
std::unique_ptr<Command> make_command(CommandSpec spec);

} // namespace isoparm::doc
