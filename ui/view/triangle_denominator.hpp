// What the domain triangle shows of a rational triangular patch's denominator
// D(r, s, t) = sum w_ijk B^n_ijk (geom::triangle_denominator): the small triangles of the grid
// (a, b, c) / N where it is negative, and its zero set, where the patch goes to infinity.
// D depends on the degree and the weights only: dragging a point never recomputes it.
#pragma once

#include <array>
#include <vector>

#include "core/geom/triangle.hpp"
#include "ui/view/triangle_domain.hpp"

namespace isoparm::ui {

struct TriangleDenominatorView {
    TriangleWeightsKey key;
    bool valid = false;
    // Small triangles of the grid with D < 0 at their centroid.
    std::vector<std::array<geom::Barycentric, 3>> negative;
    // D = 0, one segment per small triangle it crosses (marching triangles: D interpolated
    // linearly along the edges whose ends differ in sign).
    std::vector<std::array<geom::Barycentric, 2>> zero_set;
};

TriangleDenominatorView triangle_denominator_view(const geom::TrianglePatch& t, int subdivisions);
// Whether `v` was made from this patch's degree and weights on this grid.
bool same_denominator(const TriangleDenominatorView& v, const geom::TrianglePatch& t,
                      int subdivisions);

} // namespace isoparm::ui
