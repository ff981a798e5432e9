// Commands as data: every document edit as a plain value (its name and its arguments), from
// which the command is built (make_command) and which an applied command gives back
// (Command::spec). Scripts and recordings store exactly this; core/scene/command_json.hpp
// reads and writes it as JSON (docs/commands.md).
#pragma once

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "core/doc/document.hpp"
#include "core/doc/point_set.hpp"

namespace isoparm::doc {

class Command;

struct AddObjectSpec {
    static constexpr const char* script_name = "add_object";
    Object object; // id 0: the document assigns one
};
struct RemoveObjectSpec {
    static constexpr const char* script_name = "remove_object";
    std::uint64_t id = 0;
};
struct RenameObjectSpec {
    static constexpr const char* script_name = "rename_object";
    std::uint64_t id = 0;
    std::string name;
};
struct SetVisibleSpec {
    static constexpr const char* script_name = "set_visible";
    std::uint64_t id = 0;
    bool visible = true;
};
// The object's shape becomes `shape` (same kind of object). Consecutive edits of one object
// with the same non-empty merge_key are one undo step (a drag of an implicit's parameter).
struct EditShapeSpec {
    static constexpr const char* script_name = "edit_shape";
    std::uint64_t id = 0;
    Shape shape;
    std::string label;
    std::string merge_key;
};
// A control point's position, its weight, or both (curves: j = -1).
struct EditPointSpec {
    static constexpr const char* script_name = "edit_point";
    std::uint64_t id = 0;
    int i = 0, j = -1;
    std::optional<glm::dvec3> position;
    std::optional<double> weight;
};
// Knots k .. k + count - 1 (one run of equal knots) move to value.
struct MoveKnotSpec {
    static constexpr const char* script_name = "move_knot";
    std::uint64_t id = 0;
    geom::Dir dir = geom::Dir::u;
    int k = 0, count = 1;
    double value = 0;
};
struct TransformSpec {
    static constexpr const char* script_name = "transform";
    std::uint64_t id = 0;
    glm::dmat4 matrix{1.0};
    std::string label; // empty: "Transform <name>"
};
struct InsertKnotSpec {
    static constexpr const char* script_name = "insert_knot";
    std::uint64_t id = 0;
    geom::Dir dir = geom::Dir::u;
    double t = 0;
    int times = 1;
};
struct ElevateDegreeSpec {
    static constexpr const char* script_name = "elevate_degree";
    std::uint64_t id = 0;
    geom::Dir dir = geom::Dir::u;
    int times = 1;
};
struct SplitSpec {
    static constexpr const char* script_name = "split";
    std::uint64_t id = 0;
    geom::Dir dir = geom::Dir::u;
    double t = 0;
};
struct ConformBordersSpec {
    static constexpr const char* script_name = "conform_borders";
    std::uint64_t group = 0;
};
struct SetColorsSpec {
    static constexpr const char* script_name = "set_colors";
    Colors colors;
};
struct InsertCurvePointSpec {
    static constexpr const char* script_name = "insert_curve_point";
    std::uint64_t id = 0;
    int i = 0;
    glm::dvec3 position{0.0};
};
struct DeleteCurvePointSpec {
    static constexpr const char* script_name = "delete_curve_point";
    std::uint64_t id = 0;
    int i = 0;
};
struct MoveCurvePointSpec {
    static constexpr const char* script_name = "move_curve_point";
    std::uint64_t id = 0;
    int i = 0;
    glm::dvec3 position{0.0};
};
struct SetCurveDegreeSpec {
    static constexpr const char* script_name = "set_curve_degree";
    std::uint64_t id = 0;
    int degree = 1;
};
struct SetCurveKnotModeSpec {
    static constexpr const char* script_name = "set_curve_knot_mode";
    std::uint64_t id = 0;
    CurveKnotMode mode = CurveKnotMode::clamped_uniform;
};
struct SetCurvePlaneSpec {
    static constexpr const char* script_name = "set_curve_plane";
    std::uint64_t id = 0;
    CurvePlane plane = CurvePlane::xy;
    bool carry_points = false;
};
struct MakeCompatibleSpec {
    static constexpr const char* script_name = "make_compatible";
    std::vector<std::uint64_t> ids;
};
// The toolbox's shape changes (commands_reshape.cpp).
struct RemoveKnotSpec {
    static constexpr const char* script_name = "remove_knot";
    std::uint64_t id = 0;
    geom::Dir dir = geom::Dir::u;
    double t = 0;
    int times = 1;
    double tolerance = 0;
};
struct ReduceDegreeSpec {
    static constexpr const char* script_name = "reduce_degree";
    std::uint64_t id = 0;
    geom::Dir dir = geom::Dir::u;
    double tolerance = 0;
};
struct SplitKnotSpec {
    static constexpr const char* script_name = "split_knot";
    std::uint64_t id = 0;
    geom::Dir dir = geom::Dir::u;
    double t = 0;
    std::optional<double> delta;
};
struct CloseSpec {
    static constexpr const char* script_name = "close";
    std::uint64_t id = 0;
    geom::Dir dir = geom::Dir::u;
};
// Several new objects as one undo step (an import); label: the undo label, may be empty.
struct AddObjectsSpec {
    static constexpr const char* script_name = "add_objects";
    std::vector<Object> objects;
    std::string label;
};
struct ConvertSpec {
    static constexpr const char* script_name = "convert";
    std::uint64_t id = 0;
    geom::SplineType to = geom::SplineType::nurbs;
    bool reset_weights = false;
};
// A multiresolution edit (commands_multires.hpp): at coarse `level` (surfaces: `level` along
// u and `level_v` along v), coarse point i (j) moves to `position` keeping the detail, or the
// detail finer than the level is multiplied by `detail_scale` keeping the coarse points.
struct MultiresEditSpec {
    static constexpr const char* script_name = "multires_edit";
    std::uint64_t id = 0;
    int level = 0;
    std::optional<int> level_v;
    int i = 0, j = -1;
    std::optional<glm::dvec3> position;
    std::optional<double> detail_scale;
};

// A triangular patch split into three at the barycentric point `at` (commands_triangle.hpp).
struct SplitTriangleSpec {
    static constexpr const char* script_name = "split_triangle";
    std::uint64_t id = 0;
    geom::Barycentric at{};
};

// Constructions that stay linked to their inputs (commands_construction.hpp): a new object
// built by `recipe` (name: empty for the construction's own, "revolve profile"), an existing
// constructed object's recipe changed (its refinements kept), and a constructed object made
// free (its recipe dropped, its shape kept).
struct ConstructSpec {
    static constexpr const char* script_name = "construct";
    Recipe recipe;
    std::string name;
};
struct EditConstructionSpec {
    static constexpr const char* script_name = "edit_construction";
    std::uint64_t id = 0;
    Recipe recipe;
};
struct DetachSpec {
    static constexpr const char* script_name = "detach";
    std::uint64_t id = 0;
};

// Many control points of one object at once (commands_points.hpp): moved to positions (a
// drag, a symmetric edit), or mapped by an affine matrix about a pivot (typed values).
struct MovePointsSpec {
    static constexpr const char* script_name = "move_points";
    std::uint64_t id = 0;
    std::vector<PointIndex> points;
    std::vector<glm::dvec3> positions; // one per point
    std::string label;                 // empty: "Move 3 points"
};
enum class Pivot { origin, centroid, point };
struct TransformPointsSpec {
    static constexpr const char* script_name = "transform_points";
    std::uint64_t id = 0;
    std::vector<PointIndex> points;
    glm::dmat4 matrix{1.0};
    Pivot about =
        Pivot::origin; // the matrix acts about the origin, the points' centroid or `pivot`
    glm::dvec3 pivot{0};
    std::string label; // empty: "Transform 3 points"
};

// A surface's trim loops set (empty: removed) or removed (commands_trim.hpp).
struct SetTrimSpec {
    static constexpr const char* script_name = "set_trim";
    std::uint64_t id = 0;
    geom::Trim trim;
};
struct RemoveTrimSpec {
    static constexpr const char* script_name = "remove_trim";
    std::uint64_t id = 0;
};

// Every command; each names itself (Spec::name), and core/scene/command_json.cpp gives each
// its JSON form (a spec without one does not build).
using CommandSpec =
    std::variant<AddObjectSpec, RemoveObjectSpec, RenameObjectSpec, SetVisibleSpec, EditShapeSpec,
                 EditPointSpec, MoveKnotSpec, TransformSpec, InsertKnotSpec, ElevateDegreeSpec,
                 SplitSpec, ConformBordersSpec, SetColorsSpec, InsertCurvePointSpec,
                 DeleteCurvePointSpec, MoveCurvePointSpec, SetCurveDegreeSpec, SetCurveKnotModeSpec,
                 SetCurvePlaneSpec, MakeCompatibleSpec, RemoveKnotSpec, ReduceDegreeSpec,
                 SplitKnotSpec, CloseSpec, ConvertSpec, AddObjectsSpec, MultiresEditSpec,
                 SplitTriangleSpec, ConstructSpec, EditConstructionSpec, DetachSpec, MovePointsSpec,
                 TransformPointsSpec, SetTrimSpec, RemoveTrimSpec>;

namespace detail {
template <class V> struct SpecNames;
template <class... S> struct SpecNames<std::variant<S...>> {
    static constexpr std::array<const char*, sizeof...(S)> names{S::script_name...};
};
constexpr bool distinct(std::string_view a, std::string_view b) {
    return a != b;
}
template <std::size_t N> constexpr bool all_distinct(const std::array<const char*, N>& names) {
    for (std::size_t a = 0; a < N; ++a)
        for (std::size_t b = a + 1; b < N; ++b)
            if (!distinct(names[a], names[b])) return false;
    return true;
}
} // namespace detail

// The commands' names as scripts spell them ("edit_point"), indexed like CommandSpec.
inline constexpr auto command_names = detail::SpecNames<CommandSpec>::names;
static_assert(detail::all_distinct(command_names));

inline const char* command_name(const CommandSpec& spec) {
    return std::visit([](const auto& s) { return std::decay_t<decltype(s)>::script_name; }, spec);
}

// The command the spec describes (not applied yet: History::execute applies it).
std::unique_ptr<Command> make_command(CommandSpec spec);

} // namespace isoparm::doc
