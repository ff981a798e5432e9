// Tessellation of a surface over a uniform parameter grid, built on cached basis functions.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/geom/types.hpp"

namespace isoparm::geom {

struct Mesh {
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> normals;
    std::vector<std::array<std::uint32_t, 3>> triangles; // counter-clockwise about the normal
    // Per vertex: 0 where the surface point does not exist (zero denominator); such vertices
    // hold (0,0,0) and no triangle touches them. Empty when every vertex exists (the usual
    // case), so a mesh costs positions + normals + indices.
    std::vector<std::uint8_t> exists;
    bool vertex_exists(size_t k) const { return exists.empty() || exists[k] != 0; }
};

// Vertices u-major: vertex i * n_v + j at u_i = a + (b - a) i / (n_u - 1), v_j likewise.
// Triangles per cell (k = i * n_v + j): (k, k + n_v, k + n_v + 1), (k, k + n_v + 1, k + 1).
// Normals are unit, the limit from inside the domain where S_u x S_v degenerates.
// Precondition: valid surface, samples >= 2 each.
Mesh tessellate(const Surface& s, int samples_u, int samples_v);

// Uniform parameters a + (b - a) i / (n - 1), exact at both ends.
std::vector<double> uniform_params(double a, double b, int n);

} // namespace isoparm::geom
