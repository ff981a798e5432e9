// Uniform-grid tessellation: basis functions cached per row and column, then a tensor
// contraction per vertex (positions and first derivatives for normals).
#include "core/geom/tessellate.hpp"

#include <cassert>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/basis.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::geom {

std::vector<double> uniform_params(double a, double b, int n) {
    std::vector<double> t(n);
    for (int i = 0; i < n; ++i) t[i] = a + (b - a) * i / (n - 1);
    t.front() = a;
    t.back() = b;
    return t;
}

namespace {

// The spans and the values and first derivatives of the p + 1 non-zero basis functions at
// each sample parameter.
struct BasisTable {
    int p = 0;
    std::vector<int> span;
    std::vector<double> N, dN; // (p + 1) per sample
};

BasisTable tabulate(const Knots& U, int p, int n, const std::vector<double>& params) {
    BasisTable t;
    t.p = p;
    t.span.resize(params.size());
    t.N.resize(params.size() * (p + 1));
    t.dN.resize(params.size() * (p + 1));
    std::vector<double> ders(2 * (static_cast<size_t>(p) + 1));
    for (size_t k = 0; k < params.size(); ++k) {
        t.span[k] = find_span(U, p, n, params[k]);
        ders_basis_funs(t.span[k], params[k], p, 1, U, ders.data());
        std::copy(ders.begin(), ders.begin() + p + 1, t.N.begin() + k * (p + 1));
        std::copy(ders.begin() + p + 1, ders.end(), t.dN.begin() + k * (p + 1));
    }
    return t;
}

} // namespace

Mesh tessellate(const Surface& s, int samples_u, int samples_v) {
    assert(samples_u >= 2 && samples_v >= 2);
    const int p = s.degree_u, q = s.degree_v;
    const Interval du = domain(s.knots_u, p, s.n_u), dv = domain(s.knots_v, q, s.n_v);
    const std::vector<double> us = uniform_params(du.lo, du.hi, samples_u);
    const std::vector<double> vs = uniform_params(dv.lo, dv.hi, samples_v);
    const BasisTable tu = tabulate(s.knots_u, p, s.n_u, us);
    const BasisTable tv = tabulate(s.knots_v, q, s.n_v, vs);

    std::vector<HPoint> Pw(s.points.size());
    for (size_t k = 0; k < Pw.size(); ++k) Pw[k] = to_homogeneous(s.points[k], s.weights[k]);

    Mesh mesh;
    const size_t count = static_cast<size_t>(samples_u) * samples_v;
    mesh.positions.resize(count);
    mesh.normals.resize(count);
    mesh.exists.assign(count, 1);
    std::vector<HPoint> Q(s.n_v), dQ(s.n_v); // row contracted in u, and its u-derivative
    for (int i = 0; i < samples_u; ++i) {
        const double* Nu = &tu.N[static_cast<size_t>(i) * (p + 1)];
        const double* dNu = &tu.dN[static_cast<size_t>(i) * (p + 1)];
        const int row0 = tu.span[i] - p;
        for (int j = 0; j < s.n_v; ++j) {
            HPoint a(0.0), b(0.0);
            for (int r = 0; r <= p; ++r) {
                const HPoint& P = Pw[s.index(row0 + r, j)];
                a += Nu[r] * P;
                b += dNu[r] * P;
            }
            Q[j] = a;
            dQ[j] = b;
        }
        for (int j = 0; j < samples_v; ++j) {
            const double* Nv = &tv.N[static_cast<size_t>(j) * (q + 1)];
            const double* dNv = &tv.dN[static_cast<size_t>(j) * (q + 1)];
            const int col0 = tv.span[j] - q;
            HPoint A(0.0), Au(0.0), Av(0.0);
            for (int r = 0; r <= q; ++r) {
                A += Nv[r] * Q[col0 + r];
                Au += Nv[r] * dQ[col0 + r];
                Av += dNv[r] * Q[col0 + r];
            }
            const size_t k = static_cast<size_t>(i) * samples_v + j;
            if (A.w == 0.0) {
                mesh.exists[k] = 0;
                mesh.positions[k] = glm::dvec3(0.0);
                mesh.normals[k] = glm::dvec3(0.0, 0.0, 1.0);
                continue;
            }
            // Quotient rule (A4.4 to first order): S = A / w, S_u = (A_u - w_u S) / w.
            const glm::dvec3 S = glm::dvec3(A) / A.w;
            SurfaceDerivatives d;
            d.D[0][0] = S;
            d.D[1][0] = (glm::dvec3(Au) - Au.w * S) / A.w;
            d.D[0][1] = (glm::dvec3(Av) - Av.w * S) / A.w;
            mesh.positions[k] = S;
            auto n = normal_from_derivatives(d);
            mesh.normals[k] = n ? *n : surface_normal_or_limit(s, us[i], vs[j]);
        }
    }
    mesh.triangles.reserve(2 * static_cast<size_t>(samples_u - 1) * (samples_v - 1));
    for (int i = 0; i + 1 < samples_u; ++i) {
        for (int j = 0; j + 1 < samples_v; ++j) {
            const auto k = static_cast<std::uint32_t>(i * samples_v + j);
            const auto nv = static_cast<std::uint32_t>(samples_v);
            const std::array<std::uint32_t, 3> t0{k, k + nv, k + nv + 1}, t1{k, k + nv + 1, k + 1};
            for (const auto& t : {t0, t1})
                if (mesh.exists[t[0]] && mesh.exists[t[1]] && mesh.exists[t[2]])
                    mesh.triangles.push_back(t);
        }
    }
    return mesh;
}

} // namespace isoparm::geom
