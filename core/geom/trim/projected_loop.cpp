// Projecting a planar closed curve onto a surface along a direction: Newton's method on the
// two components across the direction (a curve-surface intersection with a line family),
// continued along the curve, and one least-squares fit per smooth piece.
#include "core/geom/trim/projected_loop.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <vector>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/trim/fit_samples.hpp"
#include "core/geom/trim/trim_flatten.hpp"

namespace isoparm::geom {

namespace {

std::string point_text(const glm::dvec3& p) {
    return "(" + format_short(p.x) + ", " + format_short(p.y) + ", " + format_short(p.z) + ")";
}

// The surface seen along the direction: (e1 . S, e2 . S) in a plane across it.
class Projection {
public:
    Projection(const Surface& s, glm::dvec3 direction) : s_(s), box_(domain(s)) {
        const glm::dvec3 d = glm::normalize(direction);
        const glm::dvec3 helper = std::abs(d.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        e1_ = glm::normalize(glm::cross(d, helper));
        e2_ = glm::cross(d, e1_);
        // A grid over the domain, through every knot, gives Newton its starting points.
        auto params = [](const Knots& U, Interval range) {
            std::vector<double> t;
            const auto runs = knot_runs(U);
            for (std::size_t k = 0; k + 1 < runs.size(); ++k) {
                const double a = std::max(runs[k].value, range.lo),
                             b = std::min(runs[k + 1].value, range.hi);
                if (!(a < b)) continue;
                for (int j = 0; j < 8; ++j) t.push_back(a + (b - a) * j / 8.0);
            }
            t.push_back(range.hi);
            return t;
        };
        for (double u : params(s.knots_u, box_.u))
            for (double v : params(s.knots_v, box_.v))
                if (auto p = surface_point(s, u, v)) {
                    grid_.push_back({u, v, across(*p)});
                    scale_ = std::max(scale_, glm::length(*p));
                }
    }

    // The (u, v) whose point lies on the line through p along the direction, from `start`;
    // nullopt when Newton's method does not reach the line inside the domain.
    std::optional<glm::dvec2> solve(const glm::dvec3& p, glm::dvec2 start) const {
        const glm::dvec2 target = across(p);
        glm::dvec2 uv = start;
        const double tiny = 1e-12 * std::max(scale_, glm::length(p));
        for (int it = 0; it < 40; ++it) {
            auto d = surface_derivatives(s_, uv.x, uv.y, 1);
            if (!d) return std::nullopt;
            const glm::dvec2 g = across(d->D[0][0]) - target;
            if (glm::length(g) <= tiny) return uv;
            const glm::dvec2 su = across(d->D[1][0]), sv = across(d->D[0][1]);
            const double det = su.x * sv.y - sv.x * su.y;
            if (det == 0 || !std::isfinite(det)) return std::nullopt;
            // Cramer's rule for J delta = -g, J's columns su and sv.
            const glm::dvec2 step{(-g.x * sv.y + sv.x * g.y) / det,
                                  (-su.x * g.y + g.x * su.y) / det};
            const glm::dvec2 next{std::clamp(uv.x + step.x, box_.u.lo, box_.u.hi),
                                  std::clamp(uv.y + step.y, box_.v.lo, box_.v.hi)};
            if (next == uv) break; // pinned at the domain's edge, or no change left
            uv = next;
        }
        // Accept the last iterate when it is on the line to a few ulps of the model's size.
        auto q = surface_point(s_, uv.x, uv.y);
        if (q && glm::length(across(*q) - target) <= 1e-9 * std::max(scale_, glm::length(p)))
            return uv;
        return std::nullopt;
    }

    // From the grid point nearest the line (seen along the direction).
    std::optional<glm::dvec2> solve(const glm::dvec3& p) const {
        const glm::dvec2 target = across(p);
        const Sample* best = nullptr;
        for (const Sample& g : grid_)
            if (!best || glm::length(g.seen - target) < glm::length(best->seen - target)) best = &g;
        if (!best) return std::nullopt;
        return solve(p, {best->u, best->v});
    }

private:
    struct Sample {
        double u, v;
        glm::dvec2 seen;
    };
    glm::dvec2 across(const glm::dvec3& p) const { return {glm::dot(e1_, p), glm::dot(e2_, p)}; }

    const Surface& s_;
    ParamRect box_;
    glm::dvec3 e1_{1, 0, 0}, e2_{0, 1, 0};
    std::vector<Sample> grid_;
    double scale_ = 1;
};

// (u, v) along the curve: solved densely by continuation once, then at any t from the nearest
// solved parameter (so the answer depends on t alone, and shared piece ends agree exactly).
class Trace {
public:
    Trace(const Projection& proj, const Curve& c) : proj_(proj), c_(c) {}

    Status build(Interval d, int spans) {
        const int n = std::max(256, 32 * spans);
        std::optional<glm::dvec2> previous;
        for (int k = 0; k <= n; ++k) {
            const double t = k == n ? d.hi : d.lo + (d.hi - d.lo) * k / n;
            auto p = curve_point(c_, t);
            if (!p)
                return make_error(ErrorCode::weights,
                                  "the curve has no point at t = " + format_short(t) +
                                      " (its weights make the denominator zero there)",
                                  "/curve");
            std::optional<glm::dvec2> uv = previous ? proj_.solve(*p, *previous) : std::nullopt;
            if (!uv) uv = proj_.solve(*p);
            if (!uv) return missed(t, *p);
            ts_.push_back(t);
            uvs_.push_back(*uv);
            previous = uv;
        }
        return Ok{};
    }

    glm::dvec3 operator()(double t) const {
        const auto it = std::lower_bound(ts_.begin(), ts_.end(), t);
        std::size_t k = static_cast<std::size_t>(it - ts_.begin());
        if (k == ts_.size() || (k > 0 && t - ts_[k - 1] < ts_[k] - t)) --k;
        glm::dvec2 uv = uvs_[k];
        if (ts_[k] != t) {
            if (auto p = curve_point(c_, t); p) {
                if (auto solved = proj_.solve(*p, uv))
                    uv = *solved;
                else if (!failure_)
                    failure_ = missed(t, *p).error();
            }
        }
        return {uv.x, uv.y, 0.0};
    }

    const std::optional<Error>& failure() const { return failure_; }

private:
    static Status missed(double t, const glm::dvec3& p) {
        return make_error(ErrorCode::geometry,
                          "the curve's point " + point_text(p) + " at t = " + format_short(t) +
                              " does not project onto the surface inside its domain",
                          "/curve");
    }

    const Projection& proj_;
    const Curve& c_;
    std::vector<double> ts_;
    std::vector<glm::dvec2> uvs_;
    mutable std::optional<Error> failure_;
};

// The parameters where the curve may have a kink: its ends and the interior knots of
// multiplicity >= degree (continuity at most C0 there).
std::vector<double> kinks(const Curve& c, Interval d) {
    std::vector<double> at{d.lo};
    for (const KnotRun& r : knot_runs(c.knots))
        if (r.value > d.lo && r.value < d.hi && r.multiplicity >= c.degree) at.push_back(r.value);
    at.push_back(d.hi);
    return at;
}

int spans_between(const Curve& c, double a, double b) {
    int n = 0;
    for (const KnotRun& r : knot_runs(c.knots))
        if (r.value > a && r.value < b) ++n;
    return n + 1;
}

} // namespace

Expected<TrimLoop> projected_loop(const Surface& s, const Curve& c, glm::dvec3 direction,
                                  double tolerance) {
    if (!(glm::length(direction) > 0) || !std::isfinite(glm::length(direction)))
        return make_error(ErrorCode::schema,
                          "the projection direction " + point_text(direction) +
                              " is not a direction (zero or not finite)",
                          "/direction");
    const Interval d = domain(c);
    const auto first = curve_point(c, d.lo), last = curve_point(c, d.hi);
    if (!first || !last)
        return make_error(ErrorCode::weights,
                          "the curve has no point at one of its ends (a zero weight there)",
                          "/curve");
    const double size = std::max({1.0, glm::length(*first), glm::length(*last)});
    if (glm::length(*first - *last) > 1e-9 * size)
        return make_error(ErrorCode::geometry,
                          "the curve is not closed: it starts at " + point_text(*first) +
                              " and ends at " + point_text(*last) + ", " +
                              format_short(glm::length(*first - *last)) +
                              " apart (close it in the curve designer)",
                          "/curve");

    const Projection proj(s, direction);
    Trace trace(proj, c);
    if (Status st = trace.build(d, spans_between(c, d.lo, d.hi)); !st) return st.error();

    const double tol = tolerance * domain_scale(domain(s));
    const std::vector<double> at = kinks(c, d);
    TrimLoop loop;
    for (std::size_t k = 0; k + 1 < at.size(); ++k) {
        loop.curves.push_back(fit_samples(std::cref(trace), {at[k], at[k + 1]},
                                          spans_between(c, at[k], at[k + 1]), tol));
        if (trace.failure()) return *trace.failure();
    }
    // The curve closes to 1e-9 of its size; its projection closes exactly.
    loop.curves.back().points.back() = loop.curves.front().points.front();
    return loop;
}

} // namespace isoparm::geom
