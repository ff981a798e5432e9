// The triangular patch's teaching panels without ImGui (Farin, "Curves and Surfaces for CAGD",
// ch. 17): the domain triangle on screen, typing a barycentric coordinate, the names of the
// points b^l_ijk, de Casteljau's steps, and the heat map of one Bernstein function with its
// peak. The tracing, de Casteljau and basis panels draw what these compute.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "core/doc/document.hpp"
#include "core/geom/status.hpp"
#include "core/geom/triangle.hpp"
#include "ui/view/layout.hpp"

namespace isoparm::ui {

// The selected object's patch when it is a triangle (the panels switch to the triangle only
// then: a selected surface, curve or nothing keeps the square); its object in `object`.
const geom::TrianglePatch* selected_triangle(const doc::Document& d,
                                             const doc::Object** object = nullptr);

// The domain triangle on screen, equilateral: vertex[0] is r = 1 (b_n00) bottom-right,
// vertex[1] s = 1 (b_0n0) at the top, vertex[2] t = 1 (b_00n) bottom-left. So r grows to the
// right and s upward, as u and v do on the square, and triangle_derivatives' d/dr (from b_00n
// to b_n00) points right. Equilateral, because the plane r + s + t = 1 maps onto it by a
// similarity: distances on screen are distances between barycentric points.
struct TriangleCanvas {
    std::array<glm::dvec2, 3> vertex;
};
// The largest such triangle centred in `box`, `margin` pixels inside it.
TriangleCanvas fit_triangle(const Rect& box, double margin);
glm::dvec2 barycentric_to_pixel(const TriangleCanvas& c, const geom::Barycentric& p);
// The inverse, not clamped: outside the triangle a coordinate is negative.
geom::Barycentric pixel_to_barycentric(const TriangleCanvas& c, const glm::dvec2& pixel);
// The domain point (i, j, k) / n of a degree-n patch within `radius` pixels of `pixel` (the
// nearest one), as (i, j); none when no dot is that near.
std::optional<std::pair<int, int>> domain_point_at(const TriangleCanvas& c, int n,
                                                   const glm::dvec2& pixel, double radius);
// The nearest point of the triangle (the Euclidean projection onto the simplex r, s, t >= 0,
// r + s + t = 1: Michelot's sort-and-shift). A point inside comes back unchanged.
geom::Barycentric clamp_to_triangle(const geom::Barycentric& p);

// Typing one coordinate (which: 0 r, 1 s, 2 t): the other two keep their ratio and share
// what is left, 1 - value, so the three still sum to 1 (they share it equally when both were
// 0). A value outside [0, 1] or not a number is refused with a message that says why; the
// indicator does not move (a silent clamp would put it somewhere else than typed).
geom::Expected<geom::Barycentric> set_barycentric_coordinate(const geom::Barycentric& p, int which,
                                                             double value);

// The name of b^l_ijk, i + j + k = n - l, in a patch of degree n: level 0 as point_name names
// a control point ("b210", "b1,2,10" from degree 10 on), level l > 0 "b^2_100".
std::string triangle_point_name(int n, int level, int i, int j);

// De Casteljau on the triangle in steps: step l shows level l (0 the control points, n the
// patch point S(r, s, t) = b^n_000). How many points level l has: (n - l + 1)(n - l + 2) / 2.
int triangle_level_size(int n, int level);
// "level 2, the 3 points b^2_ijk with i + j + k = 1"; step < 0: "all levels".
std::string triangle_step_text(int step, int n);
// The weights w^l_ijk of every level (the homogeneous points' last coordinate, in
// triangle_de_casteljau's order), for showing a rational construction as points and weights.
std::vector<std::vector<double>> triangle_level_weights(const geom::TrianglePatch& t,
                                                        const geom::Barycentric& p);

// An extreme value of a basis function on the triangle and where it is (triangle_basis_peak).
struct BasisPeak {
    geom::Barycentric at{};
    double value = 0;
    bool exact = false;
    bool found = false; // false: R exists nowhere on the grid, or has no extreme (unbounded)
    // The denominator sum w_abc B_abc is zero inside the triangle: R_ijk grows without bound
    // towards where it is, so there is no largest (or smallest) value to find.
    bool unbounded = false;
};

// What a picture over the domain triangle depends on when it depends on the weights alone (the
// basis heat map, the denominator's sign): dragging a control point keeps it.
struct TriangleWeightsKey {
    int degree = 0;
    bool rational = false;
    std::vector<double> weights;
    int subdivisions = 0; // of the picture's grid (a, b, c) / N, a + b + c = N
    static TriangleWeightsKey of(const geom::TrianglePatch& t, int subdivisions);
    bool matches(const geom::TrianglePatch& t, int subdivisions) const;
};
// The grid point (a, b, N - a - b) / N.
geom::Barycentric triangle_grid_point(int N, int a, int b);

// R_ijk (B^n_ijk for a non-rational patch) at the grid points (a, b, c) / N of the domain,
// a + b + c = N, in TrianglePatch::index(N, a, b) order (b_N00's corner first); NaN where the
// denominator is zero. `largest` is the largest finite value, `largest_magnitude` the
// largest |value| (the colour scale: negative weights make R negative somewhere).
struct TriangleHeat {
    // The key: R_ijk depends on the degree and the weights, not on where the points are (a
    // dragged point does not recompute the map).
    TriangleWeightsKey key;
    int i = -1, j = -1;
    std::vector<double> values;
    double largest = 0, largest_magnitude = 0;
    // The denominator is zero at a grid point, or has both signs over the grid: it vanishes
    // inside the triangle (weights of both signs).
    bool denominator_vanishes = false;
    bool valid = false;
    // The caller's triangle_basis_peak results, kept with the map they were searched from (they
    // too depend on the weights only); not filled by triangle_heat.
    BasisPeak peak, low;
};
TriangleHeat triangle_heat(const geom::TrianglePatch& t, int i, int j, int subdivisions);
// Whether `heat` is of this patch's degree and weights, point and grid (a cache in the UI state
// is then current).
bool same_heat(const TriangleHeat& heat, const geom::TrianglePatch& t, int i, int j,
               int subdivisions);

// Where R_ijk is largest on the triangle and its value there (`lowest`: smallest, for a
// negative weight, which makes R_ijk negative). B^n_ijk peaks at (i, j, k) / n (its gradient
// along the plane vanishes there; Farin 17.1), exactly. A rational R_ijk is searched: the best
// grid point of `heat`, then a compass search (steps in the six directions of the triangle's
// grid, halved down to 1e-10) inside the triangle. `exact` says which.
BasisPeak triangle_basis_peak(const geom::TrianglePatch& t, int i, int j, const TriangleHeat& heat,
                              bool lowest = false);

} // namespace isoparm::ui
