// Vertex placement on grid edges (see Refiner in polygonize_parts.hpp).
#include <glm/geometric.hpp>

#include "core/geom/implicit/polygonize_parts.hpp"

namespace isoparm::geom::implicit::detail {

void Refiner::evaluate(const Context& ctx, const std::vector<std::size_t>& which, bool full) {
    const std::size_t n = which.size();
    if (n == 0) return;
    grow(n);
    for (std::size_t k = 0; k < n; ++k) {
        const Edge& e = edges[which[k]];
        points[k] = e.p + e.t * e.d;
        directions[k] = e.d;
    }
    if (full) {
        ctx.f.values_and_gradients(points.data(), n, values.data(), gradients.data(), ctx.params,
                                   scratch);
        for (std::size_t k = 0; k < n; ++k) {
            edges[which[k]].gradient = gradients[k];
            slopes[k] = glm::dot(gradients[k], directions[k]);
        }
    } else {
        ctx.f.values_and_derivatives(points.data(), directions.data(), n, values.data(),
                                     slopes.data(), ctx.params, scratch);
    }
}

// The evaluation arrays hold at least n points (they only grow: resizing down and up again
// would fill them anew each round).
void Refiner::grow(std::size_t n) {
    if (points.size() >= n) return;
    points.resize(n);
    directions.resize(n);
    values.resize(n);
    slopes.resize(n);
    gradients.resize(n);
}

void Refiner::run(const Context& ctx, VertexGroup& out) {
    active.clear();
    for (std::size_t k = 0; k < edges.size(); ++k)
        if (!edges[k].pinned) active.push_back(k);
    while (!active.empty()) {
        by_derivative.clear();
        by_gradient.clear();
        for (std::size_t k : active) (edges[k].full ? by_gradient : by_derivative).push_back(k);
        std::size_t kept = 0;
        for (const bool full : {false, true}) {
            const std::vector<std::size_t>& which = full ? by_gradient : by_derivative;
            evaluate(ctx, which, full);
            for (std::size_t k = 0; k < which.size(); ++k)
                if (step(edges[which[k]], values[k], slopes[k])) active[kept++] = which[k];
        }
        active.resize(kept);
    }
    // Where the last evaluation was not a full one at the final point, the gradient is
    // computed there (for a pinned vertex: at its grid point). Without convergence (a
    // pole, an undefined region, a kink) the sign change is somewhere in the final bracket.
    by_gradient.clear();
    out.positions.reserve(out.positions.size() + edges.size());
    for (std::size_t k = 0; k < edges.size(); ++k) {
        Edge& e = edges[k];
        if (e.pinned) {
            out.positions.push_back(e.p);
            by_gradient.push_back(k);
            continue;
        }
        if (!e.converged) e.t = 0.5 * (e.lo + e.hi);
        out.positions.push_back(e.p + e.t * e.d);
        if (!e.converged || !e.full) by_gradient.push_back(k);
    }
    if (!by_gradient.empty()) {
        const std::size_t n = by_gradient.size();
        grow(n);
        for (std::size_t k = 0; k < n; ++k) points[k] = out.positions[edges[by_gradient[k]].id];
        ctx.f.values_and_gradients(points.data(), n, values.data(), gradients.data(), ctx.params,
                                   scratch);
        for (std::size_t k = 0; k < n; ++k) edges[by_gradient[k]].gradient = gradients[k];
    }
    out.normals.reserve(out.normals.size() + edges.size());
    for (const Edge& e : edges) {
        const double norm = glm::length(e.gradient);
        out.normals.push_back(std::isfinite(norm) && norm > 0 ? e.gradient / norm
                                                              : glm::dvec3(0.0));
    }
    edges.clear();
}

} // namespace isoparm::geom::implicit::detail
