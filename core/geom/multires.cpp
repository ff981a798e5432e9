// Decomposition and reconstruction by the filter bank (Stollnitz, DeRose & Salesin, "Wavelets
// for computer graphics", sec. 2.2's filter bank: analysis A_j, B_j level by level from the
// finest, synthesis P_j, Q_j back up), and the rules an object must meet to have levels.
#include "core/geom/multires.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

#include "core/geom/wavelet_filters.hpp"

namespace isoparm::geom {

namespace {

std::string number_text(double x) {
    std::string s = std::to_string(x);
    while (s.size() > 1 && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
}

// Named so that no argument's namespace offers another (std::apply for a std::vector).
std::vector<glm::dvec3> multiply(const DenseMatrix& M, const std::vector<glm::dvec3>& x) {
    assert(static_cast<int>(x.size()) == M.cols);
    std::vector<glm::dvec3> out(M.rows, glm::dvec3(0.0));
    for (int r = 0; r < M.rows; ++r)
        for (int c = 0; c < M.cols; ++c)
            if (const double m = M(r, c); m != 0.0) out[r] += m * x[c];
    return out;
}

// 2^J + 3 = n with 1 <= J <= max_wavelet_level, or -1.
int level_of_count(int n) {
    for (int j = 1; j <= max_wavelet_level; ++j)
        if ((1 << j) + 3 == n) return j;
    return -1;
}

// A rational object with unequal weights is not a B-spline in its control points: the filters
// act on Cartesian points, which is exact only when every weight is the same.
Status check_equal_weights(SplineType type, const std::vector<double>& w, const std::string& what) {
    if (!is_rational(type)) return Ok{};
    for (std::size_t k = 1; k < w.size(); ++k)
        if (w[k] != w[0])
            return make_error(ErrorCode::weights,
                              what + " is " + label_of(type) + " with weight " + std::to_string(k) +
                                  " = " + number_text(w[k]) +
                                  " unlike weight 0 = " + number_text(w[0]) +
                                  ": multiresolution editing takes B-splines (equal weights)",
                              "/weights/" + std::to_string(k));
    return Ok{};
}

} // namespace

Expected<int> dyadic_level(const Knots& U, int degree, int n, const DyadicPaths& at,
                           const std::string& what) {
    if (degree != 3)
        return make_error(ErrorCode::degree,
                          what + " has degree " + std::to_string(degree) +
                              ": multiresolution editing takes cubics (degree 3)",
                          at.degree);
    const int J = level_of_count(n);
    if (J < 0)
        return make_error(ErrorCode::schema,
                          what + " has " + std::to_string(n) +
                              " control points: multiresolution needs 2^j + 3 of them (5, 7, 11, "
                              "19, 35, ..., " +
                              std::to_string((1 << max_wavelet_level) + 3) + ")",
                          at.count);
    const double a = U[3], b = U[U.size() - 4];
    const int spans = 1 << J;
    const double tolerance = 1e-9 * std::abs(b - a);
    for (int k = 0; k < static_cast<int>(U.size()); ++k) {
        const int step = std::clamp(k - 3, 0, spans);
        const double expected = step == spans ? b : a + (b - a) * step / spans;
        if (std::abs(U[k] - expected) > tolerance)
            return make_error(ErrorCode::knots,
                              what + "'s knot " + std::to_string(k) + " = " + number_text(U[k]) +
                                  " is not where clamped uniform knots put it (" +
                                  number_text(expected) +
                                  "): multiresolution needs endpoint-interpolating uniform knots",
                              at.knots + "/" + std::to_string(k));
    }
    return J;
}

Expected<int> multires_level(const Curve& c) {
    if (auto st = check_equal_weights(c.type, c.weights, "the curve"); !st) return st.error();
    return dyadic_level(c.knots, c.degree, c.count(), {"/degree", "/points", "/knots"},
                        "the curve");
}

Expected<std::pair<int, int>> multires_levels(const Surface& s) {
    if (auto st = check_equal_weights(s.type, s.weights, "the surface"); !st) return st.error();
    auto ju = dyadic_level(s.knots_u, s.degree_u, s.n_u, {"/degree_u", "/n_u", "/knots_u"},
                           "the surface in u");
    if (!ju) return ju.error();
    auto jv = dyadic_level(s.knots_v, s.degree_v, s.n_v, {"/degree_v", "/n_v", "/knots_v"},
                           "the surface in v");
    if (!jv) return jv.error();
    return std::pair{*ju, *jv};
}

CurveDecomposition decompose(const std::vector<glm::dvec3>& points, int from, int to) {
    assert(0 <= to && to <= from && static_cast<int>(points.size()) == (1 << from) + 3);
    CurveDecomposition d;
    d.level = to;
    d.details.resize(from - to);
    std::vector<glm::dvec3> c = points;
    for (int j = from; j > to; --j) {
        const WaveletFilters& f = cubic_wavelet_filters(j);
        d.details[j - 1 - to] = multiply(f.B, c);
        c = multiply(f.A, c);
    }
    d.coarse = std::move(c);
    return d;
}

std::vector<glm::dvec3> reconstruct(const CurveDecomposition& d) {
    std::vector<glm::dvec3> c = d.coarse;
    for (std::size_t k = 0; k < d.details.size(); ++k) {
        const WaveletFilters& f = cubic_wavelet_filters(d.level + static_cast<int>(k) + 1);
        std::vector<glm::dvec3> fine = multiply(f.P, c);
        const std::vector<glm::dvec3> detail = multiply(f.Q, d.details[k]);
        for (std::size_t r = 0; r < fine.size(); ++r) fine[r] += detail[r];
        c = std::move(fine);
    }
    return c;
}

SurfaceDecomposition decompose(const std::vector<glm::dvec3>& net, int from_u, int from_v, int to_u,
                               int to_v) {
    const int nu = (1 << from_u) + 3, nv = (1 << from_v) + 3;
    assert(static_cast<int>(net.size()) == nu * nv);
    SurfaceDecomposition d;
    d.level_u = to_u;
    d.level_v = to_v;
    d.n_u = (1 << to_u) + 3;
    d.n_v = (1 << to_v) + 3;
    // Along u on every line of constant j: coarse_u is n_u x nv.
    std::vector<glm::dvec3> coarse_u(static_cast<std::size_t>(d.n_u) * nv);
    for (int j = 0; j < nv; ++j) {
        std::vector<glm::dvec3> line(nu);
        for (int i = 0; i < nu; ++i) line[i] = net[i * nv + j];
        CurveDecomposition cd = decompose(line, from_u, to_u);
        for (int i = 0; i < d.n_u; ++i) coarse_u[i * nv + j] = cd.coarse[i];
        cd.coarse.clear();
        d.u_lines.push_back(std::move(cd));
    }
    // Then along v on every coarse u-line.
    d.coarse.resize(static_cast<std::size_t>(d.n_u) * d.n_v);
    for (int i = 0; i < d.n_u; ++i) {
        std::vector<glm::dvec3> line(coarse_u.begin() + i * nv, coarse_u.begin() + (i + 1) * nv);
        CurveDecomposition cd = decompose(line, from_v, to_v);
        for (int j = 0; j < d.n_v; ++j) d.coarse[i * d.n_v + j] = cd.coarse[j];
        cd.coarse.clear();
        d.v_lines.push_back(std::move(cd));
    }
    return d;
}

std::vector<glm::dvec3> reconstruct(const SurfaceDecomposition& d) {
    const int from_u = d.level_u + static_cast<int>(d.u_lines.front().details.size());
    const int from_v = d.level_v + static_cast<int>(d.v_lines.front().details.size());
    const int nu = (1 << from_u) + 3, nv = (1 << from_v) + 3;
    std::vector<glm::dvec3> coarse_u(static_cast<std::size_t>(d.n_u) * nv);
    for (int i = 0; i < d.n_u; ++i) {
        CurveDecomposition cd = d.v_lines[i];
        cd.coarse.assign(d.coarse.begin() + i * d.n_v, d.coarse.begin() + (i + 1) * d.n_v);
        const std::vector<glm::dvec3> line = reconstruct(cd);
        std::copy(line.begin(), line.end(), coarse_u.begin() + i * nv);
    }
    std::vector<glm::dvec3> net(static_cast<std::size_t>(nu) * nv);
    for (int j = 0; j < nv; ++j) {
        CurveDecomposition cd = d.u_lines[j];
        cd.coarse.resize(d.n_u);
        for (int i = 0; i < d.n_u; ++i) cd.coarse[i] = coarse_u[i * nv + j];
        const std::vector<glm::dvec3> line = reconstruct(cd);
        for (int i = 0; i < nu; ++i) net[i * nv + j] = line[i];
    }
    return net;
}

} // namespace isoparm::geom
