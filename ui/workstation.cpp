// The workstation frame: theme and fonts, shortcuts, menus, laid-out panels, dialogs,
// then the 3D view into its texture and ImGui on top.
#include "ui/workstation.hpp"

#include <algorithm>
#include <backends/imgui_impl_opengl3.h>
#include <cmath>
#include <cstdio>
#include <imgui.h>

#include "ui/actions.hpp"
#include "ui/animation_actions.hpp"
#include "ui/media_export.hpp"
#include "ui/modeler_actions.hpp"
#include "ui/panels/fit_panel.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/stage_controls.hpp"
#include "ui/panels/tab_strip.hpp"
#include "ui/render/gl.hpp"
#include "ui/render/renderer.hpp"
#include "ui/retained_frame.hpp"
#include "ui/surface_actions.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/current_patch.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/implicit_meshes.hpp"
#include "ui/view/implicit_screen_level.hpp"
#include "ui/view/kinds/kind_view.hpp"
#include "ui/view/scene_builder.hpp"
#include "ui/view/surface_meshes.hpp"
#include "ui/view/triangle_domain.hpp"
#include "ui/view/triangle_meshes.hpp"

namespace isoparm::ui {

namespace {

// Panels draw no background of their own: the frame is cleared to the window colour first,
// and on a CPU rasteriser (classroom VMs, remote desktops) every blended full-panel quad
// costs milliseconds per frame.
constexpr ImGuiWindowFlags panel_flags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
    ImGuiWindowFlags_NoBackground;

bool begin_panel(const char* name, const Rect& r, ImGuiWindowFlags extra = 0) {
    ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(std::max(r.w, 1.f), std::max(r.h, 1.f)), ImGuiCond_Always);
    report_rect(std::string("panel/") + name, r.x, r.y, r.w, r.h);
    return ImGui::Begin(name, nullptr, panel_flags | extra);
}

// The layout of this frame's window size, scale and mode.
void compute_frame_layout(AppContext& ctx) {
    UiState& ui = ctx.ui;
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    ui.layout_input.width = vp->Size.x;
    ui.layout_input.height = vp->Size.y;
    ui.layout_input.top = ImGui::GetFrameHeight(); // the main menu bar
    ui.layout_input.bottom = status_bar_height();
    ui.layout_input.scale = ui.scale();
    ui.layout_input.splitter = 5 * ui.scale();
    // The 3D view is what the class looks at: on a small screen the side columns give way
    // (their text wraps) before it shrinks below this share of the width.
    ui.layout_input.min_center_fraction = ui.presentation ? 0.5f : 0.4f;
    ui.layout_input.presentation = ui.presentation; // its columns are dragged apart
    ui.layout = compute_layout(ctx.settings.layout, ui.layout_input);
}

// The teaching tabs that share the left column's lower slot.
void teaching_tabs(AppContext& ctx) {
    UiState& ui = ctx.ui;
    struct Tab {
        const char* name;
        const char* what;
        void (*draw)(AppContext&);
        StageView stage;
        const char* what_on_a_triangle = nullptr; // when it says something else there
    };
    static constexpr Tab tabs[] = {
        {"Basis", "R_ij of the selected point at (u, v), N_i and N_j", draw_basis_plot_panel,
         StageView::basis,
         "B_ijk (rational: R_ijk) of the selected point over the domain triangle"},
        {"de Boor", "de Boor's construction at (u, v), step by step", draw_deboor_panel,
         StageView::deboor, "de Casteljau's construction at (r, s, t), level by level"},
        {"Blossom", "every de Boor point as its polar form f(a_1, .., a_p)", draw_blossom_panel,
         StageView::blossom},
        {"Continuity", "every border of the patch group, measured", draw_continuity_panel,
         StageView::continuity},
        {"Homogeneous", "a curve lifted to (w x, w y, w) and projected to w = 1",
         draw_homogeneous_panel, StageView::homogeneous},
        {"Multires", "a coarse polygon plus detail at every level (wavelets)", draw_multires_panel,
         StageView::multires},
    };
    if (ui.deboor.show_tab) ui.left_tab = 1;
    if (ui.multires.show_tab) ui.left_tab = 5;
    ui.deboor.show_tab = ui.multires.show_tab = false;
    const bool triangle = selected_triangle(ctx.doc) != nullptr;
    std::vector<TabLabel> labels;
    for (const Tab& t : tabs)
        labels.push_back(
            {t.name, triangle && t.what_on_a_triangle ? t.what_on_a_triangle : t.what});
    // The stage button at the right end of the strip's first row.
    const ImVec2 start = ImGui::GetCursorScreenPos();
    ImGui::SetCursorScreenPos(ImVec2(
        ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x - ImGui::GetFrameHeight(),
        start.y));
    stage_button(ctx, tabs[ui.left_tab].stage, false);
    ImGui::SetCursorScreenPos(start);
    ui.left_tab = tab_strip(labels, ui.left_tab, ImGui::GetFrameHeight() + 4 * ui.scale());
    note_hovered_view(ctx, tabs[ui.left_tab].stage);
    tabs[ui.left_tab].draw(ctx);
}

// The right column: the selected object's editor above (the Fit panel alone while it is
// open), the scene's objects and the display settings below.
void right_column(AppContext& ctx, const Layout& l) {
    UiState& ui = ctx.ui;
    // An implicit surface has no control points: its editor takes their place.
    const doc::Object* sel = ctx.doc.selected();
    // The Fit panel takes the whole right column while it is open (a canvas, its settings and
    // its buttons need the height on a projector); Objects and display come back on Close.
    const bool fitting = ui.fit.open;
    if (fitting) {
        const Rect column{l.right[0].x, l.right[0].y, l.right[0].w,
                          l.right[1].y + l.right[1].h - l.right[0].y};
        if (begin_panel("Fit", column)) draw_fit_panel(ctx);
    } else {
        // Nothing selected: the control point panel says what to select.
        switch (sel ? editor_of(*sel) : ObjectEditor::control_points) {
        case ObjectEditor::implicit_surface:
            if (begin_panel("Implicit surface", l.right[0])) draw_implicit_panel(ctx);
            break;
        case ObjectEditor::curve_designer:
            if (begin_panel("Curve designer", l.right[0])) draw_curve_designer_panel(ctx);
            break;
        case ObjectEditor::control_points:
            if (begin_panel("Control point", l.right[0])) draw_control_point_panel(ctx);
            break;
        }
    }
    ImGui::End();
    // The scene's objects and the display settings share the slot as tabs.
    if (!fitting) {
        if (begin_panel("Objects and display", l.right[1], ImGuiWindowFlags_NoTitleBar) &&
            ImGui::BeginTabBar("##right_tabs")) {
            const ImGuiTabItemFlags bring =
                ui.object_list.show_tab ? ImGuiTabItemFlags_SetSelected : 0;
            ui.object_list.show_tab = false;
            if (ImGui::BeginTabItem("Objects", nullptr, bring)) {
                draw_object_list_panel(ctx);
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem("Display")) {
                draw_control_panel(ctx);
                ImGui::EndTabItem();
            }
            ImGui::EndTabBar();
        }
        ImGui::End();
    }
}

} // namespace

Workstation::Workstation(const WorkstationOptions& options) {
    IMGUI_CHECKVERSION();
    imgui_ = ImGui::CreateContext();
    // CreateContext makes the new context current only when there is none: a picture export's
    // workstation is made beside the window's.
    ImGui::SetCurrentContext(imgui_);
    transparent_ = options.transparent;
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // the layout is ours (settings.json), not imgui.ini
    io.LogFilename = nullptr;
    ImGui_ImplOpenGL3_Init(glsl_version);
    ImGui_ImplOpenGL3_CreateDeviceObjects();

    ctx_.ui.headless = options.headless;
    request_frame_ = options.request_frame;
    ctx_.ui.content_scale = options.content_scale > 0 ? options.content_scale : 1.f;
    ctx_.ui.view_mode = options.view;
    ctx_.remember_settings = !options.headless;
    ctx_.doc = doc::default_document();
    ctx_.history.mark_clean();
    renderer_ = std::make_unique<Renderer>(options.msaa_samples);
    software_ = options.cpu_rasteriser.value_or(software_renderer());
    ctx_.renderer = renderer_.get();
    implicit_ = std::make_unique<ImplicitMeshes>();
    triangles_ = std::make_unique<TriangleMeshes>();
    surfaces_ = std::make_unique<SurfaceMeshes>();
    ctx_.implicit_meshes = implicit_.get();
    if (options.retained && !options.transparent) retained_ = std::make_unique<RetainedFrame>();
}

Workstation::~Workstation() {
    implicit_.reset(); // stops and joins background polygonizations
    renderer_.reset();
    make_current();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext(imgui_);
}

void Workstation::make_current() {
    ImGui::SetCurrentContext(imgui_);
}

std::string Workstation::renderer_error() const {
    return renderer_->error();
}

void Workstation::splitters() {
    UiState& ui = ctx_.ui;
    // Each bar is its own window the size of the bar, never a window over the whole frame:
    // ImGui 1.86 stacks a window that first appears later (the curve designer, the implicit
    // editor) behind older NoBringToFrontOnFocus windows, so a full-window host would take
    // every click meant for such a panel. The bars lie between the panels, so no stacking
    // order can make one cover another.
    const ImGuiWindowFlags flags =
        ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoBackground |
        ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
        ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoScrollbar |
        ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoNav;
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1)); // bars are a few px thick
    bool released = false;
    auto bar = [&](const char* id, const Rect& r, bool vertical, auto on_drag) {
        if (r.w <= 0 || r.h <= 0) return;
        ImGui::SetNextWindowPos(ImVec2(r.x, r.y));
        ImGui::SetNextWindowSize(ImVec2(r.w, r.h));
        if (ImGui::Begin(id, nullptr, flags)) {
            ImGui::SetCursorScreenPos(ImVec2(r.x, r.y));
            ImGui::InvisibleButton("##bar", ImVec2(r.w, r.h));
            const bool hot = ImGui::IsItemHovered() || ImGui::IsItemActive();
            if (hot)
                ImGui::SetMouseCursor(vertical ? ImGuiMouseCursor_ResizeEW
                                               : ImGuiMouseCursor_ResizeNS);
            if (ImGui::IsItemActive()) {
                const ImVec2 d = ImGui::GetIO().MouseDelta;
                if (d.x != 0 || d.y != 0) on_drag(vertical ? d.x : d.y);
            }
            if (ImGui::IsItemDeactivated()) released = true;
            ImGui::GetWindowDrawList()->AddRectFilled(
                ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h),
                ImGui::GetColorU32(hot ? ImGuiCol_SeparatorActive : ImGuiCol_Separator,
                                   hot ? 1.f : 0.35f));
        }
        ImGui::End();
    };
    LayoutPrefs& prefs = ctx_.settings.layout;
    bar("##split_left", ui.layout.left_splitter, true,
        [&](float d) { drag_column_splitter(prefs, ui.layout, ui.layout_input, Side::left, d); });
    bar("##split_right", ui.layout.right_splitter, true,
        [&](float d) { drag_column_splitter(prefs, ui.layout, ui.layout_input, Side::right, d); });
    char id[48];
    for (std::size_t k = 0; k < ui.layout.left_row_splitters.size(); ++k) {
        std::snprintf(id, sizeof id, "##split_lrow%zu", k);
        bar(id, ui.layout.left_row_splitters[k], false, [&](float d) {
            drag_row_splitter(prefs, ui.layout, ui.layout_input, Side::left, static_cast<int>(k),
                              d);
        });
    }
    // The Fit panel spans the right column: no row splitter across it.
    const std::size_t right_rows = ui.fit.open ? 0 : ui.layout.right_row_splitters.size();
    for (std::size_t k = 0; k < right_rows; ++k) {
        std::snprintf(id, sizeof id, "##split_rrow%zu", k);
        bar(id, ui.layout.right_row_splitters[k], false, [&](float d) {
            drag_row_splitter(prefs, ui.layout, ui.layout_input, Side::right, static_cast<int>(k),
                              d);
        });
    }
    ImGui::PopStyleVar(3);
    if (released) store_settings(ctx_);
}

void Workstation::layout_panels() {
    UiState& ui = ctx_.ui;
    compute_frame_layout(ctx_);
    const Layout& l = ui.layout;
    // The stage and the four-view layout take the whole area between the menu and status bars.
    if (ui.stage.active()) {
        const LayoutInput& in = ui.layout_input;
        const Rect area{0, in.top, in.width, std::max(in.height - in.top - in.bottom, 1.f)};
        ui.drawing_rect = area;
        if (ui.stage.four_views)
            draw_four_views(ctx_, area);
        else
            draw_stage(ctx_, area);
        return;
    }

    if (begin_panel("Domain and knots", l.left[0])) draw_tracing_panel(ctx_);
    ImGui::End();
    // The teaching tabs share the slot. D (de Boor on) and Curve > Multiresolution bring their
    // tab forward. Six names do not fit a projector's column as ImGui tabs (they shrink to
    // "Hom..."): the strip wraps onto a second row instead, whole names always readable.
    if (begin_panel("Basis and de Boor", l.left[1], ImGuiWindowFlags_NoTitleBar))
        teaching_tabs(ctx_);
    ImGui::End();
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(2, 2));
    // The 3D image covers the panel: its window background would only be overdrawn.
    ui.drawing_rect = l.center;
    if (begin_panel("Drawing", l.center,
                    ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse |
                        ImGuiWindowFlags_NoBackground))
        draw_view3d_panel(ctx_);
    ImGui::End();
    ImGui::PopStyleVar();
    right_column(ctx_, l);
    // A splitter drag shows from the next frame.
    splitters();
}

void Workstation::frame(unsigned target_framebuffer) {
    UiState& ui = ctx_.ui;
    ImGuiIO& io = ImGui::GetIO();
    // Theme and font atlas follow the scale (HiDPI x presentation); rebuilt between frames.
    ui.presentation_factor = io.DisplaySize.y < 800 ? 1.25f : 1.5f;
    const float scale = ui.scale();
    const bool restyled = scale != ui.font_scale_built || ui.presentation != presentation_built_;
    if (restyled) {
        apply_theme(ui.presentation, scale);
        if (std::string note = rebuild_fonts(scale); !note.empty()) ui.status = std::move(note);
        ui.font_scale_built = scale;
        presentation_built_ = ui.presentation;
    }

    // Pictures and animations asked for last frame, between frames: they draw with workstations
    // of their own (their own ImGui contexts), then this one is current again.
    {
        MediaExportState& m = ui.media_export;
        if (m.pending || m.clipboard_pending || m.job) {
            run_media_exports(ctx_);
            make_current();
            if (m.job && request_frame_) request_frame_(); // the next frames of the animation
        }
    }
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    // Between gestures (nothing held, no field being edited) the next edit is a new undo step.
    if (!ImGui::IsAnyItemActive() && !ImGui::IsAnyMouseDown()) ctx_.seal();
    normalize_selection(ctx_.doc);
    sync_selection(ui.modeler.selection.points, ctx_.doc);
    // An animated parameter shows its value from here to the end of the frame (never an edit);
    // frames keep coming while it plays.
    if (animation_begin_frame(ctx_, ImGui::GetTime()) && request_frame_) request_frame_();
    // Whenever de Boor's construction is switched on (menu, key, a loaded scene), its tab
    // comes forward.
    if (ctx_.doc.view.display.deboor && !deboor_was_on_) ui.deboor.show_tab = true;
    deboor_was_on_ = ctx_.doc.view.display.deboor;
    // De Boor's animation steps on a clock; frames keep coming while it plays.
    if (deboor_tick(ctx_, ImGui::GetTime()) && request_frame_) request_frame_();
    ui.implicit.dragging = false; // set again by the implicit panel while a slider is held
    ui.hint_waiting = false;      // set again by a canvas whose hint waits (canvas_hint.hpp)

    // The teaching view the pointer was over last frame (T stages it).
    ui.stage.hovered = ui.stage.hovered_next;
    ui.stage.hovered_next = StageView::none;
    report_fact("stage/hovered", static_cast<double>(ui.stage.hovered));
    handle_shortcuts(ctx_); // Shift+P and Esc lead back from the 3D view alone
    // The 3D view sets its rectangle when it is drawn this frame; a staged teaching view
    // without it shows no 3D picture (nor is one rendered).
    const Rect last_view = ui.view_rect;
    ui.view_rect = Rect{};
    if (ui.view_mode == ViewMode::workstation) {
        draw_menus(ctx_);
        layout_panels();
        draw_status_bar(ctx_);
        draw_lesson_panel(ctx_);
        // The caption box placed again this frame: the next frame shows whether it stays.
        if (ui.course.caption_box.settling > 0 && ui.course.caption_box.settling < 6 &&
            request_frame_)
            request_frame_();
        draw_course_panels(ctx_); // lesson editor, exercise, Add stop / expectation
        draw_dialogs(ctx_);
        draw_construct_dialog(ctx_);
        draw_media_export_dialog(ctx_);
        draw_animate_panel(ctx_);
    } else {
        const ImGuiViewport* vp = ImGui::GetMainViewport();
        ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
        ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0);
        if (begin_panel("##view3d_only", {vp->Pos.x, vp->Pos.y, vp->Size.x, vp->Size.y},
                        ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground))
            draw_view3d_panel(ctx_);
        ImGui::End();
        ImGui::PopStyleVar(2);
    }
    draw_detach_question(ctx_); // a drag in the 3D view alone asks too
    ImGui::Render();
    if (ui.hint_waiting && request_frame_) request_frame_(); // until the hint shows
    gesture_.active = gesture_frame();
    const bool view3d_drawn = ui.view_rect.w > 0;
    if (!view3d_drawn) ui.view_rect = last_view; // its last size, for fit_view's aspect
    ui.stage.fit = false;                        // F was seen by every staged canvas this frame
    flush_ui_report(ctx_);
    ctx_.observe_for_recording(); // this frame's view changes (selection, indicator, display)
    // Subpatches: the indicator moved into another patch's part makes it current; a patch
    // picked otherwise takes the indicator along (ui/view/current_patch.hpp).
    {
        const doc::Object* current = nullptr;
        current_surface(ctx_.doc, &current);
        last_current_ = current ? sync_patch_and_indicator(ctx_.doc, current->id, last_indicator_,
                                                           last_current_)
                                : 0;
        last_indicator_ = ctx_.doc.view.indicator;
    }

    // The 3D view into its texture, with the camera and document of this very frame.
    if (view3d_drawn) render_view3d(scale);

    draw_frame(target_framebuffer, view3d_drawn, restyled);
    // The document as it is again: saving, autosave and the next frame's commands see it.
    animation_end_frame(ctx_);
}

// The 3D picture, then ImGui's drawing on top, into the target (through the kept frame when
// there is one).
void Workstation::draw_frame(unsigned target_framebuffer, bool view3d_drawn, bool full) {
    UiState& ui = ctx_.ui;
    const ImGuiIO& io = ImGui::GetIO();
    const int fb_w = static_cast<int>(io.DisplaySize.x * io.DisplayFramebufferScale.x);
    const int fb_h = static_cast<int>(io.DisplaySize.y * io.DisplayFramebufferScale.y);
    const ImVec4 bg = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg); // the panels' background
    const glm::vec4 clear = transparent_ ? glm::vec4(0) : glm::vec4(bg.x, bg.y, bg.z, 1.0f);
    // The 3D picture by a framebuffer copy (OpenGL rows run bottom-up).
    const ImVec2 fb_scale = io.DisplayFramebufferScale;
    const int view_x = static_cast<int>(std::lround(ui.view_rect.x * fb_scale.x));
    const int view_bottom =
        static_cast<int>(std::lround((ui.view_rect.y + ui.view_rect.h) * fb_scale.y));
    if (retained_) {
        Underlay under;
        if (view3d_drawn) {
            under.rect = {view_x, view_bottom - ui.view_fb_height, view_x + ui.view_fb_width,
                          view_bottom};
            under.changed = renderer_->stats().redrawn;
            under.copy = [&](GLuint fbo) { renderer_->copy_to(fbo, view_x, fb_h - view_bottom); };
        }
        redrawn_pixels_ =
            retained_->draw(*ImGui::GetDrawData(), target_framebuffer, clear, under, full);
        return;
    }
    redrawn_pixels_ = static_cast<long>(fb_w) * fb_h;
    glBindFramebuffer(GL_FRAMEBUFFER, target_framebuffer);
    glViewport(0, 0, fb_w, fb_h);
    glClearColor(clear.r, clear.g, clear.b, clear.a);
    glClear(GL_COLOR_BUFFER_BIT);
    if (view3d_drawn) renderer_->copy_to(target_framebuffer, view_x, fb_h - view_bottom);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

// A frame of a gesture: on a CPU rasteriser, while the mouse drags (in any panel: a point, the
// indicator, an orbit) or the wheel zooms, and for GestureFrames::settle_seconds after either
// stops; frames are asked for until then, so the picture is drawn in full as soon as the mouse
// rests, even while the button is still held, and at once on the release.
bool Workstation::gesture_frame() {
    if (ctx_.ui.headless && !gesture_.forced) return false;
    if (!software_ || !gesture_.coarse) return false;
    const ImGuiIO& io = ImGui::GetIO();
    const bool gesture =
        gesture_.step(ImGui::GetTime(), ImGui::IsAnyMouseDown(),
                      io.MouseDelta.x != 0 || io.MouseDelta.y != 0, io.MouseWheel != 0);
    if (gesture && request_frame_) request_frame_();
    return gesture;
}

void Workstation::render_view3d(float scale) {
    UiState& ui = ctx_.ui;
    SceneStyle style;
    style.scale = scale;
    style.deboor_step = ui.deboor.step;
    style.knot_continuity = ui.knot_continuity;
    style.border_continuity = ui.border_continuity;
    style.curve_glyphs = {ui.curve.comb, ui.curve.osculating, ui.curve.frenet};
    style.curve_t = ui.curve.trace_t;
    if (ui.drag.kind == ViewDrag::Kind::point && ui.drag.axis >= 0) {
        style.guide_axis = ui.drag.axis;
        style.guide_point = ui.drag.start;
    }
    // The working plane z = 0 and its grid, at the step the 3D view's zoom shows.
    if (ui.modeler.snap.grid_shown) {
        style.working_grid = true;
        style.grid_step = working_grid_step(ui).value();
        const double reach =
            2.5 * ui.camera.distance * std::tan(ui.camera.fov_y / 2) *
            std::max(1.0, static_cast<double>(ui.view_fb_width) / std::max(1, ui.view_fb_height));
        style.grid_lines = std::clamp(static_cast<int>(std::ceil(reach / style.grid_step)), 4, 80);
        style.grid_centre = {ui.camera.target.x, ui.camera.target.y};
    }
    if (const doc::Object* sel = ctx_.doc.selected(); sel && ui.modeler.selection.points.size() > 1)
        for (const PointIndex& p : ui.modeler.selection.points.points)
            if (!(p.i == ctx_.doc.view.selection.i &&
                  (p.j == ctx_.doc.view.selection.j || !two_index_points(sel->shape))))
                style.also_selected.push_back(doc::position_of(sel->shape, p));
    // Implicit meshes: coarse while a parameter slider moves, synchronous when headless.
    ImplicitMeshes::Mode mode;
    mode.wait = ui.headless;
    mode.coarse_id = ui.implicit.dragging ? ui.implicit.object : 0;
    if (request_frame_) mode.wake = request_frame_;
    mode.gesture = gesture_.active;
    // Each implicit surface at the grid its size on screen needs (implicit_screen_level.hpp);
    // the wireframe style draws the mesh itself, every triangle. The selected one's own mesh is
    // always made: its panel tells its triangles.
    if (ctx_.doc.view.display.style != doc::DisplayStyle::wireframe) {
        const ScreenScale screen = screen_scale(ui.camera, ui.view_fb_height);
        mode.screen_level = [screen](const doc::ImplicitObject& im) {
            return screen_level(im.lo, im.hi, im.cell, screen);
        };
    }
    if (const doc::Object* selected = ctx_.doc.selected()) mode.own_mesh_id = selected->id;
    implicit_->update(ctx_.doc, mode);
    triangles_->update(ctx_.doc, ctx_.doc.view.display.density);
    BuiltScene scene = build_scene(ctx_.doc, style, implicit_.get(), triangles_.get());
    implicit_->end_gesture_frame();
    surfaces_->update(scene.surfaces, ui.analysis.kind, gesture_.active);
    SceneView view;
    view.camera = ui.camera;
    view.width = ui.view_fb_width;
    view.height = ui.view_fb_height;
    view.background = to_vec4(ctx_.doc.colors.background);
    // Transparent: everything blends onto alpha 0 (premultiplied, made straight on read-back).
    view.background = transparent_ ? glm::vec4(0) : glm::vec4(glm::vec3(view.background), 1);
    view.analysis = ui.analysis;
    renderer_->render(view, scene.surfaces, scene.overlay);
}

} // namespace isoparm::ui
