// The grid's layers: their values and sign bits, and the vertices on their edges (see
// grid_layers.hpp). Only the points and cells with a sign change nearby are looked at.
#include "core/geom/implicit/grid_layers.hpp"

#include <algorithm>

namespace isoparm::geom::implicit::detail {

namespace {

// In-plane edge directions (x, y, x+y) and the layer-crossing ones (z, x+z, y+z, x+y+z), as
// offsets; d = 1..7 is the corner-offset bit pattern of the edge.
constexpr int edge_dx(int d) {
    return d & 1;
}
constexpr int edge_dy(int d) {
    return (d >> 1) & 1;
}

} // namespace

void evaluate_layer(const Context& ctx, int k, double* values, std::uint8_t* rows,
                    std::uint64_t* signs, std::vector<double>& scratch) {
    const Grid& g = ctx.grid;
    const std::size_t words = sign_words(g);
    ctx.f.values_on_rows(g.xs.data(), g.row, g.ys.data(), g.ys.size(), g.zs[k], values, ctx.params,
                         scratch);
    for (int j = 0; j <= g.ny; ++j) {
        const double* row = values + j * g.row;
        std::size_t count = 0;
        std::uint64_t* bits = signs + j * words;
        std::fill_n(bits, words, 0);
        for (std::size_t i = 0; i < g.row; ++i) {
            const bool p = positive(row[i]);
            count += p;
            bits[i / 64] |= static_cast<std::uint64_t>(p) << (i % 64);
        }
        rows[j] = count == 0 ? row_negative : count == g.row ? row_positive : row_mixed;
    }
}

void make_plane_vertices(const Context& ctx, int k, const double* values, const std::uint8_t* rows,
                         const std::uint64_t* signs, Index* ids, VertexGroup& out,
                         Refiner& refiner) {
    const Grid& g = ctx.grid;
    const std::size_t words = sign_words(g);
    for (int j = 0; j <= g.ny; ++j) {
        if (rows_uniform(rows, rows, j, g.ny)) continue;
        const double* row = values + j * g.row;
        const double* next = j < g.ny ? row + g.row : row; // no y edges from the last row
        const std::uint64_t* r = signs + j * words;
        const std::uint64_t* n = j < g.ny ? r + words : r;
        const auto changes = [&](std::size_t w) {
            return (r[w] ^ next_bits(r, w, words)) | (r[w] ^ n[w]) |
                   (r[w] ^ next_bits(n, w, words));
        };
        for_candidates(words, changes, [&](int i) {
            const bool s = positive(row[i]);
            const int i1 = std::min(i + 1, g.nx);
            const bool x = positive(row[i1]) != s, y = positive(next[i]) != s,
                       xy = positive(next[i1]) != s;
            if (!(x || y || xy)) return;
            for (int d = 1; d <= 3; ++d) {
                const int i2 = i + edge_dx(d), j2 = j + edge_dy(d);
                if (i2 > g.nx || j2 > g.ny) continue;
                const double fb = values[j2 * g.row + i2];
                if (positive(fb) == s) continue;
                ids[(j * g.row + i) * 3 + d - 1] =
                    refiner.add(out, g.point(i, j, k), row[i], g.index(i, j, k), g.point(i2, j2, k),
                                fb, g.index(i2, j2, k));
            }
        });
    }
    refiner.run(ctx, out);
}

void make_vertical_vertices(const Context& ctx, const Layer& bottom, const Layer& top, Index* ids,
                            VertexGroup& out, Refiner& refiner) {
    const Grid& g = ctx.grid;
    const int k = bottom.k;
    const std::size_t words = sign_words(g);
    for (int j = 0; j <= g.ny; ++j) {
        if (rows_uniform(bottom.rows, top.rows, j, g.ny)) continue;
        const double* row = bottom.values + j * g.row;
        const double* up = top.values + j * g.row;
        const double* up_next = j < g.ny ? up + g.row : up;
        const std::uint64_t* b = bottom.signs + j * words;
        const std::uint64_t* t0 = top.signs + j * words;
        const std::uint64_t* t1 = j < g.ny ? t0 + words : t0;
        const auto changes = [&](std::size_t w) {
            return (b[w] ^ t0[w]) | (b[w] ^ next_bits(t0, w, words)) | (b[w] ^ t1[w]) |
                   (b[w] ^ next_bits(t1, w, words));
        };
        for_candidates(words, changes, [&](int i) {
            const bool s = positive(row[i]);
            const int i1 = std::min(i + 1, g.nx);
            if (positive(up[i]) == s && positive(up[i1]) == s && positive(up_next[i]) == s &&
                positive(up_next[i1]) == s)
                return;
            for (int d = 4; d <= 7; ++d) {
                const int i2 = i + edge_dx(d), j2 = j + edge_dy(d);
                if (i2 > g.nx || j2 > g.ny) continue;
                const double fb = top.values[j2 * g.row + i2];
                if (positive(fb) == s) continue;
                ids[(j * g.row + i) * 4 + d - 4] =
                    refiner.add(out, g.point(i, j, k), row[i], g.index(i, j, k),
                                g.point(i2, j2, k + 1), fb, g.index(i2, j2, k + 1));
            }
        });
    }
    refiner.run(ctx, out);
}

} // namespace isoparm::geom::implicit::detail
