// Polygonization of f(x, y, z) = 0 inside a box (in the spirit of Bloomenthal's polygonizer).
#pragma once

#include <cstddef>
#include <functional>
#include <glm/vec3.hpp>
#include <vector>

#include "core/geom/implicit/expression.hpp"
#include "core/geom/tessellate.hpp"

namespace isoparm::geom {

// Answer-size caps of the meshes the protocol returns (`tessellate`, `polygonize`) and the
// workstation draws: a grid within the 10,000,000-point evaluation cap can still ask for
// gigabytes of output (a 3162 x 3162 tessellation, or a polygonization of a finely rippled
// surface), so the mesh itself is capped too. A million vertices is far more than a screen
// shows; as JSON it is about 0.1 GB of text. Docs: docs/protocol.md, "Size caps".
constexpr std::size_t max_mesh_vertices = 1000000;
constexpr std::size_t max_mesh_triangles = 2000000;

} // namespace isoparm::geom

namespace isoparm::geom::implicit {

struct PolygonizeOptions {
    glm::dvec3 lo{-1, -1, -1}, hi{1, 1, 1};
    double cell = 0.1;              // edge length; the grid has ceil(extent / cell) cells per axis,
                                    // shrunk to fit the bounds exactly (protocol convention 18)
    std::vector<double> parameters; // values of the program's named parameters
    // Progress in [0, 1], called from the calling thread; return false to cancel (the result
    // is then a `limit` error without a path: "polygonization was cancelled").
    std::function<bool(double)> progress;
    // Worker threads; 0 = std::thread::hardware_concurrency(). The mesh does not depend on it.
    int threads = 0;
    // The mesh caps, checked while the grid is worked through (after each slab) so memory
    // stays bounded: the polygonizer stops as soon as the running counts exceed them.
    std::size_t max_vertices = max_mesh_vertices;
    std::size_t max_triangles = max_mesh_triangles;
};

// A consistently oriented mesh with shared vertices, unit normals grad f / |grad f|, triangles
// counter-clockwise seen from the side the normals point to (towards f > 0). `exists` is all 1.
// Errors (paths relative to the request):
//   `schema` "/cell"       cell not finite or <= 0
//   `schema` "/bounds"     a bound not finite, or min >= max on some axis
//   `schema` "/parameters" wrong count of parameter values; "/parameters/<i>" a non-finite value
//   `limit`  "/cell"       the grid has more than max_evaluation_points points (checked before
//                          anything is allocated), or the mesh grows past max_vertices or
//                          max_triangles (checked as it grows; the message says which)
//   `limit`  (no path)     cancelled through `progress`
// An empty mesh (surface not found in the bounds) is not an error here; the caller reports it.
Expected<Mesh> polygonize(const Program& f, const PolygonizeOptions& options);

// The side from which anything outside the box sees a mesh that polygonize made with `options`:
// +1 (the f > 0 side, where its triangles are counter-clockwise) or -1 when the mesh meets no
// face of the box. Every grid point on the box's boundary is then on one side, the mesh is a
// closed surface inside, and a line of sight entering the box meets it first from that side:
// a renderer may cull the other side's triangles (they show only where the mesh passes
// through itself, as at the seams of touching sheets, and at anti-aliased edges). 0 when a vertex
// lies on a face (the surface leaves the box and its inside shows), or the mesh is empty.
int side_seen_from_outside(const Program& f, const PolygonizeOptions& options, const Mesh& mesh);

// Removes triangles that repeat a vertex (zero area by construction) and then the vertices no
// triangle uses, keeping the order of everything else. Returns the number of triangles removed.
std::size_t drop_degenerate_triangles(Mesh& mesh);

} // namespace isoparm::geom::implicit
