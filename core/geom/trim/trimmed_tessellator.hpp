// Tessellation of a trimmed surface: the grid tessellator's kernel for the grid points, the
// surface evaluated at the loop points, on the triangulation of the trimmed domain.
#pragma once

#include <memory>

#include "core/geom/grid_tessellator.hpp"
#include "core/geom/tessellate.hpp"
#include "core/geom/trim/trim.hpp"
#include "core/geom/trim/trim_triangulate.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// The chord tolerance a display uses when none is given: 5e-4 of the diagonal of the box
// around the control points (a 2000-pixel view of the surface is then within a pixel).
double default_chord_tolerance(const Surface& s);

class TrimmedTessellator {
public:
    // The triangulation of s's trimmed domain on a samples_u x samples_v grid, the loops cut
    // into chords within chord_tolerance of the surface (in 3D; <= 0: the default) and no longer
    // than a cell. Precondition: valid surface, validate_trim(trim, domain(s)) passed.
    TrimmedTessellator(const Surface& s, const Trim& trim, int samples_u, int samples_v,
                       double chord_tolerance = 0);

    // Positions, unit normals and triangles for s (which may have moved its control points
    // since: the triangulation stays, the points follow). Grid points come from the grid
    // kernel (threads as GridTessellator::evaluate), loop points from the surface itself. Where
    // a point does not exist (a zero denominator) its triangles are left out.
    void evaluate(const Surface& s, Mesh& mesh, int threads = 1) const;

    const TrimmedLayout& layout() const { return layout_; }
    const GridTessellator& grid() const { return grid_; }

private:
    GridTessellator grid_;
    TrimmedLayout layout_;
};

// One trimmed tessellation (an empty trim gives the grid's mesh).
Mesh tessellate_trimmed(const Surface& s, const Trim& trim, int samples_u, int samples_v,
                        double chord_tolerance = 0);

} // namespace isoparm::geom
