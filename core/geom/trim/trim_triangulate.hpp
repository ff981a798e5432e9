// The triangulation of a trimmed domain in (u, v): whole grid cells where no loop passes, a
// constrained Delaunay triangulation (CGAL) of the cells the loops cross, sharing the grid's
// vertices along their border so that the two parts meet without cracks.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "core/geom/trim/trim.hpp"
#include "core/geom/trim/trim_flatten.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// Vertices are grid points (grid index i * samples_v + j, for u_i, v_j) or loop points; the
// triangles run counter-clockwise in (u, v), so about S_u x S_v on the surface.
struct TrimmedLayout {
    std::vector<double> us, vs;               // the grid's parameters
    std::vector<std::uint32_t> grid_vertices; // grid indices of vertices 0..g-1
    std::vector<glm::dvec2> loop_points;      // (u, v) of vertices g, g + 1, ...
    std::vector<std::array<std::uint32_t, 3>> triangles;
    // For each loop (Trim::loop order; the domain's edge is no loop), its vertices in order:
    // the mesh's boundary edges are exactly consecutive pairs of these.
    std::vector<std::vector<std::uint32_t>> loops;
    std::size_t grid_triangles = 0; // the first ones: two per whole cell, as the grid has them

    std::size_t vertex_count() const { return grid_vertices.size() + loop_points.size(); }
    glm::dvec2 param(std::uint32_t k) const;
};

// Loops flattened by `rule` (its max_length at most a cell is sensible); a cell counts as whole
// when no chord comes within a millionth of a cell of it, and is kept when its centre is kept
// (parity along its grid row). Only the cells the loops cross go to CGAL's constrained Delaunay
// triangulation (exact predicates), with the loops' chords and the borders with whole kept
// cells as constraints; its triangles are kept by parity of the loop constraints crossed from
// outside. Grid points closer to a chord than a millionth of a cell are left out (the loop's
// own points stand there). Precondition: validate_trim(trim, domain) passed, us and vs
// increasing from the domain's lower to its upper ends, at least 2 each.
TrimmedLayout triangulate_trimmed(const std::vector<double>& us, const std::vector<double>& vs,
                                  const Trim& trim, const ParamRect& domain,
                                  const FlattenRule& rule);

} // namespace isoparm::geom
