// GLSL program compilation and linking.
#include "ui/render/gl_program.hpp"

#include <utility>
#include <vector>

namespace isoparm::ui {

namespace {

GLuint compile(GLenum kind, const char* source, std::string& error) {
    const GLuint s = glCreateShader(kind);
    glShaderSource(s, 1, &source, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
        std::vector<char> log(static_cast<std::size_t>(len > 0 ? len : 1), '\0');
        glGetShaderInfoLog(s, len, nullptr, log.data());
        const char* what = kind == GL_VERTEX_SHADER     ? "vertex"
                           : kind == GL_GEOMETRY_SHADER ? "geometry"
                                                        : "fragment";
        error = std::string(what) + " shader: " + log.data();
        glDeleteShader(s);
        return 0;
    }
    return s;
}

} // namespace

GlProgram::GlProgram(const char* vertex, const char* geometry, const char* fragment) {
    const GLuint vs = compile(GL_VERTEX_SHADER, vertex, error_);
    const GLuint gs = geometry && vs ? compile(GL_GEOMETRY_SHADER, geometry, error_) : 0;
    const GLuint fs = vs && (gs || !geometry) ? compile(GL_FRAGMENT_SHADER, fragment, error_) : 0;
    if (vs && fs && (gs || !geometry)) {
        id_ = glCreateProgram();
        glAttachShader(id_, vs);
        if (gs) glAttachShader(id_, gs);
        glAttachShader(id_, fs);
        // Attribute slots are fixed so one vertex layout serves every program.
        glBindAttribLocation(id_, 0, "a_position");
        glBindAttribLocation(id_, 1, "a_second");
        glBindAttribLocation(id_, 2, "a_scalar");
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
    for (GLuint s : {vs, gs, fs})
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
