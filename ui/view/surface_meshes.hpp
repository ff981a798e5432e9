// The surfaces' display meshes, CPU side (the owner of the cache; the renderer only uploads
// and draws them): each surface's tessellation, updated locally during drags
// (incremental_mesh.hpp), its vertices interleaved for the GPU with the curvature kind's
// scalar (mesh_data.hpp), its wireframe, and what its last change touched. A trimmed surface's
// mesh comes from the trimmed tessellator (core/geom/trim/trimmed_tessellator.hpp) instead.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/geom/trim/trimmed_tessellator.hpp"
#include "ui/view/incremental_mesh.hpp"
#include "ui/view/scene_draw.hpp"

namespace isoparm::ui {

// A trimmed surface's mesh: the triangulation of its kept domain (remade when the trim, the
// knots or the sampling change) and the points on it (remade when the surface changes).
struct TrimmedMesh {
    std::shared_ptr<const geom::TrimmedTessellator> tessellator;
    geom::Mesh mesh;
    geom::Surface surface; // what mesh was made of
    geom::Trim trim;
    int samples_u = 0, samples_v = 0;
};

struct SurfaceMesh {
    IncrementalMesh mesh; // an untrimmed surface's
    std::optional<TrimmedMesh> trimmed;
    int density = 0;
    AnalysisKind scalar_kind = AnalysisKind::off; // what the vertices' scalar holds
    std::vector<float> vertices;                  // interleaved, floats_per_vertex each
    std::vector<std::uint32_t> wire_pairs;        // index pairs into the mesh
    // Unique across all surfaces' meshes; changes with every change of this one.
    std::uint64_t revision = 0;
    // The last change: from revision `since` it touched only vertices [first, first + count)
    // (partial), or everything (the triangles and the wireframe too).
    std::uint64_t since = 0;
    bool partial = false;
    std::size_t first = 0, count = 0;
    double milliseconds = 0; // the CPU time the last change took

    // The mesh drawn: the trimmed one for a trimmed surface.
    const geom::Mesh& geometry() const { return trimmed ? trimmed->mesh : mesh.mesh(); }
};

class SurfaceMeshes {
public:
    // Brings the mesh of every surface in `surfaces` (those with SurfaceDraw::surface) up to
    // date under the analysis kind, sets its SurfaceDraw::display and mesh_revision, and drops
    // the meshes of surfaces not drawn. Returns how many changed. `gesture`: a gesture frame on
    // a CPU rasteriser, whose untrimmed surfaces are sampled coarser (gesture_samples).
    int update(std::vector<SurfaceDraw>& surfaces, AnalysisKind analysis, bool gesture = false);

private:
    bool update_one(SurfaceMesh& m, const geom::Surface& s, int density, bool gesture,
                    AnalysisKind analysis);
    bool update_trimmed(SurfaceMesh& m, const geom::Surface& s, const geom::Trim& trim, int density,
                        AnalysisKind analysis);
    struct Entry {
        SurfaceMesh mesh;
        bool used = false;
    };
    std::unordered_map<std::uint64_t, Entry> meshes_;
    std::uint64_t next_revision_ = 1;
};

} // namespace isoparm::ui
