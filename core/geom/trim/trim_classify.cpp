// Point classification in a trimmed domain: ray parity on chords, the curves themselves near a
// loop.
#include "core/geom/trim/trim_classify.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::geom {

namespace {

constexpr double classify_flatness = 1e-6; // of the domain's size
constexpr double default_boundary = 1e-9;

double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    if (len2 == 0.0) return glm::length(p - a);
    const double s = std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0);
    return glm::length(p - (a + s * ab));
}

// Even-odd crossings of the ray from p toward +u with a closed polyline.
bool odd_crossings(glm::dvec2 p, const std::vector<glm::dvec2>& poly) {
    bool odd = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const glm::dvec2 a = poly[i], b = poly[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x))
            odd = !odd;
    }
    return odd;
}

// The distance from p to curve c near parameter t (in [lo, hi]), by Newton's method on
// (C(t) - p) . C'(t) = 0 (Piegl & Tiller eq. 6.3), kept inside [lo, hi].
double nearest_on_curve(const Curve& c, glm::dvec2 p, double t, double lo, double hi) {
    double best = INFINITY;
    for (int it = 0; it < 12; ++it) {
        const auto d = curve_derivatives(c, t, 2);
        if (!d) break;
        const glm::dvec2 r = uv((*d)[0]) - p, c1 = uv((*d)[1]), c2 = uv((*d)[2]);
        best = std::min(best, glm::length(r));
        const double f = glm::dot(r, c1), df = glm::dot(c2, r) + glm::dot(c1, c1);
        if (df <= 0) break;
        const double next = std::clamp(t - f / df, lo, hi);
        if (next == t) break;
        t = next;
    }
    return best;
}

} // namespace

TrimClassifier::TrimClassifier(const Trim& trim, const ParamRect& domain, double boundary_tolerance)
    : trim_(trim), domain_(domain) {
    const double scale = domain_scale(domain);
    boundary_tolerance_ = boundary_tolerance >= 0 ? boundary_tolerance : default_boundary * scale;
    flatness_ = classify_flatness * scale;
    FlattenRule rule;
    rule.tolerance = flatness_;
    std::size_t chords = 0;
    for (int k = 0; k < trim_.loop_count(); ++k) {
        flats_.push_back(flatten_loop(trim_.loop(k), rule));
        chords += flats_.back().points.size();
    }
    g_ = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(chords))), 1, 512);
    cells_.resize(static_cast<std::size_t>(g_) * g_);
    rows_.resize(static_cast<std::size_t>(g_));
    const double band = 2 * flatness_;
    for (int l = 0; l < static_cast<int>(flats_.size()); ++l) {
        const auto& pts = flats_[static_cast<std::size_t>(l)].points;
        for (int k = 0; k < static_cast<int>(pts.size()); ++k) {
            const Chord c{l, k};
            const glm::dvec2 a = chord_start(c), b = chord_end(c);
            const glm::dvec2 lo = glm::min(a, b) - band, hi = glm::max(a, b) + band;
            const int i0 = bucket(lo.x, domain_.u.lo, domain_.u.hi);
            const int i1 = bucket(hi.x, domain_.u.lo, domain_.u.hi);
            const int j0 = bucket(lo.y, domain_.v.lo, domain_.v.hi);
            const int j1 = bucket(hi.y, domain_.v.lo, domain_.v.hi);
            for (int i = i0; i <= i1; ++i)
                for (int j = j0; j <= j1; ++j)
                    cells_[static_cast<std::size_t>(i) * g_ + j].push_back(c);
            for (int j = j0; j <= j1; ++j) rows_[static_cast<std::size_t>(j)].push_back(c);
        }
    }
}

int TrimClassifier::bucket(double t, double lo, double hi) const {
    const double f = (t - lo) / (hi - lo) * g_;
    if (!(f > 0)) return 0;
    return std::min(g_ - 1, static_cast<int>(f));
}

glm::dvec2 TrimClassifier::chord_start(const Chord& c) const {
    return flats_[static_cast<std::size_t>(c.loop)].points[static_cast<std::size_t>(c.index)];
}

glm::dvec2 TrimClassifier::chord_end(const Chord& c) const {
    const auto& pts = flats_[static_cast<std::size_t>(c.loop)].points;
    return pts[(static_cast<std::size_t>(c.index) + 1) % pts.size()];
}

bool TrimClassifier::kept_by_parity(glm::dvec2 p, const std::vector<FlatLoop>& flats) const {
    // Without an outer loop the domain rectangle is the outer boundary: start inside it.
    bool kept = !trim_.outer;
    for (const FlatLoop& f : flats) kept ^= odd_crossings(p, f.points);
    return kept;
}

bool TrimClassifier::kept_by_rows(glm::dvec2 p) const {
    bool kept = !trim_.outer;
    // The row holds every chord whose v range reaches p's row (p is inside the domain here).
    for (const Chord& c :
         rows_[static_cast<std::size_t>(bucket(p.y, domain_.v.lo, domain_.v.hi))]) {
        const glm::dvec2 a = chord_start(c), b = chord_end(c);
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x))
            kept = !kept;
    }
    return kept;
}

double TrimClassifier::chord_distance(glm::dvec2 p) const {
    double best = INFINITY;
    for (const FlatLoop& f : flats_) {
        const std::size_t n = f.points.size();
        for (std::size_t k = 0; k < n; ++k)
            best = std::min(best, distance_to_segment(p, f.points[k], f.points[(k + 1) % n]));
    }
    return best;
}

double TrimClassifier::near_chord_distance(glm::dvec2 p) const {
    double best = INFINITY;
    const int i = bucket(p.x, domain_.u.lo, domain_.u.hi),
              j = bucket(p.y, domain_.v.lo, domain_.v.hi);
    for (const Chord& c : cells_[static_cast<std::size_t>(i) * g_ + j])
        best = std::min(best, distance_to_segment(p, chord_start(c), chord_end(c)));
    return best;
}

double TrimClassifier::curve_distance(glm::dvec2 p, double band) const {
    double best = INFINITY;
    for (int l = 0; l < trim_.loop_count(); ++l) {
        const FlatLoop& f = flats_[static_cast<std::size_t>(l)];
        const TrimLoop& loop = trim_.loop(l);
        const std::size_t n = f.points.size();
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t next = (k + 1) % n;
            if (distance_to_segment(p, f.points[k], f.points[next]) > band) continue;
            const Curve& c = loop.curves[static_cast<std::size_t>(f.curve[k])];
            const double lo = f.param[k];
            const double hi = f.curve[next] == f.curve[k] ? f.param[next] : domain(c).hi;
            best = std::min(best, nearest_on_curve(c, p, 0.5 * (lo + hi), lo, hi));
        }
    }
    return best;
}

double TrimClassifier::distance_to_boundary(glm::dvec2 p) const {
    double best = INFINITY;
    if (!trim_.outer) {
        if (domain_.contains(p)) {
            best = std::min(
                {p.x - domain_.u.lo, domain_.u.hi - p.x, p.y - domain_.v.lo, domain_.v.hi - p.y});
        } else {
            const glm::dvec2 q{std::clamp(p.x, domain_.u.lo, domain_.u.hi),
                               std::clamp(p.y, domain_.v.lo, domain_.v.hi)};
            best = glm::length(p - q);
        }
    }
    const double chords = chord_distance(p);
    if (chords > 2 * flatness_) return std::min(best, chords - flatness_);
    return std::min(best, curve_distance(p, 2 * flatness_));
}

TrimSide TrimClassifier::classify(glm::dvec2 p) const {
    const double tol = boundary_tolerance_;
    const ParamRect wide{{domain_.u.lo - tol, domain_.u.hi + tol},
                         {domain_.v.lo - tol, domain_.v.hi + tol}};
    if (!wide.contains(p)) return TrimSide::cut;
    double edge = INFINITY; // to the domain's edge, where that is the outer boundary
    if (!trim_.outer) {
        edge = std::max(
            {domain_.u.lo - p.x, p.x - domain_.u.hi, domain_.v.lo - p.y, p.y - domain_.v.hi});
        edge = std::abs(edge) <= tol ? 0.0 : INFINITY;
    }
    if (edge == 0.0) return TrimSide::boundary;
    const bool near = near_chord_distance(p) <= 2 * flatness_;
    if (near && curve_distance(p, 2 * flatness_) <= tol) return TrimSide::boundary;
    if (!domain_.contains(p)) return TrimSide::cut; // past the domain's edge, beyond tolerance
    if (!near) return kept_by_rows(p) ? TrimSide::kept : TrimSide::cut;
    // Near a loop but off it: chords closer to the curves than p is decide.
    FlattenRule rule;
    rule.tolerance = std::max(curve_distance(p, 2 * flatness_), tol) / 4;
    rule.max_depth = 48;
    std::vector<FlatLoop> fine;
    for (int k = 0; k < trim_.loop_count(); ++k) fine.push_back(flatten_loop(trim_.loop(k), rule));
    return kept_by_parity(p, fine) ? TrimSide::kept : TrimSide::cut;
}

} // namespace isoparm::geom
