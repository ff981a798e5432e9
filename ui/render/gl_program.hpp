// Compiling and linking GLSL programs, with the driver's log in the error.
#pragma once

#include <string>

#include "ui/render/gl.hpp"

namespace isoparm::ui {

// The vertex attribute slots every program shares: a position, a second vector (a normal or
// a colour) and a scalar (an analysis value) per vertex; a segment's end and its colour per
// instance (ui/render/segments.hpp).
enum : GLuint {
    attrib_position = 0,
    attrib_second = 1,
    attrib_scalar = 2,
    attrib_end = 3,
    attrib_end_color = 4,
};

// Owns one linked program; empty (id 0) with `error` set when compiling or linking failed.
// The sources are GLSL without a version line: gl.hpp's glsl_prologue goes first.
class GlProgram {
public:
    GlProgram() = default;
    GlProgram(const char* vertex, const char* fragment);
    ~GlProgram();
    GlProgram(GlProgram&& o) noexcept;
    GlProgram& operator=(GlProgram&& o) noexcept;
    GlProgram(const GlProgram&) = delete;
    GlProgram& operator=(const GlProgram&) = delete;

    GLuint id() const { return id_; }
    bool ok() const { return id_ != 0; }
    const std::string& error() const { return error_; }
    GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

private:
    GLuint id_ = 0;
    std::string error_;
};

} // namespace isoparm::ui
