// Point inversion (Piegl & Tiller sec. 6.1): a start from samples, then Newton's iteration.
#include "core/geom/closest_point.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::geom {

namespace {

constexpr int max_newton_steps = 40;
// Samples per direction at most: enough for a start inside the right basin on the nets a
// student builds, bounded for a grader that projects many points.
constexpr int max_samples = 96;

// Parameters to sample along one direction: every distinct knot in the domain and points
// inside each span between them.
std::vector<double> sample_parameters(const Knots& U, int p, int n) {
    const Interval d = domain(U, p, n);
    std::vector<double> breaks{d.lo};
    for (int k = p + 1; k < n; ++k)
        if (U[k] > breaks.back() && U[k] < d.hi) breaks.push_back(U[k]);
    breaks.push_back(d.hi);
    const int spans = static_cast<int>(breaks.size()) - 1;
    const int per_span = std::max(2, std::min(2 * (p + 1), max_samples / std::max(spans, 1)));
    std::vector<double> out;
    for (int s = 0; s < spans; ++s)
        for (int k = 0; k < per_span; ++k)
            out.push_back(breaks[s] + (breaks[s + 1] - breaks[s]) * k / per_span);
    out.push_back(d.hi);
    return out;
}

template <class Foot>
std::optional<Foot> nearest_sample(const std::vector<Foot>& samples, const glm::dvec3& p) {
    std::optional<Foot> best;
    double best_d2 = 0;
    for (const Foot& f : samples) {
        const glm::dvec3 d = f.point - p;
        const double d2 = glm::dot(d, d);
        if (!best || d2 < best_d2) {
            best = f;
            best_d2 = d2;
        }
    }
    if (best) best->distance = std::sqrt(best_d2);
    return best;
}

} // namespace

CurveProjector::CurveProjector(const Curve& c) : c_(c) {
    for (double t : sample_parameters(c.knots, c.degree, c.count()))
        if (auto q = curve_point(c, t)) samples_.push_back({t, *q, 0});
}

std::optional<CurveFoot> CurveProjector::closest(const glm::dvec3& p) const {
    std::optional<CurveFoot> best = nearest_sample(samples_, p);
    if (!best) return best;
    const Interval dom = domain(c_);
    double lambda = 0; // the damping that worked last (Levenberg-Marquardt)
    for (int step = 0; step < max_newton_steps; ++step) {
        const double t = best->t;
        const auto d = curve_derivatives(c_, t, 2);
        if (!d) break;
        const glm::dvec3 r = (*d)[0] - p;
        const double f = glm::dot(r, (*d)[1]);
        const double gn = glm::dot((*d)[1], (*d)[1]); // Gauss-Newton's second derivative
        const double newton = gn + glm::dot(r, (*d)[2]);
        bool moved = false, stuck = false;
        // One trial step f / h, taken when it does not go farther (ties taken: near the
        // minimum the distance stops changing in its last bits while the foot still moves).
        auto attempt = [&](double h) {
            if (!(h > 0) || !std::isfinite(h)) return;
            const double next = std::clamp(t - f / h, dom.lo, dom.hi);
            if (next == t) {
                stuck = true;
                return;
            }
            if (auto q = curve_point(c_, next)) {
                const double dist = glm::length(*q - p);
                if (dist <= best->distance) {
                    best = CurveFoot{next, *q, dist};
                    moved = true;
                }
            }
        };
        attempt(newton); // P&T eq. 6.3, where it is a descent step
        for (double damp = std::max(lambda / 8, 1e-9); !moved && !stuck && damp < 1e12; damp *= 8) {
            attempt(gn * (1 + damp) + 1e-300);
            if (moved) lambda = damp;
        }
        // Converged when the step no longer moves the point (P&T's first criterion).
        if (!moved || std::abs(best->t - t) * std::sqrt(gn) <= 1e-15 * (1 + glm::length((*d)[0])))
            break;
    }
    return best;
}

SurfaceProjector::SurfaceProjector(const Surface& s) : s_(s) {
    const std::vector<double> us = sample_parameters(s.knots_u, s.degree_u, s.n_u);
    const std::vector<double> vs = sample_parameters(s.knots_v, s.degree_v, s.n_v);
    samples_.reserve(us.size() * vs.size());
    for (double u : us)
        for (double v : vs)
            if (auto q = surface_point(s, u, v)) samples_.push_back({u, v, *q, 0});
}

std::optional<SurfaceFoot> SurfaceProjector::closest(const glm::dvec3& p) const {
    std::optional<SurfaceFoot> best = nearest_sample(samples_, p);
    if (!best) return best;
    const ParamRect dom = domain(s_);
    double lambda = 0; // the damping that worked last (Levenberg-Marquardt)
    for (int step = 0; step < max_newton_steps; ++step) {
        const double u = best->u, v = best->v;
        const auto d = surface_derivatives(s_, u, v, 2);
        if (!d) break;
        const glm::dvec3 r = d->D[0][0] - p;
        const glm::dvec3 &Su = d->D[1][0], &Sv = d->D[0][1];
        const double f = glm::dot(r, Su), g = glm::dot(r, Sv);
        // Gauss-Newton's matrix (always positive semi-definite) and Newton's.
        const double ga = glm::dot(Su, Su), gb = glm::dot(Su, Sv), ge = glm::dot(Sv, Sv);
        const double na = ga + glm::dot(r, d->D[2][0]), nb = gb + glm::dot(r, d->D[1][1]),
                     ne = ge + glm::dot(r, d->D[0][2]);
        const bool newton_ok = na > 0 && na * ne - nb * nb > 0;
        // One trial step with the matrix [[a, b], [b, e]]: taken when it does not go farther.
        // Ties are taken: near the minimum the distance stops changing in its last bits while
        // the foot still moves toward it.
        bool moved = false, stuck = false;
        auto attempt = [&](double a, double b, double e) {
            const double det = a * e - b * b;
            if (!(det > 0) || !std::isfinite(det)) return;
            const double du = (e * f - b * g) / det, dv = (a * g - b * f) / det;
            const double nu = std::clamp(u - du, dom.u.lo, dom.u.hi);
            const double nv = std::clamp(v - dv, dom.v.lo, dom.v.hi);
            if (nu == u && nv == v) {
                stuck = true;
                return;
            }
            if (auto q = surface_point(s_, nu, nv)) {
                const double dist = glm::length(*q - p);
                if (dist <= best->distance) {
                    best = SurfaceFoot{nu, nv, *q, dist};
                    moved = true;
                }
            }
        };
        // Newton's step where its matrix is positive definite (quadratic convergence).
        if (newton_ok) attempt(na, nb, ne);
        // Else Gauss-Newton damped (Levenberg-Marquardt) until the step does not go farther.
        // At a pole one of |S_u|, |S_v| vanishes: the damping uses the larger as a floor, so
        // the step along the other stays finite.
        const double floor = 1e-6 * std::max({ga, ge, 1e-300});
        for (double damp = std::max(lambda / 8, 1e-9); !moved && !stuck && damp < 1e12; damp *= 8) {
            attempt(ga + damp * std::max(ga, floor), gb, ge + damp * std::max(ge, floor));
            if (moved) lambda = damp;
        }
        if (!moved) break;
        const double step_length = glm::length((best->u - u) * Su + (best->v - v) * Sv);
        if (step_length <= 1e-15 * (1 + glm::length(d->D[0][0]))) break;
    }
    return best;
}

std::optional<CurveFoot> closest_point(const Curve& c, const glm::dvec3& p) {
    return CurveProjector(c).closest(p);
}

std::optional<SurfaceFoot> closest_point(const Surface& s, const glm::dvec3& p) {
    return SurfaceProjector(s).closest(p);
}

} // namespace isoparm::geom
