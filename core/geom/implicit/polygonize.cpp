// Marching tetrahedra over a full grid with refined, shared vertices (Bloomenthal-style): the
// work units scheduled on worker threads, then the mesh assembled. The parts: the grid
// (polygonize_grid.cpp), its layers and their edge vertices (grid_layers.cpp, edge_refiner.cpp),
// the cells' triangles (cell_triangles.cpp, cube_cases.cpp), the arrays kept between runs
// (polygonize_buffers.cpp) and the merge (mesh_assembly.cpp).
#include "core/geom/implicit/polygonize.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <new>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "core/geom/implicit/polygonize_work.hpp"

namespace isoparm::geom::implicit {

using namespace detail;

namespace {

struct Polygonizer {
    Context ctx;
    std::vector<BoundaryPlane> planes;
    std::vector<Chunk> chunks;
    std::atomic<int> next_plane{0};
    std::atomic<int> next_chunk{0};
    std::atomic<long> units_done{0};
    long units_total = 0;
    std::atomic<bool> stop{false};
    std::atomic<std::size_t> planes_done{0};
    // The running size of the mesh against the caps (vertices counted before welding, so a
    // little above the final count), summed after every plane and slab by the worker that
    // made them: a worker overshoots by at most one slab before every worker stops.
    std::atomic<std::size_t> vertex_count{0}, triangle_count{0};
    std::size_t max_vertices = 0, max_triangles = 0;
    std::atomic<bool> over_cap{false};
    bool cancelled = false; // written by the calling thread only
    std::exception_ptr failure;
    std::mutex failure_mutex;
    const std::function<bool(double)>* progress = nullptr;

    explicit Polygonizer(Context c) : ctx(c) {}

    // Called after every unit; only the calling thread (worker 0) reports progress.
    void unit_done(int worker) {
        const long done = ++units_done;
        if (worker == 0 && *progress && !(*progress)(static_cast<double>(done) / units_total)) {
            cancelled = true;
            halt();
        }
    }

    void do_plane(BoundaryPlane& bp, Workspace& ws) {
        const Grid& g = ctx.grid;
        bp.values.resize(g.plane);
        bp.rows.resize(g.ny + 1);
        bp.signs.resize((g.ny + 1) * sign_words(g));
        bp.ids.resize(g.plane * 3);
        evaluate_layer(ctx, bp.layer, bp.values.data(), bp.rows.data(), bp.signs.data(),
                       ws.scratch);
        make_plane_vertices(ctx, bp.layer, bp.values.data(), bp.rows.data(), bp.signs.data(),
                            bp.ids.data(), bp.vertices, ws.refiner);
        count(bp.vertices.positions.size(), 0);
    }

    void do_chunk(int c, Workspace& ws, int worker) {
        const Grid& g = ctx.grid;
        Chunk& chunk = chunks[c];
        ws.vertical_ids.resize(g.plane * 4);

        Layer bottom = planes[c].view(tag_bottom);
        const BoundaryPlane& above = planes[c + 1];
        // Room for about what the chunk will make, from its boundary planes' vertices: per
        // slab about one layer's in-plane vertices and 4/3 of that across (seven edge
        // directions, three in the plane), two triangles per vertex. Growing instead would
        // copy the arrays at every doubling.
        const double per_layer = 0.5 * static_cast<double>(planes[c].vertices.positions.size() +
                                                           above.vertices.positions.size());
        const auto expected =
            static_cast<std::size_t>(2.5 * per_layer * (chunk.end_slab - chunk.first_slab));
        chunk.vertices.positions.reserve(expected);
        chunk.vertices.normals.reserve(expected);
        chunk.triangles.reserve(2 * expected);
        int buffer = 0;
        for (int k = chunk.first_slab; k < chunk.end_slab; ++k) {
            if (stop) return;
            const std::size_t vertices_before = chunk.vertices.positions.size();
            const std::size_t triangles_before = chunk.triangles.size();
            Layer top;
            if (k + 1 == above.layer) {
                top = above.view(tag_top);
            } else {
                // Interior layers live in the worker's buffers (allocated on first use).
                ws.values[buffer].resize(g.plane);
                ws.rows[buffer].resize(g.ny + 1);
                ws.signs[buffer].resize((g.ny + 1) * sign_words(g));
                ws.plane_ids[buffer].resize(g.plane * 3);
                double* values = ws.values[buffer].data();
                std::uint8_t* rows = ws.rows[buffer].data();
                std::uint64_t* signs = ws.signs[buffer].data();
                Index* ids = ws.plane_ids[buffer].data();
                evaluate_layer(ctx, k + 1, values, rows, signs, ws.scratch);
                make_plane_vertices(ctx, k + 1, values, rows, signs, ids, chunk.vertices,
                                    ws.refiner);
                top = Layer{k + 1, values, rows, signs, ids, tag_local};
            }
            make_vertical_vertices(ctx, bottom, top, ws.vertical_ids.data(), chunk.vertices,
                                   ws.refiner);
            emit_triangles(g, bottom, top, ws.vertical_ids.data(),
                           {&chunk.vertices.positions, &planes[c].vertices.positions,
                            &above.vertices.positions},
                           chunk.triangles);
            count(chunk.vertices.positions.size() - vertices_before,
                  chunk.triangles.size() - triangles_before);
            bottom = top;
            buffer ^= 1;
            unit_done(worker);
        }
    }

    void work(int worker) {
        try {
            Workspace ws;
            for (int b; !stop && (b = next_plane++) < static_cast<int>(planes.size());) {
                do_plane(planes[b], ws);
                planes_done.fetch_add(1, std::memory_order_release);
                planes_done.notify_all();
                unit_done(worker);
            }
            // The chunks read the boundary planes, so every plane must be finished first.
            for (std::size_t done;
                 !stop && (done = planes_done.load(std::memory_order_acquire)) < planes.size();)
                planes_done.wait(done, std::memory_order_acquire);
            for (int c; !stop && (c = next_chunk++) < static_cast<int>(chunks.size());)
                do_chunk(c, ws, worker);
        } catch (...) {
            {
                std::lock_guard<std::mutex> lock(failure_mutex);
                if (!failure) failure = std::current_exception();
            }
            halt();
        }
    }

    void count(std::size_t vertices, std::size_t triangles) {
        const std::size_t v = vertex_count += vertices;
        const std::size_t t = triangle_count += triangles;
        if (v > max_vertices || t > max_triangles) {
            over_cap = true;
            halt();
        }
    }

    // Stops every worker at its next unit, including one waiting for the planes.
    void halt() {
        stop = true;
        planes_done.fetch_add(planes.size(), std::memory_order_release);
        planes_done.notify_all();
    }
};

// Why the threads' work gave no mesh: an exception, a cap passed, a cancel; or nothing.
Status polygonizer_failure(const Polygonizer& pz, const PolygonizeOptions& options) {
    if (pz.failure) {
        try {
            std::rethrow_exception(pz.failure);
        } catch (const std::bad_alloc&) {
            return make_error(ErrorCode::limit, "not enough memory to polygonize this grid",
                              "/cell");
        } catch (const std::exception& e) {
            return make_error_nopath(ErrorCode::internal,
                                     std::string("polygonization failed: ") + e.what());
        }
    }
    if (pz.over_cap) {
        const bool vertices = pz.vertex_count > options.max_vertices;
        return make_error(
            ErrorCode::limit,
            "cell " + format_number(options.cell) + " gives a mesh of more than " +
                std::to_string(vertices ? options.max_vertices : options.max_triangles) +
                (vertices ? " vertices" : " triangles") +
                " (the most allowed); use a larger cell or smaller bounds",
            "/cell");
    }
    if (pz.cancelled) return make_error_nopath(ErrorCode::limit, "polygonization was cancelled");
    return Ok{};
}

} // namespace

Expected<Mesh> polygonize(const Program& f, const PolygonizeOptions& options) {
    if (Status s = check_options(f, options); !s) return s.error();

    Expected<Grid> made = make_grid(options);
    if (!made) return made.error();
    const Grid& grid = *made;
    Polygonizer pz(Context{f, options.parameters.data(), grid});
    pz.progress = &options.progress;
    pz.max_vertices = options.max_vertices;
    pz.max_triangles = options.max_triangles;
    // About eight slabs per chunk, at most 32 chunks: enough to balance two to eight threads.
    const int chunk_count = std::clamp(grid.nz / 8, 1, 32);
    Buffers reused = buffer_pool().take();
    pz.planes = std::move(reused.planes);
    pz.chunks = std::move(reused.chunks);
    pz.planes.resize(chunk_count + 1);
    pz.chunks.resize(chunk_count);
    for (BoundaryPlane& bp : pz.planes) clear(bp.vertices);
    for (Chunk& ch : pz.chunks) {
        clear(ch.vertices);
        ch.triangles.clear();
    }
    for (int c = 0; c <= chunk_count; ++c)
        pz.planes[c].layer = static_cast<int>(static_cast<long>(grid.nz) * c / chunk_count);
    for (int c = 0; c < chunk_count; ++c) {
        pz.chunks[c].first_slab = pz.planes[c].layer;
        pz.chunks[c].end_slab = pz.planes[c + 1].layer;
    }
    pz.units_total = static_cast<long>(pz.planes.size()) + grid.nz;

    int threads = options.threads > 0 ? options.threads
                                      : static_cast<int>(std::thread::hardware_concurrency());
    threads = std::clamp(threads, 1, chunk_count);
    {
        std::vector<std::jthread> helpers;
        for (int w = 1; w < threads; ++w) helpers.emplace_back([&pz, w] { pz.work(w); });
        pz.work(0);
    }
    if (Status failed = polygonizer_failure(pz, options); !failed) return failed.error();

    std::vector<std::pair<std::uint64_t, Index>> pinned;
    Expected<Mesh> merged = merge_chunks(pz.planes, pz.chunks, pinned);
    if (!merged) return merged.error();
    Mesh& mesh = *merged;
    weld_pinned(mesh, pinned);
    repair_normals(mesh);
    mesh.exists.assign(mesh.positions.size(), 1);
    if (options.progress && !options.progress(1.0))
        return make_error_nopath(ErrorCode::limit, "polygonization was cancelled");
    return std::move(mesh);
}

} // namespace isoparm::geom::implicit
