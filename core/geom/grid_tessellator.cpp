// Grid tessellation: basis tables (A2.2 / A2.3) per surface layout, the SIMD kernel of
// grid_kernel.hpp over column blocks, and the vertices that need more than the kernel
// (points that do not exist, degenerate normals).
#include "core/geom/grid_tessellator.hpp"

#include <cstdint>

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/geom/basis.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/grid_kernel.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/worker_pool.hpp"

namespace isoparm::geom {

namespace {

GridTessellator::Table tabulate(const Knots& U, int p, int n, const std::vector<double>& params) {
    GridTessellator::Table t;
    t.p = p;
    t.first.resize(params.size());
    t.N.resize(params.size() * (p + 1));
    t.dN.resize(params.size() * (p + 1));
    std::vector<double> ders(2 * (static_cast<size_t>(p) + 1));
    for (size_t k = 0; k < params.size(); ++k) {
        const int span = find_span(U, p, n, params[k]);
        t.first[k] = span - p;
        ders_basis_funs(span, params[k], p, 1, U, ders.data());
        std::copy(ders.begin(), ders.begin() + p + 1, t.N.begin() + k * (p + 1));
        std::copy(ders.begin() + p + 1, ders.end(), t.dN.begin() + k * (p + 1));
    }
    return t;
}

// The samples whose non-zero basis functions include index i: first[k] <= i <= first[k] + p.
std::pair<int, int> touching(const GridTessellator::Table& t, int i) {
    const int count = static_cast<int>(t.first.size());
    int lo = 0;
    while (lo < count && t.first[lo] + t.p < i) ++lo;
    int hi = lo - 1;
    while (hi + 1 < count && t.first[hi + 1] <= i) ++hi;
    return {lo, hi};
}

// The v basis in the kernel's banded layout: chunk k covers samples k * lanes .. + lanes - 1;
// its nc columns start at control column f0[k], lane l's values sit at their column (zeros
// elsewhere, and for the padding lanes past the last sample). nc is the widest band any chunk
// needs (at most n: then every band is the whole net), so one compiled width serves them all.
GridTessellator::Band band(const GridTessellator::Table& t, int n, int lanes) {
    GridTessellator::Band b;
    b.lanes = lanes;
    const int samples = static_cast<int>(t.first.size());
    const int chunks = (samples + lanes - 1) / lanes;
    for (int k = 0; k < chunks; ++k) {
        const int last = std::min(samples, (k + 1) * lanes) - 1;
        b.nc = std::max(b.nc, t.first[last] + t.p - t.first[k * lanes] + 1);
    }
    b.nc = std::min(b.nc, n);
    b.f0.resize(chunks);
    b.M.assign(static_cast<size_t>(chunks) * b.nc * lanes, 0.0);
    b.dM.assign(b.M.size(), 0.0);
    for (int k = 0; k < chunks; ++k) {
        const int f = std::min(t.first[k * lanes], n - b.nc);
        b.f0[k] = f;
        for (int l = 0; l < lanes && k * lanes + l < samples; ++l) {
            const int s = k * lanes + l;
            for (int r = 0; r <= t.p; ++r) {
                const size_t at = (static_cast<size_t>(k) * b.nc + t.first[s] + r - f) * lanes + l;
                b.M[at] = t.N[static_cast<size_t>(s) * (t.p + 1) + r];
                b.dM[at] = t.dN[static_cast<size_t>(s) * (t.p + 1) + r];
            }
        }
    }
    return b;
}

// Sample columns per task of a full pass, a multiple of every path's lanes (8). One thread
// takes 64: measured on 256 x 256 grids, 32 columns cost 3-5% more per vertex and 16 columns
// 5-15% more (each block runs its own loop over the rows and forms the band's extra control
// columns again), while much wider blocks would take the ring of contracted rows out of L1.
// More threads take narrower blocks, two per thread, down to 16 columns, so that the others
// absorb a thread that starts late (a helper that was asleep) or is slowed by other work. Not
// four per thread: on 256 x 256 grids with two threads (2-core Xeon, AVX-512, interleaved with
// one thread, tests/bench/compare/bench_sisl.cpp) 32-column blocks cost so much more per vertex
// than 64-column ones that two threads gained 1.05-1.2x on AVX-512 positions, against
// 1.35-1.5x (helper asleep) and 1.5-1.7x (helper spinning) with 64 columns.
int block_columns(int samples_v, int threads) {
    if (threads <= 1) return 64;
    return std::clamp(samples_v / (2 * threads) / 8 * 8, 16, 64);
}

} // namespace

GridTessellator::GridTessellator(const Surface& s, int samples_u, int samples_v)
    : degree_u_(s.degree_u), degree_v_(s.degree_v), n_u_(s.n_u), n_v_(s.n_v), knots_u_(s.knots_u),
      knots_v_(s.knots_v) {
    assert(samples_u >= 2 && samples_v >= 2);
    us_ = uniform_params(s.knots_u[s.degree_u], s.knots_u[s.n_u], samples_u);
    vs_ = uniform_params(s.knots_v[s.degree_v], s.knots_v[s.n_v], samples_v);
    tu_ = tabulate(s.knots_u, s.degree_u, s.n_u, us_);
    tv_ = tabulate(s.knots_v, s.degree_v, s.n_v, vs_);
    path_ = kernel::active_path();
    band_ = band(tv_, n_v_, kernel::lanes(path_));
}

bool GridTessellator::use_kernel(kernel::Path path, bool generic) {
    if (!kernel::supported(path)) return false;
    path_ = path;
    generic_ = generic;
    if (band_.lanes != kernel::lanes(path)) band_ = band(tv_, n_v_, kernel::lanes(path));
    return true;
}

bool GridTessellator::fits(const Surface& s, int samples_u, int samples_v) const {
    return s.degree_u == degree_u_ && s.degree_v == degree_v_ && s.n_u == n_u_ && s.n_v == n_v_ &&
           s.knots_u == knots_u_ && s.knots_v == knots_v_ && samples_u == this->samples_u() &&
           samples_v == this->samples_v();
}

std::pair<int, int> GridTessellator::rows_touching(int i) const {
    return touching(tu_, i);
}
std::pair<int, int> GridTessellator::columns_touching(int j) const {
    return touching(tv_, j);
}

long GridTessellator::evaluate_block(const Surface& s, glm::dvec3* positions, glm::dvec3* normals,
                                     std::uint8_t* status, int i0, int i1, int j0, int j1) const {
    static_assert(sizeof(glm::dvec3) == 3 * sizeof(double), "the kernel reads and writes x, y, z "
                                                            "triples");
    kernel::GridArgs a{tu_.N.data(),
                       tu_.dN.data(),
                       tu_.first.data(),
                       degree_u_,
                       band_.M.data(),
                       band_.dM.data(),
                       band_.f0.data(),
                       band_.nc,
                       &s.points[0].x,
                       s.weights.data(),
                       n_v_,
                       i0,
                       i1,
                       j0,
                       j1,
                       samples_v(),
                       &positions[0].x,
                       normals ? &normals[0].x : nullptr,
                       status,
                       nullptr,
                       generic_};
    // Grow-only per thread (the pool's threads persist): no allocation per drag frame.
    // Aligned to a cache line: the kernel's vector loads of the ring are then never split
    // across two lines (a 64-byte AVX-512 load from a 16-byte-aligned address always is).
    thread_local std::vector<double> scratch;
    const size_t need = kernel::scratch_doubles(a, band_.lanes) + 8;
    if (scratch.size() < need) scratch.resize(need);
    const auto at = reinterpret_cast<std::uintptr_t>(scratch.data());
    a.scratch = scratch.data() + ((64 - at % 64) % 64) / sizeof(double);
    return kernel::run(path_, a);
}

long GridTessellator::settle_normals(const Surface& s, const std::uint8_t* status,
                                     glm::dvec3* normals, int i0, int i1, int j0, int j1) const {
    const int sv = samples_v(), width = j1 - j0 + 1;
    long missing = 0;
    for (int i = i0; i <= i1; ++i) {
        for (int j = j0; j <= j1; ++j) {
            const std::uint8_t st = status[static_cast<size_t>(i - i0) * width + (j - j0)];
            missing += st == kernel::vertex_missing;
            if (st == kernel::vertex_degenerate)
                normals[static_cast<size_t>(i) * sv + j] =
                    surface_normal_or_limit(s, us_[i], vs_[j]);
        }
    }
    return missing;
}

void GridTessellator::settle_missing(const std::uint8_t* status, glm::dvec3* positions,
                                     glm::dvec3* normals, std::vector<std::uint8_t>& exists, int i0,
                                     int i1, int j0, int j1) const {
    const int sv = samples_v(), width = j1 - j0 + 1;
    const size_t count = static_cast<size_t>(samples_u()) * sv;
    for (int i = i0; i <= i1; ++i) {
        for (int j = j0; j <= j1; ++j) {
            const size_t k = static_cast<size_t>(i) * sv + j;
            if (status[static_cast<size_t>(i - i0) * width + (j - j0)] != kernel::vertex_missing) {
                if (!exists.empty()) exists[k] = 1;
                continue;
            }
            if (exists.empty()) exists.assign(count, 1);
            exists[k] = 0;
            positions[k] = glm::dvec3(0.0);
            if (normals) normals[k] = glm::dvec3(0.0, 0.0, 1.0);
        }
    }
}

void GridTessellator::run_rows(const Surface& s, glm::dvec3* positions, glm::dvec3* normals,
                               std::vector<std::uint8_t>& exists, int threads) const {
    const int su = samples_u(), sv = samples_v();
    const size_t count = static_cast<size_t>(su) * sv;
    exists.clear();
    // Grow-only, the caller's (the helpers get pointers: the names would be their own
    // thread_local objects): no allocation per call.
    thread_local std::vector<std::uint8_t> status_buffer;
    thread_local std::vector<long> missing_buffer;
    status_buffer.resize(count);
    std::uint8_t* const status_all = status_buffer.data();
    // Column blocks, each a task: they write disjoint vertices and statuses (block b's su rows
    // at su * j0), and each vertex is computed by the same instructions whichever thread runs
    // its block. Degenerate normals are settled in the task too (pointwise, possibly a whole
    // row of them at a pole); only points that do not exist wait for the serial pass (exists).
    // While the pool's contention guard keeps calls on the caller, the caller's blocks.
    threads = WorkerPool::shared().solo() ? 1 : std::max(threads, 1);
    const int width = block_columns(sv, threads), blocks = (sv + width - 1) / width;
    missing_buffer.assign(blocks, 0);
    long* const missing = missing_buffer.data();
    WorkerPool::shared().run(blocks, threads, [&](int b) {
        const int j0 = b * width, j1 = std::min(sv, j0 + width) - 1;
        std::uint8_t* status = status_all + static_cast<size_t>(su) * j0;
        if (evaluate_block(s, positions, normals, status, 0, su - 1, j0, j1) > 0)
            missing[b] = settle_normals(s, status, normals, 0, su - 1, j0, j1);
    });
    for (int b = 0; b < blocks; ++b) {
        if (missing[b] == 0) continue;
        const int j0 = b * width, j1 = std::min(sv, j0 + width) - 1;
        settle_missing(status_all + static_cast<size_t>(su) * j0, positions, normals, exists, 0,
                       su - 1, j0, j1);
    }
}

void GridTessellator::evaluate(const Surface& s, Mesh& mesh, int threads) const {
    const size_t count = static_cast<size_t>(samples_u()) * samples_v();
    mesh.positions.resize(count);
    mesh.normals.resize(count);
    run_rows(s, mesh.positions.data(), mesh.normals.data(), mesh.exists, threads);
    build_grid_triangles(mesh, samples_u(), samples_v());
}

void GridTessellator::evaluate_vertices(const Surface& s, std::vector<glm::dvec3>& positions,
                                        std::vector<glm::dvec3>& normals,
                                        std::vector<std::uint8_t>& exists, int threads) const {
    const size_t count = static_cast<size_t>(samples_u()) * samples_v();
    positions.resize(count);
    normals.resize(count);
    run_rows(s, positions.data(), normals.data(), exists, threads);
}

void GridTessellator::evaluate_positions(const Surface& s, std::vector<glm::dvec3>& positions,
                                         std::vector<std::uint8_t>& exists, int threads) const {
    positions.resize(static_cast<size_t>(samples_u()) * samples_v());
    run_rows(s, positions.data(), nullptr, exists, threads);
}

void GridTessellator::update_control_point(const Surface& s, Mesh& mesh, int i, int j) const {
    const auto [i0, i1] = rows_touching(i);
    const auto [j0, j1] = columns_touching(j);
    if (i0 > i1 || j0 > j1) return;
    const bool had_gaps = !mesh.exists.empty();
    std::vector<std::uint8_t> before;
    if (had_gaps) before = mesh.exists;
    std::vector<std::uint8_t> status(static_cast<size_t>(i1 - i0 + 1) * (j1 - j0 + 1));
    long missing = evaluate_block(s, mesh.positions.data(), mesh.normals.data(), status.data(), i0,
                                  i1, j0, j1);
    if (missing > 0)
        missing = settle_normals(s, status.data(), mesh.normals.data(), i0, i1, j0, j1);
    if (missing > 0 || had_gaps)
        settle_missing(status.data(), mesh.positions.data(), mesh.normals.data(), mesh.exists, i0,
                       i1, j0, j1);
    if (mesh.exists != before) {
        if (std::all_of(mesh.exists.begin(), mesh.exists.end(), [](auto e) { return e != 0; }))
            mesh.exists.clear();
        build_grid_triangles(mesh, samples_u(), samples_v());
    }
}

void build_grid_triangles(Mesh& mesh, int samples_u, int samples_v) {
    mesh.triangles.clear();
    mesh.triangles.reserve(2 * static_cast<size_t>(samples_u - 1) * (samples_v - 1));
    const bool all = mesh.exists.empty();
    const auto nv = static_cast<std::uint32_t>(samples_v);
    for (int i = 0; i + 1 < samples_u; ++i) {
        for (int j = 0; j + 1 < samples_v; ++j) {
            const auto k = static_cast<std::uint32_t>(i) * nv + static_cast<std::uint32_t>(j);
            const std::array<std::uint32_t, 3> t0{k, k + nv, k + nv + 1}, t1{k, k + nv + 1, k + 1};
            for (const auto& t : {t0, t1})
                if (all || (mesh.exists[t[0]] && mesh.exists[t[1]] && mesh.exists[t[2]]))
                    mesh.triangles.push_back(t);
        }
    }
}

} // namespace isoparm::geom
