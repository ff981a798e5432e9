// A picture's framebuffer without a window: one RGBA8 colour renderbuffer (headless renders,
// the frame benchmark). Needs a current OpenGL context.
#pragma once

#include "ui/render/gl.hpp"

namespace isoparm::ui {

class OffscreenTarget {
public:
    OffscreenTarget(int w, int h) {
        glGenRenderbuffers(1, &color_);
        glBindRenderbuffer(GL_RENDERBUFFER, color_);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
        glGenFramebuffers(1, &fbo_);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
        complete_ = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    ~OffscreenTarget() {
        glDeleteFramebuffers(1, &fbo_);
        glDeleteRenderbuffers(1, &color_);
    }
    OffscreenTarget(const OffscreenTarget&) = delete;
    OffscreenTarget& operator=(const OffscreenTarget&) = delete;
    GLuint fbo() const { return fbo_; }
    bool complete() const { return complete_; }

private:
    GLuint fbo_ = 0, color_ = 0;
    bool complete_ = false;
};

} // namespace isoparm::ui
