#include "ui/headless/frame_capture.hpp"

#include <algorithm>
#include <cfloat>
#include <cstring>
#include <imgui.h>

#include "ui/headless/offscreen_target.hpp"
#include "ui/render/gl.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/workstation.hpp"

namespace isoparm::ui {

FrameCapture::FrameCapture(const CaptureSettings& s) : settings_(s) {
    target_ = std::make_unique<OffscreenTarget>(s.width, s.height);
    if (!target_->complete()) {
        error_ = "cannot create a " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                 " framebuffer";
        return;
    }
    WorkstationOptions options;
    options.headless = true;
    options.content_scale = s.scale;
    options.view = s.view;
    options.msaa_samples = s.msaa_samples;
    options.transparent = s.transparent;
    workstation_ = std::make_unique<Workstation>(options);
    if (!workstation_->renderer_error().empty())
        error_ = "shaders failed: " + workstation_->renderer_error();
}

FrameCapture::~FrameCapture() {
    workstation_.reset(); // its ImGui and GL objects before the framebuffer
    target_.reset();
}

AppContext& FrameCapture::context() {
    return workstation_->context();
}

std::optional<Pixels> FrameCapture::capture(std::string& error, int frames) {
    if (!error_.empty()) {
        error = error_;
        return std::nullopt;
    }
    const int w = settings_.width, h = settings_.height;
    workstation_->make_current();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(w), static_cast<float>(h));
    io.DisplayFramebufferScale = ImVec2(1, 1);
    io.DeltaTime = 1.0f / 60.0f;
    io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    for (int f = 0; f < std::max(frames, 1); ++f) workstation_->frame(target_->fbo());

    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(w) * h * 4);
    while (glGetError() != GL_NO_ERROR) {
    } // only the read-back's own errors count below
    glBindFramebuffer(GL_READ_FRAMEBUFFER, target_->fbo());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (glGetError() != GL_NO_ERROR) {
        error = "reading the picture back failed";
        return std::nullopt;
    }
    // OpenGL's first row is the bottom: flip. Opaque pictures get alpha 255 everywhere; a
    // transparent one was drawn premultiplied (blending onto alpha 0) and is made straight.
    Pixels out{w, h, std::vector<std::uint8_t>(pixels.size())};
    const std::size_t row = static_cast<std::size_t>(w) * 4;
    for (int y = 0; y < h; ++y)
        std::memcpy(&out.rgba[static_cast<std::size_t>(y) * row],
                    &pixels[static_cast<std::size_t>(h - 1 - y) * row], row);
    for (std::size_t k = 0; k < out.rgba.size(); k += 4) {
        if (!settings_.transparent) {
            out.rgba[k + 3] = 255;
            continue;
        }
        const unsigned a = out.rgba[k + 3];
        for (int c = 0; c < 3; ++c)
            out.rgba[k + c] = static_cast<std::uint8_t>(
                a ? std::min(255u, (out.rgba[k + c] * 255u + a / 2) / a) : 0);
    }
    return out;
}

std::optional<Pixels> crop(const Pixels& p, int x, int y, int w, int h) {
    const int x0 = std::clamp(x, 0, p.width), y0 = std::clamp(y, 0, p.height);
    const int x1 = std::clamp(x + w, 0, p.width), y1 = std::clamp(y + h, 0, p.height);
    if (x1 <= x0 || y1 <= y0) return std::nullopt;
    Pixels out{x1 - x0, y1 - y0, {}};
    out.rgba.resize(static_cast<std::size_t>(out.width) * out.height * 4);
    for (int r = 0; r < out.height; ++r)
        std::memcpy(&out.rgba[static_cast<std::size_t>(r) * out.width * 4],
                    &p.rgba[(static_cast<std::size_t>(y0 + r) * p.width + x0) * 4],
                    static_cast<std::size_t>(out.width) * 4);
    return out;
}

void copy_view_state(const AppContext& from, AppContext& to) {
    to.doc = from.doc;
    to.file_path = from.file_path;
    to.settings.layout = from.settings.layout;
    const UiState& a = from.ui;
    UiState& b = to.ui;
    b.camera = a.camera;
    b.fit_distance = a.fit_distance;
    b.camera_needs_fit = false;
    b.presentation = a.presentation;
    b.deboor = a.deboor;
    b.curve = a.curve;
    b.homogeneous = a.homogeneous;
    b.blossom = a.blossom;
    b.multires = a.multires;
    b.left_tab = a.left_tab;
    b.knot_continuity = a.knot_continuity;
    b.border_continuity = a.border_continuity;
    b.show_denominator = a.show_denominator;
    b.show_weights = a.show_weights;
    b.fit = a.fit;
    b.object_list.show_tab = false;
    b.action_note = a.action_note;
    b.status = a.status;
    normalize_selection(to.doc);
    to.history.mark_clean();
}

} // namespace isoparm::ui
