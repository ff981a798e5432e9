// The OpenGL 3.3 renderer of the 3D view, shared by the window and headless rendering:
// surfaces from cached tessellations, plus the per-frame overlay, into an FBO texture.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "ui/view/overlay.hpp"
#include "ui/view/scene_draw.hpp"

namespace isoparm::ui {

struct RenderStats {
    bool redrawn = false;     // false: nothing changed, the last picture stands
    int retessellated = 0;    // surfaces re-tessellated in the last frame
    double tessellate_ms = 0; // CPU time they took
    long vertices = 0;        // vertices drawn
};

// True for Mesa's CPU rasterisers (llvmpipe, softpipe, swrast), where multisampling in an
// interactive window costs more than it is worth.
bool software_renderer();

class Renderer {
public:
    // Needs a current OpenGL 3.3 core context. msaa_samples: multisampling of the 3D view
    // (4 looks good; software renderers pay ~5x for it, see software_renderer()).
    explicit Renderer(int msaa_samples = 4);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    bool ok() const { return error_.empty(); }
    const std::string& error() const { return error_; }

    // Draws into the off-screen target (resized to view.width x view.height) and resolves it
    // into texture(); leaves framebuffer 0 bound. Cache entries of ids not drawn are freed.
    void render(const SceneView& view, const std::vector<SurfaceDraw>& surfaces,
                const Overlay& overlay);
    unsigned texture() const;
    // The last picture into framebuffer `fbo`, lower-left corner at (x, y) in its pixels.
    void copy_to(unsigned fbo, int x, int y) const;
    const RenderStats& stats() const { return stats_; }
    // Without multisampling the overlay's hidden and visible parts are drawn in one pass (on by
    // default); off: two depth-tested passes, as with multisampling (the reference in tests).
    void set_one_pass_overlay(bool on);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::string error_;
    RenderStats stats_;
};

} // namespace isoparm::ui
