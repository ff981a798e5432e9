// Pictures of the workstation (or its 3D view alone) as RGBA pixels: a Workstation of its own
// drawing into an off-screen framebuffer of the asked size, read back. `isoparm render`,
// `script`, `animate` and `figure` use it in an EGL context; the window's File > Export
// picture uses it in the window's own GL context (then the window's ImGui context is put back
// by the caller).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ui/app_context.hpp"

namespace isoparm::ui {

class Workstation;
class OffscreenTarget;

struct Pixels {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba; // first row at the top; straight (not premultiplied) alpha
};

struct CaptureSettings {
    int width = 1280, height = 800; // pixels of the picture
    ViewMode view = ViewMode::workstation;
    float scale = 1;          // UI scale: fonts and lines (a 2x picture of a window: 2)
    bool transparent = false; // the background left transparent (alpha 0)
    int msaa_samples = 4;
};

class FrameCapture {
public:
    // Needs a current OpenGL 3.3 context; makes a new ImGui context current.
    explicit FrameCapture(const CaptureSettings& settings);
    ~FrameCapture();
    FrameCapture(const FrameCapture&) = delete;
    FrameCapture& operator=(const FrameCapture&) = delete;

    // "" when pictures can be taken, else why not (framebuffer, shaders).
    const std::string& error() const { return error_; }
    const CaptureSettings& settings() const { return settings_; }
    AppContext& context();
    // Draws `frames` frames of the workstation as the context stands (the first settles
    // layout-dependent sizes and the camera fit) and reads the picture back; nothing, with
    // `error` set, when the read-back failed.
    std::optional<Pixels> capture(std::string& error, int frames = 2);

private:
    CaptureSettings settings_;
    std::string error_;
    std::unique_ptr<OffscreenTarget> target_;
    std::unique_ptr<Workstation> workstation_;
};

// The part [x, x + w) x [y, y + h) of a picture (clamped to it); nothing when that is empty.
std::optional<Pixels> crop(const Pixels& p, int x, int y, int w, int h);

// What the window shows beyond the document (camera, tabs, splitters, the teaching panels'
// settings) copied to another workstation's context, so its picture matches the window.
void copy_view_state(const AppContext& from, AppContext& to);

} // namespace isoparm::ui
