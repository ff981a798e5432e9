// The modelling aids' UI state (issue #32): many selected points and their handle, grid and
// snap, the animated parameter and its preview, and the question asked before a constructed
// object's own points are edited. None of it is document data, none of it is undoable.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/doc/animated.hpp"
#include "core/doc/command_spec.hpp"
#include "ui/view/animation.hpp"
#include "ui/view/point_selection.hpp"
#include "ui/view/snap.hpp"

namespace isoparm::ui {

// Where the selection's handle turns and scales about.
enum class PivotChoice { centroid, point };

// A gesture on the selection: a box being drawn (3D view or a plane canvas), or the handle held.
struct SelectionGesture {
    enum class Kind { none, box, handle } kind = Kind::none;
    int view = -1;               // -1 the 3D view, 0..2 the control point planes
    glm::dvec2 press{0}, now{0}; // pixels
    bool add = false;            // Shift: the box adds to the selection
    HandlePart part = HandlePart::none;
    std::vector<PointIndex> points; // the points the handle moves, at the press
    std::vector<glm::dvec3> start;  // their positions at the press
    glm::dvec3 pivot{0};
    glm::dvec2 pivot_px{0};
    bool toward_viewer = true; // the held ring's axis points at the viewer
};

struct SelectionState {
    PointSelection points;
    SelectionGesture gesture;
    PivotChoice pivot = PivotChoice::centroid;
    glm::dvec3 chosen_pivot{0};
    int symmetry = -1; // symmetric editing about x = 0 (0), y = 0 (1), z = 0 (2); -1 off
    // The typed transform's fields (Control point panel, "Selection").
    double move[3] = {0, 0, 0};
    double turn_degrees = 90;
    int turn_axis = 2;
    double scale[3] = {2, 2, 2};
    int mirror_axis = 0;
    bool handle = true; // the handle drawn at the pivot
};

struct SnapState {
    SnapSettings settings;
    // The grid in the planes, the curve canvas and the 3D view: off until G (Display > Grid),
    // so the teaching pictures (and their golden renders) stay as they were.
    bool grid_shown = false;
    bool snapping = true;    // View > Snap (Alt held during a drag turns it off)
    double min_grid_px = 18; // the finest grid lines' spacing, pixels at scale 1
};

// The animated parameter (Display > Animate..., a lesson's animate step): the player and what
// it shows on the document now (restored before any command, save or close).
struct AnimationState {
    bool open = false;   // the Animate panel is shown
    bool focus = false;  // bring it forward at the next frame (just opened)
    bool active = false; // a target is set (the slider shows it)
    AnimationPlayer player;
    std::optional<doc::PreviewUndo> preview;
    double shown_value = 0; // the value the preview shows
    double last_time = -1;  // the window clock at the last advance
    std::string error;      // why the target or a value was refused
    int deboor_step = -1;   // the step shown by a de Boor animation
    // The panel's form: what to animate and its range (doc::AnimatedKind's order).
    int form_kind = 0;
    double form_from = 0, form_to = 5;
    int form_dir = 0, form_k = 4; // a knot's direction (0 u, 1 v) and index
    double form_seconds = 4;
    int form_repeat = 2; // doc::Repeat: once, loop, bounce
};

// An edit of a constructed object's own points asks first (core/doc/associative.hpp): a drag
// asks at its press (and is dragged again once detached); a command (a menu's split, a typed
// value, a knot) that was refused waits in `then` and runs right after Detach.
struct DetachQuestion {
    std::uint64_t object = 0;
    std::string text;
    std::optional<doc::CommandSpec> then;
    std::string then_label; // "Split knot v = 0.5 (x2)"
    bool open = false;
};

struct ModelerState {
    SelectionState selection;
    SnapState snap;
    AnimationState animation;
    DetachQuestion detach;
};

} // namespace isoparm::ui
