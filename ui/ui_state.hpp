// UI state of the workstation: camera, gestures in progress, dialogs, caches of derived
// data. None of it is document data and none of it is undoable.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/doc/fit.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/types.hpp"
#include "core/scene/autosave.hpp"
#include "core/scene/recorder.hpp"
#include "ui/course_state.hpp"
#include "ui/lesson.hpp"
#include "ui/media_export.hpp"
#include "ui/modeler_state.hpp"
#include "ui/view/camera.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/denominator_view.hpp"
#include "ui/view/layout.hpp"
#include "ui/view/picking.hpp"
#include "ui/view/scene_draw.hpp"
#include "ui/view/stage.hpp"
#include "ui/view/triangle_denominator.hpp"
#include "ui/view/triangle_domain.hpp"

namespace isoparm::ui {

enum class ViewMode { workstation, view3d_only };

// A gesture in the 3D view, from mouse press to release.
struct ViewDrag {
    enum class Kind { none, orbit, pan, point } kind = Kind::none;
    PointRef point;      // the control point being dragged
    glm::dvec3 start{0}; // its position when the drag began
    glm::dvec2 start_mouse{0};
    int axis = -1; // -1: in the view plane; 0/1/2: constrained to x/y/z
    bool moved = false;
};

// The paper's sliders below the 3D view: spring-loaded, each drag is one transform.
struct TransformSliders {
    float move[3] = {0, 0, 0};   // along x, y, z in scene sizes (relative to the press)
    float rotate[3] = {0, 0, 0}; // degrees about x, y, z through the pivot
    int active = -1;             // which slider is held (0..5), -1 none
    float applied = 0;           // the part of the held slider's value already applied
    glm::dvec3 pivot{0};
    double scale = 1; // world units per slider unit, fixed for the gesture
};

// The control-point panel's planes keep their framing while a disk is dragged, so the
// canvas does not slide under the mouse.
struct PlaneDrag {
    int plane = -1; // 0 xy, 1 xz, 2 yz; -1 none
    PlaneMap frozen;
    glm::dvec2 grab{0}; // mouse minus the disk centre at the press, in pixels
};

struct NewSurfaceForm {
    int rows = 5, cols = 5, degree_u = 3, degree_v = 3;
    // The degrees chosen for B-spline and NURBS types: a Bezier type shows rows - 1 and
    // cols - 1 without forgetting them, so switching back restores them.
    int spline_degree_u = 3, spline_degree_v = 3;
    int type = 3; // geom::SplineType: 0 bezier, 1 rational bezier, 2 bspline, 3 nurbs
    bool open = false;
    std::string error;
};

struct FileDialog {
    enum class Mode {
        closed,
        open,
        save,
        save_recording,
        open_lesson,
        load_points,
        export_file,   // File > Export... (ui/exchange_actions.hpp)
        import_file,   // File > Import...
        save_lesson,   // the lesson editor's Save as (ui/course_actions.hpp)
        open_exercise, // Lessons > Exercises > Open exercise...
    } mode = Mode::closed;
    bool just_opened = false;
    std::string directory;
    std::string name;
    std::string error;
};

// What to do once the user has answered the unsaved-changes question.
struct PendingAction {
    enum class Kind {
        none,
        new_document,
        open_file,
        open_dialog,
        open_lesson,
        open_exercise,
        play_draft, // the lesson editor's Play from here, from stop `stop`
        quit
    } kind = Kind::none;
    std::string path;
    std::size_t stop = 0;
};

// R_ij heat map samples, recomputed only when the surface or the point changes.
struct HeatMapCache {
    geom::Surface surface;
    int i = -1, j = -1, resolution = 0;
    bool valid = false;
    std::vector<float> values; // resolution^2, row-major over (v from top, u from left)
    float max_value = 0;
};

// The implicit-surface panel's fields (the expression is applied on Enter).
struct ImplicitForm {
    std::uint64_t object = 0; // the object the fields were filled from
    std::string synced;       // its expression when the field was last filled
    std::string text;         // the expression field
    std::string error;        // why the last Enter was refused (with its column)
    bool dragging = false;    // a parameter slider is held: the mesh is polygonized coarser
    int preset = 0;           // the presets combo's choice
};

// The start-up's offer to restore autosaved work (set by the window only, never headless),
// and the answers the window's autosave timer picks up (ui/recovery.hpp).
struct RecoveryPrompt {
    std::vector<scene::RecoveryInfo> offers; // newest first; the dialog asks about the first
    std::vector<std::string> restored;       // origins whose recovery file now backs the document
    std::vector<std::string> held;           // origins the user will decide about at a later start
};

// The curve designer panel and the Construct dialog (ui/panels/curve_designer_panel.cpp,
// construct_menu.cpp): gestures in progress and the fields of their forms.
struct CurveDesignerState {
    int view_plane = 0;  // a 3D curve's canvas plane: 0 xy, 1 xz, 2 yz
    int drag_point = -1; // control point being dragged on the canvas, -1 none
    PlaneMap frozen;     // the canvas framing kept during a drag
    glm::dvec2 grab{0};  // mouse minus the point at the press, in pixels
    glm::dvec2 press{0}; // the mouse at the press: a click that does not move moves nothing
    // The canvas keeps its framing (world box) while the points stay inside it, so adding a
    // point does not shift the picture under the mouse.
    std::uint64_t frame_object = 0;
    int frame_plane = -1;
    glm::dvec2 frame_lo{0}, frame_hi{0};
    int drag_knot = -1; // knot being dragged on the knot strip, -1 none
    // The canvas's own zoom and pan over the kept framing (wheel, right or middle drag); Fit
    // (the button, or F over the canvas) goes back to the framing.
    double view_zoom = 1;
    glm::dvec2 view_pan{0};
    bool trace = true;                                     // show de Boor's construction at trace_t
    bool comb = false, osculating = false, frenet = false; // curvature at a glance
    double trace_t = 0.4;                                  // normalised to [0, 1] over the domain
    double insert_t = 0.5;                                 // knot insertion parameter (normalised)
    bool carry_points = true;                 // changing the plane moves the drawing into it
    float primitive[6] = {0, 0, 1, 0, 90, 0}; // centre a, b; radius; start, end degrees; unused
    float line_end[4] = {-1, 0, 1, 0};        // line from (a, b) to (a, b) in the plane
    std::string message;                      // the last refusal, shown in the panel
    // Construct dialog.
    int construct_kind = -1; // doc::Construction to run; -1 closed
    bool construct_open = false;
    std::vector<std::uint64_t> chosen; // curves in order
    double angle = 360, swing_scale = 1;
    int skin_degree = 0, parametrization = 0, sections = 16;
    int gordon_u_count = 2;
    int iso_dir = 0;           // isocurve: 0 u, 1 v
    double iso_t = 0.5;        // isocurve: where, in [0, 1] over the domain
    std::uint64_t editing = 0; // Edit construction: the object whose recipe the dialog changes
    std::string note;  // the last construction's report (deviation, parameters, compatibility)
    std::string error; // why the last Build was refused, shown in the dialog until the next

    // The curve's parameter at the normalised trace position.
    double trace_param(const geom::Curve& c) const {
        return denormalize_param(geom::domain(c), std::clamp(trace_t, 0.0, 1.0));
    }
};

// De Boor's construction shown one level at a time: the u-stage's levels over all
// rows, then the v-stage's. step -1 shows everything; 0 only the control points.
struct DeBoorPlayer {
    int step = -1;
    bool playing = false;
    double next_time = 0; // when the animation takes its next step (seconds, window clock)
    double seconds_per_step = 0.9;
    bool show_tab = false; // bring the de Boor tab forward once (D toggled it on)
};

// What the last teaching action at the indicator (insert, elevate, split) said: a refusal
// and its reason, or what it did (neighbours refined, a Bezier become NURBS). The tracing
// panel shows it under the square, where the action was taken, until the next action or
// edit (the history then differs from the one recorded here).
struct ActionNote {
    std::string text;
    bool refused = false;
    std::size_t history_size = 0;
    std::string undo_label;
};

// A trim loop being drawn in the tracing square (Surface > Trim > Draw ...): the corners
// clicked so far, in the surface's own (u, v). Closed into a polygon loop (or, smooth, the
// closed cubic B-spline they are the control points of), it becomes the outer loop or one
// more hole of the surface's trim (ui/trim_actions.hpp).
struct TrimDrawing {
    std::uint64_t object = 0; // the surface being trimmed; 0: not drawing
    bool hole = true;         // a hole (the kept region outside it) or the outer loop
    std::vector<glm::dvec2> corners;
    bool active() const { return object != 0; }
};

// A knot tick held in the tracing panel: the run of copies it moves.
struct KnotDrag {
    bool active = false;
    geom::Dir dir = geom::Dir::u;
    int first = 0, count = 1;
    std::uint64_t object = 0;
};

// A key press from the platform, kept until the next frame handles it (ImGui 1.86 polls key
// state once per frame and misses a press and release that fall between two frames).
struct KeyPress {
    int key = 0; // GLFW key code
    bool ctrl = false, shift = false, alt = false;
};

// The object list's rename in progress.
struct ObjectListState {
    std::uint64_t renaming = 0; // object whose name field is open, 0 none
    bool focus_rename = false;
    char name[128] = {};
    bool show_tab = false; // bring the Objects tab forward once (an object was added)
};

// Surface / Curve > Convert to, when the conversion loses something: the question asked.
struct ConvertQuestion {
    std::uint64_t object = 0;
    geom::SplineType to = geom::SplineType::nurbs;
    bool reset_weights = false; // the weights differ and a non-rational type has none
    std::string text;           // what is lost, in words
    bool open = false;          // open the question at the next frame
};

// The Fit panel (Curve > Fit curve to points, Surface > Fit surface to a grid): data points
// clicked on its canvas or loaded from a file, the fit's settings, and the last fit made from
// them (recomputed only when they change).
struct FitState {
    bool open = false; // the panel takes the right slot
    std::vector<glm::dvec3> points;
    int rows = 1, columns = 0; // a loaded grid when rows > 1
    std::string source;        // "" for clicked points, else the file loaded
    int plane = 0;             // the canvas plane: 0 xy, 1 xz, 2 yz
    doc::FitSettings settings;
    std::optional<doc::Fit> fit;
    std::string error;    // why the last fit (or load) was refused
    bool stale = true;    // points or settings changed since `fit`
    int drag = -1;        // data point being dragged, -1 none
    PlaneMap frozen;      // the canvas framing kept during a drag
    int frame_plane = -1; // the plane the kept framing belongs to (-1: frame afresh)
    glm::dvec2 frame_lo{0}, frame_hi{0};
};

// The Homogeneous tab: which curve is lifted to (w a, w b, w) and how the picture is turned.
struct HomogeneousState {
    int isocurve = 0; // of a surface: 0 the curve along u through the indicator, 1 along v
    // The coordinates seen: -1 the best plane (ui/view/homogeneous_scene.hpp), 0 xy, 1 xz,
    // 2 yz; a planar curve is always seen in its own plane.
    int plane = -1;
    double yaw = -40, pitch = 18; // degrees
    double zoom = 1;
    bool labels = true; // weights beside the lifted control points
};

// The toolbox's settings: how far knot removal and degree reduction may move the shape.
struct ToolboxState {
    double tolerance = 0.01; // model units
    ConvertQuestion convert;
};

// The Multires tab (ui/panels/multires_panel.cpp): the levels shown for the selected object and
// a coarse control point's drag on its canvas.
struct MultiresState {
    std::uint64_t object = 0;     // the object the levels were chosen for
    int level_u = 0, level_v = 0; // a curve's level is level_u
    int plane = 1;                // canvas plane of a surface or a 3D curve: 0 xy, 1 xz, 2 yz
    int drag = -1;                // the coarse point dragged (i * coarse n_v + j), -1 none
    PlaneMap frozen;              // the canvas framing kept during a drag
    glm::dvec2 grab{0}, press{0}; // pointer offset from the point's centre; where it went down
    std::uint64_t frame_object = 0;
    int frame_plane = -1;
    glm::dvec2 frame_lo{0}, frame_hi{0};
    std::string message;   // the last refusal
    bool show_tab = false; // bring the Multires tab forward once (the menu item)
};

// The Blossom tab (ui/panels/blossom_panel.cpp): the sliders' blossom arguments, kept while the
// object and its piece stay (u-arguments in `args`, a surface's v-arguments in `v_args`).
struct BlossomState {
    std::vector<double> args, v_args;
    std::uint64_t object = 0, v_object = 0;
    int span = -1, v_span = -1;
};

// The stage (ui/workstation.cpp): one teaching view at full size in the main area, or the
// four-view layout (3D + xy + xz + yz); the zoom and pan of the canvases shown there.
struct StageState {
    StageView view = StageView::none;
    bool four_views = false;
    std::map<std::string, CanvasView> canvases; // by canvas name (tracing, plane/xy, ...)
    std::string panning;                        // the canvas a right-drag pans, "" none
    StageView hovered = StageView::none;        // the teaching view under the pointer (T stages it)
    StageView hovered_next = StageView::none;   // ... as this frame's panels report it
    bool fit = false;                           // F: the staged canvases return to their fit
    bool active() const { return view != StageView::none || four_views; }
};

// When the status bar's message appeared (it fades, then goes, after status_seconds).
struct StatusAge {
    std::string text;
    double since = 0;
};
constexpr double status_seconds = 12;

struct UiState {
    Camera camera;
    double fit_distance = 6;      // camera distance of the last fit (zoom 100%)
    bool camera_needs_fit = true; // fit once the view's size is known
    double zoom_after_fit = 1.0;  // applied once after that first fit (`isoparm render --camera`)
    ViewMode view_mode = ViewMode::workstation;
    bool headless = false;           // deterministic frames: no timings, no settings
    bool presentation = false;       // classroom mode: large fonts, thick lines, high contrast
    bool fullscreen = false;         // the window covers its monitor (F11)
    bool fullscreen_request = false; // F11 pressed: the window loop toggles full screen
    float content_scale = 1;         // HiDPI factor from the window system
    float font_scale_built = 0;

    Layout layout;
    LayoutInput layout_input;
    Rect view_rect; // the 3D image, in ImGui pixels
    int view_fb_width = 1, view_fb_height = 1;
    ViewDrag drag;
    TransformSliders sliders;
    PlaneDrag plane_drag;
    bool indicator_drag = false;
    bool hint_waiting = false; // a canvas hint waits for the pointer to rest (canvas_hint.hpp)
    KnotDrag knot_drag;
    TrimDrawing trim_drawing;
    bool smooth_loops = false; // drawn loops are smooth: Surface > Trim, or C while drawing
    DeBoorPlayer deboor;
    ActionNote action_note;

    NewSurfaceForm new_surface;
    FileDialog file_dialog;
    // A stopped recording waiting to be saved (the save dialog is open for it), and whether to
    // open that dialog at the next frame (another scene was opened while recording).
    std::unique_ptr<scene::Recorder> finished_recording;
    bool offer_recording_save = false;
    // Where the 3D view's panel is this frame (the lesson bar sits over it).
    Rect drawing_rect;
    // The lesson being played (File > Open lesson), or null.
    std::unique_ptr<Lesson> lesson;
    CourseState course; // lesson editor, exercise, authoring dialogs (ui/course_state.hpp)
    PendingAction pending;
    bool confirm_unsaved = false;
    bool confirm_overwrite_changed = false; // Save found the file changed on disk: ask
    bool show_error = false;
    std::string error_title, error_message;
    bool show_about = false;
    bool quit_now = false; // the window loop should close

    std::vector<KeyPress> key_presses; // filled by the window loop, consumed by shortcuts
    double frame_ms = 0; // work per frame (build, render, swap), smoothed; set by the window loop
    std::string status;  // last message (errors of refused edits)
    StatusAge status_age;
    HeatMapCache heat;
    // The triangle's panels (ui/panels/triangle_*.cpp): the basis heat map over the domain
    // triangle, recomputed when the degree, weights or point change; and why the last typed
    // r, s or t was refused (the indicator stays; cleared by the next accepted value or drag).
    TriangleHeat triangle_heat;
    std::string barycentric_refusal;
    ImplicitForm implicit;
    RecoveryPrompt recovery;
    CurveDesignerState curve;
    ObjectListState object_list;
    ToolboxState toolbox;
    FitState fit;
    MultiresState multires;
    BlossomState blossom;
    AnalysisView analysis; // this frame's analysis colouring (the 3D view's colour bar reads it)
    bool knot_continuity = false; // Display > Knot curves by continuity
    // The current patch group's borders in the colour of their measured continuity (Display >
    // Borders by continuity, and the Continuity tab).
    bool border_continuity = false;
    // The tracing square's rational picture: the sign of the denominator w(u, v) with its zero
    // set, and each control point's weight at its Greville point.
    bool show_denominator = false, show_weights = false;
    DenominatorView denominator;
    TriangleDenominatorView triangle_denominator; // the same picture on a domain triangle
    HomogeneousState homogeneous;
    StageState stage;
    int left_tab = 0; // the teaching tab shown below the tracing square (ui/workstation.cpp)
    // Many selected points and their handle, grid and snap, the animated parameter, the detach
    // question (ui/modeler_state.hpp).
    ModelerState modeler;
    // File > Export picture / figure / animation and Ctrl+Shift+C (ui/media_export.hpp).
    MediaExportState media_export;

    // Presentation enlarges everything by half, or by a quarter in a window under 800 px
    // high (a 1024x768 projector), where text is then 19 px and the panels still fit.
    float presentation_factor = 1.5f; // set from the window's height each frame
    float scale() const { return content_scale * (presentation ? presentation_factor : 1.0f); }
};

} // namespace isoparm::ui
