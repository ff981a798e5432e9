// The workstation: one ImGui frame with every panel, the 3D view rendered into its texture,
// drawn into the current framebuffer. The window (GLFW) and headless (EGL) paths both run
// exactly this code; only the platform input and the target differ.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "ui/app_context.hpp"
#include "ui/gesture_frames.hpp"

struct ImGuiContext;

namespace isoparm::ui {

class Renderer;
class ImplicitMeshes;
class TriangleMeshes;
class SurfaceMeshes;
class RetainedFrame;

struct WorkstationOptions {
    bool headless = false;   // no timings, no settings file, deterministic
    float content_scale = 1; // HiDPI factor
    ViewMode view = ViewMode::workstation;
    int msaa_samples = 4; // multisampling of the 3D view (0: none)
    // Asks the window for another frame from any thread (a mesh ready in the background, the
    // next step of an animation); the window otherwise draws only on input. Unset headless.
    std::function<void()> request_frame;
    // Pictures with a transparent background (File > Export picture, `isoparm render
    // --transparent`): the frame is cleared to alpha 0 and everything blends onto that.
    bool transparent = false;
    // Keep the frame between frames and draw again only what changed (ui/retained_frame.hpp):
    // for a CPU rasteriser's window, where each panel's triangles cost their set-up and fill
    // every frame. Off for pictures (nothing to keep) and with `transparent`.
    bool retained = false;
    // Whether a CPU rasteriser draws (GestureFrames); unset: asked of GL_RENDERER, which a
    // browser masks (the page asks WebGL's renderer info instead).
    std::optional<bool> cpu_rasteriser = std::nullopt;
};

class Workstation {
public:
    // Needs a current OpenGL 3.3 core context. Creates the ImGui context and initialises
    // ImGui's OpenGL3 backend; a platform backend (GLFW) may be added by the caller.
    explicit Workstation(const WorkstationOptions& options);
    ~Workstation();
    Workstation(const Workstation&) = delete;
    Workstation& operator=(const Workstation&) = delete;

    // Empty when the renderer works; otherwise why not (shader errors).
    std::string renderer_error() const;

    AppContext& context() { return ctx_; }
    const AppContext& context() const { return ctx_; }

    // One frame. The caller has set io.DisplaySize, io.DeltaTime and input (or run the GLFW
    // backend's NewFrame). The frame is drawn into `target_framebuffer` (0: the window).
    void frame(unsigned target_framebuffer = 0);
    // Makes this workstation's ImGui context current (another workstation, e.g. a picture
    // export's, may have taken its place).
    void make_current();
    GestureFrames& gesture() { return gesture_; }
    // The pixels of the last frame drawn again (WorkstationOptions::retained; else all).
    long redrawn_pixels() const { return redrawn_pixels_; }

private:
    void layout_panels();
    void render_view3d(float scale); // the scene into the renderer's texture
    bool gesture_frame();            // this frame is drawn coarse (GestureFrames)
    void splitters();
    void draw_frame(unsigned target_framebuffer, bool view3d_drawn, bool full);
    AppContext ctx_;
    ImGuiContext* imgui_ = nullptr;
    bool transparent_ = false;
    bool software_ = false; // a CPU rasteriser: gestures are drawn coarse (GestureFrames)
    GestureFrames gesture_;
    std::function<void()> request_frame_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<ImplicitMeshes> implicit_;
    std::unique_ptr<TriangleMeshes> triangles_;
    std::unique_ptr<SurfaceMeshes>
        surfaces_; // the surfaces' display meshes (the renderer uploads them)
    std::unique_ptr<RetainedFrame> retained_; // WorkstationOptions::retained
    long redrawn_pixels_ = 0;
    bool presentation_built_ = false;
    bool deboor_was_on_ = false; // to bring the de Boor tab forward when it is switched on
    // The indicator and current object of the last frame (subpatch activation); NaN at first,
    // so the first frame makes the patch under a loaded scene's indicator current.
    glm::dvec2 last_indicator_{std::nan(""), std::nan("")};
    std::uint64_t last_current_ = 0;
};

} // namespace isoparm::ui
