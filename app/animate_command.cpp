// `isoparm animate INPUT -o FILE.gif|mp4`: a script or lesson (docs/script-format.md), or a
// scene with a generated sequence (de Boor's steps, a weight or knot sweep, a camera orbit),
// rendered frame by frame through EGL (no display needed) and encoded as GIF or MP4.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <unistd.h>

#include "app/command_run.hpp"
#include "app/commands.hpp"
#include "app/view_options.hpp"
#include "core/json/out_of_memory.hpp"
#include "core/scene/atomic_file.hpp"
#include "core/scene/scene_io.hpp"
#include "core/scene/script.hpp"
#include "ui/headless/animation_job.hpp"
#include "ui/headless/animation_sequences.hpp"
#include "ui/headless/egl_context.hpp"
#include "ui/view/camera.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/kinds/kind_view.hpp"
#include "ui/view/triangle_domain.hpp"

namespace isoparm::app {

namespace {

using nlohmann::json;

struct AnimateOptions {
    std::string input, output, size = "640x400", view = "3d";
    int fps = 10, step_frames = 0, frames = 40;
    bool deboor = false;
    double orbit = 0;
    std::string camera, sweep_weight, sweep_knot;
    bool quiet = false;
};

const char* const name = "isoparm animate: ";

bool is_script_file(const std::string& path) {
    std::ifstream in(path);
    const json j = json::parse(in, nullptr, false);
    return j.is_object() && j.contains("format") && j["format"] == scene::script_format_name;
}

// "a:b:c" -> {"a", "b", "c"}.
std::vector<std::string> split(const std::string& text) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const auto c = text.find(':', start);
        parts.push_back(text.substr(start, c == std::string::npos ? std::string::npos : c - start));
        if (c == std::string::npos) return parts;
        start = c + 1;
    }
}

// The options as a sequence for the scene `d`; "" or why they do not fit it.
std::string sequence_of(const AnimateOptions& o, const doc::Document& d, ui::Sequence& seq) {
    seq.deboor = o.deboor;
    seq.orbit = o.orbit;
    seq.frames = o.frames;
    if (!o.camera.empty()) {
        const auto yp = numbers(o.camera, 2, 2);
        if (!yp) return "--camera '" + o.camera + "' must be YAW,PITCH in degrees";
        seq.orbit_start = std::pair{(*yp)[0], (*yp)[1]};
    }
    if (o.sweep_weight.empty() && o.sweep_knot.empty()) return "";
    const doc::Object* obj = ui::sweep_object(d);
    if (!obj) return "a sweep needs a surface or a curve in the scene";
    if (!o.sweep_weight.empty()) {
        const std::vector<std::string> parts = split(o.sweep_weight); // I[,J]:FROM:TO
        const auto ij = parts.size() == 3 ? numbers(parts[0], 1, 2) : std::nullopt;
        const auto from = parts.size() == 3 ? numbers(parts[1], 1, 1) : std::nullopt;
        const auto to = parts.size() == 3 ? numbers(parts[2], 1, 1) : std::nullopt;
        if (!ij || !from || !to || ij->size() != (ui::two_index_points(obj->shape) ? 2u : 1u))
            return "--sweep-weight '" + o.sweep_weight +
                   "' must be I,J:FROM:TO for a surface or I:FROM:TO for a curve (" + obj->name +
                   ")";
        seq.weight = ui::WeightSweep{obj->id, static_cast<int>((*ij)[0]),
                                     ij->size() == 2 ? static_cast<int>((*ij)[1]) : -1, (*from)[0],
                                     (*to)[0]};
    }
    if (!o.sweep_knot.empty()) {
        const std::vector<std::string> parts = split(o.sweep_knot); // DIR:K:FROM:TO
        const auto k = parts.size() == 4 ? numbers(parts[1], 1, 1) : std::nullopt;
        const auto a = parts.size() == 4 ? numbers(parts[2], 1, 1) : std::nullopt;
        const auto b = parts.size() == 4 ? numbers(parts[3], 1, 1) : std::nullopt;
        if (!k || !a || !b || (parts[0] != "u" && parts[0] != "v"))
            return "--sweep-knot '" + o.sweep_knot +
                   "' must be DIR:K:FROM:TO, e.g. u:4:0.2:0.8 (knot 4 of the u knots)";
        seq.knot = ui::KnotSweep{obj->id, parts[0] == "u" ? geom::Dir::u : geom::Dir::v,
                                 static_cast<int>((*k)[0]), (*a)[0], (*b)[0]};
    }
    return "";
}

// The generated steps for `d`, or why not.
std::string generated_steps(const AnimateOptions& o, const doc::Document& d, json& steps,
                            bool deboor_on) {
    ui::Sequence seq;
    if (std::string bad = sequence_of(o, d, seq); !bad.empty()) return bad;
    std::string error;
    auto made = ui::sequence_steps(seq, d, deboor_on, error);
    if (!made) return error;
    steps = std::move(*made);
    return "";
}

void show_progress(int done, int total) {
    const int width = 30;
    const int filled = total ? done * width / total : width;
    std::fprintf(stderr, "\ranimate [%s%s] %d/%d frames", std::string(filled, '#').c_str(),
                 std::string(width - filled, '.').c_str(), done, total);
    std::fflush(stderr);
}

int run(const AnimateOptions& o) {
    ui::AnimationRequest req;
    if (!ui::video_format_of(o.output, req.video.format)) {
        std::cerr << name << "-o '" << o.output << "' must end in .gif or .mp4\n";
        return 2;
    }
    const auto size = picture_size(o.size);
    if (!size) {
        std::cerr << name << "--size '" << o.size << "' must be WxH, e.g. 640x400\n";
        return 2;
    }
    req.video.width = size->first;
    req.video.height = size->second;
    req.video.fps = o.fps;
    if (std::string bad = ui::check_video_settings(req.video); !bad.empty()) {
        std::cerr << name << bad << "\n";
        return 2;
    }
    geom::Status usable = scene::check_output_path(o.output);
    if (usable) usable = scene::check_output_is_not_input(o.output, {o.input});
    if (!usable) {
        std::cerr << name << usable.error().message << "\n";
        return 2;
    }
    const bool generated =
        o.deboor || o.orbit != 0 || !o.sweep_weight.empty() || !o.sweep_knot.empty();
    if (is_script_file(o.input)) {
        auto script = scene::load_script(o.input);
        if (!script) {
            std::cerr << name << o.input << ": " << script.error().message << "\n";
            return 2;
        }
        req.script = std::move(script).value();
        if (generated) {
            json steps = json::array();
            if (std::string bad = generated_steps(o, req.script.start, steps, false);
                !bad.empty()) {
                std::cerr << name << bad << "\n";
                return 2;
            }
            // Appended after the script's own steps, read by the one strict reader.
            auto extra = scene::script_from_json(
                {{"format", scene::script_format_name}, {"version", 1}, {"steps", steps}}, ".");
            if (!extra) {
                std::cerr << name << extra.error().message << "\n";
                return 2;
            }
            for (scene::Step& s : extra->steps) req.script.steps.push_back(std::move(s));
        }
    } else {
        auto loaded = scene::load_scene(o.input);
        if (!loaded) {
            std::cerr << name << "'" << o.input
                      << "' is neither a script nor a scene: " << loaded.error().message << "\n";
            return 2;
        }
        if (!generated) {
            std::cerr << name
                      << "a scene needs a sequence to animate: --deboor, --orbit DEGREES, "
                         "--sweep-weight or --sweep-knot (or give a script)\n";
            return 2;
        }
        doc::Document d = std::move(loaded).value();
        ui::normalize_selection(d);
        if (o.deboor) d.view.display.deboor = true;
        json steps = json::array();
        if (std::string bad = generated_steps(o, d, steps, true); !bad.empty()) {
            std::cerr << name << bad << "\n";
            return 2;
        }
        auto script = scene::script_from_json(
            {{"format", scene::script_format_name}, {"version", 1}, {"steps", steps}}, ".");
        if (!script) {
            std::cerr << name << script.error().message << "\n";
            return 2;
        }
        req.script = std::move(script).value();
        req.script.start = std::move(d);
        req.script.scene_name = o.input;
        req.include_start = false; // the sequence's first step is its first picture
    }
    req.output = o.output;
    req.view = o.view == "workstation" ? ui::ViewMode::workstation : ui::ViewMode::view3d_only;
    req.step_frames = o.step_frames > 0 ? o.step_frames : (generated ? 1 : std::max(1, o.fps / 2));
    std::string error;
    std::unique_ptr<ui::AnimationJob> job = ui::AnimationJob::create(std::move(req), error);
    if (!job) {
        std::cerr << name << o.input << ": " << error << "; nothing was written\n";
        return 2;
    }
    const std::unique_ptr<ui::EglContext> egl = ui::EglContext::create(error);
    if (!egl) {
        std::cerr << name << "no headless OpenGL: " << error << "\n";
        return 1;
    }
    const bool tty = !o.quiet && isatty(STDERR_FILENO);
    const auto t0 = std::chrono::steady_clock::now();
    while (!job->finished()) {
        if (std::string problem = job->step(); !problem.empty()) {
            if (tty) std::fputc('\n', stderr);
            std::cerr << name << problem << "; nothing was written\n";
            return 1;
        }
        if (tty) show_progress(job->frames_done(), job->total_frames());
    }
    if (tty) std::fputc('\n', stderr);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!o.quiet)
        std::fprintf(stderr, "isoparm animate: wrote %s: %d frames, %dx%d, %d fps, in %.1f s\n",
                     o.output.c_str(), job->frames_done(), size->first, size->second, o.fps,
                     seconds);
    return 0;
}

} // namespace

Action register_animate_command(CLI::App& app) {
    CLI::App* sub = app.add_subcommand(
        "animate", "A script, lesson or generated sequence as an animated GIF or an MP4 (H.264), "
                   "rendered without a display (EGL)");
    auto o = std::make_shared<AnimateOptions>();
    sub->add_option("INPUT", o->input,
                    "a script or lesson (docs/script-format.md), or a scene with --deboor, "
                    "--orbit, --sweep-weight or --sweep-knot")
        ->required();
    sub->add_option("-o,--output", o->output, "the animation: .gif or .mp4")->required();
    sub->add_option("--size", o->size, "frame size WxH in pixels (default 640x400; even for MP4)");
    sub->add_option("--fps", o->fps, "frames per second (default 10)");
    sub->add_option("--view", o->view, "3d (the 3D view alone, the default) or workstation")
        ->check(CLI::IsMember({"3d", "workstation"}));
    sub->add_option("--step-frames", o->step_frames,
                    "frames each step's picture is held (default: half a second for a script, "
                    "1 for a generated sequence)");
    sub->add_option("--frames", o->frames, "pictures in a sweep or an orbit (default 40)")
        ->check(CLI::Range(2, 10000));
    sub->add_flag("--deboor", o->deboor,
                  "de Boor's construction at the indicator, one step a picture");
    sub->add_option("--orbit", o->orbit, "turn the camera by DEGREES about the vertical");
    sub->add_option("--camera", o->camera, "the orbit's start YAW,PITCH in degrees");
    sub->add_option("--sweep-weight", o->sweep_weight,
                    "I,J:FROM:TO (a surface's point) or I:FROM:TO (a curve's): its weight from "
                    "FROM to TO over --frames pictures");
    sub->add_option("--sweep-knot", o->sweep_knot,
                    "DIR:K:FROM:TO: knot K of the u or v knots moved from FROM to TO");
    sub->add_flag("--quiet", o->quiet, "no progress bar and no summary");
    return [o]() -> int { return run_memory_guarded([&o] { return run(*o); }, name); };
}

} // namespace isoparm::app
