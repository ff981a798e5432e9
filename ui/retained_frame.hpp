// The frame kept between frames on a CPU rasteriser (llvmpipe): ImGui's drawing over the 3D
// picture in an off-screen picture of the frame's size, drawn again only inside the rectangles
// whose pixels changed (frame_damage.hpp), then copied whole into the window. During a point
// drag only the 3D view and the control point panel change: the other panels' triangles are
// neither set up nor filled again. Each redrawn rectangle is cleared and drawn exactly as the
// full frame draws it (the same triangles, scissored), so the picture is the full frame's.
#pragma once

#include <functional>
#include <glm/vec4.hpp>
#include <vector>

#include "ui/frame_damage.hpp"
#include "ui/render/gl.hpp"

struct ImDrawData;

namespace isoparm::ui {

// The 3D picture under ImGui's drawing.
struct Underlay {
    PixelRect rect;       // framebuffer pixels, rows top-down; empty: none this frame
    bool changed = false; // a new picture (the renderer drew one)
    // Copies the picture into framebuffer `fbo` at `rect`; with the scissor test on, only the
    // scissored part.
    std::function<void(GLuint fbo)> copy;
};

class RetainedFrame {
public:
    RetainedFrame();
    ~RetainedFrame();
    RetainedFrame(const RetainedFrame&) = delete;
    RetainedFrame& operator=(const RetainedFrame&) = delete;

    // The frame of `dd` over `clear` and `underlay` into `target_fbo`: the kept picture brought
    // up to date where it changed (everywhere when `full`: fonts or theme rebuilt), then copied.
    // Returns the pixels drawn again (0: the kept picture stood).
    long draw(ImDrawData& dd, GLuint target_fbo, const glm::vec4& clear, const Underlay& underlay,
              bool full);

private:
    void redraw(ImDrawData& dd, const PixelRect& r, const glm::vec4& clear,
                const Underlay& underlay) const;
    GLuint fbo_ = 0, color_ = 0;
    int width_ = 0, height_ = 0;
    bool valid_ = false;
    std::vector<DrawListPrint> last_;
    PixelRect last_underlay_;
    glm::vec4 last_clear_{-1};
};

} // namespace isoparm::ui
