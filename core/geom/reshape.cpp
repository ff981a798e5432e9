#include "core/geom/reshape.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::geom {

namespace {

SplineType without_bezier(SplineType t) {
    return is_rational(t) ? SplineType::nurbs : SplineType::bspline;
}

// Samples per knot span when measuring how far an edit moved the shape.
constexpr int samples_per_span = 32;
constexpr int max_samples_per_direction = 4096;

// Parameters covering [lo, hi] with `per_span` samples in each span of either knot vector.
std::vector<double> sample_params(double lo, double hi, int spans) {
    const int count = std::clamp(spans * samples_per_span, 2, max_samples_per_direction);
    std::vector<double> t(static_cast<std::size_t>(count) + 1);
    for (int k = 0; k <= count; ++k) t[k] = lo + (hi - lo) * k / count;
    t.back() = hi;
    return t;
}

int spans_of(const Knots& U, int p, int n) {
    int spans = 0;
    for (int k = p; k < n; ++k) spans += U[k] < U[k + 1];
    return spans;
}

// Where the split goes, checked: the index of the knot's first copy and the new value.
struct SplitPlace {
    int index = 0;
    double value = 0;
};
Expected<SplitPlace> place_split(const Knots& U, double knot, std::optional<double> delta) {
    const auto first = std::lower_bound(U.begin(), U.end(), knot);
    if (first == U.end() || *first != knot)
        return make_error(ErrorCode::schema, format_number(knot) + " is not a knot", "/knot");
    const int m = multiplicity(U, knot);
    if (m < 2)
        return make_error(ErrorCode::schema,
                          "knot " + format_number(knot) +
                              " is simple: splitting needs multiplicity 2 or more",
                          "/knot");
    if (first == U.begin())
        return make_error(ErrorCode::schema,
                          "knot " + format_number(knot) +
                              " is the first knot: no span before it to move a copy into",
                          "/knot");
    const double previous = *(first - 1);
    const double d = delta.value_or(0.01 * (knot - previous));
    if (!(d > 0) || !std::isfinite(d))
        return make_error(ErrorCode::schema, "delta must be > 0, got " + format_number(d),
                          "/delta");
    if (!(knot - d > previous))
        return make_error(ErrorCode::schema,
                          "knot - delta = " + format_number(knot - d) +
                              " must stay above the previous knot " + format_number(previous),
                          "/delta");
    return SplitPlace{static_cast<int>(first - U.begin()), knot - d};
}

} // namespace

Curve close_periodic(const Curve& c) {
    const int n = c.count(), p = c.degree;
    Curve out = c;
    out.type = without_bezier(c.type);
    for (int i = 0; i < p; ++i) {
        out.points.push_back(c.points[i % n]);
        out.weights.push_back(c.weights[i % n]);
    }
    out.knots.resize(static_cast<std::size_t>(n + 2 * p + 1));
    for (int k = 0; k <= n + 2 * p; ++k) out.knots[k] = static_cast<double>(k - p) / n;
    return out;
}

bool is_closed_periodic(const Curve& c) {
    const int p = c.degree, n = c.count() - p;
    if (n < 1 || static_cast<int>(c.knots.size()) != n + 2 * p + 1) return false;
    for (int k = 0; k <= n + 2 * p; ++k)
        if (c.knots[k] != static_cast<double>(k - p) / n) return false;
    for (int i = 0; i < p; ++i)
        if (c.points[i] != c.points[n + i] || c.weights[i] != c.weights[n + i]) return false;
    return true;
}

Surface close_periodic(const Surface& s, Dir dir) {
    std::vector<Curve> lines;
    const int across = s.count(dir == Dir::u ? Dir::v : Dir::u);
    for (int k = 0; k < across; ++k) lines.push_back(close_periodic(surface_line(s, dir, k)));
    Surface out = surface_from_lines(s, dir, lines);
    out.type = without_bezier(s.type);
    return out;
}

Expected<KnotSplit<Curve>> split_knot(const Curve& c, double knot, std::optional<double> delta) {
    auto place = place_split(c.knots, knot, delta);
    if (!place) return place.error();
    KnotSplit<Curve> out{c, 0.0};
    out.result.knots[place->index] = place->value;
    if (is_bezier(c.type)) out.result.type = without_bezier(c.type);
    const Interval a = domain(c);
    const Interval b = domain(out.result);
    for (double t : sample_params(std::max(a.lo, b.lo), std::min(a.hi, b.hi),
                                  spans_of(out.result.knots, c.degree, c.count()))) {
        const auto before = curve_point(c, t), after = curve_point(out.result, t);
        if (before && after)
            out.max_change = std::max(out.max_change, glm::length(*after - *before));
    }
    return out;
}

Expected<KnotSplit<Surface>> split_knot(const Surface& s, Dir dir, double knot,
                                        std::optional<double> delta) {
    auto place = place_split(s.knots(dir), knot, delta);
    if (!place) return place.error();
    KnotSplit<Surface> out{s, 0.0};
    (dir == Dir::u ? out.result.knots_u : out.result.knots_v)[place->index] = place->value;
    if (is_bezier(s.type)) out.result.type = without_bezier(s.type);
    std::vector<double> params[2];
    for (Dir d : {Dir::u, Dir::v}) {
        const Interval a = domain(s, d);
        const Interval b = domain(out.result, d);
        // Fewer samples across the split direction's partner keep the grid near 4096 x 64.
        params[d == Dir::u ? 0 : 1] =
            sample_params(std::max(a.lo, b.lo), std::min(a.hi, b.hi),
                          d == dir ? spans_of(out.result.knots(d), s.degree(d), s.count(d)) : 2);
    }
    for (double u : params[0])
        for (double v : params[1]) {
            const auto before = surface_point(s, u, v), after = surface_point(out.result, u, v);
            if (before && after)
                out.max_change = std::max(out.max_change, glm::length(*after - *before));
        }
    return out;
}

} // namespace isoparm::geom
