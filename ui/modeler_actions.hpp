// The modelling aids' actions shared by the 3D view, the control point planes, the curve
// designer, the menus and the keys: many selected points (rows, columns, all, Shift+click, a
// box), their moves as one command (with symmetric partners), typed transforms about the pivot,
// grid steps and snapping, and the question before a constructed object's points are edited.
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/doc/command.hpp"
#include "core/doc/command_spec.hpp"
#include "ui/app_context.hpp"

namespace isoparm::ui {

// Grid steps: the 3D view's working plane at its zoom, and a plane canvas at its scale.
GridStep working_grid_step(const UiState& ui);
GridStep plane_grid_step(const UiState& ui, const PlaneMap& map);
// Whether a drag snaps now: snapping is on and Alt is not held.
bool snapping_now(const AppContext& ctx);
// A point dragged on a plane canvas (its two coordinates ab), snapped to the other points'
// coordinates `others` (in the same plane), the axes or the grid as the settings say.
glm::dvec2 snap_in_plane(const AppContext& ctx, const PlaneMap& map, const glm::dvec2& ab,
                         const std::vector<glm::dvec2>& others);

// Whether a constructed object's own points may be edited now; when it is constructed the
// detach question opens (and the edit waits for its answer). Free objects: true.
bool may_edit_points(AppContext& ctx, std::uint64_t id);
// Opens the detach question for constructed object id; `then` (a refused command) runs after
// Detach, in an undo step of its own.
void ask_to_detach(AppContext& ctx, std::uint64_t id, std::optional<doc::CommandSpec> then = {},
                   std::string then_label = {});
// The answer Detach: the object detached (one undo step), then the waiting command.
void answer_detach(AppContext& ctx);
// Edit > Detach (Construct > Detach): the selected object forgets its recipe (one undo step).
void detach_selected(AppContext& ctx);

// Selection. The keys: R the selected point's row, Shift+R its column, Ctrl+A all points.
void select_row(AppContext& ctx);
void select_column(AppContext& ctx);
void select_all_points(AppContext& ctx);
// Shift+click: point p of object id in or out of the selection.
void toggle_point(AppContext& ctx, std::uint64_t id, PointIndex p);
// A box: these points of object id, added to the selection (Shift) or instead of it.
void select_points(AppContext& ctx, std::uint64_t id, const std::vector<PointIndex>& points,
                   bool add);
// The selection's pivot: its centroid or the chosen point.
glm::dvec3 selection_pivot(const AppContext& ctx);
// "5 points selected, centroid (0.2, 0, 1.5)" (empty for one point or none).
std::string points_selection_summary(const AppContext& ctx);

// The command that moves `points` of object id to `positions` (one move_points; with symmetric
// editing on, the mirror partners too). A drag's commands merge into one undo step.
std::unique_ptr<doc::Command> move_points_command(const AppContext& ctx, std::uint64_t id,
                                                  const std::vector<PointIndex>& points,
                                                  const std::vector<glm::dvec3>& positions,
                                                  std::string label = {});
// One point moved (a drag in the 3D view, a plane, the fields): move_control_point or, for a
// curve, move_curve_point; with symmetric editing on, move_points with its partner.
std::unique_ptr<doc::Command> point_move_command(const AppContext& ctx, std::uint64_t id, int i,
                                                 int j, const glm::dvec3& p);
// Typed values: the selection mapped by m about the pivot (one undo step).
void transform_selection(AppContext& ctx, const glm::dmat4& m, const std::string& label);

} // namespace isoparm::ui
