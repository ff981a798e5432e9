// The kept frame (see retained_frame.hpp).
#include "ui/retained_frame.hpp"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

namespace isoparm::ui {

namespace {

// At most this many rectangles are drawn again a frame: each is another pass over the lists.
constexpr std::size_t max_redrawn_rects = 3;

// ImGui_ImplOpenGL3's mapping of the frame to framebuffer pixels.
struct BackendMap {
    ImVec2 offset, scale;
    int height = 0; // of the framebuffer
};

// A command's clip rectangle cut down to `r`: the scissor box ImGui_ImplOpenGL3 computes from
// it (its own truncations, so the pixels drawn are exactly the full frame's) intersected with
// `r`, as a clip rectangle the backend turns back into exactly that box; an empty one (skipped
// by the backend) when they do not meet.
ImVec4 clip_within(const ImVec4& clip, const PixelRect& r, const BackendMap& m) {
    const float cx0 = (clip.x - m.offset.x) * m.scale.x, cy0 = (clip.y - m.offset.y) * m.scale.y;
    const float cx1 = (clip.z - m.offset.x) * m.scale.x, cy1 = (clip.w - m.offset.y) * m.scale.y;
    if (cx1 <= cx0 || cy1 <= cy0) return {0, 0, 0, 0};
    // glScissor(x, y, w, h) as the backend calls it, in rows top-down.
    const int x0 = static_cast<int>(cx0);
    const int x1 = x0 + static_cast<int>(cx1 - cx0);
    const int y1 = m.height - static_cast<int>(static_cast<float>(m.height) - cy1);
    const int y0 = y1 - static_cast<int>(cy1 - cy0);
    const PixelRect box = intersect({x0, y0, x1, y1}, r);
    if (box.empty()) return {0, 0, 0, 0};
    // Quarter-pixel nudges keep the backend's truncations on the box's own pixels.
    auto x = [&](float px) { return px / m.scale.x + m.offset.x; };
    auto y = [&](float px) { return px / m.scale.y + m.offset.y; };
    return {x(static_cast<float>(box.x0) + 0.25f), y(static_cast<float>(box.y0) - 0.5f),
            x(static_cast<float>(box.x1) + 0.5f), y(static_cast<float>(box.y1) - 0.25f)};
}

} // namespace

RetainedFrame::RetainedFrame() {
    glGenFramebuffers(1, &fbo_);
    glGenRenderbuffers(1, &color_);
}

RetainedFrame::~RetainedFrame() {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteRenderbuffers(1, &color_);
}

void RetainedFrame::redraw(ImDrawData& dd, const PixelRect& r, const glm::vec4& clear,
                           const Underlay& underlay) const {
    glEnable(GL_SCISSOR_TEST);
    glScissor(r.x0, height_ - r.y1, r.x1 - r.x0, r.y1 - r.y0);
    glClearColor(clear.r, clear.g, clear.b, clear.a);
    glClear(GL_COLOR_BUFFER_BIT);
    const PixelRect under = intersect(r, underlay.rect);
    if (underlay.copy && !under.empty()) {
        // A blit, which the scissor test keeps inside r; wholly inside, unscissored: llvmpipe
        // then copies the memory instead of drawing a textured quad.
        if (under == underlay.rect) glDisable(GL_SCISSOR_TEST);
        underlay.copy(fbo_);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    }
    glDisable(GL_SCISSOR_TEST);
    const BackendMap map{dd.DisplayPos, dd.FramebufferScale, height_};
    std::vector<ImVec4> kept;
    for (int n = 0; n < dd.CmdListsCount; ++n)
        for (ImDrawCmd& c : dd.CmdLists[n]->CmdBuffer) {
            kept.push_back(c.ClipRect);
            c.ClipRect = clip_within(c.ClipRect, r, map);
        }
    ImGui_ImplOpenGL3_RenderDrawData(&dd);
    std::size_t k = 0;
    for (int n = 0; n < dd.CmdListsCount; ++n)
        for (ImDrawCmd& c : dd.CmdLists[n]->CmdBuffer) c.ClipRect = kept[k++];
}

long RetainedFrame::draw(ImDrawData& dd, GLuint target_fbo, const glm::vec4& clear,
                         const Underlay& underlay, bool full) {
    const int w = static_cast<int>(dd.DisplaySize.x * dd.FramebufferScale.x);
    const int h = static_cast<int>(dd.DisplaySize.y * dd.FramebufferScale.y);
    if (w <= 0 || h <= 0) return 0;
    if (w != width_ || h != height_) {
        glBindRenderbuffer(GL_RENDERBUFFER, color_);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
        width_ = w;
        height_ = h;
        valid_ = false;
    }
    const PixelRect frame{0, 0, w, h};
    std::vector<DrawListPrint> prints = fingerprint(dd, ImGui::GetIO().Fonts->TexID);
    std::vector<PixelRect> rects;
    if (!valid_ || full || clear != last_clear_) {
        rects = {frame};
    } else {
        rects = damage(last_, prints, frame);
        if (underlay.changed || underlay.rect != last_underlay_) {
            rects.push_back(underlay.rect);
            rects.push_back(last_underlay_);
        }
    }
    rects = merge_rects(std::move(rects), max_redrawn_rects);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(0, 0, w, h);
    long drawn = 0;
    for (const PixelRect& r : rects) {
        redraw(dd, r, clear, underlay);
        drawn += r.area();
    }
    last_ = std::move(prints);
    last_underlay_ = underlay.rect;
    last_clear_ = clear;
    valid_ = true;
    // The whole picture into the target: the same size and format, a plain copy.
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target_fbo);
    glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, target_fbo);
    return drawn;
}

} // namespace isoparm::ui
