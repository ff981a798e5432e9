// CPU-side helpers of the mesh cache (pure): change detection and wireframe indices.
#pragma once

#include <cstdint>
#include <vector>

#include "core/geom/tessellate.hpp"
#include "core/geom/types.hpp"

namespace isoparm::ui {

// Exact equality of everything the tessellation depends on (the cache key).
bool same_surface(const geom::Surface& a, const geom::Surface& b);
// Equality of everything the basis functions R_ij depend on (type, degrees, knots, weights),
// not the points' positions: a point's drag leaves them as they were.
bool same_basis(const geom::Surface& a, const geom::Surface& b);

// Grid lines of a samples_u x samples_v vertex grid (u-major, as geom::tessellate lays it
// out) as index pairs: every stride-th line in each direction plus the last one, at most
// about `max_lines` per direction; segments touching a vertex that does not exist are left
// out.
std::vector<std::uint32_t> wire_indices(int samples_u, int samples_v,
                                        const std::vector<std::uint8_t>& exists, int max_lines);

// The scalar of a vertex where the analysis value is undefined (a pole, no point, an implicit
// surface's mesh under a curvature mode): finite, so interpolation never makes NaN, and far
// above any curvature shown (the shader draws it hatched).
constexpr float undefined_scalar = 1e30f;

// Interleaved float vertices (position, normal, analysis scalar) for the GPU: vertices
// [first, first + count) (clamped to the mesh). `scalars` holds one value per vertex of that
// range (NaN: undefined); empty: every vertex gets `fallback`.
constexpr int floats_per_vertex = 7;
std::vector<float> interleave(const geom::Mesh& mesh, std::size_t first = 0,
                              std::size_t count = static_cast<std::size_t>(-1),
                              const std::vector<double>& scalars = {}, float fallback = 0);

} // namespace isoparm::ui
