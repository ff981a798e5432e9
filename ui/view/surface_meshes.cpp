// The surfaces' display meshes (see surface_meshes.hpp).
#include "ui/view/surface_meshes.hpp"

#include <algorithm>
#include <chrono>

#include "core/geom/curvature.hpp"
#include "ui/view/analysis.hpp"
#include "ui/view/mesh_data.hpp"
#include "ui/view/tessellation_sampling.hpp"

namespace isoparm::ui {

namespace {

// Wireframe lines per direction: enough to read the shape, few enough not to hide it.
constexpr int wire_lines_per_direction = 24;

} // namespace

int SurfaceMeshes::update(std::vector<SurfaceDraw>& surfaces, AnalysisKind analysis) {
    int changed = 0;
    for (SurfaceDraw& d : surfaces) {
        if (!d.surface || d.mesh) continue;
        Entry& e = meshes_[d.id];
        e.used = true;
        if (update_one(e.mesh, *d.surface, d.density, analysis)) ++changed;
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

bool SurfaceMeshes::update_one(SurfaceMesh& m, const geom::Surface& s, int density,
                               AnalysisKind analysis) {
    // Only the curvature kinds put values in the scalar attribute.
    const AnalysisKind want = is_curvature(analysis) ? analysis : AnalysisKind::off;
    const bool rescalar = want != m.scalar_kind;
    m.scalar_kind = want;
    const auto t0 = std::chrono::steady_clock::now();
    const auto [su, sv] = display_samples(s, density);
    const bool resampled = m.density != density;
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
