// Triangular Bezier patches (Farin, "Curves and Surfaces for CAGD", ch. 17): the paper's future
// work. Degree n, control points b_ijk with i + j + k = n, barycentric parameters (r, s, t).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/geom/status.hpp"
#include "core/geom/tessellate.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// Control points in the order of the protocol: i = n..0, then j = n - i..0, k = n - i - j
// (b_n00 first, b_00n last). Non-rational patches keep unit weights.
struct TrianglePatch {
    bool rational = false;
    int degree = 1;
    std::vector<glm::dvec3> points;
    std::vector<double> weights;

    static int count_for(int n) { return (n + 1) * (n + 2) / 2; }
    // The position of b_ijk (k = n - i - j) in `points`.
    static int index(int n, int i, int j) {
        const int row = n - i;
        return row * (row + 1) / 2 + (row - j);
    }
};

using Barycentric = std::array<double, 3>; // (r, s, t), each >= 0, r + s + t = 1

// Largest degree the protocol accepts: (n + 1)(n + 2)/2 points stay within the 1,000,000 cap.
constexpr int max_triangle_degree = 1412;

// Degree >= 1 (`degree`), point count (`schema`, "/points"), finite points, weights count and
// values (`weights`): the checks every triangle passes before any algorithm runs.
Status validate_triangle(const TrianglePatch& t);

// The Bernstein polynomial B^n_ijk(r, s, t) = n! / (i! j! k!) r^i s^j t^k, k = n - i - j
// (Farin 17.1), for 0 <= i, j and i + j <= n. Low degrees by products (exact coefficient);
// high ones in logarithms, so that neither the multinomial coefficient (which overflows a
// double past n ~ 170) nor the powers (which underflow) are formed on their own. 0^0 = 1, and
// outside the triangle the polynomial keeps its sign. The B^n_ijk of one n sum to 1 where
// r + s + t = 1.
double bernstein_triangle(int n, int i, int j, const Barycentric& p);

// The denominator of a rational patch, sum w_abc B^n_abc(p) (1 for a non-rational one, whose
// weights are all 1): where it is zero the patch point does not exist.
double triangle_denominator(const TrianglePatch& t, const Barycentric& p);

// The rational basis function R_ijk = w_ijk B^n_ijk / sum w_abc B^n_abc of the patch's control
// point b_ijk (B itself for a non-rational patch); nullopt where the denominator is zero
// (the patch point does not exist there).
std::optional<double> rational_bernstein_triangle(const TrianglePatch& t, int i, int j,
                                                  const Barycentric& p);

// The Bernstein sum sum B^n_ijk(r, s, t) b_ijk (rational: in homogeneous space), by de
// Casteljau; nullopt where the weight sum is zero.
std::optional<glm::dvec3> triangle_point(const TrianglePatch& t, const Barycentric& p);

// D[a][b] = d^(a+b) S / dr^a ds^b for a + b <= d <= 2, with t = 1 - r - s (so d/dr runs along
// the edge from b_00n to b_n00 and d/ds from b_00n to b_0n0); rational derivatives by the
// quotient rule. nullopt where the point does not exist.
std::optional<std::array<std::array<glm::dvec3, 3>, 3>>
triangle_derivatives(const TrianglePatch& t, const Barycentric& p, int d);

// Every level of de Casteljau's construction: level 0 the control points, level l the
// (n - l + 1)(n - l + 2)/2 points of degree n - l in the same order, the last one point (the
// patch point). A point of zero weight is nullopt.
std::vector<std::vector<std::optional<glm::dvec3>>> triangle_de_casteljau(const TrianglePatch& t,
                                                                          const Barycentric& p);

// Degree elevation by `times` (Farin 17.6), same shape, in homogeneous space.
TrianglePatch elevate_triangle(const TrianglePatch& t, int times);

// The three patches meeting at the point p strictly inside (de Casteljau's levels): piece v
// has the point in place of vertex v (0: b_n00, 1: b_0n0, 2: b_00n) and keeps the other two;
// together they cover the patch exactly. A piece is `weights` where a level point has zero
// weight (a point at infinity cannot be a control point).
Expected<std::array<TrianglePatch, 3>> split_triangle(const TrianglePatch& t, const Barycentric& p);

// A mesh of the patch: the barycentric grid (i, j, k) / n, i + j + k = n, vertices in the
// control points' order, n^2 triangles counter-clockwise about S_r x S_s, unit normals from
// the exact derivatives (S_r x S_s; +z where it degenerates). Precondition: n >= 1.
Mesh tessellate_triangle(const TrianglePatch& t, int n);

} // namespace isoparm::geom
