// The 3D view renderer: the meshes' GPU buffers (their CPU side is surface_meshes.hpp's and the
// kinds' caches'), surface, line and point passes.
#include "ui/render/renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <string>

#include "ui/render/gl.hpp"
#include "ui/render/gl_program.hpp"
#include "ui/render/render_target.hpp"
#include "ui/render/segments.hpp"
#include "ui/render/shaders.hpp"
#include "ui/view/analysis.hpp"
#include "ui/view/face_culling.hpp"
#include "ui/view/mesh_data.hpp"
#include "ui/view/surface_meshes.hpp"

namespace isoparm::ui {

namespace {

// The mesh program's analysis uniforms (shaders.cpp, mesh_fs).
void set_analysis_uniforms(const GlProgram& p, const AnalysisView& a) {
    glUniform2f(p.uniform("u_range"), a.lo, a.hi);
    glUniform1i(p.uniform("u_diverging"), a.diverging ? 1 : 0);
    glUniform1f(p.uniform("u_stripes"), static_cast<float>(a.stripes));
    const float angle = glm::radians(a.zebra_angle);
    glUniform2f(p.uniform("u_zebra_dir"), std::cos(angle), std::sin(angle));
}

// The GPU side of an object's mesh (surface_meshes.hpp and the kinds' caches own the CPU side).
struct MeshEntry {
    std::uint64_t mesh_revision = 0;    // of the ready-made mesh uploaded (0: none)
    std::uint64_t surface_revision = 0; // of the surface mesh uploaded (0: none)
    GLuint vbo = 0, tri_ibo = 0, tri_vao = 0;
    GLsizei tri_count = 0;
    // The wireframe: index pairs into the mesh, as segments gathered from `source` (this
    // frame's mesh) when first drawn after a change.
    std::vector<std::uint32_t> wire_pairs;
    SegmentBuffer wire;
    bool wire_stale = true;
    const geom::Mesh* source = nullptr;
    long vertices = 0;
    AnalysisKind scalar_kind = AnalysisKind::off; // what the scalar attribute holds
    bool used = false;

    void create() {
        glGenBuffers(1, &vbo);
        glGenBuffers(1, &tri_ibo);
        glGenVertexArrays(1, &tri_vao);
        wire.create();
        // Triangles: position, normal and analysis scalar.
        constexpr GLsizei stride = floats_per_vertex * sizeof(float);
        glBindVertexArray(tri_vao);
        glBindBuffer(GL_ARRAY_BUFFER, vbo);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<void*>(3 * sizeof(float)));
        glEnableVertexAttribArray(2);
        glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<void*>(6 * sizeof(float)));
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, tri_ibo);
        glBindVertexArray(0);
    }
    void destroy() {
        glDeleteBuffers(1, &vbo);
        glDeleteBuffers(1, &tri_ibo);
        glDeleteVertexArrays(1, &tri_vao);
        wire.destroy();
    }
};

// One streaming buffer for the overlay's (position, colour) vertices: line batches as
// segment instances (vertex pairs), point batches as point instances (segments.hpp).
struct StreamBuffer {
    GLuint vbo = 0, vao = 0;
    static constexpr GLsizei vertex = sizeof(OverlayVertex);
    static constexpr GLintptr position = offsetof(OverlayVertex, position);
    static constexpr GLintptr color = offsetof(OverlayVertex, color);
    void create() {
        glGenBuffers(1, &vbo);
        glGenVertexArrays(1, &vao);
    }
    // The vertex array over the batch starting at vertex `first`.
    void segments_from(GLint first) const {
        point_instances(vbo, first * vertex,
                        {2 * vertex, position, color, vertex + position, vertex + color});
    }
    void points_from(GLint first) const {
        point_instances(vbo, first * vertex, {vertex, position, color, -1, -1});
    }
    void destroy() {
        glDeleteBuffers(1, &vbo);
        glDeleteVertexArrays(1, &vao);
    }
    void upload(const std::vector<OverlayVertex>& v) {
        glBindBuffer(GL_ARRAY_BUFFER, vbo);
        // Orphan then fill: the driver need not wait for last frame's draw.
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(OverlayVertex)),
                     v.data(), GL_STREAM_DRAW);
    }
};

} // namespace

// What the last picture showed, to tell whether the next frame may keep it.
struct LastPicture {
    bool valid = false;
    SceneView view;
    std::vector<SurfaceDraw> surfaces; // compared without their geometry pointers
    Overlay overlay;

    static bool same_draw(const SurfaceDraw& a, const SurfaceDraw& b) {
        return a.id == b.id && a.density == b.density && a.shaded == b.shaded &&
               a.wireframe == b.wireframe && a.fill == b.fill && a.wire == b.wire &&
               a.wire_width == b.wire_width && a.mesh_revision == b.mesh_revision;
    }
    bool matches(const SceneView& v, const std::vector<SurfaceDraw>& s, const Overlay& o) const {
        return valid && view == v && overlay == o &&
               std::equal(surfaces.begin(), surfaces.end(), s.begin(), s.end(), same_draw);
    }
};

// The mesh programs, one per kind of analysis with the kind a constant (shaders.cpp, mesh_fs):
// llvmpipe runs both sides of a branch on a uniform under a mask, so one program for all the
// kinds shaded each fragment through the curvature maps, the zebra's asin and the isophotes'
// acos as well (a third of fig. 3b's shaded pass on one core).
struct MeshPrograms {
    // off, the curvature kinds (one code: the scalar attribute carries which), zebra, isophotes
    std::array<GlProgram, 4> by_class;
    // All made with the renderer: compiled on first use instead, three GUI scenarios
    // (blossom_tab, stage_curve, labels_blossom) crashed LeakSanitizer's check at exit under
    // llvmpipe every time (not understood; compiling at start costs no measurable time in
    // `isoparm render`).
    MeshPrograms() {
        const AnalysisKind first[] = {AnalysisKind::off, AnalysisKind::gaussian,
                                      AnalysisKind::zebra, AnalysisKind::isophote};
        for (std::size_t c = 0; c < by_class.size(); ++c) {
            const std::string fs = "#define ISOPARM_ANALYSIS " +
                                   std::to_string(static_cast<int>(first[c])) + "\n" +
                                   shaders::mesh_fs;
            by_class[c] = GlProgram(shaders::mesh_vs, fs.c_str());
        }
    }
    const GlProgram& get(AnalysisKind kind) const {
        if (is_curvature(kind)) return by_class[1];
        return by_class[kind == AnalysisKind::zebra ? 2 : kind == AnalysisKind::isophote ? 3 : 0];
    }
};

struct Renderer::Impl {
    RenderTarget target;
    LastPicture last;
    MeshPrograms mesh_programs;
    GlProgram line, point;
    std::unordered_map<std::uint64_t, MeshEntry> meshes;
    StreamBuffer stream;
    bool one_pass_overlay = true; // Renderer::set_one_pass_overlay

    explicit Impl(int samples)
        : target(samples), line(shaders::line_vs, shaders::line_fs),
          point(shaders::point_vs, shaders::point_fs) {
        stream.create();
    }
    ~Impl() {
        for (auto& [id, m] : meshes) m.destroy();
        stream.destroy();
    }

    // Brings the object's buffers up to date: nothing when unchanged, the touched rows
    // after a drag, everything after other edits.
    MeshEntry& mesh_for(const SurfaceDraw& d, AnalysisKind analysis, RenderStats& stats) {
        auto [it, inserted] = meshes.try_emplace(d.id);
        MeshEntry& m = it->second;
        if (inserted) m.create();
        m.used = true;
        // Only the curvature kinds put values in the scalar attribute.
        const AnalysisKind want = is_curvature(analysis) ? analysis : AnalysisKind::off;
        const bool rescalar = want != m.scalar_kind;
        m.scalar_kind = want;

        if (d.mesh) {
            if (rescalar) m.mesh_revision = 0; // re-upload with the new scalar
            m.surface_revision = 0;
            m.source = d.mesh;
            return upload_mesh(m, d, stats);
        }
        m.mesh_revision = 0;
        if (!d.display) { // not brought up to date (surface_meshes.hpp): nothing to draw
            m.source = nullptr;
            m.tri_count = 0;
            m.wire_pairs.clear();
            m.surface_revision = 0;
            m.vertices = 0;
            return m;
        }
        const SurfaceMesh& sm = *d.display;
        const geom::Mesh& mesh = sm.geometry();
        m.source = &mesh;
        if (m.surface_revision == sm.revision) return m;
        m.wire_stale = true;
        if (sm.partial && m.surface_revision != 0 && m.surface_revision == sm.since) {
            // Only the rows the moved points' basis functions reach.
            const std::size_t at = sm.first * floats_per_vertex;
            const std::size_t n = std::min(sm.count * floats_per_vertex,
                                           sm.vertices.size() - std::min(at, sm.vertices.size()));
            glBindBuffer(GL_ARRAY_BUFFER, m.vbo);
            glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(at * sizeof(float)),
                            static_cast<GLsizeiptr>(n * sizeof(float)), sm.vertices.data() + at);
            glBindBuffer(GL_ARRAY_BUFFER, 0);
        } else {
            upload_all(m, sm.vertices, mesh.triangles, sm.wire_pairs);
        }
        m.surface_revision = sm.revision;
        stats.tessellate_ms += sm.milliseconds;
        ++stats.retessellated;
        m.vertices = static_cast<long>(mesh.positions.size());
        return m;
    }

    // Vertices, triangles and wire edges of a mesh, replacing what the entry held.
    static void upload_all(MeshEntry& m, const std::vector<float>& verts,
                           const std::vector<std::array<std::uint32_t, 3>>& triangles,
                           std::vector<std::uint32_t> wire) {
        glBindBuffer(GL_ARRAY_BUFFER, m.vbo);
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(verts.size() * sizeof(float)),
                     verts.data(), GL_DYNAMIC_DRAW);
        // Element buffers belong to their vertex arrays: fill each through its VAO.
        glBindVertexArray(m.tri_vao);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                     static_cast<GLsizeiptr>(triangles.size() * 3 * sizeof(std::uint32_t)),
                     triangles.data(), GL_DYNAMIC_DRAW);
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        m.tri_count = static_cast<GLsizei>(triangles.size() * 3);
        m.wire_pairs = std::move(wire);
        m.wire_stale = true;
    }

    // A ready-made mesh (implicit objects): everything re-uploaded when its revision changes.
    MeshEntry& upload_mesh(MeshEntry& m, const SurfaceDraw& d, RenderStats& stats) {
        if (m.mesh_revision == d.mesh_revision) return m;
        m.mesh_revision = d.mesh_revision;
        const geom::Mesh& mesh = *d.mesh;
        // An implicit surface's curvature at each vertex from f's gradient and Hessian; a mesh
        // of another kind (or an f that does not compile) is undefined under a curvature kind.
        const std::vector<double> scalars =
            m.scalar_kind == AnalysisKind::off || !d.implicit
                ? std::vector<double>{}
                : implicit_vertex_curvature(*d.implicit, mesh, m.scalar_kind);
        const std::vector<float> verts =
            interleave(mesh, 0, mesh.positions.size(), scalars,
                       m.scalar_kind == AnalysisKind::off ? 0.0f : undefined_scalar);
        // Each edge of a closed, consistently oriented mesh appears once in each direction.
        std::vector<std::uint32_t> wire;
        wire.reserve(mesh.triangles.size() * 3);
        for (const auto& t : mesh.triangles)
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t a = t[k], b = t[(k + 1) % 3];
                if (a < b) wire.insert(wire.end(), {a, b});
            }
        ++stats.retessellated;
        upload_all(m, verts, mesh.triangles, std::move(wire));
        m.vertices = static_cast<long>(mesh.positions.size());
        return m;
    }

    void draw_shaded(const SceneView& view, const std::vector<SurfaceDraw>& surfaces,
                     const std::vector<MeshEntry*>& entries, const glm::mat4& vp,
                     const glm::mat4& vmat, double aspect);
    void draw_wires(const std::vector<SurfaceDraw>& surfaces,
                    const std::vector<MeshEntry*>& entries, const glm::mat4& vp,
                    const float (&viewport)[2]);
    GLint draw_overlay_lines(const Overlay& overlay, bool one_pass);
    void draw_points(const Overlay& overlay, GLint point_base, const glm::mat4& vp,
                     const float (&viewport)[2], bool one_pass);
    bool begin_one_pass_overlay();
    void end_one_pass_overlay();

    void prune() {
        for (auto it = meshes.begin(); it != meshes.end();) {
            if (!it->second.used) {
                it->second.destroy();
                it = meshes.erase(it);
            } else {
                it->second.used = false;
                ++it;
            }
        }
    }
};

bool software_renderer() {
    const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string name = r ? r : "";
    for (const char* s : {"llvmpipe", "softpipe", "swrast"})
        if (name.find(s) != std::string::npos) return true;
    return false;
}

Renderer::Renderer(int msaa_samples) : impl_(std::make_unique<Impl>(msaa_samples)) {
    for (const GlProgram& p : impl_->mesh_programs.by_class)
        if (!p.ok()) error_ += p.error();
    for (const GlProgram* p : {&impl_->line, &impl_->point})
        if (!p->ok()) error_ += p->error();
}

Renderer::~Renderer() = default;

void Renderer::copy_to(unsigned fbo, int x, int y) const {
    impl_->target.copy_to(fbo, x, y);
}

void Renderer::set_one_pass_overlay(bool on) {
    impl_->one_pass_overlay = on;
    impl_->last.valid = false;
}

unsigned Renderer::texture() const {
    return impl_->target.texture();
}

// Pass 1: shaded surfaces, pushed back a little so lines on them stay visible.
void Renderer::Impl::draw_shaded(const SceneView& view, const std::vector<SurfaceDraw>& surfaces,
                                 const std::vector<MeshEntry*>& entries, const glm::mat4& vp,
                                 const glm::mat4& vmat, double aspect) {
    const GlProgram& mesh = mesh_programs.get(view.analysis.kind);
    glUseProgram(mesh.id());
    glUniformMatrix4fv(mesh.uniform("u_view_proj"), 1, GL_FALSE, glm::value_ptr(vp));
    glUniformMatrix4fv(mesh.uniform("u_view"), 1, GL_FALSE, glm::value_ptr(vmat));
    set_analysis_uniforms(mesh, view.analysis);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    const glm::dvec3 eye = camera_eye(view.camera);
    const double near_reach = near_plane_reach(view.camera, aspect);
    for (std::size_t k = 0; k < surfaces.size(); ++k) {
        if (!surfaces[k].shaded) continue;
        const glm::vec4& c = surfaces[k].fill;
        glUniform4f(mesh.uniform("u_color"), c.r, c.g, c.b, c.a);
        // An opaque surface replaces what is under it: blending would only read the colour
        // buffer back for every fragment (with alpha 1 the blend gives the source's bits).
        if (c.a >= 1.0f)
            glDisable(GL_BLEND);
        else
            glEnable(GL_BLEND);
        // Counter-clockwise is OpenGL's front face (never changed here).
        const HiddenFaces hidden = hidden_faces(surfaces[k], eye, near_reach);
        if (hidden == HiddenFaces::none) {
            glDisable(GL_CULL_FACE);
        } else {
            glEnable(GL_CULL_FACE);
            glCullFace(hidden == HiddenFaces::clockwise ? GL_BACK : GL_FRONT);
        }
        glBindVertexArray(entries[k]->tri_vao);
        glDrawElements(GL_TRIANGLES, entries[k]->tri_count, GL_UNSIGNED_INT, nullptr);
    }
    glDisable(GL_CULL_FACE);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glEnable(GL_BLEND);
}

// Pass 2: wireframes.
void Renderer::Impl::draw_wires(const std::vector<SurfaceDraw>& surfaces,
                                const std::vector<MeshEntry*>& entries, const glm::mat4& vp,
                                const float (&viewport)[2]) {
    glUseProgram(line.id());
    glUniformMatrix4fv(line.uniform("u_view_proj"), 1, GL_FALSE, glm::value_ptr(vp));
    glUniform2fv(line.uniform("u_viewport"), 1, viewport);
    glUniform1f(line.uniform("u_depth_bias"), 0.0f);
    glUniform1f(line.uniform("u_alpha"), 1.0f);
    for (std::size_t k = 0; k < surfaces.size(); ++k) {
        if (!surfaces[k].wireframe) continue;
        MeshEntry& m = *entries[k];
        if (m.wire_stale && m.source) {
            m.wire.fill(*m.source, m.wire_pairs);
            m.wire_stale = false;
        }
        const glm::vec4& c = surfaces[k].wire;
        glUniform1f(line.uniform("u_width"), surfaces[k].wire_width);
        glVertexAttrib4f(attrib_second, c.r, c.g, c.b, c.a); // both ends' constant colour
        glVertexAttrib4f(attrib_end_color, c.r, c.g, c.b, c.a);
        m.wire.draw();
    }
}

// Where the scene's depth is a texture (no multisampling), the overlay is drawn in one pass
// into the colour alone, each fragment comparing itself with the depth there (shaders.cpp,
// ISOPARM_OVERLAY_DEPTH): on a CPU rasteriser every overlay triangle is set up and shaded once
// instead of twice. False where the depth test's two passes are drawn instead.
bool Renderer::Impl::begin_one_pass_overlay() {
    if (!one_pass_overlay || !target.depth_texture()) return false;
    target.bind_colour_only();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, target.depth_texture());
    for (const GlProgram* p : {&line, &point}) {
        glUseProgram(p->id());
        glUniform1i(p->uniform("u_scene_depth"), 0);
    }
    return true;
}

void Renderer::Impl::end_one_pass_overlay() {
    glBindTexture(GL_TEXTURE_2D, 0); // never sampled while it is the depth attachment
    for (const GlProgram* p : {&line, &point}) {
        glUseProgram(p->id());
        glUniform1i(p->uniform("u_depth_mode"), 0);
    }
    target.bind_for_drawing();
}

// Pass 3: overlay lines; hidden parts first (faint), then the visible parts (or both in one
// pass). Uploads the points too; returns where they start in the stream.
GLint Renderer::Impl::draw_overlay_lines(const Overlay& overlay, bool one_pass) {
    std::vector<OverlayVertex> all;
    std::vector<std::pair<GLint, GLsizei>> ranges;
    for (const LineBatch& b : overlay.lines) {
        ranges.emplace_back(static_cast<GLint>(all.size()),
                            static_cast<GLsizei>(b.vertices.size()));
        all.insert(all.end(), b.vertices.begin(), b.vertices.end());
    }
    const GLint point_base = static_cast<GLint>(all.size());
    for (const PointBatch& b : overlay.points)
        all.insert(all.end(), b.points.begin(), b.points.end());
    stream.upload(all);
    glBindVertexArray(stream.vao);
    glDepthMask(GL_FALSE);
    glUniform1f(line.uniform("u_depth_bias"), 0.0005f);
    for (std::size_t k = 0; k < overlay.lines.size(); ++k) {
        const LineBatch& b = overlay.lines[k];
        if (b.vertices.empty()) continue;
        glUniform1f(line.uniform("u_width"), b.width_px);
        stream.segments_from(ranges[k].first);
        if (one_pass) {
            glUniform1i(line.uniform("u_depth_mode"), b.faint_when_hidden ? 1 : 2);
            glUniform1f(line.uniform("u_hidden_alpha"), 0.28f);
            glUniform1f(line.uniform("u_alpha"), 1.0f);
            draw_quads(ranges[k].second / 2);
            continue;
        }
        if (b.faint_when_hidden) {
            glDepthFunc(GL_GREATER);
            glUniform1f(line.uniform("u_alpha"), 0.28f);
            draw_quads(ranges[k].second / 2);
        }
        glDepthFunc(GL_LEQUAL);
        glUniform1f(line.uniform("u_alpha"), 1.0f);
        draw_quads(ranges[k].second / 2);
    }
    return point_base;
}

// Pass 4: points, the same way (or on top of everything).
void Renderer::Impl::draw_points(const Overlay& overlay, GLint point_base, const glm::mat4& vp,
                                 const float (&viewport)[2], bool one_pass) {
    glUseProgram(point.id());
    glUniformMatrix4fv(point.uniform("u_view_proj"), 1, GL_FALSE, glm::value_ptr(vp));
    glUniform2fv(point.uniform("u_viewport"), 1, viewport);
    GLint first = point_base;
    for (const PointBatch& b : overlay.points) {
        const GLsizei count = static_cast<GLsizei>(b.points.size());
        if (count == 0) continue;
        glUniform1f(point.uniform("u_size"), b.size_px);
        glUniform1i(point.uniform("u_sphere"), b.sphere ? 1 : 0);
        stream.points_from(first);
        if (one_pass) {
            glUniform1i(point.uniform("u_depth_mode"), b.on_top ? 0 : 1);
            glUniform1f(point.uniform("u_hidden_alpha"), 0.35f);
            glUniform1f(point.uniform("u_alpha"), 1.0f);
            draw_quads(count);
        } else if (b.on_top) {
            glDisable(GL_DEPTH_TEST);
            glUniform1f(point.uniform("u_alpha"), 1.0f);
            draw_quads(count);
            glEnable(GL_DEPTH_TEST);
        } else {
            glDepthFunc(GL_GREATER);
            glUniform1f(point.uniform("u_alpha"), 0.35f);
            draw_quads(count);
            glDepthFunc(GL_LEQUAL);
            glUniform1f(point.uniform("u_alpha"), 1.0f);
            draw_quads(count);
        }
        first += count;
    }
}

void Renderer::render(const SceneView& view, const std::vector<SurfaceDraw>& surfaces,
                      const Overlay& overlay) {
    stats_ = {};
    Impl& im = *impl_;
    // Geometry first: the buffers say whether any surface's shape changed.
    std::vector<MeshEntry*> entries;
    if (ok())
        for (const SurfaceDraw& d : surfaces) {
            MeshEntry& m = im.mesh_for(d, view.analysis.kind, stats_);
            entries.push_back(&m);
            stats_.vertices += m.vertices;
        }
    // A frame that changes nothing in the view (a hover, typing in a field, a panel's own
    // drag) keeps the last picture: on a CPU rasteriser a redraw costs tens of milliseconds.
    if (ok() && stats_.retessellated == 0 && im.last.matches(view, surfaces, overlay)) {
        im.prune();
        return;
    }
    im.last = {true, view, surfaces, overlay};
    stats_.redrawn = true;
    im.target.resize(view.width, view.height);
    im.target.bind_for_drawing();
    glClearColor(view.background.r, view.background.g, view.background.b, view.background.a);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!ok()) {
        im.target.resolve();
        return;
    }

    const double aspect = static_cast<double>(view.width) / std::max(view.height, 1);
    const glm::mat4 vp = glm::mat4(view_projection(view.camera, aspect));
    const glm::mat4 vmat = glm::mat4(view_matrix(view.camera));
    const float viewport[2] = {static_cast<float>(view.width), static_cast<float>(view.height)};

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_BLEND);
    // Keep destination alpha at 1 so the texture stays opaque inside ImGui.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);

    im.draw_shaded(view, surfaces, entries, vp, vmat, aspect);
    im.draw_wires(surfaces, entries, vp, viewport);
    const bool one_pass = im.begin_one_pass_overlay();
    glUseProgram(im.line.id());
    const GLint point_base = im.draw_overlay_lines(overlay, one_pass);
    im.draw_points(overlay, point_base, vp, viewport, one_pass);
    if (one_pass) im.end_one_pass_overlay();

    glBindVertexArray(0);
    glUseProgram(0);
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    im.target.resolve();
    im.prune();
}

} // namespace isoparm::ui
