// Wide lines and round points as instanced quads: one instance a segment (its two ends) or a
// point, four vertices a triangle-strip quad whose corners the vertex shader builds
// (shaders.hpp). Neither OpenGL 3.3 core nor WebGL 2 draws wide lines, and WebGL 2 has no
// geometry shaders: this is what both can do, and so the one way both builds draw.
#pragma once

#include <cstdint>
#include <vector>

#include "core/geom/tessellate.hpp"
#include "ui/render/gl.hpp"

namespace isoparm::ui {

// Where one instance's attributes lie in a buffer, in bytes from the instance's start; -1: the
// attribute is not an array (a segment's ends get the constant colour the caller sets with
// glVertexAttrib4f; a point has no end).
struct InstanceLayout {
    GLsizei stride = 0; // from one instance to the next
    GLintptr position = 0;
    GLintptr color = -1;
    GLintptr end = -1;
    GLintptr end_color = -1;
};

// Points the bound vertex array's instance attributes at `buffer`, the first instance at byte
// `base`. (WebGL 2 has no base instance: a batch in the middle of a buffer is reached this way.)
void point_instances(GLuint buffer, GLintptr base, const InstanceLayout& layout);

// Draws `instances` quads with the bound program and vertex array.
void draw_quads(GLsizei instances);

// A mesh's wireframe as segment instances (two ends of three floats each): the index pairs'
// ends gathered from the mesh's positions. Filled again only when the mesh or the pairs change
// and the wireframe is drawn.
class SegmentBuffer {
public:
    void create();
    void destroy();
    void fill(const geom::Mesh& mesh, const std::vector<std::uint32_t>& pairs);
    // Draws the segments with the bound line program; their colour is the constant
    // attribute the caller set.
    void draw() const;
    GLsizei count() const { return count_; }

private:
    GLuint vbo_ = 0, vao_ = 0;
    GLsizei count_ = 0;
    std::vector<float> scratch_;
};

} // namespace isoparm::ui
