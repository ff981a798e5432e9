// The grid's layers (z = const) as the polygonizer works through them: values, sign summaries
// and sign bits (grid_layers.cpp), the vertices on their edges (grid_layers.cpp) and the
// triangles of the cells between two layers (cell_triangles.cpp). Internal to the polygonizer.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/geom/implicit/polygonize_parts.hpp"

namespace isoparm::geom::implicit::detail {

// Row summaries: every value of a row negative, every one positive, or both signs. Rows whose
// neighbourhood has a single sign have no sign change to look at, which skips most of the grid.
enum RowSign : std::uint8_t { row_negative = 0, row_positive = 1, row_mixed = 2 };

// Sign bits: bit i % 64 of signs[j * words + i / 64] is positive(value of point (i, j)); the
// bits past a row's end are 0. Within a row that has both signs, the points and cells with a
// sign change nearby are found 64 at a time from them (for_candidates), and only those are
// looked at one by one, exactly as before.
inline std::size_t sign_words(const Grid& g) {
    return (g.row + 63) / 64;
}

// The row's bits shifted down by one (bit i: point i + 1), the next word's first bit on top.
inline std::uint64_t next_bits(const std::uint64_t* row, std::size_t w, std::size_t words) {
    return (row[w] >> 1) | (w + 1 < words ? row[w + 1] << 63 : 0);
}

// Calls f(i) for each point i of a row whose bit is set in candidates(w), in increasing order.
template <class Bits, class F> void for_candidates(std::size_t words, Bits candidates, F&& f) {
    for (std::size_t w = 0; w < words; ++w)
        for (std::uint64_t bits = candidates(w); bits != 0; bits &= bits - 1)
            f(static_cast<int>(w * 64 + static_cast<std::size_t>(std::countr_zero(bits))));
}

// True when rows j and j + 1 (if any) of both row summaries are uniform with one sign.
inline bool rows_uniform(const std::uint8_t* a, const std::uint8_t* b, int j, int last) {
    const std::uint8_t s = a[j];
    if (s == row_mixed || b[j] != s) return false;
    return j == last || (a[j + 1] == s && b[j + 1] == s);
}

// One layer of the grid as a slab sees it: values, row summaries, and where the vertices on its
// in-plane edges (d = 1, 2, 3) live (ids[point * 3 + d - 1], tagged with the owner group).
struct Layer {
    int k = 0;
    const double* values = nullptr;
    const std::uint8_t* rows = nullptr;
    const std::uint64_t* signs = nullptr;
    const Index* ids = nullptr;
    Index tag = tag_local;
};

// Values of layer k (Program::values_on_rows), each row's sign summary and sign bits.
void evaluate_layer(const Context& ctx, int k, double* values, std::uint8_t* rows,
                    std::uint64_t* signs, std::vector<double>& scratch);

// Vertices on the in-plane edges (d = 1, 2, 3) of layer k; ids[point * 3 + d - 1].
void make_plane_vertices(const Context& ctx, int k, const double* values, const std::uint8_t* rows,
                         const std::uint64_t* signs, Index* ids, VertexGroup& out,
                         Refiner& refiner);

// Vertices on the edges from layer k to layer k + 1 (d = 4..7); ids[point * 4 + d - 4].
void make_vertical_vertices(const Context& ctx, const Layer& bottom, const Layer& top, Index* ids,
                            VertexGroup& out, Refiner& refiner);

// The triangles of the cells between two layers, appended to `out` with tagged vertex ids.
// positions[tag >> 30]: the vertices of the chunk (tag_local), of its bottom boundary plane
// (tag_bottom) and of its top one (tag_top), where a quadrilateral's diagonals are measured.
void emit_triangles(const Grid& g, const Layer& bottom, const Layer& top, const Index* vertical_ids,
                    const std::array<const std::vector<glm::dvec3>*, 3>& positions,
                    std::vector<std::array<Index, 3>>& out);

} // namespace isoparm::geom::implicit::detail
