// Trim loops: naming, exact lines, arcs and polygons, reversal and affine maps.
#include "core/geom/trim/trim.hpp"

#include <cassert>
#include <cmath>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/primitives.hpp"

namespace isoparm::geom {

const TrimLoop& Trim::loop(int k) const {
    assert(k >= 0 && k < loop_count());
    if (outer) return k == 0 ? *outer : holes[static_cast<std::size_t>(k - 1)];
    return holes[static_cast<std::size_t>(k)];
}

std::string loop_name(const Trim& t, int k) {
    if (t.is_outer(k)) return "the outer loop";
    return "hole " + std::to_string(t.outer ? k - 1 : k);
}

std::string loop_path(const Trim& t, int k) {
    if (t.is_outer(k)) return "/outer";
    return "/holes" + pointer_step(t.outer ? k - 1 : k);
}

glm::dvec2 uv(const glm::dvec3& p) {
    return {p.x, p.y};
}

std::optional<glm::dvec2> curve_start(const Curve& c) {
    const auto p = curve_point(c, domain(c).lo);
    if (!p) return std::nullopt;
    return uv(*p);
}

std::optional<glm::dvec2> curve_end(const Curve& c) {
    const auto p = curve_point(c, domain(c).hi);
    if (!p) return std::nullopt;
    return uv(*p);
}

Curve trim_line(glm::dvec2 a, glm::dvec2 b) {
    Curve c;
    c.type = SplineType::bspline;
    c.degree = 1;
    c.knots = {0, 0, 1, 1};
    c.points = {{a, 0.0}, {b, 0.0}};
    c.weights = {1, 1};
    return c;
}

Expected<Curve> trim_arc(glm::dvec2 centre, double radius, double start_degrees,
                         double end_degrees) {
    const bool clockwise = end_degrees < start_degrees;
    auto arc = clockwise
                   ? circular_arc({centre, 0.0}, radius, end_degrees, start_degrees, Plane::xy)
                   : circular_arc({centre, 0.0}, radius, start_degrees, end_degrees, Plane::xy);
    if (!arc) return arc.error();
    if (clockwise) return reversed(*arc);
    return arc;
}

TrimLoop polygon_loop(const std::vector<glm::dvec2>& corners) {
    TrimLoop loop;
    const std::size_t n = corners.size();
    for (std::size_t k = 0; k < n; ++k)
        loop.curves.push_back(trim_line(corners[k], corners[(k + 1) % n]));
    return loop;
}

TrimLoop smooth_loop(const std::vector<glm::dvec2>& control) {
    TrimLoop loop;
    const std::size_t n = control.size();
    auto P = [&](std::size_t k) { return control[k % n]; };
    for (std::size_t i = 0; i < n; ++i) {
        // The span between P_i and P_(i+1): its Bezier points divide the legs in thirds and
        // sit at the neighbouring legs' weighted middles (Farin, ch. 7; uniform knots).
        const glm::dvec2 a = P(i + n - 1), b = P(i), c = P(i + 1), d = P(i + 2);
        Curve piece;
        piece.degree = 3;
        piece.knots = bezier_knots(3);
        for (const glm::dvec2 q : {(a + 4.0 * b + c) / 6.0, (2.0 * b + c) / 3.0,
                                   (b + 2.0 * c) / 3.0, (b + 4.0 * c + d) / 6.0})
            piece.points.push_back({q, 0.0});
        piece.weights.assign(4, 1.0);
        loop.curves.push_back(std::move(piece));
    }
    return loop;
}

Expected<TrimLoop> circle_loop(glm::dvec2 centre, double radius, bool clockwise) {
    auto circle = circular_arc({centre, 0.0}, radius, 0.0, 360.0, Plane::xy);
    if (!circle) return circle.error();
    TrimLoop loop;
    loop.curves.push_back(clockwise ? reversed(*circle) : *circle);
    return loop;
}

TrimLoop rectangle_loop(const ParamRect& r) {
    return polygon_loop({{r.u.lo, r.v.lo}, {r.u.hi, r.v.lo}, {r.u.hi, r.v.hi}, {r.u.lo, r.v.hi}});
}

Curve reversed(const Curve& c) {
    Curve r = c;
    const std::size_t m = c.knots.size();
    const double a = c.knots.front(), b = c.knots.back();
    // Equal knots map to equal knots (the same arithmetic), and the ends exactly to the ends.
    for (std::size_t k = 0; k < m; ++k) {
        const double t = c.knots[m - 1 - k];
        r.knots[k] = t == a ? b : t == b ? a : a + b - t;
    }
    r.points.assign(c.points.rbegin(), c.points.rend());
    r.weights.assign(c.weights.rbegin(), c.weights.rend());
    return r;
}

TrimLoop reversed(const TrimLoop& loop) {
    TrimLoop r;
    for (auto it = loop.curves.rbegin(); it != loop.curves.rend(); ++it)
        r.curves.push_back(reversed(*it));
    return r;
}

Trim map_affine(const Trim& t, glm::dvec2 scale, glm::dvec2 offset) {
    assert(scale.x > 0 && scale.y > 0);
    auto map_loop = [&](TrimLoop loop) {
        for (Curve& c : loop.curves)
            for (glm::dvec3& p : c.points) {
                p.x = scale.x * p.x + offset.x;
                p.y = scale.y * p.y + offset.y;
            }
        return loop;
    };
    Trim out;
    if (t.outer) out.outer = map_loop(*t.outer);
    for (const TrimLoop& h : t.holes) out.holes.push_back(map_loop(h));
    return out;
}

} // namespace isoparm::geom
