// `isoparm script FILE [--out DIR] [--check GOLDEN_DIR]`: runs a script (docs/script-format.md)
// without a display, writes its screenshots through EGL, checks its expectations and, with
// --check, compares every screenshot with the golden image of the same name.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "app/commands.hpp"
#include "core/doc/animated.hpp"
#include "core/json/out_of_memory.hpp"
#include "core/scene/atomic_file.hpp"
#include "core/scene/scene_io.hpp"
#include "core/scene/script.hpp"
#include "ui/app_context.hpp"
#include "ui/headless/headless_render.hpp"
#include "ui/image/png_compare.hpp"
#include "ui/view/camera.hpp"
#include "ui/view/current_patch.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/scene_budget.hpp"

namespace isoparm::app {

namespace {

struct ScriptOptions {
    std::string file;
    std::string out = ".";
    std::string check;
    std::string save; // the scene at the end of the script
    double tolerance = 16;
    double max_fraction = 0.002;
};

std::string where(const geom::Error& e) {
    return e.has_path && !e.path.empty() ? " (at " + e.path + ")" : "";
}

// The 3D view's camera as the window keeps it: fitted to the scene at the first screenshot of
// each view and size (and again after a camera step), then left where it is while the scene
// is edited, so that pictures of one sequence compare.
struct CameraMemory {
    std::map<std::tuple<int, int, int>, ui::Camera> fitted;
    std::optional<scene::CameraStep> applied;
};

bool same_step(const std::optional<scene::CameraStep>& a,
               const std::optional<scene::CameraStep>& b) {
    if (a.has_value() != b.has_value()) return false;
    return !a || (a->yaw_degrees == b->yaw_degrees && a->pitch_degrees == b->pitch_degrees &&
                  a->zoom_percent == b->zoom_percent);
}

// What a screenshot shows beyond the document: the camera and de Boor's step, and the current
// patch under the indicator (as the window follows it).
std::string configure_shot(const scene::ScriptState& state, const std::tuple<int, int, int>& key,
                           CameraMemory& memory, ui::AppContext& ctx) {
    if (!same_step(state.camera, memory.applied)) {
        memory.fitted.clear();
        memory.applied = state.camera;
    }
    if (const auto kept = memory.fitted.find(key); kept != memory.fitted.end()) {
        ctx.ui.camera = kept->second;
        ctx.ui.camera_needs_fit = false;
    } else if (state.camera) {
        ctx.ui.camera.yaw = state.camera->yaw_degrees * M_PI / 180.0;
        ctx.ui.camera.pitch = state.camera->pitch_degrees * M_PI / 180.0;
        if (state.camera->zoom_percent) ctx.ui.zoom_after_fit = *state.camera->zoom_percent / 100.0;
    }
    ctx.ui.deboor.step = state.deboor_step;
    if (state.animation && state.animation->target.kind == doc::AnimatedKind::deboor_step)
        ctx.ui.deboor.step = doc::step_at(state.animation->target, state.animation->at);
    const doc::Object* current = nullptr;
    if (ui::current_surface(ctx.doc, &current)) ui::follow_indicator(ctx.doc, current->id);
    return "";
}

// --save and --out are checked before anything runs; returns why they are refused, or "".
std::string refuse_output_paths(const ScriptOptions& o, const scene::Script& script) {
    if (!o.save.empty()) {
        geom::Status usable = scene::check_output_path(o.save);
        if (usable) usable = scene::check_output_is_not_input(o.save, {o.file, script.scene_name});
        if (!usable) return "--save: " + usable.error().message;
    }
    // The pictures are written to --out and compared with --check: one folder for both would
    // overwrite every golden image with the picture it is then compared with (a match, always).
    if (!o.check.empty()) {
        std::error_code same_ec;
        const bool same = std::filesystem::equivalent(o.out, o.check, same_ec) ||
                          std::filesystem::weakly_canonical(o.out, same_ec) ==
                              std::filesystem::weakly_canonical(o.check, same_ec);
        if (same)
            return "--out '" + o.out + "' is the --check folder '" + o.check +
                   "': the screenshots would replace the golden images they are compared "
                   "with; give another --out; nothing was written";
    }
    return "";
}

// Every step is tried first without writing anything: a step that cannot be carried out
// stops the script before its first screenshot. Returns the exit code of a refusal, or 0.
int dry_run(const ScriptOptions& o, const scene::Script& script, const std::string& name) {
    json_io::arm_memory_reserve();
    try {
        scene::ScriptState trial(script.start);
        const scene::ScriptResult dry = scene::run_script(script, trial, {}, /*dry_run=*/true);
        if (dry.stopped) {
            std::cerr << name << o.file << ": " << dry.stopped->message << where(*dry.stopped)
                      << "; nothing was written\n";
            return 2;
        }
    } catch (const std::bad_alloc&) {
        std::cerr << name << json_io::out_of_memory_message << " (trying '" << o.file
                  << "'); nothing was written\n";
        return 1;
    }
    return 0;
}

// The script's screenshot step: one headless session, made at the first picture.
struct ShotTaker {
    const ScriptOptions& o;
    const scene::Script& script;
    std::unique_ptr<ui::HeadlessSession> session;
    CameraMemory cameras;
    std::string session_error;
    std::error_code ec;

    std::string take(const scene::ScriptState& state, const scene::ScreenshotStep& shot) {
        if (!session) {
            std::filesystem::create_directories(o.out, ec);
            if (ec) return "cannot create the folder '" + o.out + "': " + ec.message();
            // Under `ulimit -v` the driver crashes when its malloc fails: refused first, as
            // `isoparm render` does.
            if (std::string short_of =
                    ui::memory_limit_problem(state.doc, ui::display_driver_bytes);
                !short_of.empty())
                return short_of;
            session = ui::HeadlessSession::create(session_error);
            if (!session) return session_error;
        }
        ui::HeadlessRequest req;
        req.scene_path = script.scene_name;
        req.output = (std::filesystem::path(o.out) / shot.name).string();
        req.width = shot.width;
        req.height = shot.height;
        req.view = shot.view == scene::ShotView::view3d ? ui::ViewMode::view3d_only
                                                        : ui::ViewMode::workstation;
        const std::tuple<int, int, int> key{static_cast<int>(shot.view), shot.width, shot.height};
        req.configure = [&state, this, key](ui::AppContext& ctx) {
            return configure_shot(state, key, cameras, ctx);
        };
        req.rendered = [this, key](const ui::AppContext& ctx) {
            cameras.fitted[key] = ctx.ui.camera;
        };
        if (!state.animation) return session->render(state.doc, req);
        // An animation's frame: its value at the step's phase, shown on a copy (never an edit).
        doc::Document shown = state.doc;
        const doc::AnimationTarget& t = state.animation->target;
        auto preview = doc::show_preview(shown, t, doc::value_at(t, state.animation->at),
                                         doc::indicator_at(t, state.animation->at));
        if (!preview) return preview.error().message;
        return session->render(shown, req);
    }
};

// --check: every screenshot against its golden image; returns the differing ones, each with
// why (and a diff picture beside it where the sizes agree).
std::vector<std::string> compare_with_golden(const ScriptOptions& o,
                                             const std::vector<std::string>& screenshots) {
    std::vector<std::string> mismatches;
    for (const std::string& shot : screenshots) {
        const std::string golden_path = (std::filesystem::path(o.check) / shot).string();
        const std::string actual_path = (std::filesystem::path(o.out) / shot).string();
        std::string error;
        const auto golden = ui::read_image(golden_path, error);
        const auto actual = golden ? ui::read_image(actual_path, error) : std::nullopt;
        if (!golden || !actual) {
            mismatches.push_back(shot + ": " + error);
            continue;
        }
        const ui::ImageComparison c =
            ui::compare_images(*golden, *actual, o.tolerance, o.max_fraction);
        std::cout << shot << ": " << c.summary << "\n";
        if (c.match) continue;
        std::string line = shot + ": " + c.summary;
        const std::string diff =
            (std::filesystem::path(o.out) / std::filesystem::path(shot).stem()).string() +
            ".diff.png";
        if (c.same_size) {
            if (const std::string problem = ui::write_diff_image(diff, *golden, c); problem.empty())
                line += " (diff: " + diff + ")";
        }
        mismatches.push_back(line);
    }
    return mismatches;
}

int run(const ScriptOptions& o) {
    const std::string name = "isoparm script: ";
    auto loaded = scene::load_script(o.file);
    if (!loaded) {
        std::cerr << name << o.file << ": " << loaded.error().message << where(loaded.error())
                  << "\n";
        return 2;
    }
    const scene::Script& script = *loaded;
    if (const std::string refused = refuse_output_paths(o, script); !refused.empty()) {
        std::cerr << name << refused << "\n";
        return 2;
    }
    if (const int refused = dry_run(o, script, name)) return refused;

    ShotTaker shots{o, script, nullptr, {}, {}, {}};
    scene::ScriptHooks hooks;
    hooks.screenshot = [&shots](const scene::ScriptState& state,
                                const scene::ScreenshotStep& shot) {
        return shots.take(state, shot);
    };
    hooks.caption = [](const scene::ScriptState&, const scene::Step& step) {
        std::cout << step.path << ": " << std::get<scene::CaptionStep>(step.action).text << "\n";
    };

    scene::ScriptState state(script.start);
    json_io::arm_memory_reserve();
    scene::ScriptResult result;
    try {
        result = scene::run_script(script, state, hooks);
    } catch (const std::bad_alloc&) {
        std::cerr << name << json_io::out_of_memory_message << " (running '" << o.file << "')\n";
        return 1;
    }
    if (result.stopped) {
        std::cerr << name << o.file << ": " << result.stopped->message << where(*result.stopped)
                  << "\n";
        return 1;
    }

    if (!o.save.empty()) {
        if (const geom::Status saved = scene::save_scene(state.doc, o.save); !saved) {
            std::cerr << name << saved.error().message << "\n";
            return 1;
        }
    }

    const std::vector<std::string> mismatches =
        o.check.empty() ? std::vector<std::string>{} : compare_with_golden(o, result.screenshots);
    for (const std::string& f : result.failed_expects) std::cerr << "expect failed: " << f << "\n";
    for (const std::string& m : mismatches) std::cerr << "screenshot differs: " << m << "\n";
    std::cout << script.steps.size() << " steps, " << result.screenshots.size() << " screenshots"
              << (o.check.empty() ? "" : ", " + std::to_string(mismatches.size()) + " differing")
              << ", " << result.failed_expects.size() << " failed expectations\n";
    return result.failed_expects.empty() && mismatches.empty() ? 0 : 1;
}

} // namespace

Action register_script_command(CLI::App& app) {
    CLI::App* sub = app.add_subcommand(
        "script", "Run a script (docs/script-format.md) without a display: its commands, "
                  "screenshots (EGL) and expectations");
    auto o = std::make_shared<ScriptOptions>();
    sub->add_option("FILE", o->file, "the script (JSON)")->required();
    sub->add_option("--out", o->out, "folder for the screenshots (default: the current folder)");
    sub->add_option("--check", o->check,
                    "compare every screenshot with the golden image of the same name in this "
                    "folder; a diff image NAME.diff.png is written beside each that differs");
    sub->add_option("--save", o->save, "save the scene as the script leaves it to this file");
    sub->add_option("--tolerance", o->tolerance,
                    "per-pixel tolerance for --check: a channel may differ by this much (0..255, "
                    "default 16)")
        ->check(CLI::Range(0.0, 255.0));
    sub->add_option("--max-fraction", o->max_fraction,
                    "for --check: the fraction of pixels allowed to differ (0..1, default 0.002)")
        ->check(CLI::Range(0.0, 1.0));
    return [o]() { return run(*o); };
}

} // namespace isoparm::app
