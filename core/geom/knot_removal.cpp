// Knot removal within a tolerance (Piegl & Tiller A5.8, eq. 5.28-5.30), checked by sampling.
#include "core/geom/knot_removal.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/refine.hpp"

namespace isoparm::geom {

OneKnotRemoval remove_knot_once(int p, const Knots& U, const std::vector<HPoint>& Pw, int r,
                                bool with_weights) {
    const double u = U[r];
    const int s = multiplicity(U, u), n = static_cast<int>(Pw.size());
    // The new points first..last-1 replace the old first..last (A5.8's indices); Q[k] holds new
    // point first - 1 + k, with Q_(first-1) = P_(first-1) and Q_last = P_(last+1) unchanged.
    const int first = r - p, last = r - s;
    auto alpha = [&](int i) { return (u - U[i]) / (U[i + p + 1] - U[i]); };
    auto distance = [&](const HPoint& a, const HPoint& b) {
        return with_weights ? glm::distance(a, b) : glm::distance(glm::dvec3(a), glm::dvec3(b));
    };
    OneKnotRemoval out;
    int moved = first - 1; // the one old point that differs after inserting the knot back
    std::vector<HPoint> Q(static_cast<size_t>(std::max(last - first + 2, 2)));
    Q.front() = Pw[first - 1];
    Q.back() = Pw[last + 1];
    if (last < first) {
        // Multiplicity p + 1: no equation, the two points on either side of the gap must agree
        // (the right one is kept, as in the book).
        out.distance = distance(Pw[first - 1], Pw[first]);
    } else {
        // Equation i (P_i = alpha_i Q_i + (1 - alpha_i) Q_(i-1), i = first..last) gives Q_i
        // from the left (eq. 5.28, dividing by alpha_i) or Q_(i-1) from the right (eq. 5.29,
        // dividing by 1 - alpha_i). The book meets in the middle; taking each time the end with
        // the larger divisor solves the same equations with less rounding where knots crowd.
        int i = first, j = last;
        while (i < j) {
            const double ai = alpha(i), aj = alpha(j);
            if (ai >= 1.0 - aj) {
                Q[i - first + 1] = (Pw[i] - (1.0 - ai) * Q[i - first]) / ai;
                ++i;
            } else {
                Q[j - first] = (Pw[j] - aj * Q[j - first + 1]) / (1.0 - aj);
                --j;
            }
        }
        // The equation left over is A5.8's test: how far its old point would move.
        const double ai = alpha(i);
        out.distance = distance(Pw[i], ai * Q[i - first + 1] + (1.0 - ai) * Q[i - first]);
        moved = i;
    }
    out.points.resize(n - 1);
    for (int k = 0; k < n - 1; ++k) {
        if (k >= last)
            out.points[k] = Pw[k + 1];
        else if (k < first)
            out.points[k] = Pw[k];
        else
            out.points[k] = Q[k - first + 1];
    }
    out.knots = U;
    out.knots.erase(out.knots.begin() + r);
    out.moved_from = U[moved];
    out.moved_to = U[moved + p + 1];
    return out;
}

namespace {

struct WeightRange {
    double w_min = std::numeric_limits<double>::infinity();
    double p_max = 0.0;
};
WeightRange weight_range(const std::vector<glm::dvec3>& points,
                         const std::vector<double>& weights) {
    WeightRange r;
    for (size_t i = 0; i < points.size(); ++i) {
        r.w_min = std::min(r.w_min, weights[i]);
        r.p_max = std::max(r.p_max, glm::length(points[i]));
    }
    return r;
}

} // namespace

double cartesian_bound(double homogeneous_bound, const std::vector<glm::dvec3>& points,
                       const std::vector<double>& weights, bool rational) {
    if (!rational || homogeneous_bound == 0.0) return homogeneous_bound;
    const WeightRange r = weight_range(points, weights);
    if (!(r.w_min > homogeneous_bound)) return std::numeric_limits<double>::infinity();
    return homogeneous_bound * (1.0 + r.p_max) / (r.w_min - homogeneous_bound);
}

double homogeneous_tolerance(double tolerance, const std::vector<glm::dvec3>& points,
                             const std::vector<double>& weights, bool rational) {
    if (!rational) return tolerance;
    const WeightRange r = weight_range(points, weights);
    if (!(r.w_min > 0.0)) return 0.0;
    return tolerance * r.w_min / (1.0 + r.p_max + tolerance);
}

namespace {

// Samples per knot span: along the removal, enough for the degree-p difference (capped: the
// test of A5.8 bounds each removal anyway); across a surface's other direction, fewer (its
// basis functions only blend the lines' differences). A surface is sampled more thinly along
// too: its samples multiply.
int samples_along(int p) {
    return std::min(2 * p + 8, 32);
}
int surface_samples_along(int p) {
    return std::min(p + 4, 12);
}
int samples_across(int q) {
    return std::min(q + 2, 6);
}

Status check_request(const Knots& U, int p, int n, double knot, int times, double tolerance) {
    if (!std::isfinite(tolerance) || tolerance < 0.0) {
        return make_error(ErrorCode::schema,
                          "tolerance must be a finite number >= 0, got " + format_number(tolerance),
                          "/tolerance");
    }
    if (times < 1)
        return make_error(ErrorCode::schema,
                          "times must be at least 1, got " + std::to_string(times), "/times");
    const Interval dom = domain(U, p, n);
    if (!(dom.lo < knot && knot < dom.hi)) {
        return make_error(ErrorCode::domain,
                          "knot " + format_number(knot) + " must lie strictly inside the domain (" +
                              format_number(dom.lo) + ", " + format_number(dom.hi) +
                              "): only interior knots can be removed",
                          "/knot");
    }
    if (multiplicity(U, knot) == 0)
        return make_error(ErrorCode::schema, format_number(knot) + " is not a knot", "/knot");
    return Ok{};
}

int last_index(const Knots& U, double t) {
    return static_cast<int>(std::upper_bound(U.begin(), U.end(), t) - U.begin()) - 1;
}

// Where `times` removals of the knot can move the curve: each removal moves the support of one
// point between the knot's p + 1 neighbours on each side, which shift by one per removal.
Interval removal_reach(const Knots& U, int p, int n, double knot, int times) {
    const int r = last_index(U, knot), s = multiplicity(U, knot);
    const int last_knot = static_cast<int>(U.size()) - 1;
    const double lo = U[std::max(0, r - p - times)];
    const double hi = U[std::min(last_knot, r - s + p + times + 1)];
    const Interval dom = domain(U, p, n);
    return {std::max(lo, dom.lo), std::min(hi, dom.hi)};
}

// Every distinct knot in [lo, hi] and per_span - 1 evenly spaced parameters inside each
// non-empty span between them.
std::vector<double> sample_params(const Knots& U, Interval range, int per_span) {
    std::vector<double> breaks{range.lo};
    for (double t : U)
        if (t > breaks.back() && t < range.hi) breaks.push_back(t);
    breaks.push_back(range.hi);
    std::vector<double> ts;
    for (size_t k = 0; k + 1 < breaks.size(); ++k)
        for (int i = 0; i < per_span; ++i)
            ts.push_back(breaks[k] + (breaks[k + 1] - breaks[k]) * i / per_span);
    ts.push_back(range.hi);
    return ts;
}

// The distance between two samples of the same parameter: infinite where only one exists.
double sample_distance(const std::optional<glm::dvec3>& a, const std::optional<glm::dvec3>& b) {
    if (a.has_value() != b.has_value()) return std::numeric_limits<double>::infinity();
    return a ? glm::distance(*a, *b) : 0.0;
}

// The part of the domain along dir the removals can change, and the whole other direction.
struct SurfaceSamples {
    std::vector<double> along, across;
};
SurfaceSamples surface_samples(const Surface& s, Dir dir, double knot, int steps) {
    const Dir other = dir == Dir::u ? Dir::v : Dir::u;
    const int p = s.degree(dir), n = s.count(dir);
    const Knots& V = s.knots(other);
    return {sample_params(s.knots(dir), removal_reach(s.knots(dir), p, n, knot, steps),
                          surface_samples_along(p)),
            sample_params(V, domain(V, s.degree(other), s.count(other)),
                          samples_across(s.degree(other)))};
}

std::optional<glm::dvec3> surface_sample(const Surface& s, Dir dir, double along, double across) {
    return dir == Dir::u ? surface_point(s, along, across) : surface_point(s, across, along);
}

} // namespace

Expected<CurveKnotRemoval> remove_knot(const Curve& c, double knot, int times, double tolerance) {
    const int p = c.degree, n = c.count();
    if (Status ok = check_request(c.knots, p, n, knot, times, tolerance); !ok) return ok.error();
    const bool rational = is_rational(c.type);
    const double tolerance_4d = homogeneous_tolerance(tolerance, c.points, c.weights, rational);
    const int steps = std::min(times, multiplicity(c.knots, knot));
    const std::vector<double> ts =
        sample_params(c.knots, removal_reach(c.knots, p, n, knot, steps), samples_along(p));
    std::vector<std::optional<glm::dvec3>> original(ts.size());
    for (size_t k = 0; k < ts.size(); ++k) original[k] = curve_point(c, ts[k]);

    CurveKnotRemoval out{c, 0, 0.0};
    Knots U = c.knots;
    std::vector<HPoint> Pw = homogeneous_points(c);
    for (int step = 0; step < steps; ++step) {
        OneKnotRemoval one = remove_knot_once(p, U, Pw, last_index(U, knot), rational);
        if (!(one.distance <= tolerance_4d)) break;
        Expected<Curve> candidate = curve_from_homogeneous(c, p, one.knots, one.points, nullptr);
        if (!candidate) break; // a point at infinity: not removable
        double deviation = 0.0;
        for (size_t k = 0; k < ts.size(); ++k)
            deviation =
                std::max(deviation, sample_distance(original[k], curve_point(*candidate, ts[k])));
        if (!(deviation <= tolerance)) break;
        out.curve = std::move(candidate).value();
        out.removed = step + 1;
        out.max_deviation = deviation;
        U = std::move(one.knots);
        Pw = std::move(one.points);
    }
    return out;
}

Expected<SurfaceKnotRemoval> remove_knot(const Surface& s, Dir dir, double knot, int times,
                                         double tolerance) {
    const int p = s.degree(dir), n = s.count(dir);
    if (Status ok = check_request(s.knots(dir), p, n, knot, times, tolerance); !ok)
        return ok.error();
    const bool rational = is_rational(s.type);
    const int across = s.count(dir == Dir::u ? Dir::v : Dir::u);
    std::vector<Curve> lines;
    std::vector<std::vector<HPoint>> Pw;
    std::vector<double> tolerance_4d;
    for (int l = 0; l < across; ++l) {
        lines.push_back(surface_line(s, dir, l));
        Pw.push_back(homogeneous_points(lines.back()));
        tolerance_4d.push_back(
            homogeneous_tolerance(tolerance, lines.back().points, lines.back().weights, rational));
    }
    const int steps = std::min(times, multiplicity(s.knots(dir), knot));
    const SurfaceSamples grid = surface_samples(s, dir, knot, steps);
    std::vector<std::optional<glm::dvec3>> original;
    original.reserve(grid.along.size() * grid.across.size());
    for (double a : grid.along)
        for (double b : grid.across) original.push_back(surface_sample(s, dir, a, b));

    SurfaceKnotRemoval out{s, 0, 0.0};
    Knots U = s.knots(dir);
    for (int step = 0; step < steps; ++step) {
        const int r = last_index(U, knot);
        std::vector<OneKnotRemoval> ones;
        std::vector<Curve> candidate_lines;
        for (int l = 0; l < across; ++l) {
            ones.push_back(remove_knot_once(p, U, Pw[l], r, rational));
            if (!(ones.back().distance <= tolerance_4d[l])) break;
            Expected<Curve> line =
                curve_from_homogeneous(lines[l], p, ones.back().knots, ones.back().points, nullptr);
            if (!line) break;
            candidate_lines.push_back(std::move(line).value());
        }
        if (static_cast<int>(candidate_lines.size()) < across) break; // a line failed
        Surface candidate = surface_from_lines(s, dir, candidate_lines);
        double deviation = 0.0;
        size_t k = 0;
        for (double a : grid.along)
            for (double b : grid.across)
                deviation =
                    std::max(deviation,
                             sample_distance(original[k++], surface_sample(candidate, dir, a, b)));
        if (!(deviation <= tolerance)) break;
        out.surface = std::move(candidate);
        out.removed = step + 1;
        out.max_deviation = deviation;
        U = ones.front().knots;
        for (int l = 0; l < across; ++l) Pw[l] = std::move(ones[l].points);
    }
    return out;
}

WorkEstimate knot_removal_cost(const Curve& c, double knot, int times) {
    const int p = c.degree, n = c.count();
    if (!check_request(c.knots, p, n, knot, times, 0.0)) return {};
    const int steps = std::min(times, multiplicity(c.knots, knot));
    const double samples =
        static_cast<double>(
            sample_params(c.knots, removal_reach(c.knots, p, n, knot, steps), samples_along(p))
                .size()) *
        (steps + 1);
    WorkEstimate e = estimate_curve_evaluation(samples, p, 0);
    e.steps += steps * 4.0 * (p + 1);
    e.answer_numbers = 4.0 * n + c.knots.size(); // the curve: points, weights, knots
    return e;
}

WorkEstimate knot_removal_cost(const Surface& s, Dir dir, double knot, int times) {
    const int p = s.degree(dir), n = s.count(dir);
    if (!check_request(s.knots(dir), p, n, knot, times, 0.0)) return {};
    const int steps = std::min(times, multiplicity(s.knots(dir), knot));
    const SurfaceSamples grid = surface_samples(s, dir, knot, steps);
    const double samples =
        static_cast<double>(grid.along.size()) * grid.across.size() * (steps + 1);
    WorkEstimate e = estimate_surface_evaluation(samples, s.degree_u, s.degree_v, 0, false);
    const double points = static_cast<double>(s.n_u) * s.n_v;
    e.steps += steps * 4.0 * (p + 1) * points / n;
    e.answer_numbers = 4.0 * points + s.knots_u.size() + s.knots_v.size();
    return e;
}

} // namespace isoparm::geom
