// A surfaceless EGL context (Mesa's EGL_PLATFORM_SURFACELESS_MESA): OpenGL 3.3 core with no
// window and no X server, for rendering pictures headless.
#pragma once

#include <memory>
#include <string>

namespace isoparm::ui {

class EglContext {
public:
    // The context is current on return; nullptr with `error` set when EGL cannot provide it.
    static std::unique_ptr<EglContext> create(std::string& error);
    ~EglContext();
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;
    std::string renderer_name() const; // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"

private:
    EglContext() = default;
    void* display_ = nullptr;
    void* context_ = nullptr;
};

} // namespace isoparm::ui
