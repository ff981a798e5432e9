// The one place that includes OpenGL, and the one place that chooses which: core profile 3.3
// entry points called directly (glvnd) on the desktop, OpenGL ES 3.0 (WebGL 2) in the browser
// build. Everything drawn uses only what both have: no geometry shaders, no polygon mode, no
// wide lines (thick lines and points are quads built in the vertex shader, ui/render/shaders).
#pragma once

#ifdef __EMSCRIPTEN__
#include <GLES3/gl3.h>
#else
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES
#endif
#include <GL/glcorearb.h>
#endif

namespace isoparm::ui {

// The first lines of every GLSL source (shaders.cpp and ImGui's backend): the language
// version, and for GLSL ES the default precision a fragment shader must declare.
#ifdef __EMSCRIPTEN__
inline constexpr const char* glsl_version = "#version 300 es";
inline constexpr const char* glsl_prologue = "#version 300 es\n"
                                             "precision highp float;\n"
                                             "precision highp int;\n";
#else
inline constexpr const char* glsl_version = "#version 330 core";
inline constexpr const char* glsl_prologue = "#version 330 core\n";
#endif

} // namespace isoparm::ui
