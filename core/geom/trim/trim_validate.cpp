// Trim validation: each loop's curves, closure, domain and orientation, then crossings (chords
// bucketed on a grid, so a check costs about linear time) and nesting.
#include "core/geom/trim/trim_validate.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <tuple>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/trim/trim_flatten.hpp"
#include "core/geom/validate.hpp"

namespace isoparm::geom {

namespace {

std::string point_text(glm::dvec2 p) {
    return "(u, v) = (" + format_short(p.x, 6) + ", " + format_short(p.y, 6) + ")";
}

std::string rect_text(const ParamRect& d) {
    return "[" + format_number(d.u.lo) + ", " + format_number(d.u.hi) + "] x [" +
           format_number(d.v.lo) + ", " + format_number(d.v.hi) + "]";
}

double cross(glm::dvec2 a, glm::dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

int sign(double x) {
    return (x > 0) - (x < 0);
}

// Whether segments pq and rs meet (crossing, touching or overlapping), and where.
std::optional<glm::dvec2> segments_meet(glm::dvec2 p, glm::dvec2 q, glm::dvec2 r, glm::dvec2 s) {
    const int o1 = sign(cross(q - p, r - p)), o2 = sign(cross(q - p, s - p));
    const int o3 = sign(cross(s - r, p - r)), o4 = sign(cross(s - r, q - r));
    auto on = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) { // c on segment ab, collinear
        return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) &&
               std::min(a.y, b.y) <= c.y && c.y <= std::max(a.y, b.y);
    };
    if (o1 != o2 && o3 != o4) {
        const glm::dvec2 d1 = q - p, d2 = s - r;
        const double den = cross(d1, d2);
        if (den == 0) return p;
        return p + d1 * (cross(r - p, d2) / den);
    }
    if (o1 == 0 && on(p, q, r)) return r;
    if (o2 == 0 && on(p, q, s)) return s;
    if (o3 == 0 && on(r, s, p)) return p;
    if (o4 == 0 && on(r, s, q)) return q;
    return std::nullopt;
}

struct Segment {
    int loop, index;
    glm::dvec2 a, b;
};

// Neighbours on one loop share an end; they meet only by folding back along each other.
bool neighbours(const Segment& s, const Segment& t, std::size_t loop_size) {
    if (s.loop != t.loop) return false;
    const auto n = static_cast<int>(loop_size);
    return (s.index + 1) % n == t.index || (t.index + 1) % n == s.index;
}

bool folds_back(const Segment& s, const Segment& t) {
    // s ends where t starts (or the other way round): collinear and turning back is an overlap.
    const Segment& first = s.b == t.a ? s : t;
    const Segment& second = s.b == t.a ? t : s;
    const glm::dvec2 d1 = first.b - first.a, d2 = second.b - second.a;
    return cross(d1, d2) == 0 && glm::dot(d1, d2) < 0;
}

// Segments of two loops that meet at `where` touch there: `where` is within `touch` of an end
// of either, and they do not run along each other for longer than `touch`.
bool is_touch(const Segment& s, const Segment& t, glm::dvec2 where, double touch) {
    const bool at_end = glm::length(where - s.a) <= touch || glm::length(where - s.b) <= touch ||
                        glm::length(where - t.a) <= touch || glm::length(where - t.b) <= touch;
    if (!at_end) return false;
    const glm::dvec2 d = s.b - s.a;
    const double len = glm::length(d);
    if (len == 0) return true;
    // Collinear within `touch`: the overlap of t's projection on s.
    const double da = std::abs(cross(d, t.a - s.a)) / len, db = std::abs(cross(d, t.b - s.a)) / len;
    if (da > touch || db > touch) return true;
    const double ta = glm::dot(t.a - s.a, d) / len, tb = glm::dot(t.b - s.a, d) / len;
    const double overlap = std::min(len, std::max(ta, tb)) - std::max(0.0, std::min(ta, tb));
    return overlap <= touch;
}

} // namespace

std::optional<Crossing> find_crossing(const std::vector<std::vector<glm::dvec2>>& loops,
                                      double touch, std::vector<Crossing>* touches) {
    std::vector<Segment> segments;
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    for (std::size_t l = 0; l < loops.size(); ++l) {
        const auto& pts = loops[l];
        for (std::size_t k = 0; k < pts.size(); ++k) {
            segments.push_back(
                {static_cast<int>(l), static_cast<int>(k), pts[k], pts[(k + 1) % pts.size()]});
            lo = glm::min(lo, pts[k]);
            hi = glm::max(hi, pts[k]);
        }
    }
    if (segments.size() < 2) return std::nullopt;
    // Buckets: about one segment per cell, so each segment meets a few others.
    const int g =
        std::clamp(static_cast<int>(std::sqrt(static_cast<double>(segments.size()))), 1, 1024);
    const glm::dvec2 size = glm::max(hi - lo, glm::dvec2(1e-300));
    auto cell = [&](double x, double origin, double extent) {
        return std::clamp(static_cast<int>((x - origin) / extent * g), 0, g - 1);
    };
    std::vector<std::vector<int>> buckets(static_cast<std::size_t>(g) * g);
    for (std::size_t k = 0; k < segments.size(); ++k) {
        const Segment& s = segments[k];
        const int i0 = cell(std::min(s.a.x, s.b.x), lo.x, size.x);
        const int i1 = cell(std::max(s.a.x, s.b.x), lo.x, size.x);
        const int j0 = cell(std::min(s.a.y, s.b.y), lo.y, size.y);
        const int j1 = cell(std::max(s.a.y, s.b.y), lo.y, size.y);
        for (int i = i0; i <= i1; ++i)
            for (int j = j0; j <= j1; ++j)
                buckets[static_cast<std::size_t>(i) * g + j].push_back(static_cast<int>(k));
    }
    std::optional<Crossing> best;
    auto key = [](const Crossing& c) {
        return std::tuple(c.loop_a, c.segment_a, c.loop_b, c.segment_b);
    };
    for (const auto& bucket : buckets) {
        for (std::size_t x = 0; x < bucket.size(); ++x) {
            for (std::size_t y = x + 1; y < bucket.size(); ++y) {
                const Segment& s = segments[static_cast<std::size_t>(bucket[x])];
                const Segment& t = segments[static_cast<std::size_t>(bucket[y])];
                std::optional<glm::dvec2> where;
                if (neighbours(s, t, loops[static_cast<std::size_t>(s.loop)].size())) {
                    if (loops[static_cast<std::size_t>(s.loop)].size() > 2 && folds_back(s, t))
                        where = s.b == t.a ? s.b : s.a;
                } else {
                    where = segments_meet(s.a, s.b, t.a, t.b);
                }
                if (!where) continue;
                Crossing c{s.loop, s.index, t.loop, t.index, *where};
                if (std::tie(t.loop, t.index) < std::tie(s.loop, s.index))
                    c = {t.loop, t.index, s.loop, s.index, *where};
                if (touches && s.loop != t.loop && is_touch(s, t, *where, touch)) {
                    touches->push_back(c);
                    continue;
                }
                if (!best || key(c) < key(*best)) best = c;
            }
        }
    }
    return best;
}

namespace {

// A loop's chords without repeated points, remembering each point's curve.
struct CheckedLoop {
    std::vector<glm::dvec2> points;
    std::vector<int> curve;
};

CheckedLoop chords(const TrimLoop& loop, double flatness) {
    FlattenRule rule;
    rule.tolerance = flatness;
    const FlatLoop flat = flatten_loop(loop, rule);
    CheckedLoop out;
    for (std::size_t k = 0; k < flat.points.size(); ++k) {
        if (!out.points.empty() && flat.points[k] == out.points.back()) continue;
        out.points.push_back(flat.points[k]);
        out.curve.push_back(flat.curve[k]);
    }
    while (out.points.size() > 1 && out.points.back() == out.points.front()) {
        out.points.pop_back();
        out.curve.pop_back();
    }
    return out;
}

Status check_curves(const Trim& trim, int k, const ParamRect& domain) {
    const TrimLoop& loop = trim.loop(k);
    const std::string at = loop_path(trim, k), name = loop_name(trim, k);
    if (loop.curves.empty())
        return make_error(ErrorCode::schema, name + " has no curves: a loop needs at least one",
                          at);
    for (std::size_t c = 0; c < loop.curves.size(); ++c) {
        const Curve& curve = loop.curves[c];
        const std::string cat = at + pointer_step(static_cast<long>(c));
        if (auto v = validate_curve(curve); !v) {
            Error e = v.error().under(cat);
            e.message = name + ", curve " + std::to_string(c) + ": " + e.message;
            return e;
        }
        for (std::size_t w = 0; w < curve.weights.size(); ++w) {
            if (!(curve.weights[w] > 0))
                return make_error(ErrorCode::weights,
                                  name + ", curve " + std::to_string(c) + ": weight " +
                                      std::to_string(w) + " is " + format_number(curve.weights[w]) +
                                      "; trim curves need positive weights",
                                  cat + "/weights" + pointer_step(static_cast<long>(w)));
        }
    }
    // Closed: each curve starts where the one before it ends.
    const double gap = trim_gap * domain_scale(domain);
    for (std::size_t c = 0; c < loop.curves.size(); ++c) {
        const std::size_t before = (c + loop.curves.size() - 1) % loop.curves.size();
        const glm::dvec2 end = *curve_end(loop.curves[before]);
        const glm::dvec2 start = *curve_start(loop.curves[c]);
        const double d = glm::length(start - end);
        if (d > gap) {
            const std::string what =
                loop.curves.size() == 1
                    ? "its curve ends at " + point_text(end) + " but starts at " + point_text(start)
                    : "curve " + std::to_string(before) + " ends at " + point_text(end) +
                          " but curve " + std::to_string(c) + " starts at " + point_text(start);
            return make_error(ErrorCode::geometry,
                              name + " is not closed: " + what + " (a gap of " +
                                  format_short(d, 3) + "; at most " + format_short(gap, 3) +
                                  " closes)",
                              at + pointer_step(static_cast<long>(c)));
        }
    }
    return Ok{};
}

Status check_domain(const Trim& trim, int k, const CheckedLoop& flat, const ParamRect& domain) {
    const double gap = trim_gap * domain_scale(domain);
    const ParamRect wide{{domain.u.lo - gap, domain.u.hi + gap},
                         {domain.v.lo - gap, domain.v.hi + gap}};
    for (std::size_t p = 0; p < flat.points.size(); ++p) {
        if (wide.contains(flat.points[p])) continue;
        return make_error(ErrorCode::domain,
                          loop_name(trim, k) + " leaves the domain " + rect_text(domain) +
                              ": curve " + std::to_string(flat.curve[p]) + " reaches " +
                              point_text(flat.points[p]),
                          loop_path(trim, k) + pointer_step(flat.curve[p]));
    }
    return Ok{};
}

// Even-odd test of a point against a closed polygon.
bool inside_polygon(glm::dvec2 p, const std::vector<glm::dvec2>& poly) {
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const glm::dvec2 a = poly[i], b = poly[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x))
            in = !in;
    }
    return in;
}

// The points of loop k that decide where it lies: its first point, or, where it touches
// another loop, each of its points farther than `near` from every touching point (a point at a
// touch lies on both loops, so on neither side).
std::vector<glm::dvec2> witnesses(int k, const CheckedLoop& flat,
                                  const std::vector<Crossing>& touches, double near) {
    std::vector<glm::dvec2> at;
    for (const Crossing& t : touches)
        if (t.loop_a == k || t.loop_b == k) at.push_back(t.where);
    if (at.empty()) return {flat.points.front()};
    std::vector<glm::dvec2> out;
    for (const glm::dvec2& p : flat.points)
        if (std::all_of(at.begin(), at.end(),
                        [&](glm::dvec2 q) { return glm::length(p - q) > near; }))
            out.push_back(p);
    return out;
}

// Each hole inside the outer loop and outside every other hole.
Status check_nesting(const Trim& trim, const std::vector<CheckedLoop>& flats,
                     const std::vector<Crossing>& touches, double near) {
    const int first_hole = trim.outer ? 1 : 0;
    for (int k = first_hole; k < trim.loop_count(); ++k) {
        for (const glm::dvec2& p :
             witnesses(k, flats[static_cast<std::size_t>(k)], touches, near)) {
            if (trim.outer && !inside_polygon(p, flats[0].points))
                return make_error(ErrorCode::geometry,
                                  loop_name(trim, k) + " lies outside the outer loop",
                                  loop_path(trim, k));
            for (int h = first_hole; h < trim.loop_count(); ++h) {
                if (h == k || !inside_polygon(p, flats[static_cast<std::size_t>(h)].points))
                    continue;
                return make_error(ErrorCode::geometry,
                                  loop_name(trim, k) + " lies inside " + loop_name(trim, h) +
                                      " (a region cut away already)",
                                  loop_path(trim, k));
            }
        }
    }
    return Ok{};
}

} // namespace

Status validate_trim(const Trim& trim, const ParamRect& domain) {
    const double flatness = trim_check_flatness * domain_scale(domain);
    std::vector<CheckedLoop> flats;
    for (int k = 0; k < trim.loop_count(); ++k) {
        if (auto s = check_curves(trim, k, domain); !s) return s;
        flats.push_back(chords(trim.loop(k), flatness));
        const CheckedLoop& flat = flats.back();
        if (auto s = check_domain(trim, k, flat, domain); !s) return s;
        const std::string at = loop_path(trim, k), name = loop_name(trim, k);
        if (auto c = find_crossing({flat.points})) {
            const int ca = flat.curve[static_cast<std::size_t>(c->segment_a)];
            const int cb = flat.curve[static_cast<std::size_t>(c->segment_b)];
            const std::string curves =
                ca == cb
                    ? "its curve " + std::to_string(ca) + " meets itself"
                    : "its curves " + std::to_string(ca) + " and " + std::to_string(cb) + " meet";
            return make_error(ErrorCode::geometry,
                              name + " is self-intersecting: " + curves + " at " +
                                  point_text(c->where),
                              at + pointer_step(ca));
        }
        const double area = twice_signed_area(flat.points);
        if (std::abs(area) <= flatness * flatness)
            return make_error(ErrorCode::geometry, name + " encloses no area", at);
        const bool outer = trim.is_outer(k);
        if (outer && area < 0)
            return make_error(ErrorCode::geometry,
                              name + " runs clockwise; the outer loop must run counter-clockwise "
                                     "(the kept region lies to the left of every loop)",
                              at);
        if (!outer && area > 0)
            return make_error(ErrorCode::geometry,
                              name + " runs counter-clockwise; a hole must run clockwise (the "
                                     "kept region lies to the left of every loop)",
                              at);
    }
    std::vector<std::vector<glm::dvec2>> all;
    for (const CheckedLoop& f : flats) all.push_back(f.points);
    std::vector<Crossing> touches;
    if (auto c = find_crossing(all, trim_touch * domain_scale(domain), &touches)) {
        // Within one loop there are none (checked above): two loops meet.
        return make_error(ErrorCode::geometry,
                          loop_name(trim, c->loop_b) + " crosses " + loop_name(trim, c->loop_a) +
                              " at " + point_text(c->where),
                          loop_path(trim, c->loop_b));
    }
    return check_nesting(trim, flats, touches, flatness);
}

} // namespace isoparm::geom
