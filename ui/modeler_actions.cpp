// Selections of many points, their moves and transforms, grid steps and snapping, and the
// detach question, for every view that edits points.
#include "ui/modeler_actions.hpp"

#include <cmath>
#include <cstdio>
#include <imgui.h>
#include <utility>

#include "core/doc/commands.hpp"
#include "core/doc/commands_construction.hpp"
#include "core/doc/commands_curve.hpp"
#include "core/doc/commands_points.hpp"
#include "core/doc/point_set.hpp"
#include "ui/surface_actions.hpp"
#include "ui/view/kinds/kind_view.hpp"

namespace isoparm::ui {

GridStep working_grid_step(const UiState& ui) {
    const double h = std::max(1.0, static_cast<double>(ui.view_rect.h));
    const double ppu = h / (2 * ui.camera.distance * std::tan(ui.camera.fov_y / 2));
    return grid_step_for(ppu, ui.modeler.snap.min_grid_px * ui.scale());
}

GridStep plane_grid_step(const UiState& ui, const PlaneMap& map) {
    return grid_step_for(1.0 / std::max(map.units_per_px, 1e-300),
                         ui.modeler.snap.min_grid_px * ui.scale());
}

bool snapping_now(const AppContext& ctx) {
    return ctx.ui.modeler.snap.snapping && !ImGui::GetIO().KeyAlt;
}

glm::dvec2 snap_in_plane(const AppContext& ctx, const PlaneMap& map, const glm::dvec2& ab,
                         const std::vector<glm::dvec2>& others) {
    if (!snapping_now(ctx)) return ab;
    SnapSettings s = ctx.ui.modeler.snap.settings;
    s.radius_px *= ctx.ui.scale();
    return snap_plane_point(ab, s, plane_grid_step(ctx.ui, map), map.units_per_px, others).p;
}

bool may_edit_points(AppContext& ctx, std::uint64_t id) {
    const doc::Object* o = ctx.doc.find(id);
    if (!o || !o->construction) return true;
    ask_to_detach(ctx, id);
    return false;
}

void ask_to_detach(AppContext& ctx, std::uint64_t id, std::optional<doc::CommandSpec> then,
                   std::string then_label) {
    const doc::Object* o = ctx.doc.find(id);
    if (!o || !o->construction) return;
    DetachQuestion& q = ctx.ui.modeler.detach;
    q.object = id;
    q.then = std::move(then);
    q.then_label = std::move(then_label);
    std::string inputs;
    for (std::size_t k = 0; k < o->construction->curves.size(); ++k) {
        const doc::Object* in = ctx.doc.find(o->construction->curves[k]);
        inputs += (k ? ", '" : "'") + (in ? in->name : std::string("?")) + "'";
    }
    q.text = "'" + o->name + "' is a " + doc::construction_label(o->construction->kind) + " of " +
             inputs + " and follows " + (o->construction->curves.size() > 1 ? "them" : "it") +
             ": its own control points are not edited. Detach it to edit its points freely? It "
             "then no longer follows " +
             inputs + " (Ctrl+Z links it again).";
    if (q.then) q.text += "\n\nDetach, then: " + q.then_label;
    q.open = true;
    ctx.ui.status = "'" + o->name + "' follows " + inputs + ": detach it to edit its points";
}

void answer_detach(AppContext& ctx) {
    DetachQuestion& q = ctx.ui.modeler.detach;
    const std::optional<doc::CommandSpec> then = std::exchange(q.then, std::nullopt);
    q.then_label.clear();
    ctx.seal();
    if (!ctx.execute(doc::detach(q.object))) return;
    ctx.seal();
    const std::string name = ctx.doc.find(q.object) ? ctx.doc.find(q.object)->name : "";
    if (!then) {
        ctx.ui.status = "Detached '" + name + "': its points are free to edit";
        return;
    }
    const bool ok = ctx.execute(doc::make_command(*then));
    ctx.seal();
    note_action(ctx,
                ok ? "Detached '" + name + "', then " + ctx.history.undo_label() + "."
                   : "Detached '" + name + "'; " + ctx.ui.status,
                !ok);
}

void detach_selected(AppContext& ctx) {
    const doc::Object* o = ctx.doc.selected();
    if (!o || !o->construction) return;
    const std::string name = o->name;
    ctx.seal();
    if (ctx.execute(doc::detach(o->id)))
        ctx.ui.status = "Detached '" + name + "': it no longer follows its curves";
    ctx.seal();
}

namespace {

const doc::Object* selected_with_point(const AppContext& ctx) {
    const doc::Object* o = ctx.doc.selected();
    if (!o || !ctx.doc.view.selection.has_point()) return nullptr;
    return o;
}

void set_points(AppContext& ctx, const doc::Object& o, std::vector<PointIndex> pts) {
    PointSelection& s = ctx.ui.modeler.selection.points;
    s.set(o.id, std::move(pts));
    sync_selection(s, ctx.doc);
}

} // namespace

void select_row(AppContext& ctx) {
    if (const doc::Object* o = selected_with_point(ctx))
        set_points(ctx, *o, doc::row_points(o->shape, ctx.doc.view.selection.i));
}

void select_column(AppContext& ctx) {
    if (const doc::Object* o = selected_with_point(ctx))
        set_points(ctx, *o,
                   doc::column_points(o->shape,
                                      two_index_points(o->shape) ? ctx.doc.view.selection.j : 0));
}

void select_all_points(AppContext& ctx) {
    const doc::Object* o = ctx.doc.selected();
    if (!o) return;
    std::vector<PointIndex> all = doc::all_points(o->shape);
    if (all.empty()) return;
    if (!ctx.doc.view.selection.has_point())
        ctx.doc.view.selection = {o->id, all.front().i, all.front().j};
    set_points(ctx, *o, std::move(all));
}

void toggle_point(AppContext& ctx, std::uint64_t id, PointIndex p) {
    PointSelection& s = ctx.ui.modeler.selection.points;
    doc::Selection& sel = ctx.doc.view.selection;
    if (sel.object != id || !sel.has_point()) {
        sel = {id, p.i, p.j};
        s = PointSelection{id, {p}};
        return;
    }
    const PointIndex primary{sel.i, sel.j};
    s.toggle(p);
    if (const auto next = primary_after_toggle(s, p, primary)) {
        sel.i = next->i;
        sel.j = next->j;
    } else {
        sel.i = sel.j = -1;
    }
}

void select_points(AppContext& ctx, std::uint64_t id, const std::vector<PointIndex>& points,
                   bool add) {
    PointSelection& s = ctx.ui.modeler.selection.points;
    doc::Selection& sel = ctx.doc.view.selection;
    if (points.empty() && add) return;
    if (!add || s.object != id) {
        s.set(id, points);
    } else {
        s.add(points);
    }
    if (s.points.empty()) {
        if (sel.object == id) sel.i = sel.j = -1;
        return;
    }
    if (sel.object != id || !sel.has_point() || !s.contains({sel.i, sel.j}))
        sel = {id, s.points.front().i, s.points.front().j};
}

glm::dvec3 selection_pivot(const AppContext& ctx) {
    const SelectionState& st = ctx.ui.modeler.selection;
    if (st.pivot == PivotChoice::point) return st.chosen_pivot;
    const doc::Object* o = ctx.doc.find(st.points.object);
    if (!o || st.points.points.empty()) return glm::dvec3(0);
    return doc::centroid(o->shape, st.points.points);
}

std::string points_selection_summary(const AppContext& ctx) {
    const PointSelection& s = ctx.ui.modeler.selection.points;
    if (s.size() < 2 || !ctx.doc.find(s.object)) return {};
    const glm::dvec3 c = doc::centroid(ctx.doc.find(s.object)->shape, s.points);
    return std::to_string(s.size()) + " points selected, centroid (" + geom::format_short(c.x) +
           ", " + geom::format_short(c.y) + ", " + geom::format_short(c.z) + ")";
}

std::unique_ptr<doc::Command> move_points_command(const AppContext& ctx, std::uint64_t id,
                                                  const std::vector<PointIndex>& points,
                                                  const std::vector<glm::dvec3>& positions,
                                                  std::string label) {
    doc::MovePointsSpec spec{id, points, positions, std::move(label)};
    const int axis = ctx.ui.modeler.selection.symmetry;
    if (axis >= 0)
        if (const doc::Object* o = ctx.doc.find(id)) {
            doc::SymmetricMove m = doc::symmetric_move(o->shape, points, positions, axis);
            spec.points = std::move(m.points);
            spec.positions = std::move(m.positions);
        }
    return doc::move_points(std::move(spec));
}

std::unique_ptr<doc::Command> point_move_command(const AppContext& ctx, std::uint64_t id, int i,
                                                 int j, const glm::dvec3& p) {
    const doc::Object* o = ctx.doc.find(id);
    const bool curve = o && !two_index_points(o->shape);
    if (ctx.ui.modeler.selection.symmetry >= 0 && o) {
        const PointIndex at{i, curve ? -1 : j};
        return move_points_command(
            ctx, id, {at}, {p},
            "Move " +
                std::string(curve ? "P" + std::to_string(i)
                                  : "P" + std::to_string(i) + std::to_string(j)) +
                " symmetrically");
    }
    if (o) return move_point_command(*o, i, j, p);
    return doc::move_control_point(id, i, j, p); // refused: no such object
}

void transform_selection(AppContext& ctx, const glm::dmat4& m, const std::string& label) {
    const SelectionState& st = ctx.ui.modeler.selection;
    const doc::Object* o = ctx.doc.find(st.points.object);
    if (!o || st.points.points.empty() || !may_edit_points(ctx, o->id)) return;
    const std::uint64_t id = o->id;
    ctx.seal();
    if (st.symmetry < 0) {
        doc::TransformPointsSpec spec{id, st.points.points, m, doc::Pivot::centroid, {}, label};
        if (st.pivot == PivotChoice::point) {
            spec.about = doc::Pivot::point;
            spec.pivot = st.chosen_pivot;
        }
        ctx.execute(doc::transform_points(std::move(spec)));
    } else {
        const glm::dmat4 about = doc::about(m, selection_pivot(ctx));
        std::vector<glm::dvec3> positions;
        for (const PointIndex& p : st.points.points)
            positions.push_back(doc::apply_affine(about, doc::position_of(o->shape, p)));
        ctx.execute(move_points_command(ctx, id, st.points.points, positions, label));
    }
    ctx.seal();
}

} // namespace isoparm::ui
