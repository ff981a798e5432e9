// The surfaces' display meshes (see surface_meshes.hpp).
#include "ui/view/surface_meshes.hpp"

#include <algorithm>
#include <chrono>
#include <limits>

#include "core/geom/curvature.hpp"
#include "ui/view/analysis.hpp"
#include "ui/view/mesh_data.hpp"
#include "ui/view/tessellation_sampling.hpp"

namespace isoparm::ui {

namespace {

// Wireframe lines per direction: enough to read the shape, few enough not to hide it.
constexpr int wire_lines_per_direction = 24;

} // namespace

int SurfaceMeshes::update(std::vector<SurfaceDraw>& surfaces, AnalysisKind analysis, bool gesture) {
    int changed = 0;
    for (SurfaceDraw& d : surfaces) {
        if (!d.surface || d.mesh) continue;
        Entry& e = meshes_[d.id];
        e.used = true;
        const bool updated = d.trim && !d.trim->empty()
                                 ? update_trimmed(e.mesh, *d.surface, *d.trim, d.density, analysis)
                                 : update_one(e.mesh, *d.surface, d.density, gesture, analysis);
        if (updated) ++changed;
        d.display = &e.mesh;
        d.mesh_revision = e.mesh.revision;
    }
    for (auto it = meshes_.begin(); it != meshes_.end();) {
        if (!it->second.used) {
            it = meshes_.erase(it);
        } else {
            it->second.used = false;
            ++it;
        }
    }
    return changed;
}

namespace {

bool same_trim_curves(const geom::TrimLoop& a, const geom::TrimLoop& b) {
    return std::equal(a.curves.begin(), a.curves.end(), b.curves.begin(), b.curves.end(),
                      [](const geom::Curve& x, const geom::Curve& y) {
                          return x.degree == y.degree && x.knots == y.knots &&
                                 x.points == y.points && x.weights == y.weights;
                      });
}

bool same_trim(const geom::Trim& a, const geom::Trim& b) {
    if (a.outer.has_value() != b.outer.has_value()) return false;
    if (a.outer && !same_trim_curves(*a.outer, *b.outer)) return false;
    return std::equal(a.holes.begin(), a.holes.end(), b.holes.begin(), b.holes.end(),
                      same_trim_curves);
}

bool same_domain_layout(const geom::Surface& a, const geom::Surface& b) {
    return a.degree_u == b.degree_u && a.degree_v == b.degree_v && a.knots_u == b.knots_u &&
           a.knots_v == b.knots_v;
}

bool same_points(const geom::Surface& a, const geom::Surface& b) {
    return a.type == b.type && a.n_u == b.n_u && a.n_v == b.n_v && a.points == b.points &&
           a.weights == b.weights;
}

// The wireframe of a trimmed mesh: its loops (the boundary) and, every few rows and columns,
// the grid lines between kept grid vertices.
std::vector<std::uint32_t> trimmed_wire(const geom::TrimmedLayout& layout, int max_lines) {
    std::vector<std::uint32_t> pairs;
    for (const auto& loop : layout.loops)
        for (std::size_t k = 0; k < loop.size(); ++k) {
            pairs.push_back(loop[k]);
            pairs.push_back(loop[(k + 1) % loop.size()]);
        }
    const auto nu = static_cast<std::uint32_t>(layout.us.size());
    const auto nv = static_cast<std::uint32_t>(layout.vs.size());
    // Grid index (i * nv + j) -> vertex, for the grid points kept.
    std::vector<std::int64_t> vertex(std::size_t(nu) * nv, -1);
    for (std::size_t k = 0; k < layout.grid_vertices.size(); ++k)
        vertex[layout.grid_vertices[k]] = static_cast<std::int64_t>(k);
    const std::uint32_t step_u = std::max<std::uint32_t>(1, (nu - 1) / max_lines);
    const std::uint32_t step_v = std::max<std::uint32_t>(1, (nv - 1) / max_lines);
    auto link = [&](std::uint32_t a, std::uint32_t b) {
        if (vertex[a] < 0 || vertex[b] < 0) return;
        pairs.push_back(static_cast<std::uint32_t>(vertex[a]));
        pairs.push_back(static_cast<std::uint32_t>(vertex[b]));
    };
    for (std::uint32_t i = 0; i < nu; i += step_u)
        for (std::uint32_t j = 0; j + 1 < nv; ++j) link(i * nv + j, i * nv + j + 1);
    for (std::uint32_t j = 0; j < nv; j += step_v)
        for (std::uint32_t i = 0; i + 1 < nu; ++i) link(i * nv + j, (i + 1) * nv + j);
    return pairs;
}

// Curvature at each vertex of a trimmed mesh, at its own (u, v).
std::vector<double> trimmed_curvature(const geom::Surface& s, const geom::TrimmedLayout& layout,
                                      AnalysisKind kind) {
    // NaN where the curvature does not exist, as curvature_grid gives it.
    std::vector<double> out(layout.vertex_count(), std::numeric_limits<double>::quiet_NaN());
    const geom::CurvatureKind which = curvature_kind(kind);
    for (std::size_t k = 0; k < out.size(); ++k) {
        const glm::dvec2 p = layout.param(static_cast<std::uint32_t>(k));
        const auto c = geom::surface_curvature(s, p.x, p.y);
        if (!c) continue;
        out[k] = which == geom::CurvatureKind::gaussian ? c->gaussian
                 : which == geom::CurvatureKind::mean   ? c->mean
                 : which == geom::CurvatureKind::k_max  ? c->k1
                                                        : c->k2;
    }
    return out;
}

} // namespace

// A trimmed surface's mesh, remade whole on every change (a drag of a trimmed face re-evaluates
// every point; the triangulation is kept while only the control points move).
bool SurfaceMeshes::update_trimmed(SurfaceMesh& m, const geom::Surface& s, const geom::Trim& trim,
                                   int density, AnalysisKind analysis) {
    const AnalysisKind want = is_curvature(analysis) ? analysis : AnalysisKind::off;
    const auto [su, sv] = display_samples(s, density);
    const bool was_trimmed = m.trimmed.has_value();
    if (!was_trimmed) {
        m.trimmed.emplace();
        m.mesh = IncrementalMesh{};
    }
    TrimmedMesh& t = *m.trimmed;
    const bool relayout = !t.tessellator || t.samples_u != su || t.samples_v != sv ||
                          !same_domain_layout(t.surface, s) || !same_trim(t.trim, trim);
    const bool moved = relayout || !same_points(t.surface, s);
    if (!moved && want == m.scalar_kind && m.density == density) return false;
    const auto t0 = std::chrono::steady_clock::now();
    if (relayout) {
        t.tessellator = std::make_shared<const geom::TrimmedTessellator>(s, trim, su, sv);
        t.trim = trim;
        t.samples_u = su;
        t.samples_v = sv;
    }
    if (moved) {
        t.tessellator->evaluate(s, t.mesh);
        t.surface = s;
    }
    m.scalar_kind = want;
    m.density = density;
    const geom::TrimmedLayout& layout = t.tessellator->layout();
    const std::vector<double> scalars =
        want == AnalysisKind::off ? std::vector<double>{} : trimmed_curvature(s, layout, want);
    m.vertices = interleave(t.mesh, 0, t.mesh.positions.size(), scalars);
    m.wire_pairs = trimmed_wire(layout, wire_lines_per_direction);
    m.since = m.revision;
    m.revision = next_revision_++;
    m.partial = false;
    m.first = 0;
    m.count = t.mesh.positions.size();
    m.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return true;
}

bool SurfaceMeshes::update_one(SurfaceMesh& m, const geom::Surface& s, int density, bool gesture,
                               AnalysisKind analysis) {
    if (m.trimmed) { // trimmed before: start the incremental mesh afresh
        m.trimmed.reset();
        m.mesh = IncrementalMesh{};
        m.revision = 0;
    }
    // Only the curvature kinds put values in the scalar attribute.
    const AnalysisKind want = is_curvature(analysis) ? analysis : AnalysisKind::off;
    const bool rescalar = want != m.scalar_kind;
    m.scalar_kind = want;
    const auto t0 = std::chrono::steady_clock::now();
    const auto [su, sv] = gesture ? gesture_samples(s, density) : display_samples(s, density);
    const bool resampled = m.mesh.samples_u() != su || m.mesh.samples_v() != sv;
    m.density = density;
    const MeshChange change = m.mesh.update(s, su, sv);
    if (!change.any && !rescalar) return false;
    const geom::Mesh& mesh = m.mesh.mesh();
    const bool full = rescalar || change.topology || resampled || m.revision == 0 ||
                      change.vertex_count == static_cast<int>(mesh.positions.size());
    const std::size_t first = full ? 0 : static_cast<std::size_t>(change.first_vertex);
    const std::size_t count =
        full ? mesh.positions.size() : static_cast<std::size_t>(change.vertex_count);
    // Curvature from exact derivatives at the vertices (never from the mesh).
    const std::vector<double> scalars =
        want == AnalysisKind::off
            ? std::vector<double>{}
            : geom::curvature_grid(s, su, sv, curvature_kind(want), first, count);
    std::vector<float> verts = interleave(mesh, first, count, scalars);
    if (full) {
        m.vertices = std::move(verts);
        m.wire_pairs = wire_indices(su, sv, mesh.exists, wire_lines_per_direction);
    } else {
        // Only the rows the moved points' basis functions reach.
        std::copy(verts.begin(), verts.end(),
                  m.vertices.begin() + static_cast<std::ptrdiff_t>(first * floats_per_vertex));
    }
    m.since = m.revision;
    m.revision = next_revision_++;
    m.partial = !full;
    m.first = first;
    m.count = count;
    m.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return true;
}

} // namespace isoparm::ui
