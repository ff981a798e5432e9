// Fitting a function of one parameter: least squares on uniform samples, refined until it holds
// between the samples too.
#include "core/geom/trim/fit_samples.hpp"

#include <algorithm>
#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/fitting.hpp"

namespace isoparm::geom {

Curve fit_samples(const std::function<glm::dvec3(double)>& f, Interval d, int pieces,
                  double tolerance) {
    return fit_samples_limited(f, d, pieces, tolerance, 16384).curve;
}

SampleFit fit_samples_limited(const std::function<glm::dvec3(double)>& f, Interval d, int pieces,
                              double tolerance, int max_samples) {
    auto rescale = [&](Curve& c) {
        const double a = c.knots.front(), b = c.knots.back();
        for (double& k : c.knots)
            k = k == a ? d.lo : k == b ? d.hi : d.lo + (k - a) / (b - a) * (d.hi - d.lo);
    };
    int samples =
        std::clamp(32 * std::max(pieces, 1), 32, std::max(32, std::min(2048, max_samples)));
    Curve best;
    for (;;) {
        std::vector<glm::dvec3> pts(static_cast<std::size_t>(samples) + 1);
        for (int k = 0; k <= samples; ++k)
            pts[static_cast<std::size_t>(k)] = f(d.lo + (d.hi - d.lo) * k / samples);
        bool one_point = true;
        for (const glm::dvec3& p : pts)
            one_point = one_point && glm::length(p - pts[0]) <= tolerance;
        if (one_point) {
            Curve c;
            c.type = SplineType::bspline;
            c.degree = 1;
            c.knots = {d.lo, d.lo, d.hi, d.hi};
            c.points = {pts.front(), pts.front()};
            c.weights = {1, 1};
            return {c, true};
        }
        for (int count = 8;; count = std::min(2 * count, samples + 1)) {
            auto fit =
                approximate_curve(pts, 3, std::min(count, samples + 1), Parametrization::uniform);
            if (fit) {
                Curve c = std::move(fit->curve);
                rescale(c);
                double worst = fit->max_error;
                for (int k = 0; k < samples && worst <= tolerance; ++k) {
                    const double t = d.lo + (d.hi - d.lo) * (k + 0.5) / samples;
                    worst = std::max(
                        worst, glm::length(curve_point(c, t).value_or(glm::dvec3(0.0)) - f(t)));
                }
                best = c;
                if (worst <= tolerance) return {c, true};
            }
            if (count >= samples + 1) break;
        }
        if (samples >= max_samples) return {best, false};
        samples = std::min(2 * samples, max_samples);
    }
}

} // namespace isoparm::geom
