#include "core/geom/triangle.hpp"

#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/binomial.hpp"

namespace isoparm::geom {

namespace {

// Up to this degree bernstein_triangle multiplies (3^n < 2^53 keeps the coefficient exact);
// above it, logarithms.
constexpr int exact_bernstein_degree = 32;

using Net = std::vector<HPoint>; // a triangular net of some degree m, in the patch's order

Net homogeneous(const TrianglePatch& t) {
    Net net(t.points.size());
    for (std::size_t k = 0; k < net.size(); ++k) net[k] = to_homogeneous(t.points[k], t.weights[k]);
    return net;
}

int degree_of(const Net& net) {
    int m = 0;
    while (TrianglePatch::count_for(m) < static_cast<int>(net.size())) ++m;
    return m;
}

// One de Casteljau step: b^(l+1)_ijk = r b^l_(i+1)jk + s b^l_i(j+1)k + t b^l_ij(k+1).
Net step(const Net& net, const Barycentric& p) {
    const int m = degree_of(net) - 1;
    Net next(static_cast<std::size_t>(TrianglePatch::count_for(m)));
    for (int i = m; i >= 0; --i)
        for (int j = m - i; j >= 0; --j)
            next[TrianglePatch::index(m, i, j)] =
                p[0] * net[TrianglePatch::index(m + 1, i + 1, j)] +
                p[1] * net[TrianglePatch::index(m + 1, i, j + 1)] +
                p[2] * net[TrianglePatch::index(m + 1, i, j)];
    return next;
}

HPoint apex(Net net, const Barycentric& p) {
    while (net.size() > 1) net = step(net, p);
    return net[0];
}

// The difference net along r (or s) with t = 1 - r - s: b_(i+1)jk - b_ij(k+1) (b_i(j+1)k -
// b_ij(k+1)), degree m - 1; the derivative is m times its value.
Net difference(const Net& net, bool along_r) {
    const int m = degree_of(net) - 1;
    Net out(static_cast<std::size_t>(TrianglePatch::count_for(m)));
    for (int i = m; i >= 0; --i)
        for (int j = m - i; j >= 0; --j) {
            const HPoint& ahead = along_r ? net[TrianglePatch::index(m + 1, i + 1, j)]
                                          : net[TrianglePatch::index(m + 1, i, j + 1)];
            out[TrianglePatch::index(m, i, j)] = ahead - net[TrianglePatch::index(m + 1, i, j)];
        }
    return out;
}

std::optional<glm::dvec3> cartesian(const HPoint& h) {
    if (h.w == 0.0) return std::nullopt;
    return glm::dvec3(h) / h.w;
}

} // namespace

Status validate_triangle(const TrianglePatch& t) {
    if (t.degree < 1)
        return make_error(ErrorCode::degree, "the degree must be at least 1", "/degree");
    if (t.degree > max_triangle_degree)
        return make_error(ErrorCode::limit,
                          "degree " + std::to_string(t.degree) + " is above the cap of " +
                              std::to_string(max_triangle_degree),
                          "/degree");
    const int want = TrianglePatch::count_for(t.degree);
    if (static_cast<int>(t.points.size()) != want)
        return make_error(ErrorCode::schema,
                          "a triangle of degree " + std::to_string(t.degree) + " has " +
                              std::to_string(want) + " control points, got " +
                              std::to_string(t.points.size()),
                          "/points");
    for (std::size_t k = 0; k < t.points.size(); ++k)
        for (int a = 0; a < 3; ++a)
            if (!std::isfinite(t.points[k][a]))
                return make_error(ErrorCode::schema, "a coordinate must be a finite number",
                                  "/points/" + std::to_string(k) + "/" + std::to_string(a));
    if (t.weights.size() != t.points.size())
        return make_error(ErrorCode::weights,
                          "one weight per control point: " + std::to_string(t.points.size()) +
                              " points, " + std::to_string(t.weights.size()) + " weights",
                          "/weights");
    for (std::size_t k = 0; k < t.weights.size(); ++k)
        if (!std::isfinite(t.weights[k]))
            return make_error(ErrorCode::weights, "a weight must be a finite number",
                              "/weights/" + std::to_string(k));
    return Ok{};
}

double bernstein_triangle(int n, int i, int j, const Barycentric& p) {
    const int power[3] = {i, j, n - i - j};
    if (n <= exact_bernstein_degree) {
        // n! / (i! j! k!) = C(n, i) C(n - i, j) is an integer below 3^n < 2^53: exact, and
        // so are the products at points like (1/2, 1/2, 0).
        double value = binomial(n, i) * binomial(n - i, j);
        for (int a = 0; a < 3; ++a)
            for (int e = 0; e < power[a]; ++e) value *= p[a];
        return value;
    }
    // log(n! / (i! j! k!)) + i log|r| + j log|s| + k log|t|, with the sign kept apart.
    double log_value = std::lgamma(n + 1.0);
    double sign = 1;
    for (int a = 0; a < 3; ++a) {
        log_value -= std::lgamma(power[a] + 1.0);
        if (power[a] == 0) continue; // x^0 = 1, also for x = 0
        if (p[a] == 0.0) return 0.0;
        if (p[a] < 0 && power[a] % 2 == 1) sign = -sign;
        log_value += power[a] * std::log(std::abs(p[a]));
    }
    return sign * std::exp(log_value);
}

double triangle_denominator(const TrianglePatch& t, const Barycentric& p) {
    const int n = t.degree;
    double denominator = 0;
    for (int a = n; a >= 0; --a)
        for (int b = n - a; b >= 0; --b)
            denominator +=
                t.weights[TrianglePatch::index(n, a, b)] * bernstein_triangle(n, a, b, p);
    return denominator;
}

std::optional<double> rational_bernstein_triangle(const TrianglePatch& t, int i, int j,
                                                  const Barycentric& p) {
    const int n = t.degree;
    const double denominator = triangle_denominator(t, p);
    if (denominator == 0.0) return std::nullopt;
    return t.weights[TrianglePatch::index(n, i, j)] * bernstein_triangle(n, i, j, p) / denominator;
}

std::optional<glm::dvec3> triangle_point(const TrianglePatch& t, const Barycentric& p) {
    return cartesian(apex(homogeneous(t), p));
}

std::optional<std::array<std::array<glm::dvec3, 3>, 3>>
triangle_derivatives(const TrianglePatch& t, const Barycentric& p, int d) {
    // Homogeneous derivatives H[a][b] = (n! / (n - a - b)!) x the difference net's value.
    const Net net = homogeneous(t);
    const int n = t.degree;
    HPoint H[3][3] = {};
    for (int a = 0; a <= d; ++a)
        for (int b = 0; a + b <= d; ++b) {
            if (a + b > n) continue; // a polynomial of degree n: zero beyond
            Net diff = net;
            double factor = 1;
            for (int k = 0; k < a; ++k) factor *= n - k, diff = difference(diff, true);
            for (int k = 0; k < b; ++k) factor *= n - a - k, diff = difference(diff, false);
            H[a][b] = factor * apex(diff, p);
        }
    const double w = H[0][0].w;
    if (w == 0.0) return std::nullopt;
    // Quotient rule (Piegl & Tiller eq. 4.20): S^(a,b) = (A^(a,b) - sum over (i,j) != (0,0) of
    // C(a,i) C(b,j) w^(i,j) S^(a-i,b-j)) / w.
    std::array<std::array<glm::dvec3, 3>, 3> S{};
    const double binomial[3][3] = {{1, 0, 0}, {1, 1, 0}, {1, 2, 1}};
    for (int a = 0; a <= d; ++a)
        for (int b = 0; a + b <= d; ++b) {
            glm::dvec3 v(H[a][b]);
            for (int i = 0; i <= a; ++i)
                for (int j = 0; j <= b; ++j)
                    if (i + j > 0)
                        v -= binomial[a][i] * binomial[b][j] * H[i][j].w * S[a - i][b - j];
            S[a][b] = v / w;
        }
    return S;
}

std::vector<std::vector<std::optional<glm::dvec3>>> triangle_de_casteljau(const TrianglePatch& t,
                                                                          const Barycentric& p) {
    // Level 0 is the control points as given (a division by the weight would round them).
    std::vector<std::vector<std::optional<glm::dvec3>>> levels(1);
    for (const glm::dvec3& b : t.points) levels[0].push_back(b);
    Net net = homogeneous(t);
    while (net.size() > 1) {
        net = step(net, p);
        auto& level = levels.emplace_back();
        for (const HPoint& h : net) level.push_back(cartesian(h));
    }
    return levels;
}

TrianglePatch elevate_triangle(const TrianglePatch& t, int times) {
    Net net = homogeneous(t);
    for (int e = 0; e < times; ++e) {
        // Farin 17.6: b'_ijk = (i b_(i-1)jk + j b_i(j-1)k + k b_ij(k-1)) / (m + 1), degree m + 1.
        const int m = degree_of(net), up = m + 1;
        Net next(static_cast<std::size_t>(TrianglePatch::count_for(up)));
        for (int i = up; i >= 0; --i)
            for (int j = up - i; j >= 0; --j) {
                const int k = up - i - j;
                HPoint sum(0.0);
                if (i > 0) sum += static_cast<double>(i) * net[TrianglePatch::index(m, i - 1, j)];
                if (j > 0) sum += static_cast<double>(j) * net[TrianglePatch::index(m, i, j - 1)];
                if (k > 0) sum += static_cast<double>(k) * net[TrianglePatch::index(m, i, j)];
                next[TrianglePatch::index(up, i, j)] = sum / static_cast<double>(up);
            }
        net = std::move(next);
    }
    TrianglePatch out;
    out.rational = t.rational;
    out.degree = t.degree + times;
    for (const HPoint& h : net) {
        out.weights.push_back(h.w);
        out.points.push_back(h.w != 0.0 ? glm::dvec3(h) / h.w : glm::dvec3(h));
    }
    return out;
}

Expected<std::array<TrianglePatch, 3>> split_triangle(const TrianglePatch& t,
                                                      const Barycentric& p) {
    // levels[l][index(n - l, i, j)] = b^l_ijk. Piece v takes, for its control point with index
    // a in place of vertex v, the level-a point whose v-th index is 0 (Farin 17.5).
    std::vector<Net> levels{homogeneous(t)};
    while (levels.back().size() > 1) levels.push_back(step(levels.back(), p));
    const int n = t.degree;
    std::array<TrianglePatch, 3> pieces;
    for (int v = 0; v < 3; ++v) {
        TrianglePatch& piece = pieces[v];
        piece.rational = t.rational;
        piece.degree = n;
        piece.points.resize(t.points.size());
        piece.weights.resize(t.points.size());
        for (int i = n; i >= 0; --i)
            for (int j = n - i; j >= 0; --j) {
                const int idx[3] = {i, j, n - i - j};
                const int level = idx[v];
                int sub[3] = {idx[0], idx[1], idx[2]};
                sub[v] = 0;
                const HPoint& h = levels[level][TrianglePatch::index(n - level, sub[0], sub[1])];
                if (h.w == 0.0 && glm::dvec3(h) != glm::dvec3(0.0))
                    return make_error(ErrorCode::weights,
                                      "splitting here puts a control point at infinity (a "
                                      "de Casteljau point of weight 0)",
                                      "/param");
                const int at = TrianglePatch::index(n, i, j);
                piece.weights[at] = h.w;
                piece.points[at] = h.w != 0.0 ? glm::dvec3(h) / h.w : glm::dvec3(h);
            }
    }
    return pieces;
}

Mesh tessellate_triangle(const TrianglePatch& t, int n) {
    Mesh mesh;
    for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j) {
            const Barycentric p = {static_cast<double>(i) / n, static_cast<double>(j) / n,
                                   static_cast<double>(n - i - j) / n};
            const auto D = triangle_derivatives(t, p, 1);
            if (!D) {
                if (mesh.exists.empty())
                    mesh.exists.assign(static_cast<std::size_t>(TrianglePatch::count_for(n)), 1);
                mesh.exists[mesh.positions.size()] = 0;
                mesh.positions.push_back(glm::dvec3(0.0));
                mesh.normals.push_back({0, 0, 1});
                continue;
            }
            const glm::dvec3 normal = glm::cross((*D)[1][0], (*D)[0][1]);
            const double length = glm::length(normal);
            mesh.positions.push_back((*D)[0][0]);
            mesh.normals.push_back(length > 0 ? normal / length : glm::dvec3(0, 0, 1));
        }
    // Grid cell below (i, j): vertices (i, j), (i - 1, j), (i - 1, j + 1) up, and the down
    // triangle beside it; ordered so that +r, +s turn counter-clockwise about S_r x S_s.
    auto at = [&](int i, int j) {
        return static_cast<std::uint32_t>(TrianglePatch::index(n, i, j));
    };
    auto usable = [&](std::uint32_t v) { return mesh.vertex_exists(v); };
    auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (usable(a) && usable(b) && usable(c)) mesh.triangles.push_back({a, b, c});
    };
    for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j) {
            add(at(i, j), at(i + 1, j), at(i, j + 1));
            if (i + j + 2 <= n) add(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
        }
    return mesh;
}

} // namespace isoparm::geom
