// An animation rendered frame by frame: a script's steps (a lesson, a recording, or steps
// generated for a de Boor sequence, a knot or weight sweep, a camera orbit) run one at a
// time, the view pictured after each step that changes what is seen, every picture encoded
// (GIF or MP4, ui/figure/video_encoder.hpp). `isoparm animate` runs it in an EGL context;
// File > Export animation runs a few frames per window frame and shows the progress.
#pragma once

#include <memory>
#include <string>

#include "core/scene/script.hpp"
#include "ui/app_context.hpp"
#include "ui/figure/video_encoder.hpp"

namespace isoparm::ui {

class FrameCapture;

struct AnimationRequest {
    scene::Script script;
    std::string output; // .gif or .mp4
    VideoSettings video;
    ViewMode view = ViewMode::view3d_only;
    float scale = 1;
    int step_frames = 1;       // frames each picture is held (1..600)
    bool include_start = true; // a first picture of the scene before the first step
};

// Whether a step changes what a picture shows (commands, undo, selection, view and camera
// steps); screenshots, captions, pauses and expectations do not, and make no frame.
bool step_makes_frame(const scene::Step& step);

class AnimationJob {
public:
    // Checks the request and tries every step on a copy first: nothing, with `error` naming
    // the step that cannot be carried out, before anything is rendered. Needs a current GL
    // context from the first frame on (not here).
    static std::unique_ptr<AnimationJob> create(AnimationRequest request, std::string& error);
    ~AnimationJob();

    int total_frames() const { return total_; }
    int frames_done() const { return done_; }
    bool finished() const { return finished_; }
    // Renders the next picture (and encodes it step_frames times); after the last, finishes
    // the file. "" or why it failed (then nothing is written).
    std::string step();

private:
    AnimationJob() = default;
    std::string picture();
    AnimationRequest req_;
    std::unique_ptr<scene::ScriptState> state_;
    std::unique_ptr<FrameCapture> capture_;
    std::unique_ptr<VideoEncoder> encoder_;
    scene::ScriptResult result_;
    std::size_t next_step_ = 0;
    bool start_done_ = false, finished_ = false, first_picture_ = true;
    std::optional<scene::CameraStep> camera_applied_;
    int total_ = 0, done_ = 0;
};

} // namespace isoparm::ui
