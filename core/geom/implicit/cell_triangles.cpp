// The triangles of the cells between two layers: each cell's case from its corners' signs
// (cube_cases.cpp), its polygons' vertices from the layers' and the slab's edge ids.
#include <glm/geometric.hpp>

#include "core/geom/implicit/grid_layers.hpp"

namespace isoparm::geom::implicit::detail {

void emit_triangles(const Grid& g, const Layer& bottom, const Layer& top, const Index* vertical_ids,
                    const std::array<const std::vector<glm::dvec3>*, 3>& positions,
                    std::vector<std::array<Index, 3>>& out) {
    const auto position_of = [&](Index id) -> const glm::dvec3& {
        return (*positions[id >> 30])[id & ~tag_mask];
    };
    const CubeCase* cases = cube_cases();
    const std::size_t words = sign_words(g);
    // Where each edge code finds its vertex id, relative to the cell's first point.
    struct EdgeSlot {
        const Index* ids = nullptr;
        std::size_t stride = 0, offset = 0;
        Index tag = 0;
    };
    std::array<EdgeSlot, 64> slots{};
    for (int c1 = 0; c1 < 8; ++c1)
        for (int d = 1; d < 8; ++d) {
            if ((c1 & d) != 0) continue;
            EdgeSlot& s = slots[c1 * 8 + d];
            const std::size_t point = ((c1 >> 1) & 1) * g.row + (c1 & 1);
            if (d & 4)
                s = EdgeSlot{vertical_ids, 4, point * 4 + d - 4, tag_local};
            else if (c1 & 4)
                s = EdgeSlot{top.ids, 3, point * 3 + d - 1, top.tag};
            else
                s = EdgeSlot{bottom.ids, 3, point * 3 + d - 1, bottom.tag};
        }
    for (int j = 0; j < g.ny; ++j) {
        if (rows_uniform(bottom.rows, top.rows, j, g.ny)) continue;
        const double* b0 = bottom.values + j * g.row;
        const double* b1 = b0 + g.row;
        const double* t0 = top.values + j * g.row;
        const double* t1 = t0 + g.row;
        // Cells whose eight corners may not all have one sign: a column (the four corners
        // at x_i) with both signs, at i or i + 1, or two columns of different signs.
        const std::uint64_t* sb0 = bottom.signs + j * words;
        const std::uint64_t* sb1 = sb0 + words;
        const std::uint64_t* st0 = top.signs + j * words;
        const std::uint64_t* st1 = st0 + words;
        const auto column = [&](std::size_t w) {
            return w < words ? (sb0[w] ^ sb1[w]) | (sb0[w] ^ st0[w]) | (sb0[w] ^ st1[w])
                             : std::uint64_t{0};
        };
        const auto changes = [&](std::size_t w) {
            const std::uint64_t c = column(w);
            return c | (c >> 1) | (column(w + 1) << 63) | (sb0[w] ^ next_bits(sb0, w, words));
        };
        for_candidates(words, changes, [&](int i) {
            if (i >= g.nx) return;
            const unsigned left = positive(b0[i]) << 0 | positive(b1[i]) << 2 |
                                  positive(t0[i]) << 4 | positive(t1[i]) << 6;
            const unsigned right = positive(b0[i + 1]) << 0 | positive(b1[i + 1]) << 2 |
                                   positive(t0[i + 1]) << 4 | positive(t1[i + 1]) << 6;
            const unsigned mask = left | right << 1;
            if (mask == 0 || mask == 255) return;
            const std::size_t point = j * g.row + i;
            const CubeCase& cc = cases[mask];
            for (int k = 0; k < cc.count; ++k) {
                const Polygon& poly = cc.polygons[k];
                Index v[4];
                for (int e = 0; e < poly.n; ++e) {
                    const EdgeSlot& s = slots[poly.e[e]];
                    v[e] = s.tag | s.ids[point * s.stride + s.offset];
                }
                if (poly.n == 3) {
                    out.push_back({v[0], v[1], v[2]});
                    continue;
                }
                // A quadrilateral: split along its shorter diagonal (the better-shaped
                // pair); either split keeps the orientation.
                const double d02 = glm::length(position_of(v[0]) - position_of(v[2]));
                const double d13 = glm::length(position_of(v[1]) - position_of(v[3]));
                if (d02 <= d13) {
                    out.push_back({v[0], v[1], v[2]});
                    out.push_back({v[0], v[2], v[3]});
                } else {
                    out.push_back({v[1], v[2], v[3]});
                    out.push_back({v[1], v[3], v[0]});
                }
            }
        });
    }
}

} // namespace isoparm::geom::implicit::detail
