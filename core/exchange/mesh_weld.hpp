// Welding a tessellation into one connected surface mesh before it is written as a mesh file.
//
// geom::tessellate lays a (n_u x n_v) grid over the parameter domain, so a closed surface
// repeats its seam (the rows at u0 and u1 of a full revolution hold the same points) and a
// pole is a whole row of vertices at one point, with zero-area triangles beside it. Mesh
// readers, slicers and the watertightness rule (every edge shared by exactly two triangles)
// need those vertices to be one: this merges them and drops the triangles that collapse.
#pragma once

#include <cstddef>

#include "core/geom/tessellate.hpp"

namespace isoparm::exchange {

// The default welding distance, relative to the diagonal of the mesh's bounding box: far
// above the rounding left by an exact construction (a seam's two copies differ by ~1e-16 of
// the size), far below any sampling step a mesh format could carry.
inline constexpr double weld_relative_tolerance = 1e-9;

// Merges the vertices that lie within `relative_tolerance` x the bounding-box diagonal of one
// another (each vertex joins the first earlier vertex in reach, found through a uniform grid of
// that cell size, so the cost is linear), averaging their unit normals (a seam's copies agree;
// a pole's limit normals are averaged), then removes the triangles that repeat a vertex and the
// vertices no triangle uses. Vertices that do not exist (Mesh::exists) are never merged and,
// being unused, are removed. The triangles keep their order and orientation, so a grid that
// was consistently oriented stays so across the seam. Returns the number of vertices merged.
std::size_t weld(geom::Mesh& mesh, double relative_tolerance = weld_relative_tolerance);

} // namespace isoparm::exchange
