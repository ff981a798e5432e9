// The polygonizer's parts shared by its files (polygonize.cpp schedules the work,
// grid_layers.cpp walks the grid's layers, cell_triangles.cpp makes the cells' triangles from
// the marching-tetrahedra case table in cube_cases.cpp, edge_refiner.cpp places the vertices on
// their edges). Internal: nothing outside these files includes it.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "core/geom/implicit/expression.hpp"

namespace isoparm::geom::implicit::detail {

using Index = std::uint32_t;

// Triangles inside a chunk name vertices of three groups; the top two bits say which, and the
// merge turns them into global indices.
constexpr Index tag_local = 0u << 30;
constexpr Index tag_bottom = 1u << 30; // the chunk's bottom boundary plane
constexpr Index tag_top = 2u << 30;    // the chunk's top boundary plane
constexpr Index tag_mask = 3u << 30;

// The sign convention: NaN counts as positive ("outside"), zero counts as positive, so every
// grid point is on exactly one side and a zero lies on the surface only through its edges.
inline bool positive(double v) {
    return !(v < 0.0);
}

// ---------------------------------------------------------------------------------------------
// After J. Bloomenthal, "An Implicit Surface Polygonizer", Graphics Gems IV (1994), in its
// full-grid form with tetrahedral decomposition.
//
// The case table. Cube corner c sits at offset (c & 1, c >> 1 & 1, c >> 2 & 1). The Kuhn
// (Freudenthal) triangulation splits the cube into six tetrahedra 0 -> e_a -> e_a + e_b -> 7,
// one per axis order (a, b, c); all share the main diagonal 0-7, and each cube face is split by
// the diagonal from its lowest to its highest corner, so neighbouring cubes agree on every face
// and the surface has no cracks and no ambiguous faces (a tetrahedron has none).
// Every tetrahedron edge joins corners c1 < c2 with c1's bits a subset of c2's: the edge is the
// grid edge from the point at c1 in direction d = c1 ^ c2 (1..7), coded c1 * 8 + d.

struct Polygon {
    std::uint8_t n = 0;  // 3 or 4
    std::uint8_t e[4]{}; // edge codes, counter-clockwise seen from f > 0
};

struct CubeCase {
    std::uint8_t count = 0;
    Polygon polygons[6];
};

// The 256 cases, by the signs of the cube's corners (bit c set: corner c positive).
const CubeCase* cube_cases();

// ---------------------------------------------------------------------------------------------
// Vertices.

// The vertices one work unit makes. A normal of (0,0,0) means grad f vanished or was not finite
// there; it is replaced by the average face normal at the end.
struct VertexGroup {
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> normals;
    // Vertices lying exactly on a grid point where f == 0, with that point's index: several
    // edges meet there, and the vertices are welded into one at the end.
    std::vector<std::pair<Index, std::uint64_t>> pinned;
};

struct Grid {
    int nx = 0, ny = 0, nz = 0;
    std::size_t row = 0;   // nx + 1
    std::size_t plane = 0; // (nx + 1) * (ny + 1)
    std::vector<double> xs, ys, zs;

    glm::dvec3 point(int i, int j, int k) const { return {xs[i], ys[j], zs[k]}; }
    std::uint64_t index(int i, int j, int k) const {
        return (static_cast<std::uint64_t>(k) * (ny + 1) + j) * row + i;
    }
};

struct Context {
    const Program& f;
    const double* params;
    const Grid& grid;
};

// The vertices of a layer's edges are placed together (Refiner::run), so the expression is
// evaluated a block of points at a time (Program::values_and_derivatives / _gradients) instead
// of one point per call: the interpreter's dispatch was most of the polygonizer's time. Each
// edge goes through exactly the steps it would alone, so the mesh is the same to the bit.
//
// On the grid edge from a (value fa) to b (value fb), where the sign changes: safeguarded
// Newton on g(t) = f(p + t (q - p)) from the positive end p: the bracket [lo, hi] always holds
// the sign change, and a Newton step that leaves it becomes a bisection (as in rtsafe,
// Numerical Recipes 9.4). It stops once the Newton step is below 1e-12 edge lengths, so the
// point is that close to the surface along the edge, and |f| <= 1e-12 |grad f| |q - p|.
// Steps use the cheap directional derivative g'(t) = grad f . (q - p); the full gradient (for
// the normal) is computed where the next point is expected to be the last.
struct Refiner {
    struct Edge {
        Index id = 0;
        glm::dvec3 p, d; // the positive end and q - p
        double lo = 0.0, hi = 1.0, t = 0.5;
        int evaluations = 0;
        bool full = false, converged = false, pinned = false;
        glm::dvec3 gradient{0.0};
    };
    std::vector<Edge> edges;
    // Per round: the edges still iterating, split by the evaluation they need, and the
    // evaluation's points and results.
    std::vector<std::size_t> active, by_derivative, by_gradient;
    std::vector<glm::dvec3> points, directions, gradients;
    std::vector<double> values, slopes;
    std::vector<double> scratch;

    // Queues the vertex on the edge from a to b and returns its id; run() appends its position
    // and normal to `out` (the ids follow on from what `out` holds).
    Index add(VertexGroup& out, const glm::dvec3& a, double fa, std::uint64_t ga,
              const glm::dvec3& b, double fb, std::uint64_t gb) {
        const bool a_positive = positive(fa);
        const glm::dvec3& p = a_positive ? a : b;
        const glm::dvec3& q = a_positive ? b : a;
        const double fp = a_positive ? fa : fb;
        const double fq = a_positive ? fb : fa;
        Edge e;
        e.id = static_cast<Index>(out.positions.size() + edges.size());
        e.p = p;
        if (fp == 0.0) {
            e.pinned = true;
            out.pinned.emplace_back(e.id, a_positive ? ga : gb);
        } else {
            e.d = q - p;
            e.t = std::isfinite(fp) && std::isfinite(fq) ? fp / (fp - fq) : 0.5;
            if (!(e.t > e.lo && e.t < e.hi)) e.t = 0.5;
        }
        edges.push_back(e);
        return e.id;
    }

    // One Newton step of an edge given g(t) and g'(t); false when the edge is finished.
    static bool step(Edge& e, double v, double slope) {
        ++e.evaluations;
        // The side picked by address, not by a branch: v's sign is as likely one way as the
        // other, so a branch on it is often mispredicted.
        (positive(v) ? e.lo : e.hi) = e.t;
        const double step = v / slope;
        if (v == 0.0 || std::fabs(step) <= 1e-12) {
            e.converged = true;
            return false;
        }
        double next = e.t - step;
        if (!(next > e.lo && next < e.hi)) next = 0.5 * (e.lo + e.hi);
        if (next == e.t || !(next > e.lo && next < e.hi)) return false; // one ulp wide
        // Newton squares the error: after a step of 1e-4 the next one is tiny.
        e.full = std::fabs(e.t - next) <= 1e-4;
        e.t = next;
        return e.evaluations < 100;
    }

    // Evaluates f with its derivative along each edge (full: its gradient) at the edges' t.
    void evaluate(const Context& ctx, const std::vector<std::size_t>& which, bool full);

    // Places every queued vertex and sets its normal; the queue is then empty.
    void run(const Context& ctx, VertexGroup& out);
    void grow(std::size_t n);
};

} // namespace isoparm::geom::implicit::detail
