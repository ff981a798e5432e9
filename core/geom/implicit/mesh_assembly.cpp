// The polygonizer's mesh from its work units: merged in a fixed order, the vertices on zero
// grid points welded, the normals that grad f could not give repaired (see polygonize_work.hpp);
// and the public helpers on a finished mesh (polygonize.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/geom/implicit/polygonize.hpp"
#include "core/geom/implicit/polygonize_work.hpp"

namespace isoparm::geom::implicit {

using namespace detail;

int side_seen_from_outside(const Program& f, const PolygonizeOptions& options, const Mesh& mesh) {
    if (mesh.triangles.empty()) return 0;
    // A vertex on a face is where a grid edge in that face changes sign. Its coordinate across
    // the face is the bound up to the rounding of an interpolation along the edge; a vertex of
    // an edge into the box comes this near only at the edge's end on the face (the surface
    // touches the face there): also open, on the safe side.
    const glm::dvec3 tolerance =
        1e-9 * glm::max(glm::abs(options.lo), glm::abs(options.hi)) + 1e-9 * options.cell;
    for (const glm::dvec3& p : mesh.positions)
        for (int a = 0; a < 3; ++a)
            if (!(p[a] - options.lo[a] > tolerance[a] && options.hi[a] - p[a] > tolerance[a]))
                return 0;
    return positive(f.value(options.lo, options.parameters.data())) ? 1 : -1;
}

std::size_t drop_degenerate_triangles(Mesh& mesh) {
    const std::size_t before = mesh.triangles.size();
    std::erase_if(mesh.triangles, [](const std::array<Index, 3>& t) {
        return t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
    });
    const std::size_t removed = before - mesh.triangles.size();
    std::vector<Index> remap(mesh.positions.size(), 0);
    for (const auto& t : mesh.triangles)
        for (Index v : t) remap[v] = 1;
    if (std::all_of(remap.begin(), remap.end(), [](Index r) { return r != 0; })) return removed;
    Index next = 0;
    for (std::size_t v = 0; v < remap.size(); ++v) {
        if (!remap[v]) continue;
        remap[v] = next;
        mesh.positions[next] = mesh.positions[v];
        if (v < mesh.normals.size()) mesh.normals[next] = mesh.normals[v];
        if (v < mesh.exists.size()) mesh.exists[next] = mesh.exists[v];
        ++next;
    }
    mesh.positions.resize(next);
    if (mesh.normals.size() > next) mesh.normals.resize(next);
    if (mesh.exists.size() > next) mesh.exists.resize(next);
    for (auto& t : mesh.triangles)
        for (Index& v : t) v = remap[v];
    return removed;
}

namespace detail {

// Merge in a fixed order: plane 0, chunk 0, plane 1, chunk 1, ..., the last plane. The
// vertices that sit on a zero grid point are listed in `pinned` (point, vertex).
Expected<Mesh> merge_chunks(std::vector<BoundaryPlane>& planes, std::vector<Chunk>& chunks,
                            std::vector<std::pair<std::uint64_t, Index>>& pinned) {
    Mesh mesh;
    std::vector<std::size_t> plane_offset(planes.size()), chunk_offset(chunks.size());
    auto append = [&](const VertexGroup& g) {
        const std::size_t offset = mesh.positions.size();
        mesh.positions.insert(mesh.positions.end(), g.positions.begin(), g.positions.end());
        mesh.normals.insert(mesh.normals.end(), g.normals.begin(), g.normals.end());
        for (const auto& [id, point] : g.pinned)
            pinned.emplace_back(point, static_cast<Index>(offset + id));
        return offset;
    };
    // Sized once: appended group by group, the arrays would be copied again at every growth.
    std::size_t vertex_total = 0;
    for (const BoundaryPlane& bp : planes) vertex_total += bp.vertices.positions.size();
    for (const Chunk& ch : chunks) vertex_total += ch.vertices.positions.size();
    mesh.positions.reserve(vertex_total);
    mesh.normals.reserve(vertex_total);
    std::size_t triangle_count = 0;
    for (std::size_t c = 0; c < chunks.size(); ++c) {
        plane_offset[c] = append(planes[c].vertices);
        chunk_offset[c] = append(chunks[c].vertices);
        triangle_count += chunks[c].triangles.size();
    }
    plane_offset.back() = append(planes.back().vertices);
    if (mesh.positions.size() >= static_cast<std::size_t>(tag_bottom))
        return make_error(ErrorCode::limit, "the mesh has too many vertices", "/cell");
    mesh.triangles.resize(triangle_count);
    std::array<Index, 3>* out = mesh.triangles.data();
    for (std::size_t c = 0; c < chunks.size(); ++c) {
        const Index offsets[3] = {static_cast<Index>(chunk_offset[c]),
                                  static_cast<Index>(plane_offset[c]),
                                  static_cast<Index>(plane_offset[c + 1])};
        for (const auto& t : chunks[c].triangles) {
            for (int k = 0; k < 3; ++k) (*out)[k] = (t[k] & ~tag_mask) + offsets[t[k] >> 30];
            ++out;
        }
    }
    buffer_pool().give(Buffers{std::move(planes), std::move(chunks)});
    planes.clear();
    chunks.clear();

    return mesh;
}

// Weld the vertices that sit on the same zero grid point, then drop the triangles that
// collapsed (they repeat a vertex).
void weld_pinned(Mesh& mesh, std::vector<std::pair<std::uint64_t, Index>>& pinned) {
    if (pinned.empty()) return;
    std::sort(pinned.begin(), pinned.end());
    std::vector<Index> remap(mesh.positions.size());
    for (std::size_t v = 0; v < remap.size(); ++v) remap[v] = static_cast<Index>(v);
    for (std::size_t s = 0; s < pinned.size();) {
        std::size_t e = s;
        while (e < pinned.size() && pinned[e].first == pinned[s].first) ++e;
        for (std::size_t k = s + 1; k < e; ++k) remap[pinned[k].second] = pinned[s].second;
        s = e;
    }
    for (auto& t : mesh.triangles)
        for (Index& v : t) v = remap[v];
    drop_degenerate_triangles(mesh);
}

// Unit normals for vertices whose gradient vanished: the area-weighted average of the normals
// of the triangles around them.
void repair_normals(Mesh& mesh) {
    std::vector<char> needs(mesh.positions.size(), 0);
    bool any = false;
    for (std::size_t v = 0; v < mesh.normals.size(); ++v)
        if (mesh.normals[v] == glm::dvec3(0.0)) needs[v] = 1, any = true;
    if (!any) return;
    std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
    for (const auto& t : mesh.triangles) {
        if (!needs[t[0]] && !needs[t[1]] && !needs[t[2]]) continue;
        const glm::dvec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                        mesh.positions[t[2]] - mesh.positions[t[0]]);
        for (Index v : t) sum[v] += n;
    }
    for (std::size_t v = 0; v < mesh.normals.size(); ++v) {
        if (!needs[v]) continue;
        const double len = glm::length(sum[v]);
        mesh.normals[v] = std::isfinite(len) && len > 0 ? sum[v] / len : glm::dvec3(0.0, 0.0, 1.0);
    }
}

} // namespace detail

} // namespace isoparm::geom::implicit
