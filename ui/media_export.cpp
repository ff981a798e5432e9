// File > Export picture / figure / animation and Ctrl+Shift+C: the work, between frames.
#include "ui/media_export.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "core/scene/atomic_file.hpp"
#include "core/scene/script.hpp"
#include "ui/app_context.hpp"
#include "ui/figure/drawing_files.hpp"
#include "ui/headless/animation_job.hpp"
#include "ui/headless/animation_sequences.hpp"
#include "ui/headless/frame_capture.hpp"
#include "ui/headless/view3d_figure_capture.hpp"
#include "ui/image/png_writer.hpp"
#include "ui/lesson.hpp"
#include "ui/platform/files.hpp"
#include "ui/view/figures.hpp"

namespace isoparm::ui {

namespace fs = std::filesystem;

namespace {

std::string scene_stem(const AppContext& ctx) {
    return ctx.file_path.empty() ? std::string("untitled")
                                 : fs::path(ctx.file_path).stem().string();
}

Rect target_rect(const UiState& ui, PictureTarget t) {
    const Layout& l = ui.layout;
    switch (t) {
    case PictureTarget::view3d:
        return ui.view_rect;
    case PictureTarget::window:
        return {0, 0, ui.layout_input.width, ui.layout_input.height};
    case PictureTarget::tracing:
        return l.left[0];
    case PictureTarget::teaching_tabs:
        return l.left[1];
    case PictureTarget::right_top:
        return l.right[0];
    case PictureTarget::right_bottom:
        return l.right[1];
    }
    return ui.view_rect;
}

// A picture of what the window shows, `scale` times its pixels: the 3D view alone, the whole
// window, or a panel cut out of the whole window.
std::optional<Pixels> take_picture(const AppContext& ctx, PictureTarget target, int width,
                                   int height, float scale, bool transparent, std::string& error) {
    const UiState& ui = ctx.ui;
    const bool view3d = target == PictureTarget::view3d;
    const Rect on_screen = target_rect(ui, view3d ? target : PictureTarget::window);
    CaptureSettings cs;
    cs.width = static_cast<int>(std::lround((width > 0 ? width : on_screen.w) * scale));
    cs.height = static_cast<int>(std::lround((height > 0 ? height : on_screen.h) * scale));
    if (cs.width < 16 || cs.height < 16 || cs.width > 8192 || cs.height > 8192) {
        error = "the picture would be " + std::to_string(cs.width) + "x" +
                std::to_string(cs.height) + " pixels; it must be 16..8192 a side";
        return std::nullopt;
    }
    cs.view = view3d ? ViewMode::view3d_only : ViewMode::workstation;
    cs.scale = ui.content_scale * scale;
    cs.transparent = transparent;
    FrameCapture capture(cs);
    if (!capture.error().empty()) {
        error = capture.error();
        return std::nullopt;
    }
    copy_view_state(ctx, capture.context());
    // The same framing at another size: the view's camera keeps its distance.
    std::optional<Pixels> p = capture.capture(error);
    if (!p || view3d || target == PictureTarget::window) return p;
    const Rect r = target_rect(capture.context().ui, target);
    auto cut = crop(*p, static_cast<int>(r.x), static_cast<int>(r.y), static_cast<int>(r.w),
                    static_cast<int>(r.h));
    if (!cut) error = "that panel is not shown";
    return cut;
}

FigureOptions figure_options(const AppContext& ctx) {
    FigureOptions o;
    o.t = ctx.ui.curve.trace_t;
    o.transparent = ctx.ui.media_export.transparent;
    o.comb = ctx.ui.curve.comb || !ctx.ui.curve.frenet; // the designer's glyphs, or both
    o.frenet = ctx.ui.curve.frenet || !ctx.ui.curve.comb;
    return o;
}

// The animation's script: the lesson being played, or a sequence on the scene as it is.
std::optional<scene::Script> animation_script(const AppContext& ctx, std::string& error,
                                              bool& include_start) {
    const MediaExportState& m = ctx.ui.media_export;
    include_start = false;
    if (m.animation_source == 3) {
        if (!ctx.ui.lesson) {
            error = "no lesson is open (File > Open lesson...)";
            return std::nullopt;
        }
        include_start = true;
        return ctx.ui.lesson->script;
    }
    Sequence seq;
    seq.frames = m.frames;
    doc::Document start = ctx.doc;
    if (m.animation_source == 0) {
        seq.deboor = true;
        start.view.display.deboor = true;
    } else if (m.animation_source == 1) {
        seq.orbit = 360;
        seq.orbit_start =
            std::pair{ctx.ui.camera.yaw * 180 / M_PI, ctx.ui.camera.pitch * 180 / M_PI};
    } else {
        const doc::Object* sel = ctx.doc.selected();
        const bool point = sel && ctx.doc.view.selection.i >= 0 && (sel->surface() || sel->curve());
        if (!point) {
            error = "select a control point of a surface or a curve for a weight sweep";
            return std::nullopt;
        }
        const int i = ctx.doc.view.selection.i, j = sel->surface() ? ctx.doc.view.selection.j : -1;
        const double w = sel->surface() ? sel->surface()->weight(i, j) : sel->curve()->weights[i];
        // From a fifth of the weight to five times it: the pull of the point, both ways.
        seq.weight = WeightSweep{sel->id, i, j, w / 5, w * 5};
    }
    std::string problem;
    const auto steps = sequence_steps(seq, start, true, problem);
    if (!steps) {
        error = problem;
        return std::nullopt;
    }
    auto script = scene::script_from_json(
        {{"format", scene::script_format_name}, {"version", 1}, {"steps", *steps}}, ".");
    if (!script) {
        error = script.error().message;
        return std::nullopt;
    }
    script->start = std::move(start);
    script->scene_name = ctx.file_path;
    return std::move(script).value();
}

// One export as the dialog asked; "" (and a status line) or why not.
std::string export_now(AppContext& ctx) {
    MediaExportState& m = ctx.ui.media_export;
    const std::string path = (fs::path(m.directory) / m.name).string();
    if (m.name.empty()) return "Type a file name.";
    std::vector<std::string> inputs;
    if (!ctx.file_path.empty()) inputs.push_back(ctx.file_path);
    geom::Status usable = scene::check_output_path(path);
    if (usable) usable = scene::check_output_is_not_input(path, inputs);
    if (!usable) return usable.error().message;
    const std::string ext = fs::path(path).extension().string();
    switch (m.kind) {
    case MediaExportState::Kind::picture: {
        if (ext != ".png" && ext != ".PNG") return "A picture is a PNG: the name ends in .png.";
        std::string error;
        const auto p = take_picture(ctx, static_cast<PictureTarget>(m.target), m.width, m.height,
                                    m.scale, m.transparent, error);
        if (!p) return error;
        if (std::string problem = write_png(path, p->width, p->height, p->rgba); !problem.empty())
            return problem;
        ctx.ui.status = "Wrote " + path + " (" + std::to_string(p->width) + "x" +
                        std::to_string(p->height) + ")";
        files::hand_over(path); // the browser downloads it
        return "";
    }
    case MediaExportState::Kind::figure: {
        if (!drawing_format_of(path))
            return "A figure is .svg, .pdf, .tex (TikZ) or .png: '" + m.name + "' is none.";
        FigureOptions o = figure_options(ctx);
        geom::Expected<Drawing> d = geom::make_error_nopath(geom::ErrorCode::internal, "");
        if (m.figure_view == 6) {
            // The page at the view's shape, three quarters of its pixels in points.
            o.width = std::max(ctx.ui.view_rect.w * 0.75, 16.0);
            o.height = std::max(ctx.ui.view_rect.h * 0.75, 16.0);
            d = capture_view3d_figure(ctx, o, 2, true);
        } else {
            // The panel's own Picture where it draws one (one drawing code per view), else
            // the figure in print colours.
            std::string why;
            if (auto panel = capture_panel_figure(ctx, static_cast<FigureView>(m.figure_view),
                                                  static_cast<int>(ctx.ui.layout_input.width),
                                                  static_cast<int>(ctx.ui.layout_input.height),
                                                  ctx.ui.content_scale, why))
                d = std::move(*panel);
            else
                d = make_figure(ctx.doc, static_cast<FigureView>(m.figure_view), o);
        }
        if (!d) return d.error().message;
        if (std::string problem = write_drawing(*d, path); !problem.empty()) return problem;
        ctx.ui.status = "Wrote " + path;
        files::hand_over(path);
        return "";
    }
    case MediaExportState::Kind::animation: {
        AnimationRequest req;
        if (!video_format_of(path, req.video.format))
            return "An animation is .gif or .mp4: '" + m.name + "' is neither.";
        std::string error;
        auto script = animation_script(ctx, error, req.include_start);
        if (!script) return error;
        req.script = std::move(*script);
        req.output = path;
        req.video.fps = m.fps;
        // The 3D view's size on screen, even for H.264.
        req.video.width = std::max(16, static_cast<int>(ctx.ui.view_rect.w) / 2 * 2);
        req.video.height = std::max(16, static_cast<int>(ctx.ui.view_rect.h) / 2 * 2);
        req.view = ViewMode::view3d_only;
        req.scale = ctx.ui.content_scale;
        req.step_frames = req.include_start ? std::max(1, m.fps) : 1; // a lesson: 1 s a step
        auto job = AnimationJob::create(std::move(req), error);
        if (!job) return error;
        m.job = std::move(job);
        m.job_output = path;
        return "";
    }
    }
    return "";
}

} // namespace

void request_media_export(AppContext& ctx, MediaExportState::Kind kind) {
    MediaExportState& m = ctx.ui.media_export;
    if (m.job) return; // one animation at a time; its dialog is open
    m.kind = kind;
    m.open = m.just_opened = true;
    m.error.clear();
    if (m.directory.empty()) {
        std::error_code ec;
        m.directory = ctx.file_path.empty() ? fs::current_path(ec).string()
                                            : fs::path(ctx.file_path).parent_path().string();
        if (m.directory.empty()) m.directory = ".";
    }
    const std::string stem = scene_stem(ctx);
    switch (kind) {
    case MediaExportState::Kind::picture:
        m.name = stem + ".png";
        break;
    case MediaExportState::Kind::figure:
        m.name = stem + "-figure.svg";
        break;
    case MediaExportState::Kind::animation:
        m.name = stem + ".gif";
        break;
    }
}

void run_media_exports(AppContext& ctx) {
    MediaExportState& m = ctx.ui.media_export;
    if (m.clipboard_pending) {
        m.clipboard_pending = false;
        std::string error;
        const auto p = take_picture(ctx, PictureTarget::view3d, 0, 0, 1, false, error);
        const auto png = p ? encode_png(p->width, p->height, p->rgba) : std::nullopt;
        if (p && !png) error = "out of memory encoding the picture";
        if (png) error = files::copy_picture(*png);
        ctx.ui.status = error.empty() ? "Copied the 3D view (" + std::to_string(p->width) + "x" +
                                            std::to_string(p->height) + ") to the clipboard"
                                      : "Copy picture: " + error;
    }
    if (m.pending) {
        m.pending = false;
        m.error = export_now(ctx);
        if (m.error.empty() && !m.job) m.open = false;
    }
    if (m.job) {
        // About a twentieth of a second of frames per window frame: the window stays
        // responsive (Cancel, the progress bar) while the animation renders.
        const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(50);
        while (!m.job->finished() && std::chrono::steady_clock::now() < until) {
            if (std::string problem = m.job->step(); !problem.empty()) {
                m.error = problem;
                m.job.reset();
                return;
            }
        }
        if (m.job->finished()) {
            ctx.ui.status =
                "Wrote " + m.job_output + " (" + std::to_string(m.job->frames_done()) + " frames)";
            m.job.reset();
            m.open = false;
        }
    }
}

} // namespace isoparm::ui
