// The comb, osculating circle and Frenet frame of a curve (see the header).
#include "ui/view/curve_glyphs.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/curvature.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/tessellate.hpp"

namespace isoparm::ui {

namespace {

constexpr int comb_samples_per_span = 24;

// Parameters over the domain with samples in every knot span, so a comb stays dense where the
// curve has many spans.
std::vector<double> comb_params(const geom::Curve& c) {
    const geom::Interval d = geom::domain(c);
    int spans = 0;
    for (int k = c.degree; k < c.count(); ++k) spans += c.knots[k] < c.knots[k + 1];
    return geom::uniform_params(d.lo, d.hi, std::clamp(spans * comb_samples_per_span, 48, 600));
}

// Comb and frame lengths are a fraction of the control polygon's size, so they read at any
// scale.
double polygon_size(const geom::Curve& c) {
    glm::dvec3 lo = c.points.front(), hi = lo;
    for (const glm::dvec3& p : c.points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return std::max(glm::length(hi - lo), 1e-9);
}

} // namespace

CurveGlyphs curve_glyphs(const geom::Curve& c, double t, const CurveGlyphRequest& want) {
    CurveGlyphs g;
    if (c.points.empty()) return g;
    const double size = polygon_size(c);
    if (want.comb) {
        std::vector<std::pair<glm::dvec3, glm::dvec3>> teeth; // base, -N kappa
        double kmax = 0;
        for (double s : comb_params(c)) {
            const auto p = geom::curve_point(c, s);
            const auto f = geom::curve_curvature(c, s);
            if (!p || !f || !f->curvature) continue;
            teeth.emplace_back(*p, f->normal ? -*f->normal * *f->curvature : glm::dvec3(0));
            kmax = std::max(kmax, *f->curvature);
        }
        const double scale = kmax > 0 ? 0.2 * size / kmax : 0;
        for (const auto& [base, dir] : teeth) {
            g.teeth.emplace_back(base, base + dir * scale);
            g.rim.push_back(base + dir * scale);
        }
    }
    const auto f = geom::curve_curvature(c, t);
    const auto p = geom::curve_point(c, t);
    if (!f || !p) return g;
    if (want.osculating && f->curvature && *f->curvature > 0 && f->normal && f->tangent) {
        const double r = 1 / *f->curvature;
        const glm::dvec3 centre = *p + *f->normal * r;
        g.centre = centre;
        for (int s = 0; s <= 96; ++s) {
            const double a = 2 * 3.14159265358979323846 * s / 96;
            g.circle.push_back(centre +
                               r * (std::cos(a) * *f->tangent + std::sin(a) * -*f->normal));
        }
    }
    if (want.frenet && f->tangent) {
        g.point = *p;
        g.tangent = f->tangent;
        g.normal = f->normal;
        g.binormal = f->binormal;
        g.frame_length = 0.18 * size;
    }
    return g;
}

} // namespace isoparm::ui
