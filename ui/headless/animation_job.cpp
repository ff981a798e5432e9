#include "ui/headless/animation_job.hpp"

#include <algorithm>
#include <cmath>

#include "ui/headless/frame_capture.hpp"
#include "ui/view/camera.hpp"
#include "ui/view/current_patch.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

bool step_makes_frame(const scene::Step& step) {
    return !std::holds_alternative<scene::ScreenshotStep>(step.action) &&
           !std::holds_alternative<scene::CaptionStep>(step.action) &&
           !std::holds_alternative<scene::PauseStep>(step.action) &&
           !std::holds_alternative<scene::ExpectStep>(step.action);
}

std::unique_ptr<AnimationJob> AnimationJob::create(AnimationRequest request, std::string& error) {
    error = check_video_settings(request.video);
    if (!error.empty()) return nullptr;
    if (request.step_frames < 1 || request.step_frames > 600) {
        error = "frames per step must be 1..600, not " + std::to_string(request.step_frames);
        return nullptr;
    }
    {
        scene::ScriptState trial(request.script.start);
        const scene::ScriptResult dry = scene::run_script(request.script, trial, {}, true);
        if (dry.stopped) {
            error = dry.stopped->message + (dry.stopped->has_path && !dry.stopped->path.empty()
                                                ? " (at " + dry.stopped->path + ")"
                                                : "");
            return nullptr;
        }
    }
    std::unique_ptr<AnimationJob> job(new AnimationJob());
    int pictures = request.include_start ? 1 : 0;
    for (const scene::Step& s : request.script.steps) pictures += step_makes_frame(s);
    if (pictures == 0) {
        error = "the script has no step that changes the picture (only screenshots, captions, "
                "pauses or expectations)";
        return nullptr;
    }
    job->total_ = pictures * request.step_frames;
    job->state_ = std::make_unique<scene::ScriptState>(request.script.start);
    job->req_ = std::move(request);
    return job;
}

AnimationJob::~AnimationJob() = default;

// The view after the steps so far, held step_frames times.
std::string AnimationJob::picture() {
    if (!capture_) {
        CaptureSettings cs;
        cs.width = req_.video.width;
        cs.height = req_.video.height;
        cs.view = req_.view;
        cs.scale = req_.scale;
        capture_ = std::make_unique<FrameCapture>(cs);
        if (!capture_->error().empty()) return capture_->error();
        std::string error;
        encoder_ = VideoEncoder::create(req_.video, error);
        if (!encoder_) return error;
    }
    AppContext& ctx = capture_->context();
    const scene::ScriptState& st = *state_;
    ctx.doc = st.doc;
    normalize_selection(ctx.doc);
    // The camera is fitted at the first picture and then stays, as in the window; a camera
    // step turns it (and sets the zoom in percent of that fit).
    const bool camera_changed =
        st.camera.has_value() != camera_applied_.has_value() ||
        (st.camera && (st.camera->yaw_degrees != camera_applied_->yaw_degrees ||
                       st.camera->pitch_degrees != camera_applied_->pitch_degrees ||
                       st.camera->zoom_percent != camera_applied_->zoom_percent));
    if (camera_changed && st.camera) {
        ctx.ui.camera.yaw = st.camera->yaw_degrees * M_PI / 180.0;
        ctx.ui.camera.pitch = st.camera->pitch_degrees * M_PI / 180.0;
        if (st.camera->zoom_percent) {
            if (first_picture_)
                ctx.ui.zoom_after_fit = *st.camera->zoom_percent / 100.0;
            else
                ctx.ui.camera.distance = ctx.ui.fit_distance / (*st.camera->zoom_percent / 100.0);
        }
    }
    camera_applied_ = st.camera;
    ctx.ui.deboor.step = st.deboor_step;
    const doc::Object* current = nullptr;
    if (current_surface(ctx.doc, &current)) follow_indicator(ctx.doc, current->id);
    std::string error;
    const std::optional<Pixels> p = capture_->capture(error, first_picture_ ? 2 : 1);
    first_picture_ = false;
    if (!p) return error;
    for (int k = 0; k < req_.step_frames; ++k) {
        if (std::string problem = encoder_->add_frame(p->rgba); !problem.empty()) return problem;
        ++done_;
    }
    return "";
}

std::string AnimationJob::step() {
    if (finished_) return "";
    if (req_.include_start && !start_done_) {
        start_done_ = true;
        return picture();
    }
    start_done_ = true;
    while (next_step_ < req_.script.steps.size()) {
        const scene::Step& s = req_.script.steps[next_step_++];
        if (const geom::Status ran = scene::run_step(s, *state_, {}, false, result_); !ran)
            return ran.error().message;
        if (step_makes_frame(s)) return picture();
    }
    finished_ = true;
    if (!encoder_) return "the animation has no frames";
    return encoder_->finish(req_.output);
}

} // namespace isoparm::ui
