// Implicit surfaces' curvature from the gradient and Hessian of f (Goldman 2005).
#include "core/geom/implicit/curvature.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/mat3x3.hpp>

namespace isoparm::geom::implicit {

std::optional<SurfaceCurvature> implicit_curvature(const Program& f, const glm::dvec3& p,
                                                   const double* params) {
    glm::dvec3 g;
    f.value_and_gradient(p, g, params);
    const double g2 = glm::dot(g, g);
    if (!(g2 > 0) || !std::isfinite(g2)) return std::nullopt;
    // H by central differences of the exact gradient: column j is d(grad f)/dx_j.
    const double scale = std::max({1.0, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    const double h = std::cbrt(std::numeric_limits<double>::epsilon()) * scale;
    glm::dmat3 H(0.0);
    for (int j = 0; j < 3; ++j) {
        glm::dvec3 step(0.0);
        step[j] = h;
        glm::dvec3 plus, minus;
        f.value_and_gradient(p + step, plus, params);
        f.value_and_gradient(p - step, minus, params);
        H[j] = (plus - minus) / (2 * h); // glm: H[j] is column j
    }
    H = 0.5 * (H + glm::transpose(H)); // symmetric, as a Hessian is
    // adj(H) of a symmetric matrix: the cofactors.
    const auto c = [&](int r, int col) { return H[col][r]; };
    glm::dmat3 adj;
    for (int r = 0; r < 3; ++r)
        for (int col = 0; col < 3; ++col) {
            const int r0 = (col + 1) % 3, r1 = (col + 2) % 3, c0 = (r + 1) % 3, c1 = (r + 2) % 3;
            adj[col][r] = c(r0, c0) * c(r1, c1) - c(r0, c1) * c(r1, c0);
        }
    const double glen = std::sqrt(g2);
    SurfaceCurvature k;
    k.gaussian = glm::dot(g, adj * g) / (g2 * g2);
    const double trace = H[0][0] + H[1][1] + H[2][2];
    k.mean = (glm::dot(g, H * g) - g2 * trace) / (2 * g2 * glen);
    const double spread = std::sqrt(std::max(k.mean * k.mean - k.gaussian, 0.0));
    k.k1 = k.mean + spread;
    k.k2 = k.mean - spread;
    if (!std::isfinite(k.gaussian) || !std::isfinite(k.mean)) return std::nullopt;
    return k;
}

double implicit_curvature_value(const Program& f, const glm::dvec3& p, CurvatureKind kind,
                                const double* params) {
    const std::optional<SurfaceCurvature> k = implicit_curvature(f, p, params);
    if (!k) return std::numeric_limits<double>::quiet_NaN();
    switch (kind) {
    case CurvatureKind::gaussian:
        return k->gaussian;
    case CurvatureKind::mean:
        return k->mean;
    case CurvatureKind::k_max:
        return k->k1;
    case CurvatureKind::k_min:
        return k->k2;
    }
    return k->gaussian;
}

} // namespace isoparm::geom::implicit
