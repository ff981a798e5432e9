// Adaptive chords of trim loops: recursive halving of each knot span until the curve stays
// within the tolerance of its chord (in the domain, or on the surface in 3D).
#include "core/geom/trim/trim_flatten.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::geom {

namespace {

glm::dvec2 point_at(const Curve& c, double t) {
    const auto p = curve_point(c, t);
    assert(p); // positive weights: every point exists
    return p ? uv(*p) : glm::dvec2(0.0);
}

template <class V> double distance_to_segment(const V& p, const V& a, const V& b) {
    const V ab = b - a;
    const double len2 = glm::dot(ab, ab);
    if (len2 == 0.0) return glm::length(p - a);
    const double s = std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0);
    return glm::length(p - (a + s * ab));
}

// The surface point of a trim point, the parameter clamped into the surface's domain (a loop
// may stray outside it by the trim's closing tolerance).
glm::dvec3 surface_at(const Surface& s, const ParamRect& d, glm::dvec2 p) {
    const double u = std::clamp(p.x, d.u.lo, d.u.hi), v = std::clamp(p.y, d.v.lo, d.v.hi);
    return surface_point(s, u, v).value_or(glm::dvec3(0.0));
}

class Flattener {
public:
    Flattener(const FlattenRule& rule, FlatLoop& out)
        : rule_(rule), out_(out), domain_(rule.surface ? domain(*rule.surface) : ParamRect{}) {}

    void curve(const Curve& c, int index) {
        const auto runs = knot_runs(c.knots);
        const Interval d = domain(c);
        std::vector<double> breaks{d.lo};
        for (const KnotRun& r : runs)
            if (r.value > d.lo && r.value < d.hi) breaks.push_back(r.value);
        breaks.push_back(d.hi);
        const int pieces = c.degree > 1 ? 2 : 1;
        for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
            const double t0 = breaks[k], t1 = breaks[k + 1];
            for (int s = 0; s < pieces; ++s) {
                const double a = s == 0 ? t0 : t0 + (t1 - t0) * s / pieces;
                const double b = s + 1 == pieces ? t1 : t0 + (t1 - t0) * (s + 1) / pieces;
                split(c, index, node(c, a), node(c, b), node(c, 0.5 * (a + b)), 0);
            }
        }
    }

private:
    // A point of the curve: its parameter, (u, v) and, measuring on a surface, its 3D point.
    struct Node {
        double t;
        glm::dvec2 p;
        glm::dvec3 s;
    };
    Node node(const Curve& c, double t) const {
        const glm::dvec2 p = point_at(c, t);
        return {t, p, rule_.surface ? surface_at(*rule_.surface, domain_, p) : glm::dvec3(0.0)};
    }

    // Emits the chords from a toward b (m halfway between), without b. The quarter points
    // tested here are the halves' middles, so every point is evaluated once.
    void split(const Curve& c, int index, const Node& a, const Node& b, const Node& m, int depth) {
        const Node q1 = node(c, 0.5 * (a.t + m.t)), q3 = node(c, 0.5 * (m.t + b.t));
        if (depth >= rule_.max_depth || !(m.t > a.t && m.t < b.t) || accepted(a, b, m, q1, q3)) {
            out_.points.push_back(a.p);
            out_.curve.push_back(index);
            out_.param.push_back(a.t);
            return;
        }
        split(c, index, a, m, q1, depth + 1);
        split(c, index, m, b, q3, depth + 1);
    }

    bool accepted(const Node& a, const Node& b, const Node& m, const Node& q1,
                  const Node& q3) const {
        if (glm::length(b.p - a.p) > rule_.max_length) return false;
        if (!rule_.surface) {
            return distance_to_segment(m.p, a.p, b.p) <= rule_.tolerance &&
                   distance_to_segment(q1.p, a.p, b.p) <= rule_.tolerance &&
                   distance_to_segment(q3.p, a.p, b.p) <= rule_.tolerance;
        }
        return distance_to_segment(m.s, a.s, b.s) <= rule_.tolerance &&
               distance_to_segment(q1.s, a.s, b.s) <= rule_.tolerance &&
               distance_to_segment(q3.s, a.s, b.s) <= rule_.tolerance;
    }

    const FlattenRule& rule_;
    FlatLoop& out_;
    ParamRect domain_;
};

} // namespace

FlatLoop flatten_loop(const TrimLoop& loop, const FlattenRule& rule) {
    FlatLoop out;
    Flattener f(rule, out);
    for (std::size_t k = 0; k < loop.curves.size(); ++k)
        f.curve(loop.curves[k], static_cast<int>(k));
    return out;
}

double twice_signed_area(const std::vector<glm::dvec2>& polygon) {
    double a = 0;
    const std::size_t n = polygon.size();
    if (n < 3) return 0;
    // Relative to the first point, so a loop far from the origin keeps its digits.
    const glm::dvec2 o = polygon[0];
    for (std::size_t k = 1; k + 1 < n; ++k) {
        const glm::dvec2 p = polygon[k] - o, q = polygon[k + 1] - o;
        a += p.x * q.y - p.y * q.x;
    }
    return a;
}

double domain_scale(const ParamRect& domain) {
    return std::max(domain.u.hi - domain.u.lo, domain.v.hi - domain.v.lo);
}

} // namespace isoparm::geom
