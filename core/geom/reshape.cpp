#include "core/geom/reshape.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/basis.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/work_budget.hpp"

namespace isoparm::geom {

namespace {

SplineType without_bezier(SplineType t) {
    return is_rational(t) ? SplineType::nurbs : SplineType::bspline;
}

// How far a split moved the shape: the largest distance between the old and new curve (or
// surface) over their common domain. The difference is a polynomial (rational) on each piece
// between consecutive breakpoints of either knot vector, so each piece is sampled on its own,
// its ends included as that piece's own limits: at a knot of multiplicity p + 1 the curve
// jumps, and the supremum is the limit from the side where the distance is largest (the
// settled reading of geom-protocol-2.md). Samples: up to 32 a piece, at most 4096 along the
// split direction (64 across it, for a surface).
constexpr int samples_per_piece = 32;
constexpr int max_samples_split = 4096;
constexpr int max_samples_across = 64;

// A piece [lo, hi] between consecutive distinct breakpoints and the span of each knot vector
// it lies in.
struct Piece {
    double lo = 0, hi = 0;
    int span_before = 0, span_after = 0;
};

std::vector<Piece> pieces_of(const Knots& before, const Knots& after, int p, int n, double lo,
                             double hi) {
    std::vector<double> cuts{lo, hi};
    for (const Knots* U : {&before, &after})
        for (double t : *U)
            if (t > lo && t < hi) cuts.push_back(t);
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    std::vector<Piece> out;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
        out.push_back({cuts[k], cuts[k + 1], find_span(before, p, n, cuts[k]),
                       find_span(after, p, n, cuts[k])});
    return out;
}

int samples_for(std::size_t pieces, int most) {
    return std::clamp(most / static_cast<int>(std::max<std::size_t>(pieces, 1)), 1,
                      samples_per_piece);
}

double sample(const Piece& piece, int k, int m) {
    return k == m ? piece.hi : piece.lo + (piece.hi - piece.lo) * k / m;
}

// The point of the polynomial piece on knot span `span` at t, also at the span's ends (its
// limits there): Piegl & Tiller A2.2 evaluates a span's basis polynomials at any t.
std::optional<glm::dvec3> piece_point(const Curve& c, int span, double t) {
    std::vector<double> N(static_cast<std::size_t>(c.degree) + 1);
    basis_funs(span, t, c.degree, c.knots, N.data());
    HPoint sum{0, 0, 0, 0};
    for (int j = 0; j <= c.degree; ++j) sum += N[j] * c.hpoint(span - c.degree + j);
    if (sum.w == 0) return std::nullopt;
    return glm::dvec3(sum) / sum.w;
}

std::optional<glm::dvec3> piece_point(const Surface& s, int span_u, int span_v, double u,
                                      double v) {
    std::vector<double> Nu(static_cast<std::size_t>(s.degree_u) + 1),
        Nv(static_cast<std::size_t>(s.degree_v) + 1);
    basis_funs(span_u, u, s.degree_u, s.knots_u, Nu.data());
    basis_funs(span_v, v, s.degree_v, s.knots_v, Nv.data());
    HPoint sum{0, 0, 0, 0};
    for (int a = 0; a <= s.degree_u; ++a)
        for (int b = 0; b <= s.degree_v; ++b)
            sum += Nu[a] * Nv[b] * s.hpoint(span_u - s.degree_u + a, span_v - s.degree_v + b);
    if (sum.w == 0) return std::nullopt;
    return glm::dvec3(sum) / sum.w;
}

double common_lo(const Interval& a, const Interval& b) {
    return std::max(a.lo, b.lo);
}
double common_hi(const Interval& a, const Interval& b) {
    return std::min(a.hi, b.hi);
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

Expected<KnotSplit<Curve>> split_knot(const Curve& c, double knot, std::optional<double> delta,
                                      const std::string& budget_path) {
    auto place = place_split(c.knots, knot, delta);
    if (!place) return place.error();
    KnotSplit<Curve> out{c, 0.0};
    out.result.knots[place->index] = place->value;
    if (is_bezier(c.type)) out.result.type = without_bezier(c.type);
    const Interval a = domain(c), b = domain(out.result);
    const std::vector<Piece> pieces =
        pieces_of(c.knots, out.result.knots, c.degree, c.count(), common_lo(a, b), common_hi(a, b));
    const int m = samples_for(pieces.size(), max_samples_split);
    const double count = static_cast<double>(pieces.size()) * (m + 1);
    if (Status ok =
            spend_work({2 * estimate_curve_evaluation(count, c.degree, 0).steps, 0}, budget_path,
                       "measuring the change at " + with_thousands(count) + " points of a degree-" +
                           std::to_string(c.degree) + " curve");
        !ok)
        return ok.error();
    for (const Piece& piece : pieces)
        for (int k = 0; k <= m; ++k) {
            const double t = sample(piece, k, m);
            const auto before = piece_point(c, piece.span_before, t);
            const auto after = piece_point(out.result, piece.span_after, t);
            if (before && after)
                out.max_change = std::max(out.max_change, glm::length(*after - *before));
        }
    return out;
}

Expected<KnotSplit<Surface>> split_knot(const Surface& s, Dir dir, double knot,
                                        std::optional<double> delta,
                                        const std::string& budget_path) {
    auto place = place_split(s.knots(dir), knot, delta);
    if (!place) return place.error();
    KnotSplit<Surface> out{s, 0.0};
    (dir == Dir::u ? out.result.knots_u : out.result.knots_v)[place->index] = place->value;
    if (is_bezier(s.type)) out.result.type = without_bezier(s.type);
    std::vector<Piece> pieces[2];
    int samples[2];
    for (Dir d : {Dir::u, Dir::v}) {
        const int k = d == Dir::u ? 0 : 1;
        const Interval a = domain(s, d), b = domain(out.result, d);
        pieces[k] = pieces_of(s.knots(d), out.result.knots(d), s.degree(d), s.count(d),
                              common_lo(a, b), common_hi(a, b));
        samples[k] =
            samples_for(pieces[k].size(), d == dir ? max_samples_split : max_samples_across);
    }
    const double count = static_cast<double>(pieces[0].size()) * (samples[0] + 1) *
                         static_cast<double>(pieces[1].size()) * (samples[1] + 1);
    if (Status ok = spend_work(
            {2 * estimate_surface_evaluation(count, s.degree_u, s.degree_v, 0, false).steps, 0},
            budget_path,
            "measuring the change at " + with_thousands(count) + " points of a degree (" +
                std::to_string(s.degree_u) + ", " + std::to_string(s.degree_v) + ") surface");
        !ok)
        return ok.error();
    for (const Piece& pu : pieces[0])
        for (int i = 0; i <= samples[0]; ++i)
            for (const Piece& pv : pieces[1])
                for (int j = 0; j <= samples[1]; ++j) {
                    const double u = sample(pu, i, samples[0]), v = sample(pv, j, samples[1]);
                    const auto before = piece_point(s, pu.span_before, pv.span_before, u, v);
                    const auto after = piece_point(out.result, pu.span_after, pv.span_after, u, v);
                    if (before && after)
                        out.max_change = std::max(out.max_change, glm::length(*after - *before));
                }
    return out;
}

} // namespace isoparm::geom
