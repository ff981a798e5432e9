// Trimmed surface area by quadrature on the trimmed domain's triangulation.
#include "core/geom/trim/trim_area.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/trim/trim_triangulate.hpp"

namespace isoparm::geom {

namespace {

// Every distinct knot inside [lo, hi], each span cut into equal pieces so that the whole
// direction has at least `pieces` (the integrand is smooth between knots).
std::vector<double> knot_grid(const Knots& U, Interval d, int pieces) {
    std::vector<double> breaks{d.lo};
    for (const KnotRun& r : knot_runs(U))
        if (r.value > d.lo && r.value < d.hi) breaks.push_back(r.value);
    breaks.push_back(d.hi);
    std::vector<double> out;
    const double width = d.hi - d.lo;
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
        const double a = breaks[k], b = breaks[k + 1];
        const int m = std::max(1, static_cast<int>(std::ceil(pieces * (b - a) / width)));
        for (int i = 0; i < m; ++i) out.push_back(i == 0 ? a : a + (b - a) * i / m);
    }
    out.push_back(d.hi);
    return out;
}

// Dunavant's degree-5 rule: barycentric points and weights (summing to 1).
struct QuadraturePoint {
    double a, b, c, w;
};
constexpr double a1 = 0.059715871789770, b1 = 0.470142064105115;
constexpr double a2 = 0.797426985353087, b2 = 0.101286507323456;
constexpr double w0 = 0.225, w1 = 0.132394152788506, w2 = 0.125939180544827;
constexpr std::array<QuadraturePoint, 7> dunavant5{{
    {1.0 / 3, 1.0 / 3, 1.0 / 3, w0},
    {a1, b1, b1, w1},
    {b1, a1, b1, w1},
    {b1, b1, a1, w1},
    {a2, b2, b2, w2},
    {b2, a2, b2, w2},
    {b2, b2, a2, w2},
}};

// The signed area between a curve piece and its chord, (1/2) closed integral of x dy - y dx
// along the piece from a and back along the chord (Green's theorem), by 8-point Gauss-Legendre:
// positive where the piece bulges to the chord's right (outward from a loop's kept side).
double sliver_area(const Curve& c, double t0, double t1, glm::dvec2 a) {
    static constexpr std::array<double, 4> x{0.1834346424956498, 0.5255324099163290,
                                             0.7966664774136267, 0.9602898564975363};
    static constexpr std::array<double, 4> w{0.3626837833783620, 0.3137066458778873,
                                             0.2223810344533745, 0.1012285362903763};
    double sum = 0;
    const double mid = 0.5 * (t0 + t1), half = 0.5 * (t1 - t0);
    for (std::size_t k = 0; k < 4; ++k) {
        for (double sgn : {-1.0, 1.0}) {
            const auto d = curve_derivatives(c, mid + sgn * half * x[k], 1);
            if (!d) continue;
            const glm::dvec2 p = uv((*d)[0]) - a, dp = uv((*d)[1]);
            sum += w[k] * half * (p.x * dp.y - p.y * dp.x);
        }
    }
    // Back along the chord from b to a (relative to a): (b - a) x 0 contributes nothing.
    return 0.5 * sum;
}

// The same surface and trim with v scaled about the domain's start by k (knots and loop control
// points: an affine map of the parameter, so the same piece of surface).
void scale_v(Surface& s, Trim& trim, double k) {
    const double v0 = domain(s).v.lo;
    for (double& t : s.knots_v) t = v0 + (t - v0) * k;
    const auto scale_loop = [&](TrimLoop& loop) {
        for (Curve& c : loop.curves)
            for (glm::dvec3& p : c.points) p.y = v0 + (p.y - v0) * k;
    };
    if (trim.outer) scale_loop(*trim.outer);
    for (TrimLoop& hole : trim.holes) scale_loop(hole);
}

double area_on_layout(const Surface& s, const Trim& trim, int pieces);

} // namespace

// A domain much wider in one direction than the other (bug23171_tube_surf.igs's half tube: u
// over 3.14, v over 1350) gives the layout cells 400 times longer than wide, and the quadrature
// loses its order there (2.5e-4 low at 96 pieces, 6e-5 at 384): the area, which does not depend
// on the parameters, is taken with v scaled to u's width. Domains within a factor 4 of square
// are left as they are.
double trimmed_area(const Surface& s, const Trim& trim, int pieces) {
    const ParamRect d = domain(s);
    const double wu = d.u.hi - d.u.lo, wv = d.v.hi - d.v.lo;
    if (wu > 0 && wv > 0 && (wv > 4 * wu || wu > 4 * wv)) {
        Surface scaled = s;
        Trim scaled_trim = trim;
        scale_v(scaled, scaled_trim, wu / wv);
        return area_on_layout(scaled, scaled_trim, pieces);
    }
    return area_on_layout(s, trim, pieces);
}

namespace {

double area_on_layout(const Surface& s, const Trim& trim, int pieces) {
    const ParamRect d = domain(s);
    FlattenRule rule;
    rule.tolerance = 1e-6 * domain_scale(d);
    const auto us = knot_grid(s.knots_u, d.u, pieces);
    const auto vs = knot_grid(s.knots_v, d.v, pieces);
    rule.max_length = std::max(d.u.hi - d.u.lo, d.v.hi - d.v.lo) / pieces;
    const TrimmedLayout layout = triangulate_trimmed(us, vs, trim, d, rule);
    auto jacobian = [&](glm::dvec2 p) {
        const double u = std::clamp(p.x, d.u.lo, d.u.hi), v = std::clamp(p.y, d.v.lo, d.v.hi);
        const auto der = surface_derivatives(s, u, v, 1);
        return der ? glm::length(glm::cross(der->D[1][0], der->D[0][1])) : 0.0;
    };
    double area = 0;
    for (const auto& t : layout.triangles) {
        const glm::dvec2 p0 = layout.param(t[0]), p1 = layout.param(t[1]), p2 = layout.param(t[2]);
        const double jac =
            0.5 * std::abs((p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x));
        double sum = 0;
        for (const QuadraturePoint& q : dunavant5)
            sum += q.w * jacobian(q.a * p0 + q.b * p1 + q.c * p2);
        area += jac * sum;
    }
    // The slivers between the chords and the curves, each weighted by |S_u x S_v| at the
    // curve's middle: the chords' polygon misses them (the same chords as the layout's).
    for (int l = 0; l < trim.loop_count(); ++l) {
        const TrimLoop& loop = trim.loop(l);
        const FlatLoop flat = flatten_loop(loop, rule);
        const std::size_t n = flat.points.size();
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t next = (k + 1) % n;
            const Curve& c = loop.curves[static_cast<std::size_t>(flat.curve[k])];
            const double t0 = flat.param[k];
            const double t1 =
                flat.curve[next] == flat.curve[k] && next != 0 ? flat.param[next] : domain(c).hi;
            const glm::dvec2 a = flat.points[k];
            const auto mid = curve_point(c, 0.5 * (t0 + t1));
            if (!mid) continue;
            area += jacobian(uv(*mid)) * sliver_area(c, t0, t1, a);
        }
    }
    return area;
}

} // namespace

} // namespace isoparm::geom
