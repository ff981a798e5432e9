// Pictures, figures and animations from the window (File > Export picture / figure /
// animation, Ctrl+Shift+C): the dialog's state, and the work it asks for, run between window
// frames (a picture is a second workstation drawing off screen in the window's GL context,
// ui/headless/frame_capture.hpp; an animation runs a few of its frames per window frame so
// the progress bar moves and Cancel works).
#pragma once

#include <memory>
#include <string>

namespace isoparm::ui {

struct AppContext;
class AnimationJob;

// What File > Export picture can picture: the 3D view, the whole window, or one panel.
enum class PictureTarget { view3d, window, tracing, teaching_tabs, right_top, right_bottom };

struct MediaExportState {
    enum class Kind { picture, figure, animation } kind = Kind::picture;
    bool open = false, just_opened = false;
    // Picture: what, its size in screen pixels (0: as on screen), scale 1..4, background.
    int target = 0;
    int width = 0, height = 0;
    float scale = 1;
    bool transparent = false;
    // Figure: the view (FigureView, or 6 for the 3D view) and its page size in points.
    int figure_view = 0;
    // Animation: what moves, frames per second, pictures in a sweep or orbit, frame size.
    int animation_source = 0;
    int fps = 10, frames = 40;
    std::string directory, name, error;
    bool pending = false;              // export at the start of the next frame
    bool clipboard_pending = false;    // Ctrl+Shift+C
    std::shared_ptr<AnimationJob> job; // an animation being rendered
    std::string job_output;
};

// Opens the dialog for `kind` with a name from the scene's.
void request_media_export(AppContext& ctx, MediaExportState::Kind kind);
// Runs what the dialog or the shortcut asked for. Called before the frame's ImGui work, with
// the window's GL context current; the caller makes its own ImGui context current after.
void run_media_exports(AppContext& ctx);
// The dialog (once a frame, in the workstation's dialogs).
void draw_media_export_dialog(AppContext& ctx);

} // namespace isoparm::ui
