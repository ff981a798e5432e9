// Trimmed tessellation: grid points from the grid kernel, loop points from the evaluator, on the
// trimmed domain's triangulation.
#include "core/geom/trim/trimmed_tessellator.hpp"

#include <algorithm>
#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::geom {

double default_chord_tolerance(const Surface& s) {
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::dvec3& p : s.points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double diagonal = s.points.empty() ? 1.0 : glm::length(hi - lo);
    return 5e-4 * (diagonal > 0 ? diagonal : 1.0);
}

TrimmedTessellator::TrimmedTessellator(const Surface& s, const Trim& trim, int samples_u,
                                       int samples_v, double chord_tolerance)
    : grid_(s, samples_u, samples_v) {
    FlattenRule rule;
    rule.surface = &s;
    rule.tolerance = chord_tolerance > 0 ? chord_tolerance : default_chord_tolerance(s);
    const auto& us = grid_.params_u();
    const auto& vs = grid_.params_v();
    rule.max_length = std::min((us.back() - us.front()) / (us.size() - 1),
                               (vs.back() - vs.front()) / (vs.size() - 1));
    layout_ = triangulate_trimmed(us, vs, trim, domain(s), rule);
}

void TrimmedTessellator::evaluate(const Surface& s, Mesh& mesh, int threads) const {
    std::vector<glm::dvec3> positions, normals;
    std::vector<std::uint8_t> exists;
    grid_.evaluate_vertices(s, positions, normals, exists, threads);
    const std::size_t g = layout_.grid_vertices.size(), n = layout_.vertex_count();
    mesh.positions.resize(n);
    mesh.normals.resize(n);
    mesh.exists.clear();
    bool gaps = false;
    std::vector<std::uint8_t> here(n, 1);
    for (std::size_t k = 0; k < g; ++k) {
        const std::uint32_t at = layout_.grid_vertices[k];
        mesh.positions[k] = positions[at];
        mesh.normals[k] = normals[at];
        if (!exists.empty() && !exists[at]) here[k] = 0, gaps = true;
    }
    const ParamRect d = domain(s);
    for (std::size_t k = g; k < n; ++k) {
        const glm::dvec2 p = layout_.loop_points[k - g];
        // Loops may stray outside the domain by the trim's closing tolerance.
        const double u = std::clamp(p.x, d.u.lo, d.u.hi), v = std::clamp(p.y, d.v.lo, d.v.hi);
        const auto der = surface_derivatives(s, u, v, 1);
        if (!der) {
            mesh.positions[k] = glm::dvec3(0.0);
            mesh.normals[k] = {0, 0, 1};
            here[k] = 0, gaps = true;
            continue;
        }
        mesh.positions[k] = der->D[0][0];
        const auto strict = normal_from_derivatives(*der);
        mesh.normals[k] = strict ? *strict : surface_normal_or_limit(s, u, v);
    }
    if (!gaps) {
        mesh.triangles = layout_.triangles;
        return;
    }
    mesh.exists = std::move(here);
    mesh.triangles.clear();
    for (const auto& t : layout_.triangles)
        if (mesh.exists[t[0]] && mesh.exists[t[1]] && mesh.exists[t[2]])
            mesh.triangles.push_back(t);
}

Mesh tessellate_trimmed(const Surface& s, const Trim& trim, int samples_u, int samples_v,
                        double chord_tolerance) {
    if (trim.empty()) return tessellate(s, samples_u, samples_v);
    Mesh mesh;
    TrimmedTessellator(s, trim, samples_u, samples_v, chord_tolerance).evaluate(s, mesh);
    return mesh;
}

} // namespace isoparm::geom
