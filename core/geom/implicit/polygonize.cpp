// Marching tetrahedra over a full grid with refined, shared vertices (Bloomenthal-style).
#include "core/geom/implicit/polygonize.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <exception>
#include <mutex>
#include <new>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/geom/implicit/polygonize_parts.hpp"
#include "core/geom/validate.hpp"

namespace isoparm::geom::implicit {

using namespace detail;

namespace {

// Coordinates lo + (hi - lo) i / n, exact at both ends.
std::vector<double> grid_coordinates(double lo, double hi, int n) {
    std::vector<double> c(n + 1);
    for (int i = 0; i < n; ++i) c[i] = lo + (hi - lo) * (static_cast<double>(i) / n);
    c[n] = hi;
    return c;
}

// In-plane edge directions (x, y, x+y) and the layer-crossing ones (z, x+z, y+z, x+y+z), as
// offsets; d = 1..7 is the corner-offset bit pattern of the edge.
constexpr int edge_dx(int d) {
    return d & 1;
}
constexpr int edge_dy(int d) {
    return (d >> 1) & 1;
}

// Row summaries: every value of a row negative, every one positive, or both signs. Rows whose
// neighbourhood has a single sign have no sign change to look at, which skips most of the grid.
enum RowSign : std::uint8_t { row_negative = 0, row_positive = 1, row_mixed = 2 };

// Sign bits: bit i % 64 of signs[j * words + i / 64] is positive(value of point (i, j)); the
// bits past a row's end are 0. Within a row that has both signs, the points and cells with a
// sign change nearby are found 64 at a time from them (for_candidates), and only those are
// looked at one by one, exactly as before.
std::size_t sign_words(const Grid& g) {
    return (g.row + 63) / 64;
}

// The row's bits shifted down by one (bit i: point i + 1), the next word's first bit on top.
inline std::uint64_t next_bits(const std::uint64_t* row, std::size_t w, std::size_t words) {
    return (row[w] >> 1) | (w + 1 < words ? row[w + 1] << 63 : 0);
}

// Calls f(i) for each point i of a row whose bit is set in candidates(w), in increasing order.
template <class Bits, class F> void for_candidates(std::size_t words, Bits candidates, F&& f) {
    for (std::size_t w = 0; w < words; ++w)
        for (std::uint64_t bits = candidates(w); bits != 0; bits &= bits - 1)
            f(static_cast<int>(w * 64 + static_cast<std::size_t>(std::countr_zero(bits))));
}

// Values of layer k, one batch evaluation per row, each row's sign summary and sign bits.
void evaluate_layer(const Context& ctx, int k, double* values, std::uint8_t* rows,
                    std::uint64_t* signs, std::vector<double>& scratch) {
    const Grid& g = ctx.grid;
    const std::size_t words = sign_words(g);
    for (int j = 0; j <= g.ny; ++j) {
        double* row = values + j * g.row;
        ctx.f.values_along_x(g.xs.data(), g.row, g.ys[j], g.zs[k], row, ctx.params, scratch);
        std::size_t count = 0;
        std::uint64_t* bits = signs + j * words;
        std::fill_n(bits, words, 0);
        for (std::size_t i = 0; i < g.row; ++i) {
            const bool p = positive(row[i]);
            count += p;
            bits[i / 64] |= static_cast<std::uint64_t>(p) << (i % 64);
        }
        rows[j] = count == 0 ? row_negative : count == g.row ? row_positive : row_mixed;
    }
}

// True when rows j and j + 1 (if any) of both row summaries are uniform with one sign.
inline bool rows_uniform(const std::uint8_t* a, const std::uint8_t* b, int j, int last) {
    const std::uint8_t s = a[j];
    if (s == row_mixed || b[j] != s) return false;
    return j == last || (a[j + 1] == s && b[j + 1] == s);
}

// One layer of the grid as a slab sees it: values, row summaries, and where the vertices on its
// in-plane edges (d = 1, 2, 3) live (ids[point * 3 + d - 1], tagged with the owner group).
struct Layer {
    int k = 0;
    const double* values = nullptr;
    const std::uint8_t* rows = nullptr;
    const std::uint64_t* signs = nullptr;
    const Index* ids = nullptr;
    Index tag = tag_local;
};

// Vertices on the in-plane edges (d = 1, 2, 3) of layer k; ids[point * 3 + d - 1].
void make_plane_vertices(const Context& ctx, int k, const double* values, const std::uint8_t* rows,
                         const std::uint64_t* signs, Index* ids, VertexGroup& out,
                         Refiner& refiner) {
    const Grid& g = ctx.grid;
    const std::size_t words = sign_words(g);
    for (int j = 0; j <= g.ny; ++j) {
        if (rows_uniform(rows, rows, j, g.ny)) continue;
        const double* row = values + j * g.row;
        const double* next = j < g.ny ? row + g.row : row; // no y edges from the last row
        const std::uint64_t* r = signs + j * words;
        const std::uint64_t* n = j < g.ny ? r + words : r;
        const auto changes = [&](std::size_t w) {
            return (r[w] ^ next_bits(r, w, words)) | (r[w] ^ n[w]) |
                   (r[w] ^ next_bits(n, w, words));
        };
        for_candidates(words, changes, [&](int i) {
            const bool s = positive(row[i]);
            const int i1 = std::min(i + 1, g.nx);
            const bool x = positive(row[i1]) != s, y = positive(next[i]) != s,
                       xy = positive(next[i1]) != s;
            if (!(x || y || xy)) return;
            for (int d = 1; d <= 3; ++d) {
                const int i2 = i + edge_dx(d), j2 = j + edge_dy(d);
                if (i2 > g.nx || j2 > g.ny) continue;
                const double fb = values[j2 * g.row + i2];
                if (positive(fb) == s) continue;
                ids[(j * g.row + i) * 3 + d - 1] =
                    refiner.add(out, g.point(i, j, k), row[i], g.index(i, j, k), g.point(i2, j2, k),
                                fb, g.index(i2, j2, k));
            }
        });
    }
    refiner.run(ctx, out);
}

// Vertices on the edges from layer k to layer k + 1 (d = 4..7); ids[point * 4 + d - 4].
void make_vertical_vertices(const Context& ctx, const Layer& bottom, const Layer& top, Index* ids,
                            VertexGroup& out, Refiner& refiner) {
    const Grid& g = ctx.grid;
    const int k = bottom.k;
    const std::size_t words = sign_words(g);
    for (int j = 0; j <= g.ny; ++j) {
        if (rows_uniform(bottom.rows, top.rows, j, g.ny)) continue;
        const double* row = bottom.values + j * g.row;
        const double* up = top.values + j * g.row;
        const double* up_next = j < g.ny ? up + g.row : up;
        const std::uint64_t* b = bottom.signs + j * words;
        const std::uint64_t* t0 = top.signs + j * words;
        const std::uint64_t* t1 = j < g.ny ? t0 + words : t0;
        const auto changes = [&](std::size_t w) {
            return (b[w] ^ t0[w]) | (b[w] ^ next_bits(t0, w, words)) | (b[w] ^ t1[w]) |
                   (b[w] ^ next_bits(t1, w, words));
        };
        for_candidates(words, changes, [&](int i) {
            const bool s = positive(row[i]);
            const int i1 = std::min(i + 1, g.nx);
            if (positive(up[i]) == s && positive(up[i1]) == s && positive(up_next[i]) == s &&
                positive(up_next[i1]) == s)
                return;
            for (int d = 4; d <= 7; ++d) {
                const int i2 = i + edge_dx(d), j2 = j + edge_dy(d);
                if (i2 > g.nx || j2 > g.ny) continue;
                const double fb = top.values[j2 * g.row + i2];
                if (positive(fb) == s) continue;
                ids[(j * g.row + i) * 4 + d - 4] =
                    refiner.add(out, g.point(i, j, k), row[i], g.index(i, j, k),
                                g.point(i2, j2, k + 1), fb, g.index(i2, j2, k + 1));
            }
        });
    }
    refiner.run(ctx, out);
}

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

    std::size_t bytes() const {
        std::size_t n = 0;
        auto group = [&](const VertexGroup& g) {
            n += (g.positions.capacity() + g.normals.capacity()) * sizeof(glm::dvec3) +
                 g.pinned.capacity() * sizeof(g.pinned[0]);
        };
        for (const BoundaryPlane& p : planes) {
            group(p.vertices);
            n += p.values.capacity() * sizeof(double) + p.rows.capacity() +
                 p.ids.capacity() * sizeof(Index);
        }
        for (const Chunk& c : chunks) {
            group(c.vertices);
            n += c.triangles.capacity() * sizeof(c.triangles[0]);
        }
        return n;
    }
};

class BufferPool {
public:
    Buffers take() {
        std::lock_guard lock(mutex_);
        if (free_.empty()) return {};
        Buffers b = std::move(free_.back());
        free_.pop_back();
        return b;
    }
    void give(Buffers&& b) {
        if (b.bytes() > (std::size_t{128} << 20)) return;
        std::lock_guard lock(mutex_);
        if (free_.size() < 2) free_.push_back(std::move(b));
    }

private:
    std::mutex mutex_;
    std::vector<Buffers> free_;
};

BufferPool& buffer_pool() {
    static BufferPool pool;
    return pool;
}

// Empty arrays that keep their room.
void clear(VertexGroup& g) {
    g.positions.clear();
    g.normals.clear();
    g.pinned.clear();
}

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
            emit_triangles(c, bottom, top, ws.vertical_ids.data());
            count(chunk.vertices.positions.size() - vertices_before,
                  chunk.triangles.size() - triangles_before);
            bottom = top;
            buffer ^= 1;
            unit_done(worker);
        }
    }

    const glm::dvec3& position_of(int c, Index id) const {
        const Index local = id & ~tag_mask;
        switch (id & tag_mask) {
        case tag_bottom:
            return planes[c].vertices.positions[local];
        case tag_top:
            return planes[c + 1].vertices.positions[local];
        default:
            return chunks[c].vertices.positions[local];
        }
    }

    void emit_triangles(int c, const Layer& bottom, const Layer& top, const Index* vertical_ids) {
        const Grid& g = ctx.grid;
        const CubeCase* cases = cube_cases();
        const std::size_t words = sign_words(g);
        std::vector<std::array<Index, 3>>& out = chunks[c].triangles;
        // Where each edge code finds its vertex id, relative to the cell's first point.
        struct EdgeSlot {
            const Index* ids = nullptr;
            std::size_t stride = 0, offset = 0;
            Index tag = 0;
        };
        std::array<EdgeSlot, 64> slots{};
        for (int c1 = 0; c1 < 8; ++c1)
            for (int d = 1; d < 8; ++d) {
                if ((c1 & d) != 0) continue;
                EdgeSlot& s = slots[c1 * 8 + d];
                const std::size_t point = ((c1 >> 1) & 1) * g.row + (c1 & 1);
                if (d & 4)
                    s = EdgeSlot{vertical_ids, 4, point * 4 + d - 4, tag_local};
                else if (c1 & 4)
                    s = EdgeSlot{top.ids, 3, point * 3 + d - 1, top.tag};
                else
                    s = EdgeSlot{bottom.ids, 3, point * 3 + d - 1, bottom.tag};
            }
        for (int j = 0; j < g.ny; ++j) {
            if (rows_uniform(bottom.rows, top.rows, j, g.ny)) continue;
            const double* b0 = bottom.values + j * g.row;
            const double* b1 = b0 + g.row;
            const double* t0 = top.values + j * g.row;
            const double* t1 = t0 + g.row;
            // Cells whose eight corners may not all have one sign: a column (the four corners
            // at x_i) with both signs, at i or i + 1, or two columns of different signs.
            const std::uint64_t* sb0 = bottom.signs + j * words;
            const std::uint64_t* sb1 = sb0 + words;
            const std::uint64_t* st0 = top.signs + j * words;
            const std::uint64_t* st1 = st0 + words;
            const auto column = [&](std::size_t w) {
                return w < words ? (sb0[w] ^ sb1[w]) | (sb0[w] ^ st0[w]) | (sb0[w] ^ st1[w])
                                 : std::uint64_t{0};
            };
            const auto changes = [&](std::size_t w) {
                const std::uint64_t c = column(w);
                return c | (c >> 1) | (column(w + 1) << 63) | (sb0[w] ^ next_bits(sb0, w, words));
            };
            for_candidates(words, changes, [&](int i) {
                if (i >= g.nx) return;
                const unsigned left = positive(b0[i]) << 0 | positive(b1[i]) << 2 |
                                      positive(t0[i]) << 4 | positive(t1[i]) << 6;
                const unsigned right = positive(b0[i + 1]) << 0 | positive(b1[i + 1]) << 2 |
                                       positive(t0[i + 1]) << 4 | positive(t1[i + 1]) << 6;
                const unsigned mask = left | right << 1;
                if (mask == 0 || mask == 255) return;
                const std::size_t point = j * g.row + i;
                const CubeCase& cc = cases[mask];
                for (int k = 0; k < cc.count; ++k) {
                    const Polygon& poly = cc.polygons[k];
                    Index v[4];
                    for (int e = 0; e < poly.n; ++e) {
                        const EdgeSlot& s = slots[poly.e[e]];
                        v[e] = s.tag | s.ids[point * s.stride + s.offset];
                    }
                    if (poly.n == 3) {
                        out.push_back({v[0], v[1], v[2]});
                        continue;
                    }
                    // A quadrilateral: split along its shorter diagonal (the better-shaped
                    // pair); either split keeps the orientation.
                    const double d02 = glm::length(position_of(c, v[0]) - position_of(c, v[2]));
                    const double d13 = glm::length(position_of(c, v[1]) - position_of(c, v[3]));
                    if (d02 <= d13) {
                        out.push_back({v[0], v[1], v[2]});
                        out.push_back({v[0], v[2], v[3]});
                    } else {
                        out.push_back({v[1], v[2], v[3]});
                        out.push_back({v[1], v[3], v[0]});
                    }
                }
            });
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

Status check_options(const Program& f, const PolygonizeOptions& o) {
    if (!std::isfinite(o.cell) || o.cell <= 0)
        return make_error(ErrorCode::schema,
                          "cell " + format_number(o.cell) + " must be a finite number > 0",
                          "/cell");
    static const char* axes = "xyz";
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(o.lo[a]) || !std::isfinite(o.hi[a]))
            return make_error(ErrorCode::schema,
                              std::string("bounds on ") + axes[a] + " must be finite numbers",
                              "/bounds");
        if (!(o.lo[a] < o.hi[a]))
            return make_error(ErrorCode::schema,
                              std::string("bounds on ") + axes[a] + " must have min < max, got " +
                                  format_number(o.lo[a]) + " and " + format_number(o.hi[a]),
                              "/bounds");
        if (!std::isfinite(o.hi[a] - o.lo[a]))
            return make_error(ErrorCode::schema,
                              std::string("bounds on ") + axes[a] + " span more than a double",
                              "/bounds");
    }
    const auto& names = f.parameter_names();
    if (o.parameters.size() != names.size())
        return make_error(ErrorCode::schema,
                          "expected " + std::to_string(names.size()) + " parameter values, got " +
                              std::to_string(o.parameters.size()),
                          "/parameters");
    for (std::size_t k = 0; k < o.parameters.size(); ++k)
        if (!std::isfinite(o.parameters[k]))
            return make_error(ErrorCode::schema,
                              "parameter '" + names[k] + "' must be a finite number, got " +
                                  format_number(o.parameters[k]),
                              "/parameters/" + std::to_string(k));
    return Ok{};
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

} // namespace

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

namespace {

// The grid: ceil(extent / cell) cells per axis, the cell shrunk to fit (convention 18).
Expected<Grid> make_grid(const PolygonizeOptions& options) {
    // Counted in double first so a tiny cell cannot overflow an int before the check.
    double n[3], points = 1.0;
    for (int a = 0; a < 3; ++a) {
        n[a] = std::max(1.0, std::ceil((options.hi[a] - options.lo[a]) / options.cell));
        points *= n[a] + 1.0;
    }
    if (points > static_cast<double>(max_evaluation_points))
        return make_error(ErrorCode::limit,
                          "cell " + format_number(options.cell) + " gives a grid of " +
                              format_number(n[0] + 1) + " x " + format_number(n[1] + 1) + " x " +
                              format_number(n[2] + 1) + " points, more than the " +
                              std::to_string(max_evaluation_points) + " allowed",
                          "/cell");
    Grid grid;
    grid.nx = static_cast<int>(n[0]);
    grid.ny = static_cast<int>(n[1]);
    grid.nz = static_cast<int>(n[2]);
    grid.row = static_cast<std::size_t>(grid.nx) + 1;
    grid.plane = grid.row * (static_cast<std::size_t>(grid.ny) + 1);
    grid.xs = grid_coordinates(options.lo.x, options.hi.x, grid.nx);
    grid.ys = grid_coordinates(options.lo.y, options.hi.y, grid.ny);
    grid.zs = grid_coordinates(options.lo.z, options.hi.z, grid.nz);

    return grid;
}

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

// Merge in a fixed order: plane 0, chunk 0, plane 1, chunk 1, ..., the last plane. The
// vertices that sit on a zero grid point are listed in `pinned` (point, vertex).
Expected<Mesh> merge_chunks(Polygonizer& pz, std::vector<std::pair<std::uint64_t, Index>>& pinned) {
    Mesh mesh;
    std::vector<std::size_t> plane_offset(pz.planes.size()), chunk_offset(pz.chunks.size());
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
    for (const BoundaryPlane& bp : pz.planes) vertex_total += bp.vertices.positions.size();
    for (const Chunk& ch : pz.chunks) vertex_total += ch.vertices.positions.size();
    mesh.positions.reserve(vertex_total);
    mesh.normals.reserve(vertex_total);
    std::size_t triangle_count = 0;
    for (std::size_t c = 0; c < pz.chunks.size(); ++c) {
        plane_offset[c] = append(pz.planes[c].vertices);
        chunk_offset[c] = append(pz.chunks[c].vertices);
        triangle_count += pz.chunks[c].triangles.size();
    }
    plane_offset.back() = append(pz.planes.back().vertices);
    if (mesh.positions.size() >= static_cast<std::size_t>(tag_bottom))
        return make_error(ErrorCode::limit, "the mesh has too many vertices", "/cell");
    mesh.triangles.resize(triangle_count);
    std::array<Index, 3>* out = mesh.triangles.data();
    for (std::size_t c = 0; c < pz.chunks.size(); ++c) {
        const Index offsets[3] = {static_cast<Index>(chunk_offset[c]),
                                  static_cast<Index>(plane_offset[c]),
                                  static_cast<Index>(plane_offset[c + 1])};
        for (const auto& t : pz.chunks[c].triangles) {
            for (int k = 0; k < 3; ++k) (*out)[k] = (t[k] & ~tag_mask) + offsets[t[k] >> 30];
            ++out;
        }
    }
    buffer_pool().give(Buffers{std::move(pz.planes), std::move(pz.chunks)});
    pz.planes.clear();
    pz.chunks.clear();

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
    Expected<Mesh> merged = merge_chunks(pz, pinned);
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
