// The marching-tetrahedra case table (see polygonize_parts.hpp and docs/implicit.md).
#include <algorithm>
#include <array>
#include <cassert>

#include <glm/geometric.hpp>

#include "core/geom/implicit/polygonize_parts.hpp"

namespace isoparm::geom::implicit::detail {

namespace {

glm::dvec3 corner_position(int c) {
    return {c & 1, (c >> 1) & 1, (c >> 2) & 1};
}

std::uint8_t edge_code(int a, int b) {
    if (a > b) std::swap(a, b);
    assert((a & b) == a);
    return static_cast<std::uint8_t>(a * 8 + (a ^ b));
}

glm::dvec3 edge_midpoint(std::uint8_t code) {
    const int c1 = code >> 3;
    const int c2 = c1 | (code & 7);
    return 0.5 * (corner_position(c1) + corner_position(c2));
}

// One tetrahedron's polygon for the signs of its corners (bit k set = corner v[k] positive):
// a triangle around a lone corner, or the quadrilateral between two and two. Its orientation is
// fixed on the exact midpoint geometry: counter-clockwise seen from the positive corners.
Polygon tetrahedron_polygon(const int v[4], int mask) {
    Polygon poly;
    int pos[4], neg[4], np = 0, nn = 0;
    for (int k = 0; k < 4; ++k) (mask >> k & 1 ? pos[np++] : neg[nn++]) = v[k];
    if (np == 0 || nn == 0) return poly;
    if (np == 1 || nn == 1) {
        const int lone = np == 1 ? pos[0] : neg[0];
        const int* others = np == 1 ? neg : pos;
        poly.n = 3;
        for (int k = 0; k < 3; ++k) poly.e[k] = edge_code(lone, others[k]);
    } else {
        // The cycle ac, ad, bd, bc: consecutive edges share a corner.
        const int a = pos[0], b = pos[1], c = neg[0], d = neg[1];
        poly.n = 4;
        poly.e[0] = edge_code(a, c);
        poly.e[1] = edge_code(a, d);
        poly.e[2] = edge_code(b, d);
        poly.e[3] = edge_code(b, c);
    }
    glm::dvec3 toward_positive(0.0);
    for (int k = 0; k < np; ++k) toward_positive += corner_position(pos[k]) / double(np);
    for (int k = 0; k < nn; ++k) toward_positive -= corner_position(neg[k]) / double(nn);
    const glm::dvec3 m0 = edge_midpoint(poly.e[0]), m1 = edge_midpoint(poly.e[1]),
                     m2 = edge_midpoint(poly.e[2]);
    const glm::dvec3 normal = poly.n == 3 ? glm::cross(m1 - m0, m2 - m0)
                                          : glm::cross(m2 - m0, edge_midpoint(poly.e[3]) - m1);
    assert(glm::dot(normal, toward_positive) != 0.0);
    if (glm::dot(normal, toward_positive) < 0) std::reverse(poly.e + 1, poly.e + poly.n);
    return poly;
}

std::array<CubeCase, 256> build_cube_cases() {
    static const int axis_orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                          {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    std::array<CubeCase, 256> cases{};
    for (int mask = 0; mask < 256; ++mask) {
        CubeCase& cc = cases[mask];
        for (const auto& order : axis_orders) {
            const int v1 = 1 << order[0];
            const int v2 = v1 | (1 << order[1]);
            const int v[4] = {0, v1, v2, 7};
            int m = 0;
            for (int k = 0; k < 4; ++k) m |= (mask >> v[k] & 1) << k;
            Polygon poly = tetrahedron_polygon(v, m);
            if (poly.n != 0) cc.polygons[cc.count++] = poly;
        }
    }
    return cases;
}

} // namespace

const CubeCase* cube_cases() {
    static const std::array<CubeCase, 256> cases = build_cube_cases();
    return cases.data();
}

} // namespace isoparm::geom::implicit::detail
