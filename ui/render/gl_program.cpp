// GLSL program compilation and linking.
#include "ui/render/gl_program.hpp"

#include <utility>
#include <vector>

namespace isoparm::ui {

namespace {

GLuint compile(GLenum kind, const char* source, std::string& error) {
    const GLuint s = glCreateShader(kind);
    // The version line (and GLSL ES's precision) for the GL this build draws with, then the body.
    const char* parts[] = {glsl_prologue, source};
    glShaderSource(s, 2, parts, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
        std::vector<char> log(static_cast<std::size_t>(len > 0 ? len : 1), '\0');
        glGetShaderInfoLog(s, len, nullptr, log.data());
        const char* what = kind == GL_VERTEX_SHADER ? "vertex" : "fragment";
        error = std::string(what) + " shader: " + log.data();
        glDeleteShader(s);
        return 0;
    }
    return s;
}

} // namespace

GlProgram::GlProgram(const char* vertex, const char* fragment) {
    const GLuint vs = compile(GL_VERTEX_SHADER, vertex, error_);
    const GLuint fs = vs ? compile(GL_FRAGMENT_SHADER, fragment, error_) : 0;
    if (vs && fs) {
        id_ = glCreateProgram();
        glAttachShader(id_, vs);
        glAttachShader(id_, fs);
        // Attribute slots are fixed so one vertex layout serves every program.
        glBindAttribLocation(id_, attrib_position, "a_position");
        glBindAttribLocation(id_, attrib_second, "a_second");
        glBindAttribLocation(id_, attrib_scalar, "a_scalar");
        glBindAttribLocation(id_, attrib_end, "a_end");
        glBindAttribLocation(id_, attrib_end_color, "a_end_color");
        glLinkProgram(id_);
        GLint ok = 0;
        glGetProgramiv(id_, GL_LINK_STATUS, &ok);
        if (!ok) {
            char log[2048] = {0};
            glGetProgramInfoLog(id_, sizeof log, nullptr, log);
            error_ = std::string("link: ") + log;
            glDeleteProgram(id_);
            id_ = 0;
        }
    }
    for (GLuint s : {vs, fs})
        if (s) glDeleteShader(s);
}

GlProgram::~GlProgram() {
    if (id_) glDeleteProgram(id_);
}

GlProgram::GlProgram(GlProgram&& o) noexcept
    : id_(std::exchange(o.id_, 0)), error_(std::move(o.error_)) {}

GlProgram& GlProgram::operator=(GlProgram&& o) noexcept {
    if (this != &o) {
        if (id_) glDeleteProgram(id_);
        id_ = std::exchange(o.id_, 0);
        error_ = std::move(o.error_);
    }
    return *this;
}

} // namespace isoparm::ui
