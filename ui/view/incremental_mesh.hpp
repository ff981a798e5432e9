// A surface's display mesh kept up to date between frames: a drag that moved a few control
// points re-evaluates only the grid rows their basis functions touch (geom::GridTessellator's
// local update); anything else re-tessellates. Header-only, so the core-only drag benchmark
// measures exactly what the renderer runs.
#pragma once

#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

#include "core/geom/grid_tessellator.hpp"
#include "core/geom/tessellate.hpp"
#include "core/geom/types.hpp"

namespace isoparm::ui {

// What the last update changed, for the GPU upload.
struct MeshChange {
    bool any = false;      // nothing to upload when false
    bool topology = false; // triangles (and wireframe) must be rebuilt too
    int first_vertex = 0;  // the changed vertices: [first_vertex, first_vertex + count)
    int vertex_count = 0;
};

class IncrementalMesh {
public:
    // More changed points than this re-tessellates (a transform moves them all).
    static constexpr int max_local_points = 8;

    MeshChange update(const geom::Surface& s, int samples_u, int samples_v) {
        MeshChange c;
        if (tess_ && tess_->fits(s, samples_u, samples_v) && same_layout(s)) {
            const std::vector<std::pair<int, int>> moved = changed_points(s);
            if (moved.empty()) return c;
            if (static_cast<int>(moved.size()) <= max_local_points) {
                const std::size_t triangles = mesh_.triangles.size();
                const std::vector<std::uint8_t> exists = mesh_.exists;
                int r0 = samples_u, r1 = -1;
                for (const auto& [i, j] : moved) {
                    tess_->update_control_point(s, mesh_, i, j);
                    const auto [a, b] = tess_->rows_touching(i);
                    r0 = std::min(r0, a);
                    r1 = std::max(r1, b);
                }
                source_ = s;
                c.any = r1 >= r0;
                c.topology = mesh_.exists != exists || mesh_.triangles.size() != triangles;
                c.first_vertex = std::max(r0, 0) * samples_v;
                c.vertex_count = std::max(r1 - r0 + 1, 0) * samples_v;
                return c;
            }
        }
        if (!tess_ || !tess_->fits(s, samples_u, samples_v))
            tess_ = std::make_unique<geom::GridTessellator>(s, samples_u, samples_v);
        tess_->evaluate(s, mesh_, 1);
        source_ = s;
        c.any = c.topology = true;
        c.first_vertex = 0;
        c.vertex_count = static_cast<int>(mesh_.positions.size());
        return c;
    }

    const geom::Mesh& mesh() const { return mesh_; }
    int samples_u() const { return tess_ ? tess_->samples_u() : 0; }
    int samples_v() const { return tess_ ? tess_->samples_v() : 0; }

private:
    bool same_layout(const geom::Surface& s) const {
        return s.type == source_.type && s.degree_u == source_.degree_u &&
               s.degree_v == source_.degree_v && s.n_u == source_.n_u && s.n_v == source_.n_v &&
               s.knots_u == source_.knots_u && s.knots_v == source_.knots_v &&
               s.points.size() == source_.points.size() &&
               s.weights.size() == source_.weights.size();
    }
    // The control points whose position or weight differs from the last build (exactly).
    std::vector<std::pair<int, int>> changed_points(const geom::Surface& s) const {
        std::vector<std::pair<int, int>> out;
        for (int i = 0; i < s.n_u; ++i)
            for (int j = 0; j < s.n_v; ++j) {
                const int k = s.index(i, j);
                if (s.points[k] != source_.points[k] || s.weights[k] != source_.weights[k]) {
                    out.emplace_back(i, j);
                    if (static_cast<int>(out.size()) > max_local_points) return out;
                }
            }
        return out;
    }

    std::unique_ptr<geom::GridTessellator> tess_;
    geom::Mesh mesh_;
    geom::Surface source_;
};

} // namespace isoparm::ui
