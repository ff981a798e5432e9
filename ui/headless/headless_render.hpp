// Rendering the workstation (or its 3D view alone) to a PNG without a display: the same
// Workstation frame as the window, into an EGL context's framebuffer.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "ui/app_context.hpp"

namespace isoparm::ui {

struct HeadlessRequest {
    std::string scene_path; // empty: the default scene
    std::string output;     // PNG path
    int width = 1280, height = 800;
    ViewMode view = ViewMode::workstation;
    float scale = 1;          // UI scale (fonts, lines)
    bool transparent = false; // background left transparent (alpha 0)
    // Adjusts the state after loading and before rendering (selection, indicator, camera,
    // display toggles...); the render command's options go through here. Returns "" or the
    // reason the options do not fit the scene (then nothing is rendered).
    std::function<std::string(AppContext&)> configure;
    // Sees the state after the frames were drawn (a script keeps the fitted camera).
    std::function<void(const AppContext&)> rendered;
};

// Returns "" on success, else one sentence saying what failed (no partial PNG is left).
std::string render_headless(const HeadlessRequest& request);

class EglContext;

// One EGL context for many pictures (a script's screenshots): each render draws the workstation
// with the given document (request.scene_path only names it; nothing is loaded).
class HeadlessSession {
public:
    // Nothing, with `error` saying why, where there is no headless OpenGL.
    static std::unique_ptr<HeadlessSession> create(std::string& error);
    ~HeadlessSession();
    // "" or one sentence saying what failed (no partial PNG is left).
    std::string render(doc::Document document, const HeadlessRequest& request);

private:
    explicit HeadlessSession(std::unique_ptr<EglContext> egl);
    std::unique_ptr<EglContext> egl_;
};

} // namespace isoparm::ui
