// Multisampled framebuffer plus resolve texture for the 3D view.
#include "ui/render/render_target.hpp"

#include <algorithm>

namespace isoparm::ui {

namespace {

// A texture read texel for texel (nearest, clamped): the picture and the depth the overlay
// compares against are both sampled at their own pixels.
GLuint nearest_texture() {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    return t;
}

} // namespace

RenderTarget::RenderTarget(int samples) {
    GLint max_samples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    samples_ = std::clamp(static_cast<int>(max_samples), 0, samples);
    glGenFramebuffers(1, &msaa_fbo_);
    glGenRenderbuffers(1, &msaa_color_);
    glGenRenderbuffers(1, &msaa_depth_);
    glGenFramebuffers(1, &resolve_fbo_);
    // Shown 1:1 in the panel: nearest is exact and much cheaper on software renderers.
    texture_ = nearest_texture();
    if (samples_ == 0) {
        depth_texture_ = nearest_texture();
        glGenFramebuffers(1, &colour_only_fbo_);
    }
    resize(16, 16);
}

RenderTarget::~RenderTarget() {
    glDeleteFramebuffers(1, &msaa_fbo_);
    glDeleteRenderbuffers(1, &msaa_color_);
    glDeleteRenderbuffers(1, &msaa_depth_);
    glDeleteFramebuffers(1, &resolve_fbo_);
    glDeleteTextures(1, &texture_);
    if (depth_texture_) glDeleteTextures(1, &depth_texture_);
    if (colour_only_fbo_) glDeleteFramebuffers(1, &colour_only_fbo_);
}

void RenderTarget::resize(int width, int height) {
    width = std::max(width, 1);
    height = std::max(height, 1);
    if (width == width_ && height == height_) return;
    width_ = width;
    height_ = height;

    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo_);
    if (depth_texture_) {
        // No multisampling: the scene is drawn straight into the texture (no resolve copy).
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
    } else {
        glBindRenderbuffer(GL_RENDERBUFFER, msaa_color_);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                  msaa_color_);
    }
    if (depth_texture_) {
        glBindTexture(GL_TEXTURE_2D, depth_texture_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, width, height, 0, GL_DEPTH_COMPONENT,
                     GL_UNSIGNED_INT, nullptr);
        glBindTexture(GL_TEXTURE_2D, 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_texture_,
                               0);
        glBindFramebuffer(GL_FRAMEBUFFER, colour_only_fbo_);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
    } else {
        glBindRenderbuffer(GL_RENDERBUFFER, msaa_depth_);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24, width,
                                         height);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                  msaa_depth_);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void RenderTarget::bind_for_drawing() const {
    glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo_);
    glViewport(0, 0, width_, height_);
}

void RenderTarget::bind_colour_only() const {
    glBindFramebuffer(GL_FRAMEBUFFER, colour_only_fbo_);
    glViewport(0, 0, width_, height_);
}

void RenderTarget::resolve() const {
    if (depth_texture_) { // drawn into the texture itself
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return;
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, msaa_fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void RenderTarget::copy_to(GLuint fbo, int x, int y) const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
    glBlitFramebuffer(0, 0, width_, height_, x, y, x + width_, y + height_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
}

} // namespace isoparm::ui
