// Scripts (docs/script-format.md): a starting scene and steps (document commands, view
// changes, screenshots, captions, pauses and checks on the document), read strictly and run
// without a window. `isoparm script` renders the screenshots; lessons and recordings are
// scripts too.
#pragma once

#include <functional>
#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/doc/animated.hpp"
#include "core/doc/command.hpp"
#include "core/doc/command_spec.hpp"
#include "core/doc/document.hpp"
#include "core/geom/status.hpp"
#include "core/scene/expect.hpp"

namespace isoparm::scene {

inline constexpr const char* script_format_name = "isoparm-script";
inline constexpr int script_format_version = 1;

// The screenshots' budget: one picture at most 4096 x 4096 pixels (about 0.7 GB to render with
// its multisampled buffers), all of a script's together at most 3e8 (about 300 pictures of
// 1280 x 800), checked when the script is read, before anything runs.
inline constexpr double max_screenshot_pixels = 4096.0 * 4096.0;
inline constexpr double max_script_pixels = 3e8;
// The steps' budget: at most 100,000 steps (checked when the script is read), each command
// within the protocol's work budget, and the trial run (run_script with dry_run), which does
// every command's work, stops with `limit` at the step it reaches after this many seconds.
inline constexpr double max_trial_seconds = 120;

// Why `name` is not a screenshot's file name ("" when it is one): checked byte by byte (a NUL
// would end the name the system sees early), no separators or control characters, no leading
// dot, ending in .png.
std::string screenshot_name_problem(const std::string& name);

// View steps: they change what is looked at, not the scene's geometry (no undo step).
struct UndoStep {};
struct RedoStep {};
struct SelectStep {
    nlohmann::json selection; // as a scene file's "selection" (checked against the document)
};
struct IndicatorStep {
    glm::dvec2 uv{0.5, 0.5}; // over the current domain, in [0, 1]^2
};
struct BarycentricStep {
    geom::Barycentric rst{1.0 / 3, 1.0 / 3, 1.0 / 3}; // a triangle's indicator (r, s, t)
};
struct DisplayStep {
    nlohmann::json display; // as a scene file's "display"; members not named keep their value
};
// One object's own display toggles ({"object_display": {"object": id, "control_points": ...}});
// members not named keep the object's value.
struct ObjectDisplayStep {
    std::uint64_t object = 0;
    nlohmann::json display;
};
struct ContinuityStep {
    doc::Continuity mode = doc::Continuity::off;
};
// The 3D view's camera for the screenshots that follow (degrees; zoom in percent of the
// fit-to-view distance).
struct CameraStep {
    double yaw_degrees = 0, pitch_degrees = 0;
    std::optional<double> zoom_percent;
};
// De Boor's construction shown up to this step in the screenshots that follow (-1: all).
struct DeBoorStep {
    int step = -1;
};
enum class ShotView { workstation, view3d };
struct ScreenshotStep {
    std::string name; // a file name ending in .png, no folders
    ShotView view = ShotView::workstation;
    int width = 1280, height = 800;
};
struct CaptionStep {
    std::string text;
};
struct PauseStep {};
// An animated parameter (docs/script-format.md, "animate"): a lesson played in the window runs
// it on its slider; `isoparm script`'s screenshots after it show the value at phase `at` as a
// preview. It never edits the document. `stop` ends the animation shown.
struct AnimateStep {
    doc::AnimationTarget target;
    double seconds = 4, speed = 1;
    doc::Repeat repeat = doc::Repeat::bounce;
    double at = 0; // the phase in [0, 1] the screenshots show
    bool play = true;
    bool stop = false;
};
using StepAction =
    std::variant<doc::CommandSpec, UndoStep, RedoStep, SelectStep, IndicatorStep, DisplayStep,
                 ContinuityStep, CameraStep, DeBoorStep, ScreenshotStep, CaptionStep, PauseStep,
                 ExpectStep, BarycentricStep, AnimateStep, ObjectDisplayStep>;

struct Step {
    StepAction action;
    std::string path;                // "/steps/12", for every message about this step
    nlohmann::json source = nullptr; // the step as written (the lesson editor writes it back)
};

struct Script {
    doc::Document start;
    std::string scene_name; // the starting scene's file, "(inline)" or "(default)"
    std::vector<Step> steps;
    // What the Lessons menu shows: a title and a one-line summary (both optional).
    std::string title, summary;
};

// Reads a script: the format and version, the starting scene ("scene": a path relative to
// `script_dir`, or a scene object inline; absent: the default scene) and every step, each
// checked for its form with its path ("/steps/12/point"). Whether a step applies to the
// document as it is then is found by running it (run_script with dry_run).
geom::Expected<Script> script_from_json(const nlohmann::json& j, const std::string& script_dir);
// The same from a file: strict JSON (duplicate keys refused), a regular file of at most 64 MiB.
geom::Expected<Script> load_script(const std::string& path);

// The state a script runs in: the document and its history (its own, or the window's), and
// what screenshots show beyond the document (camera, de Boor step, caption).
struct ScriptState {
    // A state of its own, starting from `start` (isoparm script, tests).
    explicit ScriptState(doc::Document start)
        : own_doc_(std::move(start)), doc(own_doc_), history(own_history_) {}
    // The window's document and history (a lesson played in the workstation).
    ScriptState(doc::Document& d, doc::History& h) : doc(d), history(h) {}
    ScriptState(const ScriptState&) = delete;
    ScriptState& operator=(const ScriptState&) = delete;

private:
    doc::Document own_doc_;
    doc::History own_history_;

public:
    doc::Document& doc;
    doc::History& history;
    std::optional<CameraStep> camera;
    int deboor_step = -1;
    std::string caption;
    std::optional<AnimateStep> animation; // the last animate step, until a stop
};

struct ScriptHooks {
    // Renders the state to `step.name`; "" or the reason it failed. Not called in a dry run.
    std::function<std::string(const ScriptState&, const ScreenshotStep&)> screenshot;
    // A caption or a pause reached (a window shows them; a headless run may print them).
    std::function<void(const ScriptState&, const Step&)> caption, pause;
};

struct ScriptResult {
    // The first step that could not be carried out (a refused command, a selection of a
    // missing object, a screenshot that failed): the run stopped there.
    std::optional<geom::Error> stopped;
    // Every expect that did not hold, one sentence each naming its step.
    std::vector<std::string> failed_expects;
    std::vector<std::string> screenshots; // names written, in order
    bool ok() const { return !stopped && failed_expects.empty(); }
};

// Runs the steps in order on `state` (which starts as script.start). In a dry run no hook is
// called: it finds every step that cannot be carried out before anything is written, and the
// steps that would take more than `trial_seconds` (a dry run only).
ScriptResult run_script(const Script& script, ScriptState& state, const ScriptHooks& hooks,
                        bool dry_run = false, double trial_seconds = max_trial_seconds);

// One step (the runner's and a lesson player's unit). Returns the refusal, with the step's path.
geom::Status run_step(const Step& step, ScriptState& state, const ScriptHooks& hooks, bool dry_run,
                      ScriptResult& result);

} // namespace isoparm::scene
