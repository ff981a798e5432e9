// Instanced quads for lines and points (see segments.hpp).
#include "ui/render/segments.hpp"

#include "ui/render/gl_program.hpp"

namespace isoparm::ui {

void point_instances(GLuint buffer, GLintptr base, const InstanceLayout& l) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    const auto array = [&](GLuint slot, GLint size, GLintptr at) {
        if (at < 0) {
            glDisableVertexAttribArray(slot);
            return;
        }
        glEnableVertexAttribArray(slot);
        glVertexAttribPointer(slot, size, GL_FLOAT, GL_FALSE, l.stride,
                              reinterpret_cast<const void*>(base + at));
        glVertexAttribDivisor(slot, 1);
    };
    array(attrib_position, 3, l.position);
    array(attrib_second, 4, l.color);
    array(attrib_end, 3, l.end);
    array(attrib_end_color, 4, l.end_color);
}

void draw_quads(GLsizei instances) {
    if (instances > 0) glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, instances);
}

void SegmentBuffer::create() {
    glGenBuffers(1, &vbo_);
    glGenVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    constexpr GLsizei stride = 6 * sizeof(float);
    point_instances(vbo_, 0, {stride, 0, -1, 3 * sizeof(float), -1});
    glBindVertexArray(0);
}

void SegmentBuffer::destroy() {
    glDeleteBuffers(1, &vbo_);
    glDeleteVertexArrays(1, &vao_);
    vbo_ = vao_ = 0;
}

void SegmentBuffer::fill(const geom::Mesh& mesh, const std::vector<std::uint32_t>& pairs) {
    scratch_.clear();
    scratch_.reserve(pairs.size() * 3);
    for (const std::uint32_t k : pairs) {
        const glm::dvec3& p = mesh.positions[k];
        scratch_.insert(scratch_.end(), {static_cast<float>(p.x), static_cast<float>(p.y),
                                         static_cast<float>(p.z)});
    }
    count_ = static_cast<GLsizei>(pairs.size() / 2);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(scratch_.size() * sizeof(float)),
                 scratch_.data(), GL_DYNAMIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void SegmentBuffer::draw() const {
    glBindVertexArray(vao_);
    draw_quads(count_);
}

} // namespace isoparm::ui
