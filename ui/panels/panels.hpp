// The workstation's panels: each draws its content inside the window the layout gave it,
// reads the document and changes it only through commands.
#pragma once

#include <string>

#include "ui/app_context.hpp"

namespace isoparm::ui {

void draw_menus(AppContext& ctx);                // the main menu bar
void handle_shortcuts(AppContext& ctx);          // keyboard shortcuts shown in the menus
void draw_view3d_panel(AppContext& ctx);         // the 3D drawing view and its sliders
void draw_tracing_panel(AppContext& ctx);        // the domain square and the indicator (u, v)
void draw_control_point_panel(AppContext& ctx);  // xy / xz / yz planes, fields, weight
void draw_implicit_panel(AppContext& ctx);       // expression, parameters, bounds, presets
void draw_curve_designer_panel(AppContext& ctx); // the selected curve: canvas, knots, basis
void draw_construct_menus(AppContext& ctx);      // Curve and Construct menus (in the menu bar)
void toolbox_items(AppContext& ctx, bool curve); // removal, reduction, splitting, closing, convert
void draw_construct_dialog(AppContext& ctx);     // the Construct menu's dialog
void draw_animate_panel(AppContext& ctx);        // an animated parameter: play, keep, stop
void draw_detach_question(AppContext& ctx);      // before a constructed object's points move
void draw_basis_plot_panel(AppContext& ctx);     // R_ij at (u, v), its support, N_i and N_j
void draw_deboor_panel(AppContext& ctx);         // de Boor's levels at (u, v), step control
void draw_blossom_panel(AppContext& ctx);        // polar forms of de Boor's points, f(a_1..a_p)
void draw_continuity_panel(AppContext& ctx);     // a patch group's borders, measured
void draw_multires_panel(AppContext& ctx);       // levels, coarse points, detail (wavelets)
void draw_homogeneous_panel(AppContext& ctx);    // a curve lifted to (w x, w y, w), projected
void draw_control_panel(AppContext& ctx);        // colours and display settings
void draw_object_list_panel(AppContext& ctx);    // every object: select, rename, hide, delete
void draw_status_bar(AppContext& ctx);           // frame time, object, unsaved mark
void draw_lesson_panel(AppContext& ctx);         // a lesson's caption and Next / Restart
void draw_lessons_menu(AppContext& ctx);         // Lessons: shipped, mine, writing one
void draw_exercises_menu(AppContext& ctx);       // Exercises: shipped, open, check
void draw_lesson_editor_panel(AppContext& ctx);  // a lesson's stops, captions, order, play
void draw_exercise_panel(AppContext& ctx);       // an exercise's task, Check and hints
void draw_course_panels(AppContext& ctx);        // the two above and the authoring dialogs
void draw_dialogs(AppContext& ctx);              // new surface, files, unsaved changes, errors

// The stage (stage_panel.cpp): the staged teaching view at full size in `area`, or the
// four-view layout (xy, 3D, xz, yz) in it.
void draw_stage(AppContext& ctx, const Rect& area);
void draw_four_views(AppContext& ctx, const Rect& area);
// A coordinate plane (0 xy, 1 xz, 2 yz) of every visible object, its selected point dragged
// in it (plane_view.cpp); reported as plane/<xy|xz|yz>.
void draw_plane_view(AppContext& ctx, int plane, const Rect& canvas);

// Curve / Surface > Multiresolution editing: brings the Multires tab forward; greyed with the
// reason when the selected object has no levels.
void multires_menu_item(AppContext& ctx, bool curve);

// The selected object when it is a curve or an implicit surface (the surface panels then
// describe it rather than another object), else null.
const doc::Object* selected_non_surface(const doc::Document& d);
// One line about the selected object, whatever its kind (the status bar).
std::string selection_summary(const AppContext& ctx);
// The left column's text where a surface is expected but the selection is something else (a
// curve, an implicit surface) or there is none: what is selected, and where its panel is.
void no_surface_text(AppContext& ctx);
// The start of the three teaching panels (tracing, basis, de Boor) shown as `view`: a selected
// triangular patch gets the panel's triangle version `triangle_panel`, a selection that is no
// surface gets no_surface_text; both return null. Otherwise the surface to show, its object in
// `obj`.
using TrianglePanel = void (*)(AppContext&, const doc::Object&, const geom::TrianglePatch&);
const geom::Surface* teaching_panel_surface(AppContext& ctx, StageView view,
                                            TrianglePanel triangle_panel, const doc::Object** obj);

// Height the status bar takes (for the layout).
float status_bar_height();

} // namespace isoparm::ui
