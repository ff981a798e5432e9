// The polygonizer's work units and their arrays (polygonize.cpp schedules them,
// mesh_assembly.cpp merges them, polygonize_buffers.cpp keeps their arrays for the next
// polygonization). Internal to the polygonizer.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <utility>
#include <vector>

#include "core/geom/implicit/grid_layers.hpp"
#include "core/geom/implicit/polygonize.hpp"
#include "core/geom/implicit/polygonize_parts.hpp"
#include "core/geom/status.hpp"
#include "core/geom/tessellate.hpp"

namespace isoparm::geom::implicit::detail {

// ---------------------------------------------------------------------------------------------
// Work units: the boundary planes (layers where chunks meet, and the first and last layer),
// then the chunks of slabs between them. The split depends on the grid only, never on the
// number of threads, so the mesh and its vertex order are the same for any thread count.

struct BoundaryPlane {
    int layer = 0;
    std::vector<double> values;
    std::vector<std::uint8_t> rows;
    std::vector<std::uint64_t> signs;
    std::vector<Index> ids; // in-plane edge vertex ids, 3 per point
    VertexGroup vertices;

    Layer view(Index tag) const {
        return Layer{layer, values.data(), rows.data(), signs.data(), ids.data(), tag};
    }
};

struct Chunk {
    int first_slab = 0, end_slab = 0; // slabs [first, end): cells between layers k and k + 1
    VertexGroup vertices;
    std::vector<std::array<Index, 3>> triangles; // tagged ids
};

// A worker's reusable buffers.
struct Workspace {
    std::vector<double> scratch;
    std::vector<double> values[2];
    std::vector<std::uint8_t> rows[2];
    std::vector<std::uint64_t> signs[2];
    std::vector<Index> plane_ids[2];
    std::vector<Index> vertical_ids;
    Refiner refiner;
};

// The planes' and chunks' arrays of finished polygonizations, kept for the next one: the
// workstation polygonizes again at every parameter change and `isoparm render` one surface after
// another, and arrays of that size are fresh pages from the kernel each time (their page faults
// cost about a sixth of the gallery's polygonization). At most two sets and 128 MiB are kept.
struct Buffers {
    std::vector<BoundaryPlane> planes;
    std::vector<Chunk> chunks;

    std::size_t bytes() const;
};

class BufferPool {
public:
    Buffers take();
    void give(Buffers&& b);

private:
    std::mutex mutex_;
    std::vector<Buffers> free_;
};

BufferPool& buffer_pool();

// Empty arrays that keep their room.
void clear(VertexGroup& g);

// The options' errors (see polygonize.hpp), then the grid: ceil(extent / cell) cells per axis,
// the cell shrunk to fit (convention 18); a `limit` error past max_evaluation_points
// (polygonize_grid.cpp).
Status check_options(const Program& f, const PolygonizeOptions& o);
Expected<Grid> make_grid(const PolygonizeOptions& options);

// The mesh (mesh_assembly.cpp): the units merged in a fixed order (plane 0, chunk 0, plane 1,
// ..., the last plane), their arrays then given back to the buffer pool; `pinned` lists the
// vertices on zero grid points (point, vertex), which weld_pinned welds. repair_normals gives
// the vertices whose gradient vanished the average normal of their triangles.
Expected<Mesh> merge_chunks(std::vector<BoundaryPlane>& planes, std::vector<Chunk>& chunks,
                            std::vector<std::pair<std::uint64_t, Index>>& pinned);
void weld_pinned(Mesh& mesh, std::vector<std::pair<std::uint64_t, Index>>& pinned);
void repair_normals(Mesh& mesh);

} // namespace isoparm::geom::implicit::detail
