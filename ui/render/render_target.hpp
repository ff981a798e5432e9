// The 3D view's off-screen target: a multisampled framebuffer resolved into a texture
// that is copied into the frame under ImGui's drawing (the same in the window and headless).
#pragma once

#include "ui/render/gl.hpp"

namespace isoparm::ui {

class RenderTarget {
public:
    explicit RenderTarget(int samples); // MSAA samples (0: none), capped by the driver
    ~RenderTarget();
    RenderTarget(const RenderTarget&) = delete;
    RenderTarget& operator=(const RenderTarget&) = delete;

    // Reallocates storage when the size changed; the texture name never changes, so an
    // ImGui::Image recorded earlier in the frame stays valid.
    void resize(int width, int height);
    void bind_for_drawing() const; // the multisampled framebuffer
    // Without multisampling the depth is a texture (0 otherwise): the overlay then reads it in
    // one pass, drawn into the colour alone (bind_colour_only), instead of a pass for its
    // hidden parts and another for its visible ones.
    GLuint depth_texture() const { return depth_texture_; }
    void bind_colour_only() const;
    void resolve() const; // multisampled -> texture
    // The texture's picture into framebuffer `fbo` with its lower-left corner at (x, y), a
    // plain copy; leaves `fbo` bound.
    void copy_to(GLuint fbo, int x, int y) const;
    GLuint texture() const { return texture_; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    GLuint msaa_fbo_ = 0, msaa_color_ = 0, msaa_depth_ = 0;
    GLuint resolve_fbo_ = 0, texture_ = 0;
    GLuint depth_texture_ = 0, colour_only_fbo_ = 0;
    int width_ = 0, height_ = 0, samples_ = 0;
};

} // namespace isoparm::ui
