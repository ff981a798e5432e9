// The main menu bar (File, Edit, Surface, Display, Help) and its keyboard shortcuts.
#include <cmath>
#include <filesystem>
#include <imgui.h>
#include <imgui_internal.h> // the popup stack: which open popups are menus
#include <string>
#include <tuple>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h> // key codes only: ImGui 1.86 indexes keys by the platform's codes

#include "core/doc/commands.hpp"
#include "core/doc/placement.hpp"
#include "ui/actions.hpp"
#include "ui/animation_actions.hpp"
#include "ui/exchange_actions.hpp"
#include "ui/fit_actions.hpp"
#include "ui/modeler_actions.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/stage_controls.hpp"
#include "ui/platform/files.hpp"
#include "ui/surface_actions.hpp"
#include "ui/theme.hpp"
#include "ui/toolbox_actions.hpp"
#include "ui/triangle_actions.hpp"
#include "ui/trim_actions.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/data_dir.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/implicit_support.hpp"

namespace isoparm::ui {

namespace {

// The reason a greyed item cannot act, when the pointer rests on it.
void explain_greyed(const std::string& why) {
    if (!why.empty() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        wrapped_tooltip(why);
}

// Whether the open popups are menus only (the menu bar's and their submenus), not a dialog or a
// combo's list.
bool only_menus_open() {
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    if (g.OpenPopupStack.Size == 0) return false;
    for (const ImGuiPopupData& p : g.OpenPopupStack)
        if (!p.Window || !(p.Window->Flags & ImGuiWindowFlags_ChildMenu)) return false;
    return true;
}

void close_menus() {
    ImGui::ClosePopupToLevel(0, true);
}

// C, N, I, K: the selected object's own toggle (made from the defaults at its first change);
// with nothing selected, the defaults every object without its own shows.
void toggle_object_display(AppContext& ctx, bool doc::ObjectDisplay::*flag) {
    doc::ViewState& v = ctx.doc.view;
    if (ctx.doc.selected()) {
        doc::ObjectDisplay& own =
            v.object_display.try_emplace(v.selection.object, doc::defaults_of(v.display))
                .first->second;
        own.*flag = !(own.*flag);
        return;
    }
    doc::ObjectDisplay all = doc::defaults_of(v.display);
    all.*flag = !(all.*flag);
    v.display.control_points = all.control_points;
    v.display.control_net = all.control_net;
    v.display.point_ids = all.point_ids;
    v.display.knot_curves = all.knot_curves;
}

// F: on the stage the staged canvases return to their fit (and the 3D view fits too where it
// is shown); elsewhere the 3D view fits the scene.
void fit_or_reset(AppContext& ctx) {
    StageState& st = ctx.ui.stage;
    if (st.active()) st.fit = true;
    if (!st.active() || st.four_views || st.view == StageView::deboor) fit_view(ctx);
}

void file_menu(AppContext& ctx) {
    if (!begin_menu("File")) return;
    if (menu_item("New", "Ctrl+N")) request_new_document(ctx);
    if (menu_item("Open...", "Ctrl+O")) request_open_dialog(ctx);
    // In a browser, files from the user's computer last one visit: only those still here.
    std::vector<std::string> recent = ctx.settings.recent;
    if (files::in_browser())
        std::erase_if(recent, [](const std::string& r) { return !std::filesystem::exists(r); });
    if (begin_menu("Open Recent", !recent.empty())) {
        std::string chosen;
        for (const std::string& r : recent)
            if (menu_item(r.c_str())) chosen = r;
        ImGui::Separator();
        if (menu_item("Clear list")) {
            ctx.settings.recent.clear();
            store_settings(ctx);
        }
        ImGui::EndMenu();
        if (!chosen.empty()) request_open_file(ctx, chosen);
    }
    // The paper's figures as scenes, from the installed share/isoparm (or the source tree).
    if (begin_menu("Open Example")) {
        std::string chosen;
        for (const std::string& path : example_scenes())
            if (menu_item(std::filesystem::path(path).stem().string().c_str())) chosen = path;
        ImGui::EndMenu();
        if (!chosen.empty()) request_open_file(ctx, chosen);
    }
    if (menu_item("Save", "Ctrl+S")) save(ctx);
    if (menu_item("Save As...", "Ctrl+Shift+S")) request_save_as(ctx);
    // Exchange files (core/scene/export_document, import_document): ui/exchange_actions.hpp.
    if (menu_item("Export...")) request_export_dialog(ctx);
    if (menu_item("Import...")) request_import_dialog(ctx);
    ImGui::Separator();
    // Pictures, vector figures and animations for slides and notes (ui/media_export.hpp).
    if (menu_item("Export picture...")) request_media_export(ctx, MediaExportState::Kind::picture);
    if (menu_item("Export figure...")) request_media_export(ctx, MediaExportState::Kind::figure);
    const std::string no_animation = files::unavailable(files::Feature::animation);
    if (menu_item("Export animation...", nullptr, false, no_animation.empty()))
        request_media_export(ctx, MediaExportState::Kind::animation);
    explain_greyed(no_animation);
    if (menu_item("Copy 3D view", "Ctrl+Shift+C")) ctx.ui.media_export.clipboard_pending = true;
    ImGui::Separator();
    if (menu_item("Open lesson...")) request_open_lesson_dialog(ctx);
    // Recording: the session's edits as a script (docs/script-format.md) to replay or to show.
    if (!ctx.recorder) {
        if (menu_item("Start recording")) start_recording(ctx);
    } else {
        const std::string stop =
            "Stop recording (" + std::to_string(ctx.recorder->step_count()) + " steps)...";
        if (menu_item(stop.c_str())) request_stop_recording(ctx);
    }
    ImGui::Separator();
    const std::string no_quit = files::unavailable(files::Feature::quit);
    if (menu_item("Quit", "Ctrl+Q", false, no_quit.empty())) request_quit(ctx);
    explain_greyed(no_quit);
    ImGui::EndMenu();
}

void edit_menu(AppContext& ctx) {
    if (!begin_menu("Edit")) return;
    const std::string u = ctx.history.can_undo() ? "Undo " + ctx.history.undo_label() : "Undo";
    const std::string r = ctx.history.can_redo() ? "Redo " + ctx.history.redo_label() : "Redo";
    if (menu_item(u.c_str(), "Ctrl+Z", false, ctx.history.can_undo())) undo(ctx);
    if (menu_item(r.c_str(), "Ctrl+Y", false, ctx.history.can_redo())) redo(ctx);
    ImGui::Separator();
    const bool has_point = has_valid_point(ctx.doc);
    if (menu_item("Deselect point", "Esc", false, has_point)) {
        ctx.doc.view.selection.i = ctx.doc.view.selection.j = -1;
    }
    // Many points: Shift+click adds or removes one, Ctrl+drag draws a box (3D view; a plain
    // drag on empty space in a plane).
    if (menu_item("Select row of the point", "R", false, has_point)) select_row(ctx);
    if (menu_item("Select column of the point", "Shift+R", false, has_point)) select_column(ctx);
    const doc::Object* sel = ctx.doc.selected();
    if (menu_item("Select all points", "Ctrl+A", false,
                  sel && !doc::control_points_of(sel->shape).empty()))
        select_all_points(ctx);
    ImGui::Separator();
    SelectionState& st = ctx.ui.modeler.selection;
    if (begin_menu("Symmetric editing")) {
        const char* planes[] = {"Off", "About x = 0", "About y = 0", "About z = 0"};
        for (int a = -1; a < 3; ++a)
            if (menu_item(planes[a + 1], nullptr, st.symmetry == a)) st.symmetry = a;
        ImGui::EndMenu();
    }
    ImGui::EndMenu();
}

void action_item(AppContext& ctx, const ActionState& a, const char* shortcut,
                 void (*run)(AppContext&, geom::Dir), geom::Dir dir) {
    if (menu_item(a.label.c_str(), shortcut, false, a.enabled)) run(ctx, dir);
    if (!a.enabled && !a.why.empty() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        wrapped_tooltip(a.why);
}

// An item whose label carries numbers: `name` reports it to the GUI tests.
void named_action_item(AppContext& ctx, const ActionState& state, void (*run)(AppContext&),
                       const char* name) {
    const bool picked = menu_item(state.label.c_str(), nullptr, false, state.enabled);
    report_item(name);
    if (picked) run(ctx);
    if (!state.enabled && !state.why.empty() &&
        ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        wrapped_tooltip(state.why);
}

// The scene's curves, each an item that trims the current surface by its projection (as a
// hole, or as the outer loop); the items are reported as menu/surface/hole_along/<k>.
void curves_to_trim_by(AppContext& ctx, bool hole) {
    if (!begin_menu(hole ? "Cut a hole along a curve" : "Keep the inside of a curve")) return;
    ImGui::TextDisabled("A closed curve from the curve designer, projected onto the surface");
    int k = 0;
    std::uint64_t picked_curve = 0; // run after the loop: the command edits ctx.doc.objects
    for (const doc::Object& o : ctx.doc.objects) {
        if (!o.curve_object()) continue;
        const ActionState state = trim_by_curve_state(ctx, o);
        ImGui::PushID(static_cast<int>(o.id));
        const bool picked = menu_item(state.label.c_str(), nullptr, false, state.enabled);
        report_item(std::string(hole ? "menu/surface/hole_along/" : "menu/surface/keep_inside/") +
                    std::to_string(k++));
        if (!state.enabled && !state.why.empty() &&
            ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            wrapped_tooltip(state.why);
        ImGui::PopID();
        if (picked) picked_curve = o.id;
    }
    if (k == 0) ImGui::TextDisabled("No curves yet: draw a closed one in the curve designer");
    ImGui::EndMenu();
    if (picked_curve) trim_by_curve(ctx, picked_curve, hole);
}

// Trimming in the window (ui/trim_actions.hpp): a hole at the indicator, and the whole domain
// back. A submenu: the Surface menu must still fit a 1024x768 projector in presentation mode.
void trim_menu(AppContext& ctx) {
    if (!begin_menu("Trim")) return;
    ImGui::TextDisabled("What the surface keeps of its domain (its points stay)");
    named_action_item(ctx, draw_hole_state(ctx), start_drawing_hole, "menu/surface/draw_hole");
    named_action_item(ctx, draw_outer_state(ctx), start_drawing_outer, "menu/surface/draw_outer");
    if (menu_item("Smooth drawn loops", "C", ctx.ui.smooth_loops)) toggle_smooth_loops(ctx);
    report_item("menu/surface/smooth_loops");
    if (ImGui::IsItemHovered())
        wrapped_tooltip("The clicked corners become the control points of a closed cubic "
                        "B-spline (smooth) instead of a polygon's corners");
    named_action_item(ctx, punch_hole_state(ctx), punch_hole_at_indicator,
                      "menu/surface/punch_hole");
    curves_to_trim_by(ctx, true);
    curves_to_trim_by(ctx, false);
    named_action_item(ctx, remove_trim_state(ctx), remove_trim_current, "menu/surface/remove_trim");
    ImGui::EndMenu();
}

// Knot insertion, degree elevation and splitting at the indicator, and how subpatches stay
// joined.
void refine_items(AppContext& ctx) {
    using geom::Dir;
    ImGui::TextDisabled("At the indicator (shape unchanged)");
    // A selected triangle has one degree and a barycentric indicator: its own two items.
    if (const doc::Object* sel = ctx.doc.selected(); sel && sel->triangle()) {
        // The labels carry numbers; the report names them for the GUI tests too.
        named_action_item(ctx, elevate_triangle_state(ctx), elevate_selected_triangle,
                          "menu/triangle/elevate");
        named_action_item(ctx, split_triangle_state(ctx), split_triangle_at_indicator,
                          "menu/triangle/split");
        return;
    }
    action_item(ctx, insert_knot_state(ctx, Dir::u), "U", insert_knot_at_indicator, Dir::u);
    action_item(ctx, insert_knot_state(ctx, Dir::v), "V", insert_knot_at_indicator, Dir::v);
    action_item(ctx, elevate_state(ctx, Dir::u), "Shift+U", elevate_current, Dir::u);
    action_item(ctx, elevate_state(ctx, Dir::v), "Shift+V", elevate_current, Dir::v);
    action_item(ctx, split_state(ctx, Dir::u), "S", split_at_indicator, Dir::u);
    action_item(ctx, split_state(ctx, Dir::v), "Shift+S", split_at_indicator, Dir::v);
    if (begin_menu("Continuity across patch borders")) {
        for (doc::Continuity c : {doc::Continuity::off, doc::Continuity::c0, doc::Continuity::c1})
            if (menu_item(doc::continuity_name(c), nullptr, ctx.doc.continuity == c))
                set_continuity(ctx, c);
        ImGui::EndMenu();
    }
    trim_menu(ctx);
}

} // namespace

// The toolbox's items for the current surface (both directions) or the selected curve: shape
// changes bounded by the tolerance, closing, and Convert to.
void toolbox_items(AppContext& ctx, bool curve) {
    using geom::Dir;
    // A submenu: the Surface menu must still fit a 1024x768 projector in presentation mode.
    if (!begin_menu(curve ? "Reshape the curve" : "Reshape")) {
        if (begin_menu(curve ? "Convert curve to" : "Convert to")) {
            for (const auto& t : geom::spline_type_names)
                if (menu_item(geom::label_of(t.value))) request_convert(ctx, t.value, curve);
            ImGui::EndMenu();
        }
        return;
    }
    ImGui::TextDisabled("At the knot under the indicator (the shape may change)");
    const Tool tools[] = {Tool::remove_knot, Tool::reduce_degree, Tool::split_knot, Tool::close};
    for (Tool tool : tools)
        for (Dir dir : {Dir::u, Dir::v}) {
            if (curve && dir == Dir::v) continue;
            const ActionState a = tool_state(ctx, tool, dir, curve);
            if (menu_item(a.label.c_str(), nullptr, false, a.enabled))
                run_tool(ctx, tool, dir, curve);
            if (!a.enabled && !a.why.empty() &&
                ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
                wrapped_tooltip(a.why);
        }
    ImGui::SetNextItemWidth(110 * ctx.ui.scale());
    double& tol = ctx.ui.toolbox.tolerance;
    // A negative tolerance is not clamped: the commands refuse it, and the items say why.
    ImGui::InputDouble(curve ? "Tolerance##curve" : "Tolerance##surface", &tol, 0, 0, "%.3g");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("How far (model units) knot removal and degree reduction may move the "
                          "shape.");
    ImGui::EndMenu();
    if (begin_menu(curve ? "Convert curve to" : "Convert to")) {
        for (const auto& t : geom::spline_type_names)
            if (menu_item(geom::label_of(t.value))) request_convert(ctx, t.value, curve);
        ImGui::EndMenu();
    }
}

namespace {

void surface_menu(AppContext& ctx) {
    if (!begin_menu("Surface")) return;
    if (menu_item("New Surface...", "Ctrl+Shift+N")) ctx.ui.new_surface.open = true;
    if (menu_item("Fit surface to a grid of points...")) {
        open_fit_panel(ctx);
        request_load_points_dialog(ctx);
    }
    if (menu_item("New implicit surface")) {
        // A sphere to start from; the implicit panel's presets and fields shape it.
        doc::Object o;
        o.name = fresh_name(ctx.doc, "implicit");
        o.shape = implicit_presets().front().object;
        doc::place_beside_scene(ctx.doc, o.shape); // beside the scene, its formula moved too
        ctx.seal();
        if (ctx.execute(doc::add_object(std::move(o)))) {
            ctx.doc.view.selection = {ctx.doc.objects.back().id, -1, -1};
            fit_view(ctx);
        }
        ctx.seal();
    }
    if (begin_menu("New triangular patch")) {
        for (int n = 1; n <= 4; ++n)
            if (menu_item(("Degree " + std::to_string(n)).c_str())) new_triangle(ctx, n, false);
        if (menu_item("Rational cubic")) new_triangle(ctx, 3, true);
        ImGui::EndMenu();
    }
    ImGui::Separator();
    ImGui::TextDisabled("Select");
    std::uint64_t pick = 0;
    for (const doc::Object& o : ctx.doc.objects) {
        const std::string label = o.name.empty() ? "object " + std::to_string(o.id) : o.name;
        if (menu_item(label.c_str(), nullptr, o.id == ctx.doc.view.selection.object)) pick = o.id;
    }
    if (pick != 0 && pick != ctx.doc.view.selection.object) ctx.doc.view.selection = {pick, -1, -1};
    ImGui::Separator();
    refine_items(ctx);
    ImGui::Separator();
    toolbox_items(ctx, false);
    multires_menu_item(ctx, false);
    ImGui::Separator();
    const doc::Object* sel = ctx.doc.selected();
    if (menu_item("Delete Selected", nullptr, false, sel != nullptr)) {
        const std::uint64_t id = sel->id;
        ctx.seal();
        if (ctx.execute(doc::remove_object(id))) normalize_selection(ctx.doc);
        ctx.seal();
    }
    ImGui::EndMenu();
}

void display_menu(AppContext& ctx) {
    if (!begin_menu("Display")) return;
    doc::DisplaySettings& d = ctx.doc.view.display;
    if (menu_item("Shaded", "1", d.style == doc::DisplayStyle::shaded))
        d.style = doc::DisplayStyle::shaded;
    if (menu_item("Wireframe", "2", d.style == doc::DisplayStyle::wireframe))
        d.style = doc::DisplayStyle::wireframe;
    if (menu_item("Shaded + wireframe", "3", d.style == doc::DisplayStyle::both))
        d.style = doc::DisplayStyle::both;
    ImGui::Separator();
    // The selected object's own toggles (the defaults for every object without its own when
    // nothing is selected).
    const doc::Object* sel = ctx.doc.selected();
    ImGui::TextDisabled("%s", sel ? ("Of " + sel->name).c_str() : "Of every object");
    const doc::ObjectDisplay od = doc::display_of(ctx.doc.view, ctx.doc.view.selection.object);
    if (menu_item("Control points", "C", od.control_points))
        toggle_object_display(ctx, &doc::ObjectDisplay::control_points);
    if (menu_item("Control net", "N", od.control_net))
        toggle_object_display(ctx, &doc::ObjectDisplay::control_net);
    if (menu_item("Point IDs (P_ij)", "I", od.point_ids))
        toggle_object_display(ctx, &doc::ObjectDisplay::point_ids);
    if (menu_item("Knot curves", "K", od.knot_curves))
        toggle_object_display(ctx, &doc::ObjectDisplay::knot_curves);
    if (begin_menu("Defaults for new objects")) {
        menu_item("Control points##default", nullptr, &d.control_points);
        menu_item("Control net##default", nullptr, &d.control_net);
        menu_item("Point IDs (P_ij)##default", nullptr, &d.point_ids);
        menu_item("Knot curves##default", nullptr, &d.knot_curves);
        ImGui::EndMenu();
    }
    ImGui::Separator();
    menu_item("Indicator point S(u,v)", nullptr, &d.indicator_point);
    // Yellow C1, orange C0, red C-1: why a knot's multiplicity changes smoothness.
    if (menu_item("Knot curves by continuity", nullptr, &ctx.ui.knot_continuity) &&
        ctx.ui.knot_continuity && !od.knot_curves)
        toggle_object_display(ctx, &doc::ObjectDisplay::knot_curves);
    // The measured continuity of each patch border: red broken .. cyan C1 + G2.
    menu_item("Borders by continuity", nullptr, &ctx.ui.border_continuity);
    if (menu_item("de Boor's construction", "D", &d.deboor) && d.deboor)
        ctx.ui.deboor.show_tab = true;
    if (menu_item("de Boor: step back", "[")) deboor_step(ctx, -1);
    if (menu_item("de Boor: step forward", "]")) deboor_step(ctx, +1);
    if (menu_item(ctx.ui.deboor.playing ? "de Boor: pause" : "de Boor: play", "Space"))
        deboor_toggle_play(ctx, ImGui::GetTime());
    ImGui::Separator();
    // Grid and snap: the planes, the curve designer and the 3D view's working plane z = 0;
    // Alt held during a drag snaps nothing.
    SnapState& snap = ctx.ui.modeler.snap;
    menu_item("Grid", "G", &snap.grid_shown);
    menu_item("Snap while dragging (Alt: off)", nullptr, &snap.snapping);
    if (begin_menu("Snap to")) {
        menu_item("Grid steps", nullptr, &snap.settings.grid);
        menu_item("Axes", nullptr, &snap.settings.axes);
        menu_item("Other points", nullptr, &snap.settings.points);
        ImGui::EndMenu();
    }
    if (menu_item("Animate...", nullptr, ctx.ui.modeler.animation.open)) {
        AnimationState& a = ctx.ui.modeler.animation;
        if (!a.open) a.focus = true;
        a.open = !a.open;
        if (!a.open) stop_animation(ctx);
    }
    if (begin_menu("Analysis")) {
        // Curvature from exact derivatives as false colour, or reflection lines.
        for (const auto& m : doc::analysis_mode_names)
            if (menu_item(geom::label_of(m.value), nullptr, d.analysis == m.value))
                d.analysis = m.value;
        ImGui::Separator();
        ImGui::SetNextItemWidth(110 * ctx.ui.scale());
        ImGui::SliderInt("Stripes", &d.stripes, 2, 64);
        ImGui::SetNextItemWidth(110 * ctx.ui.scale());
        float angle = static_cast<float>(d.zebra_angle);
        if (ImGui::SliderFloat("Zebra angle", &angle, -90, 90, "%.0f deg")) d.zebra_angle = angle;
        ImGui::Checkbox("Fixed colour range", &d.analysis_fixed);
        if (d.analysis_fixed) {
            double range[2] = {d.analysis_lo, d.analysis_hi};
            ImGui::SetNextItemWidth(160 * ctx.ui.scale());
            if (ImGui::InputScalarN("low, high", ImGuiDataType_Double, range, 2, nullptr, nullptr,
                                    "%.4g") &&
                std::isfinite(range[0]) && std::isfinite(range[1]) && range[0] < range[1]) {
                // An empty or reversed range is not taken: the last good one stays.
                d.analysis_lo = range[0];
                d.analysis_hi = range[1];
            }
        }
        ImGui::EndMenu();
    }
    ImGui::EndMenu();
}

// The views: a teaching view on the stage, the four-view layout, the 3D view alone, and the
// projector's settings.
void view_menu(AppContext& ctx) {
    if (!begin_menu("View")) return;
    StageState& st = ctx.ui.stage;
    if (begin_menu("Stage")) {
        // T stages the view under the pointer; the items name every one.
        for (const StageViewInfo& i : stage_views)
            if (menu_item(i.title, nullptr, st.view == i.view))
                set_stage(ctx, st.view == i.view ? StageView::none : i.view);
        ImGui::EndMenu();
    }
    if (menu_item("Four views (xy, 3D, xz, yz)", "4", st.four_views))
        set_four_views(ctx, !st.four_views);
    if (menu_item("Back to the workstation", "Esc", false, st.active()))
        set_stage(ctx, StageView::none);
    if (menu_item("3D view only", "Shift+P", ctx.ui.view_mode == ViewMode::view3d_only))
        toggle_view_only(ctx);
    ImGui::Separator();
    if (menu_item("Fit to view", "F")) fit_or_reset(ctx);
    if (menu_item("Presentation mode", "P", ctx.ui.presentation)) toggle_presentation(ctx);
    if (!ctx.ui.headless && menu_item("Full screen", "F11", ctx.ui.fullscreen))
        ctx.ui.fullscreen_request = true;
    ImGui::EndMenu();
}

void help_menu(AppContext& ctx) {
    if (!begin_menu("Help")) return;
    if (menu_item("Mouse and keys...")) ctx.ui.show_about = true;
    ImGui::EndMenu();
}

// Ctrl and a key: the file and history commands.
void ctrl_shortcut(AppContext& ctx, const KeyPress& k) {
    switch (k.key) {
    case GLFW_KEY_N:
        if (k.shift)
            ctx.ui.new_surface.open = true;
        else
            request_new_document(ctx);
        break;
    case GLFW_KEY_O:
        request_open_dialog(ctx);
        break;
    case GLFW_KEY_S:
        if (k.shift)
            request_save_as(ctx);
        else
            save(ctx);
        break;
    case GLFW_KEY_Z:
        if (k.shift)
            redo(ctx);
        else
            undo(ctx);
        break;
    case GLFW_KEY_Y:
        redo(ctx);
        break;
    case GLFW_KEY_C:
        if (k.shift) ctx.ui.media_export.clipboard_pending = true; // the 3D view
        break;
    case GLFW_KEY_Q:
        request_quit(ctx);
        break;
    case GLFW_KEY_A:
        select_all_points(ctx);
        break;
    default:
        break;
    }
}

// A key alone (Shift aside): views, display toggles, de Boor's steps and surface edits.
void plain_shortcut(AppContext& ctx, const KeyPress& k) {
    doc::DisplaySettings& d = ctx.doc.view.display;
    switch (k.key) {
    case GLFW_KEY_F:
        fit_or_reset(ctx);
        break;
    case GLFW_KEY_T:
        // The teaching view under the pointer takes the stage; on the stage, T gives it back.
        if (ctx.ui.stage.view != StageView::none)
            set_stage(ctx, StageView::none);
        else if (ctx.ui.stage.hovered != StageView::none)
            set_stage(ctx, ctx.ui.stage.hovered);
        break;
    case GLFW_KEY_4:
        set_four_views(ctx, !ctx.ui.stage.four_views);
        break;
    case GLFW_KEY_R:
        (k.shift ? select_column : select_row)(ctx);
        break;
    case GLFW_KEY_G:
        ctx.ui.modeler.snap.grid_shown = !ctx.ui.modeler.snap.grid_shown;
        break;
    case GLFW_KEY_F11:
        ctx.ui.fullscreen_request = true;
        break;
    case GLFW_KEY_P:
        if (k.shift)
            toggle_view_only(ctx);
        else
            toggle_presentation(ctx);
        break;
    case GLFW_KEY_1:
        d.style = doc::DisplayStyle::shaded;
        break;
    case GLFW_KEY_2:
        d.style = doc::DisplayStyle::wireframe;
        break;
    case GLFW_KEY_3:
        d.style = doc::DisplayStyle::both;
        break;
    case GLFW_KEY_C:
        toggle_object_display(ctx, &doc::ObjectDisplay::control_points);
        break;
    case GLFW_KEY_N:
        toggle_object_display(ctx, &doc::ObjectDisplay::control_net);
        break;
    case GLFW_KEY_I:
        toggle_object_display(ctx, &doc::ObjectDisplay::point_ids);
        break;
    case GLFW_KEY_K:
        toggle_object_display(ctx, &doc::ObjectDisplay::knot_curves);
        break;
    case GLFW_KEY_D:
        d.deboor = !d.deboor;
        ctx.ui.deboor.show_tab = d.deboor;
        break;
    case GLFW_KEY_LEFT_BRACKET:
        deboor_step(ctx, -1);
        break;
    case GLFW_KEY_RIGHT_BRACKET:
        deboor_step(ctx, +1);
        break;
    case GLFW_KEY_SPACE:
        deboor_toggle_play(ctx, ImGui::GetTime());
        break;
    case GLFW_KEY_U:
        (k.shift ? elevate_current : insert_knot_at_indicator)(ctx, geom::Dir::u);
        break;
    case GLFW_KEY_V:
        (k.shift ? elevate_current : insert_knot_at_indicator)(ctx, geom::Dir::v);
        break;
    case GLFW_KEY_S:
        split_at_indicator(ctx, k.shift ? geom::Dir::v : geom::Dir::u);
        break;
    case GLFW_KEY_ESCAPE:
        if (ctx.ui.stage.active())
            set_stage(ctx, StageView::none);
        else if (ctx.ui.view_mode == ViewMode::view3d_only && !ctx.ui.headless)
            toggle_view_only(ctx);
        else
            ctx.doc.view.selection.i = ctx.doc.view.selection.j = -1; // and the many points
        break;
    default:
        break;
    }
}

// While a trim loop is drawn in the tracing square, Enter closes it, Backspace takes its last
// corner back and Escape abandons it; other keys keep their meaning.
bool trim_drawing_key(AppContext& ctx, int key) {
    if (!ctx.ui.trim_drawing.active()) return false;
    switch (key) {
    case GLFW_KEY_ENTER:
    case GLFW_KEY_KP_ENTER:
        close_drawn_loop(ctx);
        return true;
    case GLFW_KEY_BACKSPACE:
        take_back_loop_corner(ctx);
        return true;
    case GLFW_KEY_ESCAPE:
        cancel_loop_drawing(ctx);
        return true;
    case GLFW_KEY_C:
        toggle_smooth_loops(ctx);
        return true;
    default:
        return false;
    }
}

} // namespace

void draw_menus(AppContext& ctx) {
    if (!ImGui::BeginMainMenuBar()) return;
    file_menu(ctx);
    draw_lessons_menu(ctx);   // lessons_menu.cpp
    draw_exercises_menu(ctx); // lessons_menu.cpp
    edit_menu(ctx);
    surface_menu(ctx);
    draw_construct_menus(ctx); // Curve, Construct (construct_menu.cpp)
    display_menu(ctx);
    view_menu(ctx);
    help_menu(ctx);
    ImGui::EndMainMenuBar();
}

void handle_shortcuts(AppContext& ctx) {
    std::vector<KeyPress> keys;
    keys.swap(ctx.ui.key_presses);
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput) return; // typing in a field: keys belong to the field
    // An open menu does not swallow the keys: Escape closes it, a shortcut closes it and acts.
    // A dialog (a modal popup) or a combo's list keeps them.
    const bool menus = only_menus_open();
    if (!menus && ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopupId)) return;
    for (const KeyPress& k : keys) {
        if (k.alt) continue;
        if (menus && only_menus_open()) {
            close_menus();
            if (k.key == GLFW_KEY_ESCAPE) continue;
        }
        if (!k.ctrl && trim_drawing_key(ctx, k.key)) continue;
        if (k.ctrl)
            ctrl_shortcut(ctx, k);
        else
            plain_shortcut(ctx, k);
    }
}

} // namespace isoparm::ui
