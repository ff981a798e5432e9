// Multiresolution curves and surfaces (Finkelstein & Salesin 1994): a cubic B-spline with
// clamped uniform knots and 2^J + 3 control points is a coarse curve of level j < J plus the
// detail of each level between, by the wavelet filters of wavelet_filters.hpp. Surfaces with
// such knots in both directions are decomposed one direction at a time.
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// J for a curve that qualifies: equal weights (any non-rational type, or a rational one whose
// weights are all the same, which is then a B-spline), degree 3, 2^J + 3 control points (1 <= J <=
// max_wavelet_level), clamped knots with equal interior spans. Otherwise the refusal names
// the offending value: "/weights/k", "/degree", "/points" (the count), "/knots/k" (that knot).
Expected<int> multires_level(const Curve& c);
// (J_u, J_v) for a surface under the same rules per direction ("/knots_u/k", "/n_v", ...).
Expected<std::pair<int, int>> multires_levels(const Surface& s);
// The same rules for one direction's degree, knots and count; `what` starts the messages.
struct DyadicPaths {
    std::string degree, count, knots;
};
Expected<int> dyadic_level(const Knots& U, int degree, int n, const DyadicPaths& at,
                           const std::string& what);

// A level-J point sequence as its level-j coarse points and the detail of levels j .. J - 1:
// details[k] holds D_(j+k), the 2^(j+k) coefficients between level j + k and j + k + 1.
struct CurveDecomposition {
    int level = 0;
    std::vector<glm::dvec3> coarse;
    std::vector<std::vector<glm::dvec3>> details;
};

// Preconditions: points.size() == 2^from + 3 and 0 <= to <= from <= max_wavelet_level.
CurveDecomposition decompose(const std::vector<glm::dvec3>& points, int from, int to);
// The level-(level + details.size()) points again (exact up to rounding).
std::vector<glm::dvec3> reconstruct(const CurveDecomposition& d);

// A (2^Ju + 3) x (2^Jv + 3) net (row-major, i along u) decomposed along u to level_u on every
// line of constant j, then along v to level_v on every line of the coarse u-points.
struct SurfaceDecomposition {
    int level_u = 0, level_v = 0;
    int n_u = 0, n_v = 0;                    // the coarse net's size
    std::vector<glm::dvec3> coarse;          // n_u x n_v, row-major
    std::vector<CurveDecomposition> u_lines; // per fine j: the u-detail (coarse unused)
    std::vector<CurveDecomposition> v_lines; // per coarse i: the v-detail (coarse unused)
};

// Preconditions: net is (2^from_u + 3) x (2^from_v + 3), 0 <= to <= from in each direction.
SurfaceDecomposition decompose(const std::vector<glm::dvec3>& net, int from_u, int from_v, int to_u,
                               int to_v);
std::vector<glm::dvec3> reconstruct(const SurfaceDecomposition& d);

} // namespace isoparm::geom
