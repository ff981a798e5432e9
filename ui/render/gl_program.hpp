// Compiling and linking GLSL programs, with the driver's log in the error.
#pragma once

#include <string>

#include "ui/render/gl.hpp"

namespace isoparm::ui {

// Owns one linked program; empty (id 0) with `error` set when compiling or linking failed.
class GlProgram {
public:
    GlProgram() = default;
    GlProgram(const char* vertex, const char* geometry, const char* fragment);
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
