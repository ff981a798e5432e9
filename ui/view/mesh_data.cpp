// Mesh cache helpers: surface comparison, wireframe indices, vertex interleaving.
#include "ui/view/mesh_data.hpp"

#include <cmath>

#include <algorithm>

namespace isoparm::ui {

bool same_surface(const geom::Surface& a, const geom::Surface& b) {
    return a.type == b.type && a.degree_u == b.degree_u && a.degree_v == b.degree_v &&
           a.n_u == b.n_u && a.n_v == b.n_v && a.knots_u == b.knots_u && a.knots_v == b.knots_v &&
           a.points == b.points && a.weights == b.weights;
}

bool same_basis(const geom::Surface& a, const geom::Surface& b) {
    return a.type == b.type && a.degree_u == b.degree_u && a.degree_v == b.degree_v &&
           a.n_u == b.n_u && a.n_v == b.n_v && a.knots_u == b.knots_u && a.knots_v == b.knots_v &&
           a.weights == b.weights;
}

std::vector<std::uint32_t> wire_indices(int su, int sv, const std::vector<std::uint8_t>& exists,
                                        int max_lines) {
    std::vector<std::uint32_t> out;
    if (su < 2 || sv < 2) return out;
    max_lines = std::max(max_lines, 1);
    const int stride_u = std::max(1, (su - 1 + max_lines - 1) / max_lines);
    const int stride_v = std::max(1, (sv - 1 + max_lines - 1) / max_lines);
    auto ok = [&](int k) { return exists.empty() || exists[static_cast<std::size_t>(k)] != 0; };
    auto segment = [&](int a, int b) {
        if (ok(a) && ok(b)) {
            out.push_back(static_cast<std::uint32_t>(a));
            out.push_back(static_cast<std::uint32_t>(b));
        }
    };
    // Lines of constant u (rows i), then of constant v (columns j).
    for (int i = 0; i < su; ++i) {
        if (i % stride_u != 0 && i != su - 1) continue;
        for (int j = 0; j + 1 < sv; ++j) segment(i * sv + j, i * sv + j + 1);
    }
    for (int j = 0; j < sv; ++j) {
        if (j % stride_v != 0 && j != sv - 1) continue;
        for (int i = 0; i + 1 < su; ++i) segment(i * sv + j, (i + 1) * sv + j);
    }
    return out;
}

std::vector<float> interleave(const geom::Mesh& mesh, std::size_t first, std::size_t count,
                              const std::vector<double>& scalars, float fallback) {
    std::vector<float> v;
    const std::size_t end =
        first + std::min(count, mesh.positions.size() - std::min(first, mesh.positions.size()));
    v.reserve((end - std::min(first, end)) * floats_per_vertex);
    for (std::size_t k = first; k < end; ++k) {
        const glm::dvec3& p = mesh.positions[k];
        const glm::dvec3 n = k < mesh.normals.size() ? mesh.normals[k] : glm::dvec3(0, 0, 1);
        float scalar = fallback;
        if (k - first < scalars.size()) {
            const double value = scalars[k - first];
            scalar = std::isfinite(value) && std::abs(value) < 1e20 ? static_cast<float>(value)
                                                                    : undefined_scalar;
        }
        v.insert(v.end(), {static_cast<float>(p.x), static_cast<float>(p.y),
                           static_cast<float>(p.z), static_cast<float>(n.x),
                           static_cast<float>(n.y), static_cast<float>(n.z), scalar});
    }
    return v;
}

} // namespace isoparm::ui
