// Curve and surface points, derivatives and normals (Piegl & Tiller A3.2, A3.6, A4.2, A4.4).
#include "core/geom/evaluate.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/basis.hpp"
#include "core/geom/binomial.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/small_buffer.hpp"

namespace isoparm::geom {

namespace {

// |S_u x S_v| below this fraction of max(|S_u|, |S_v|)^2 counts as degenerate. Measured
// against the larger derivative, not |S_u| |S_v|: at a pole one derivative is rounding noise
// (1e-17, not 0) and its cross product with the other has a meaningless direction.
constexpr double degenerate_ratio = 1e-10;

} // namespace

std::optional<std::vector<glm::dvec3>> curve_derivatives(const Curve& c, double t, int d) {
    const int p = c.degree, n = c.count();
    const int span = find_span(c.knots, p, n, t);
    SmallBuffer<double, 64> ders(static_cast<size_t>(d + 1) * (p + 1));
    ders_basis_funs(span, t, p, d, c.knots, ders.data());
    // A3.2 on homogeneous points: A^(k) and w^(k).
    std::vector<HPoint> Aw(d + 1, HPoint(0.0));
    for (int k = 0; k <= d; ++k)
        for (int r = 0; r <= p; ++r) Aw[k] += ders[k * (p + 1) + r] * c.hpoint(span - p + r);
    if (Aw[0].w == 0.0) return std::nullopt;
    // A4.2: C^(k) = (A^(k) - sum_{i=1..k} C(k,i) w^(i) C^(k-i)) / w.
    std::vector<glm::dvec3> C(d + 1);
    for (int k = 0; k <= d; ++k) {
        glm::dvec3 v(Aw[k]);
        for (int i = 1; i <= k; ++i) v -= binomial(k, i) * Aw[i].w * C[k - i];
        C[k] = v / Aw[0].w;
    }
    return C;
}

std::optional<glm::dvec3> curve_point(const Curve& c, double t) {
    auto d = curve_derivatives(c, t, 0);
    if (!d) return std::nullopt;
    return (*d)[0];
}

std::optional<SurfaceDerivatives> surface_derivatives(const Surface& s, double u, double v, int d) {
    assert(d >= 0 && d <= max_derivative_order);
    const int p = s.degree_u, q = s.degree_v;
    const int su = find_span(s.knots_u, p, s.n_u, u);
    const int sv = find_span(s.knots_v, q, s.n_v, v);
    SmallBuffer<double, 64> Nu(static_cast<size_t>(d + 1) * (p + 1)),
        Nv(static_cast<size_t>(d + 1) * (q + 1));
    ders_basis_funs(su, u, p, d, s.knots_u, Nu.data());
    ders_basis_funs(sv, v, q, d, s.knots_v, Nv.data());
    // A3.6 on homogeneous points.
    HPoint Aw[max_derivative_order + 1][max_derivative_order + 1] = {};
    SmallBuffer<HPoint, 16> temp(static_cast<size_t>(q) + 1);
    for (int k = 0; k <= d; ++k) {
        for (int b = 0; b <= q; ++b) {
            temp[b] = HPoint(0.0);
            for (int a = 0; a <= p; ++a)
                temp[b] += Nu[k * (p + 1) + a] * s.hpoint(su - p + a, sv - q + b);
        }
        for (int l = 0; l + k <= d; ++l) {
            Aw[k][l] = HPoint(0.0);
            for (int b = 0; b <= q; ++b) Aw[k][l] += Nv[l * (q + 1) + b] * temp[b];
        }
    }
    if (Aw[0][0].w == 0.0) return std::nullopt;
    // A4.4: the rational quotient rule in two variables.
    SurfaceDerivatives out;
    auto& S = out.D;
    const double w = Aw[0][0].w;
    for (int k = 0; k <= d; ++k) {
        for (int l = 0; l + k <= d; ++l) {
            glm::dvec3 val(Aw[k][l]);
            for (int j = 1; j <= l; ++j) val -= binomial(l, j) * Aw[0][j].w * S[k][l - j];
            for (int i = 1; i <= k; ++i) {
                val -= binomial(k, i) * Aw[i][0].w * S[k - i][l];
                glm::dvec3 v2(0.0);
                for (int j = 1; j <= l; ++j) v2 += binomial(l, j) * Aw[i][j].w * S[k - i][l - j];
                val -= binomial(k, i) * v2;
            }
            S[k][l] = val / w;
        }
    }
    return out;
}

std::optional<glm::dvec3> surface_point(const Surface& s, double u, double v) {
    auto d = surface_derivatives(s, u, v, 0);
    if (!d) return std::nullopt;
    return d->D[0][0];
}

std::optional<glm::dvec3> normal_from_derivatives(const SurfaceDerivatives& d) {
    const glm::dvec3& Su = d.D[1][0];
    const glm::dvec3& Sv = d.D[0][1];
    const glm::dvec3 n = glm::cross(Su, Sv);
    const double len = glm::length(n);
    const double big = std::max(glm::length(Su), glm::length(Sv));
    if (!(len > degenerate_ratio * big * big) || !std::isfinite(len)) return std::nullopt;
    return n / len;
}

std::optional<glm::dvec3> limit_normal_from_derivatives(const SurfaceDerivatives& d, double du,
                                                        double dv) {
    // First-order expansion of S_u x S_v about the point:
    // d/du (S_u x S_v) = S_uu x S_v + S_u x S_uv,  d/dv (S_u x S_v) = S_uv x S_v + S_u x S_vv.
    const glm::dvec3 &Su = d.D[1][0], &Sv = d.D[0][1], &Suu = d.D[2][0], &Suv = d.D[1][1],
                     &Svv = d.D[0][2];
    const glm::dvec3 Cu = glm::cross(Suu, Sv) + glm::cross(Su, Suv);
    const glm::dvec3 Cv = glm::cross(Suv, Sv) + glm::cross(Su, Svv);
    const glm::dvec3 n = du * Cu + dv * Cv;
    const double len = glm::length(n);
    const double scale = glm::length(Suu) * glm::length(Sv) + glm::length(Su) * glm::length(Suv) +
                         glm::length(Suv) * glm::length(Sv) + glm::length(Su) * glm::length(Svv);
    if (!(len > degenerate_ratio * scale) || !std::isfinite(len)) return std::nullopt;
    return n / len;
}

std::optional<glm::dvec3> surface_normal(const Surface& s, double u, double v) {
    auto d = surface_derivatives(s, u, v, 1);
    if (!d) return std::nullopt;
    return normal_from_derivatives(*d);
}

glm::dvec3 surface_normal_or_limit(const Surface& s, double u, double v) {
    auto d = surface_derivatives(s, u, v, 2);
    if (d) {
        if (auto n = normal_from_derivatives(*d)) return *n;
    }
    const Interval du_dom = domain(s, Dir::u);
    const Interval dv_dom = domain(s, Dir::v);
    // Approach from inside the domain: towards its centre in each direction.
    const double du = u < 0.5 * (du_dom.lo + du_dom.hi) ? 1.0 : -1.0;
    const double dv = v < 0.5 * (dv_dom.lo + dv_dom.hi) ? 1.0 : -1.0;
    const bool u_end = u == du_dom.lo || u == du_dom.hi;
    const bool v_end = v == dv_dom.lo || v == dv_dom.hi;
    if (d) {
        // At an edge only the direction across the edge leads inside; at a corner both do.
        const double eu = u_end || !v_end ? du : 0.0;
        const double ev = v_end || !u_end ? dv : 0.0;
        if (auto n = limit_normal_from_derivatives(*d, eu, ev)) return *n;
    }
    // Higher-order degeneracy: a nearby point inside the domain.
    for (double step : {1e-7, 1e-5, 1e-3}) {
        const double uu = u + du * step * (du_dom.hi - du_dom.lo);
        const double vv = v + dv * step * (dv_dom.hi - dv_dom.lo);
        if (auto n = surface_normal(s, uu, vv)) return *n;
    }
    return {0.0, 0.0, 1.0};
}

} // namespace isoparm::geom
