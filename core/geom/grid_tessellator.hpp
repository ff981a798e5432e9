// The interactive tessellation engine: basis tables cached per surface layout (in the layout the
// SIMD kernel streams, core/geom/grid_kernel.hpp), column blocks shared out to the persistent
// worker pool for full passes, and local updates for single control points.
#pragma once

#include <utility>
#include <vector>

#include "core/geom/grid_kernel.hpp"
#include "core/geom/tessellate.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

class GridTessellator {
public:
    // Tabulates spans, basis values and first derivatives for the sample grid of s.
    GridTessellator(const Surface& s, int samples_u, int samples_v);

    // True when s has the layout these tables were built for (degrees, knots, counts), so
    // only control points or weights changed and the tables can be reused.
    bool fits(const Surface& s, int samples_u, int samples_v) const;

    // All vertices and the triangles. threads > 1 shares column blocks out to the worker pool
    // (WorkerPool::shared()); results are bit-identical to threads == 1 (every vertex is
    // computed by the same instructions whatever the split).
    void evaluate(const Surface& s, Mesh& mesh, int threads = 1) const;

    // Positions and unit normals without the triangles (what a renderer re-uploads when only
    // control points changed; also the benchmark's positions + normals case).
    void evaluate_vertices(const Surface& s, std::vector<glm::dvec3>& positions,
                           std::vector<glm::dvec3>& normals, std::vector<std::uint8_t>& exists,
                           int threads = 1) const;

    // Positions only (no derivatives, no normals, no triangles): exists gets 0 where the
    // point does not exist (and is left empty when every point exists).
    void evaluate_positions(const Surface& s, std::vector<glm::dvec3>& positions,
                            std::vector<std::uint8_t>& exists, int threads = 1) const;

    // After control point (i, j) moved or changed weight: recompute only the vertices its
    // basis function's support touches (local support). Rebuilds the triangles only when a
    // vertex starts or stops existing.
    void update_control_point(const Surface& s, Mesh& mesh, int i, int j) const;

    // The block of sample rows / columns whose values depend on control row i / column j.
    std::pair<int, int> rows_touching(int i) const;
    std::pair<int, int> columns_touching(int j) const;

    int samples_u() const { return static_cast<int>(us_.size()); }
    int samples_v() const { return static_cast<int>(vs_.size()); }
    const std::vector<double>& params_u() const { return us_; }
    const std::vector<double>& params_v() const { return vs_; }

    // The kernel build this tessellator uses (kernel::active_path() unless changed) and, for
    // the tests, the generic run-time-degree code instead of the specialised one. Returns
    // false, changing nothing, where the CPU does not run that path.
    bool use_kernel(kernel::Path path, bool generic = false);
    kernel::Path kernel_path() const { return path_; }
    // Control columns each vector of the v contraction reads (the banded basis's width).
    int band_columns() const { return band_.nc; }

    struct Table {
        int p = 0;
        std::vector<int> first;    // span - p for each sample
        std::vector<double> N, dN; // (p + 1) per sample
    };
    // The v basis banded per chunk of `lanes` samples, as the kernel streams it.
    struct Band {
        int lanes = 0, nc = 0;
        std::vector<int> f0;
        std::vector<double> M, dM;
    };

private:
    // Rows i0..i1, columns j0..j1; normals == nullptr evaluates positions only. status gets
    // the block's (i1 - i0 + 1) x (j1 - j0 + 1) vertices. Returns how many are not
    // kernel::vertex_ok.
    long evaluate_block(const Surface& s, glm::dvec3* positions, glm::dvec3* normals,
                        std::uint8_t* status, int i0, int i1, int j0, int j1) const;
    // The block's degenerate normals, from the surface (touches only the block's vertices:
    // safe in a task). Returns how many of its vertices do not exist.
    long settle_normals(const Surface& s, const std::uint8_t* status, glm::dvec3* normals, int i0,
                        int i1, int j0, int j1) const;
    // The block's vertices that do not exist (and exists for all of the block's vertices once
    // exists is not empty): serial, exists is the whole grid's.
    void settle_missing(const std::uint8_t* status, glm::dvec3* positions, glm::dvec3* normals,
                        std::vector<std::uint8_t>& exists, int i0, int i1, int j0, int j1) const;
    void run_rows(const Surface& s, glm::dvec3* positions, glm::dvec3* normals,
                  std::vector<std::uint8_t>& exists, int threads) const;

    int degree_u_ = 0, degree_v_ = 0, n_u_ = 0, n_v_ = 0;
    Knots knots_u_, knots_v_;
    std::vector<double> us_, vs_;
    Table tu_, tv_;
    Band band_;
    kernel::Path path_ = kernel::Path::baseline;
    bool generic_ = false;
};

// Triangles of the grid (k, k + n_v, k + n_v + 1), (k, k + n_v + 1, k + 1), skipping cells
// that touch a vertex that does not exist.
void build_grid_triangles(Mesh& mesh, int samples_u, int samples_v);

} // namespace isoparm::geom
