#include "core/exchange/mesh_weld.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/type_precision.hpp>
#include <unordered_map>
#include <vector>

#include "core/geom/implicit/polygonize.hpp"

namespace isoparm::exchange {

namespace {

struct CellHash {
    std::size_t operator()(const glm::i64vec3& c) const {
        // Large odd multipliers spread neighbouring cells over the table (spatial hashing,
        // Teschner et al. 2003).
        return static_cast<std::size_t>(c.x * 73856093LL ^ c.y * 19349663LL ^ c.z * 83492791LL);
    }
};

} // namespace

std::size_t weld(geom::Mesh& mesh, double relative_tolerance) {
    const std::size_t n = mesh.positions.size();
    if (n == 0) return 0;
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (std::size_t k = 0; k < n; ++k)
        if (mesh.vertex_exists(k))
            lo = glm::min(lo, mesh.positions[k]), hi = glm::max(hi, mesh.positions[k]);
    const double diagonal = glm::distance(lo, hi);
    const double tolerance = relative_tolerance * diagonal;
    if (!(tolerance > 0) || !std::isfinite(tolerance)) { // one point, or nothing exists
        geom::implicit::drop_degenerate_triangles(mesh);
        return 0;
    }

    std::unordered_map<glm::i64vec3, std::vector<std::uint32_t>, CellHash> cells;
    std::vector<std::uint32_t> target(n);
    std::vector<glm::dvec3> normal_sum(n, glm::dvec3(0.0));
    std::size_t merged = 0;
    for (std::size_t k = 0; k < n; ++k) {
        target[k] = static_cast<std::uint32_t>(k);
        if (!mesh.vertex_exists(k)) continue;
        const glm::dvec3& p = mesh.positions[k];
        const glm::i64vec3 cell(glm::floor((p - lo) / tolerance));
        bool found = false;
        for (int dx = -1; dx <= 1 && !found; ++dx)
            for (int dy = -1; dy <= 1 && !found; ++dy)
                for (int dz = -1; dz <= 1 && !found; ++dz) {
                    const auto it = cells.find(cell + glm::i64vec3(dx, dy, dz));
                    if (it == cells.end()) continue;
                    for (std::uint32_t r : it->second)
                        if (glm::distance(mesh.positions[r], p) <= tolerance) {
                            target[k] = r;
                            found = true;
                            break;
                        }
                }
        if (found) {
            ++merged;
        } else {
            cells[cell].push_back(static_cast<std::uint32_t>(k));
        }
        if (k < mesh.normals.size()) normal_sum[target[k]] += mesh.normals[k];
    }
    for (std::size_t k = 0; k < mesh.normals.size(); ++k)
        if (target[k] == k && mesh.vertex_exists(k)) {
            const double length = glm::length(normal_sum[k]);
            if (length > 0) mesh.normals[k] = normal_sum[k] / length;
        }
    for (auto& t : mesh.triangles)
        for (std::uint32_t& v : t) v = target[v];
    geom::implicit::drop_degenerate_triangles(mesh);
    return merged;
}

} // namespace isoparm::exchange
