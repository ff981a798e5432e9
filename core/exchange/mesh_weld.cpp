#include "core/exchange/mesh_weld.hpp"

#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/gtc/type_precision.hpp>
#include <unordered_map>
#include <vector>

#include "core/geom/implicit/polygonize.hpp"

namespace isoparm::exchange {

namespace {

// splitmix64's finalizer (Steele, Lea and Flood 2014): every input bit moves every output bit.
std::uint64_t mix(std::uint64_t x) {
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

struct CellHash {
    std::size_t operator()(const glm::i64vec3& c) const {
        // Spatial hashing (Teschner et al. 2003) with the coordinates mixed one after another:
        // the classic XOR of three products collides by the thousand on the tiny cells of a
        // dense grid (1,000 x 1,000 samples took 20 s in its chains).
        std::uint64_t h = mix(static_cast<std::uint64_t>(c.x));
        h = mix(h ^ static_cast<std::uint64_t>(c.y));
        return static_cast<std::size_t>(mix(h ^ static_cast<std::uint64_t>(c.z)));
    }
};

constexpr std::uint32_t none = 0xffffffffu;

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

    const double cell_size = 64 * tolerance;
    // Each cell holds the first vertex kept in it; `next` chains the others (no list per cell).
    std::unordered_map<glm::i64vec3, std::uint32_t, CellHash> cells;
    cells.reserve(n);
    std::vector<std::uint32_t> next(n, none);
    std::vector<std::uint32_t> target(n);
    std::vector<glm::dvec3> normal_sum(n, glm::dvec3(0.0));
    std::size_t merged = 0;
    for (std::size_t k = 0; k < n; ++k) {
        target[k] = static_cast<std::uint32_t>(k);
        if (!mesh.vertex_exists(k)) continue;
        const glm::dvec3& p = mesh.positions[k];
        const glm::dvec3 scaled = (p - lo) / cell_size;
        const glm::i64vec3 cell(glm::floor(scaled));
        // A neighbouring cell can hold a vertex within the tolerance only across a face this
        // one is nearer than the tolerance to: with cells 64 tolerances wide, one lookup for
        // nearly every vertex (27 each made a 1,000 x 1,000 mesh wait on memory for 10 s).
        int from[3], to[3];
        for (int a = 0; a < 3; ++a) {
            const double inside = (scaled[a] - static_cast<double>(cell[a])) * cell_size;
            from[a] = inside <= tolerance ? -1 : 0;
            to[a] = cell_size - inside <= tolerance ? 1 : 0;
        }
        bool found = false;
        for (int dx = from[0]; dx <= to[0] && !found; ++dx)
            for (int dy = from[1]; dy <= to[1] && !found; ++dy)
                for (int dz = from[2]; dz <= to[2] && !found; ++dz) {
                    const auto it = cells.find(cell + glm::i64vec3(dx, dy, dz));
                    if (it == cells.end()) continue;
                    for (std::uint32_t r = it->second; r != none; r = next[r])
                        if (glm::distance(mesh.positions[r], p) <= tolerance) {
                            target[k] = r;
                            found = true;
                            break;
                        }
                }
        if (found) {
            ++merged;
        } else {
            const auto [it, inserted] = cells.try_emplace(cell, static_cast<std::uint32_t>(k));
            if (!inserted) {
                next[k] = it->second;
                it->second = static_cast<std::uint32_t>(k);
            }
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
