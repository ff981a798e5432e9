// Surfaceless EGL context creation.
#include "ui/headless/egl_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <cstdio>
#include <cstring>

#include "ui/render/gl.hpp"

namespace isoparm::ui {

namespace {
std::string egl_error(const char* what) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s failed (EGL error 0x%04x)", what, eglGetError());
    return buf;
}
} // namespace

std::unique_ptr<EglContext> EglContext::create(std::string& error) {
    const char* exts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!exts || !std::strstr(exts, "EGL_MESA_platform_surfaceless")) {
        error = "EGL has no surfaceless platform (EGL_MESA_platform_surfaceless); install Mesa's "
                "EGL (libegl1-mesa)";
        return nullptr;
    }
    const auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_display) {
        error = "EGL lacks eglGetPlatformDisplayEXT";
        return nullptr;
    }
    EGLDisplay dpy = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &major, &minor)) {
        error = egl_error("eglInitialize on the surfaceless platform");
        return nullptr;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        error = egl_error("eglBindAPI(EGL_OPENGL_API)");
        eglTerminate(dpy);
        return nullptr;
    }
    // Any configuration will do: we render into our own framebuffer objects.
    const EGLint config_attribs[] = {EGL_SURFACE_TYPE,
                                     EGL_PBUFFER_BIT,
                                     EGL_RENDERABLE_TYPE,
                                     EGL_OPENGL_BIT,
                                     EGL_RED_SIZE,
                                     8,
                                     EGL_GREEN_SIZE,
                                     8,
                                     EGL_BLUE_SIZE,
                                     8,
                                     EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(dpy, config_attribs, &config, 1, &count) || count == 0) config = nullptr;
    const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                      3,
                                      EGL_CONTEXT_MINOR_VERSION,
                                      3,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                      EGL_NONE};
    EGLContext ctx =
        eglCreateContext(dpy, config ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, context_attribs);
    if (ctx == EGL_NO_CONTEXT) {
        error = egl_error("creating an OpenGL 3.3 core context");
        eglTerminate(dpy);
        return nullptr;
    }
    if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
        error = egl_error("eglMakeCurrent without a surface");
        eglDestroyContext(dpy, ctx);
        eglTerminate(dpy);
        return nullptr;
    }
    std::unique_ptr<EglContext> out(new EglContext());
    out->display_ = dpy;
    out->context_ = ctx;
    return out;
}

EglContext::~EglContext() {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
}

std::string EglContext::renderer_name() const {
    const auto* s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return s ? s : "";
}

} // namespace isoparm::ui
