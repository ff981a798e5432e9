#include "core/geom/curvature.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>

#include "core/geom/knots.hpp"
#include "core/geom/tessellate.hpp"

namespace isoparm::geom {

namespace {

// A vector is taken as zero when it is this small relative to the magnitudes it was formed
// from: rounding leaves ~1e-16 relative residue where the exact value is zero (a straight
// line's C' x C'').
constexpr double relative_zero = 1e-12;

// An eigenvector (a, b) of the shape operator for eigenvalue k, in the (S_u, S_v) basis:
// (II - k I) (a, b) = 0. Either row of the singular 2x2 matrix gives it; the longer one is
// the better conditioned.
glm::dvec2 principal_coefficients(double L, double M, double N, double E, double F, double G,
                                  double k) {
    const double a = L - k * E, b = M - k * F, c = N - k * G;
    const glm::dvec2 from_first(-b, a), from_second(c, -b);
    return glm::dot(from_first, from_first) >= glm::dot(from_second, from_second) ? from_first
                                                                                  : from_second;
}

} // namespace

std::optional<SurfaceCurvature> curvature_from_derivatives(const SurfaceDerivatives& d) {
    const std::optional<glm::dvec3> normal = normal_from_derivatives(d);
    if (!normal) return std::nullopt;
    const glm::dvec3 n = *normal;
    const glm::dvec3 &Su = d.D[1][0], &Sv = d.D[0][1];
    // The first and second fundamental forms (do Carmo 3-3).
    const double E = glm::dot(Su, Su), F = glm::dot(Su, Sv), G = glm::dot(Sv, Sv);
    const double L = glm::dot(d.D[2][0], n), M = glm::dot(d.D[1][1], n), N = glm::dot(d.D[0][2], n);
    const double det_I = E * G - F * F;
    if (!(det_I > 0) || !std::isfinite(det_I)) return std::nullopt;
    SurfaceCurvature k;
    k.gaussian = (L * N - M * M) / det_I;
    k.mean = (E * N - 2 * F * M + G * L) / (2 * det_I);
    const double spread = std::sqrt(std::max(k.mean * k.mean - k.gaussian, 0.0));
    k.k1 = k.mean + spread;
    k.k2 = k.mean - spread;
    if (!std::isfinite(k.gaussian) || !std::isfinite(k.mean) || !std::isfinite(k.k1))
        return std::nullopt;

    // d1 from the eigenvector of k1; at an umbilic (every direction principal) S_u.
    const glm::dvec2 ab = principal_coefficients(L, M, N, E, F, G, k.k1);
    glm::dvec3 d1 = ab.x * Su + ab.y * Sv;
    const double scale =
        std::max({std::abs(L), std::abs(M), std::abs(N), std::abs(k.k1) * E, std::abs(k.k1) * G}) *
        std::sqrt(std::max(E, G));
    if (!(glm::length(d1) > relative_zero * scale)) d1 = Su;
    // Remove any normal component rounding left, so that d1, d2 and n are orthonormal.
    d1 -= glm::dot(d1, n) * n;
    k.d1 = glm::normalize(d1);
    k.d2 = glm::cross(n, k.d1);
    return k;
}

std::optional<SurfaceCurvature> surface_curvature(const Surface& s, double u, double v) {
    const std::optional<SurfaceDerivatives> d = surface_derivatives(s, u, v, 2);
    if (!d) return std::nullopt;
    return curvature_from_derivatives(*d);
}

std::optional<CurveCurvature> curve_curvature(const Curve& c, double t) {
    const auto C = curve_derivatives(c, t, 3);
    if (!C) return std::nullopt;
    const glm::dvec3 &d1 = (*C)[1], &d2 = (*C)[2], &d3 = (*C)[3];
    CurveCurvature k;
    const double speed = glm::length(d1);
    if (!(speed > 0) || !std::isfinite(speed)) return k;
    k.tangent = d1 / speed;
    const glm::dvec3 b = glm::cross(d1, d2);
    const double b_length = glm::length(b);
    k.curvature = b_length / (speed * speed * speed);
    if (!(b_length > relative_zero * speed * glm::length(d2))) {
        k.curvature = 0.0; // a straight piece: C'' is parallel to C' (or zero)
        return k;
    }
    // Frenet-Serret: B = C' x C'' / |C' x C''|, N = B x T, tau = (C' x C'') . C''' / |C' x C''|^2.
    k.binormal = b / b_length;
    k.normal = glm::cross(*k.binormal, *k.tangent);
    k.torsion = glm::dot(b, d3) / (b_length * b_length);
    return k;
}

std::vector<double> curvature_grid(const Surface& s, int samples_u, int samples_v,
                                   CurvatureKind kind, std::size_t first, std::size_t count) {
    const Interval du = domain(s, Dir::u), dv = domain(s, Dir::v);
    const std::vector<double> us = uniform_params(du.lo, du.hi, samples_u);
    const std::vector<double> vs = uniform_params(dv.lo, dv.hi, samples_v);
    const std::size_t total = static_cast<std::size_t>(samples_u) * samples_v;
    const std::size_t end = first + std::min(count, total - std::min(first, total));
    std::vector<double> out;
    out.reserve(end - std::min(first, end));
    for (std::size_t k = first; k < end; ++k) {
        const auto c = surface_curvature(s, us[k / samples_v], vs[k % samples_v]);
        if (!c) {
            out.push_back(std::numeric_limits<double>::quiet_NaN());
            continue;
        }
        switch (kind) {
        case CurvatureKind::gaussian:
            out.push_back(c->gaussian);
            break;
        case CurvatureKind::mean:
            out.push_back(c->mean);
            break;
        case CurvatureKind::k_max:
            out.push_back(c->k1);
            break;
        case CurvatureKind::k_min:
            out.push_back(c->k2);
            break;
        }
    }
    return out;
}

} // namespace isoparm::geom
