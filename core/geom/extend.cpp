#include "core/geom/extend.hpp"

#include <algorithm>
#include <cmath>

#include "core/geom/deboor.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/refine.hpp"

namespace isoparm::geom {

namespace {

// A Bezier type says "one piece on [0, 1]"; continued, it is the B-spline form of that piece.
SplineType spline_type_of(SplineType t) {
    if (t == SplineType::bezier) return SplineType::bspline;
    if (t == SplineType::rational_bezier) return SplineType::nurbs;
    return t;
}

std::string interval_text(Interval i) {
    return "[" + format_number(i.lo) + ", " + format_number(i.hi) + "]";
}

} // namespace

Expected<Curve> extend_domain(const Curve& c, Interval to) {
    const int p = c.degree, n = c.count();
    if (!is_clamped(c.knots, p, n))
        return make_error(ErrorCode::schema,
                          "only a curve clamped at both ends can be extended (its end knots "
                          "repeated degree + 1 times)",
                          "/knots");
    const Interval d = domain(c);
    if (!std::isfinite(to.lo) || !std::isfinite(to.hi) || !(to.lo <= d.lo && to.hi >= d.hi))
        return make_error(ErrorCode::domain,
                          "the extended domain " + interval_text(to) +
                              " must be finite and hold the domain " + interval_text(d),
                          "/domain");
    const std::vector<HPoint> Pw = homogeneous_points(c);
    Knots U = c.knots;
    for (int k = 0; k <= p; ++k) {
        U[k] = to.lo;
        U[n + k] = to.hi;
    }
    std::vector<HPoint> out = Pw;
    // Each replaced control point is a blossom of an end piece at its new knots; every piece it
    // spans gives the same value there, since its arguments hold all the interior knots between.
    const auto blossom_at_new_knots = [&](int span, int i) {
        const std::vector<double> args(U.begin() + i + 1, U.begin() + i + p + 1);
        return deboor_polar(c.knots, p, Pw, span, args).levels.back().front();
    };
    if (to.lo < d.lo) {
        const int first = find_span(c.knots, p, n, d.lo);
        for (int i = 0; i < std::min(p, n); ++i) out[i] = blossom_at_new_knots(first, i);
    }
    if (to.hi > d.hi) {
        const int last = find_span(c.knots, p, n, d.hi);
        for (int i = std::max(0, n - p); i < n; ++i) out[i] = blossom_at_new_knots(last, i);
    }
    Curve e = c;
    e.type = spline_type_of(c.type);
    e.knots = std::move(U);
    const auto replaced = [&](int i) {
        return (to.lo < d.lo && i < p) || (to.hi > d.hi && i >= n - p);
    };
    for (int i = 0; i < n; ++i) {
        if (!replaced(i)) continue; // kept exactly (no round trip through w P / w)
        const HPoint& h = out[static_cast<std::size_t>(i)];
        if (!is_rational(c.type)) {
            e.points[i] = glm::dvec3(h); // an affine combination of unit-weight points
            continue;
        }
        // A continuation whose control weight is not positive may have a zero weight (a point
        // at infinity) within `to`: refused, not guessed at.
        if (!(h.w > 0))
            return make_error(ErrorCode::weights,
                              "continued to " + interval_text(to) + ", control point " +
                                  std::to_string(i) + " would have weight " + format_number(h.w) +
                                  " (not positive): the rational end piece cannot be extended "
                                  "that far",
                              "/weights/" + std::to_string(i));
        e.points[i] = glm::dvec3(h) / h.w;
        e.weights[i] = h.w;
    }
    return e;
}

Expected<Surface> extend_domain(const Surface& s, const ParamRect& to) {
    Surface out = s;
    for (const Dir dir : {Dir::u, Dir::v}) {
        const int across = out.count(opposite(dir));
        std::vector<Curve> lines;
        lines.reserve(static_cast<std::size_t>(across));
        for (int l = 0; l < across; ++l) {
            Expected<Curve> r = extend_domain(surface_line(out, dir, l), to.interval(dir));
            if (!r) return r.error();
            lines.push_back(std::move(r).value());
        }
        const SplineType type = spline_type_of(out.type);
        out = surface_from_lines(out, dir, lines);
        out.type = type;
    }
    return out;
}

} // namespace isoparm::geom
