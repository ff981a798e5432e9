// Degree reduction of curves and surfaces (Piegl & Tiller A5.11, eq. 5.41-5.46) with its error
// bound.
#include "core/geom/degree_reduction.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <vector>

#include "core/geom/knot_removal.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/refine.hpp"

namespace isoparm::geom {

namespace {

double point_distance(const HPoint& a, const HPoint& b, bool with_weights) {
    return with_weights ? glm::distance(a, b) : glm::distance(glm::dvec3(a), glm::dvec3(b));
}

// Eq. 5.41 from the left, eq. 5.42 from the right: the Bezier piece P_0..P_p of degree p as
// Q_0..Q_(p-1) of degree p - 1; returns the error bound, eq. 5.45 (p even: the unused middle
// equation) or eq. 5.46 (p odd: Q_r computed from both sides, the average kept).
double reduce_bezier_piece(const HPoint* P, int p, HPoint* Q, bool with_weights) {
    const int r = (p - 1) / 2;
    auto alpha = [p](int i) { return static_cast<double>(i) / p; };
    Q[0] = P[0];
    Q[p - 1] = P[p];
    for (int i = 1; i <= r; ++i) Q[i] = (P[i] - alpha(i) * Q[i - 1]) / (1.0 - alpha(i));
    for (int i = p - 2; i >= r + 1; --i)
        Q[i] = (P[i + 1] - (1.0 - alpha(i + 1)) * Q[i + 1]) / alpha(i + 1);
    if (p % 2 == 0) return point_distance(P[r + 1], 0.5 * (Q[r] + Q[r + 1]), with_weights);
    const HPoint from_right = (P[r + 1] - (1.0 - alpha(r + 1)) * Q[r + 1]) / alpha(r + 1);
    const double bound = 0.5 * (1.0 - alpha(r)) * point_distance(Q[r], from_right, with_weights);
    Q[r] = 0.5 * (Q[r] + from_right);
    return bound;
}

struct ReducedHomogeneous {
    Knots knots;
    std::vector<HPoint> points;
    double bound = 0; // in the units of point_distance
};

// Removes knots (value, times) given in increasing order of value, one run at a time, left to
// right. A removal of A5.8 reads q + 2 knots on each side of its knot and changes the points
// just before it, so only a window of the curve is kept in play: the part before it is final,
// the part after it not yet read. (On the whole curve every removal would copy it all: hours for
// a degree-100 curve of 4,000 points.) `removed` sees every removal.
template <class Observer>
void remove_knots_in_order(int q, ReducedHomogeneous& curve,
                           const std::vector<std::pair<double, int>>& removals, bool with_weights,
                           Observer removed) {
    const Knots& U = curve.knots;
    const std::vector<HPoint>& P = curve.points;
    Knots done_knots, window_knots;
    std::vector<HPoint> done_points, window_points;
    size_t next = 0; // the first knot (and point) of `curve` not yet in the window
    auto read = [&] {
        window_knots.push_back(U[next]);
        if (next < P.size()) window_points.push_back(P[next]);
        ++next;
    };
    for (const auto& removal : removals) {
        // Plain names, not a structured binding: clang 14 (the fuzz build) cannot capture one.
        const auto value = removal.first;
        const auto times = removal.second;
        // Every copy of the knot and q + 2 knots after them.
        auto after = [&] {
            return window_knots.end() -
                   std::upper_bound(window_knots.begin(), window_knots.end(), value);
        };
        while (next < U.size() && (window_knots.empty() || after() < q + 2)) read();
        for (int k = 0; k < times; ++k) {
            const int r =
                static_cast<int>(std::upper_bound(window_knots.begin(), window_knots.end(), value) -
                                 window_knots.begin()) -
                1;
            OneKnotRemoval one = remove_knot_once(q, window_knots, window_points, r, with_weights);
            removed(one);
            window_knots = std::move(one.knots);
            window_points = std::move(one.points);
        }
        // Keep q + 1 knots before this one's first copy: the next knot needs them.
        const long first_copy = std::lower_bound(window_knots.begin(), window_knots.end(), value) -
                                window_knots.begin();
        const long final_count = std::max(0L, first_copy - q - 2);
        done_knots.insert(done_knots.end(), window_knots.begin(),
                          window_knots.begin() + final_count);
        done_points.insert(done_points.end(), window_points.begin(),
                           window_points.begin() + final_count);
        window_knots.erase(window_knots.begin(), window_knots.begin() + final_count);
        window_points.erase(window_points.begin(), window_points.begin() + final_count);
    }
    while (next < U.size()) read();
    done_knots.insert(done_knots.end(), window_knots.begin(), window_knots.end());
    done_points.insert(done_points.end(), window_points.begin(), window_points.end());
    curve.knots = std::move(done_knots);
    curve.points = std::move(done_points);
}

// A5.11 on a clamped homogeneous curve of degree p >= 2.
ReducedHomogeneous reduce_homogeneous(int p, const Knots& U0, std::vector<HPoint> Pw,
                                      bool with_weights) {
    const int n0 = static_cast<int>(Pw.size());
    const double a = U0[p], b = U0[n0];
    std::vector<KnotRun> interior;
    for (const KnotRun& run : knot_runs(U0))
        if (run.value > a && run.value < b) interior.push_back(run);

    // Bezier pieces (A5.4): every interior knot raised to multiplicity p (p + 1 stays).
    Knots U = U0;
    std::vector<double> X;
    for (const KnotRun& run : interior)
        for (int m = run.multiplicity; m < p; ++m) X.push_back(run.value);
    if (!X.empty()) refine_knot_vector(p, U, Pw, X);

    // Each piece reduced; pieces that meet share their end point (all but the knots of
    // multiplicity p + 1, where the curve may jump).
    const int q = p - 1;
    const size_t pieces = interior.size() + 1;
    std::vector<double> breaks{a}, piece_bound(pieces, 0.0);
    ReducedHomogeneous out;
    out.knots.assign(q + 1, a);
    std::vector<HPoint> reduced(p);
    int start = 0;
    for (size_t k = 0; k < pieces; ++k) {
        piece_bound[k] = reduce_bezier_piece(&Pw[start], p, reduced.data(), with_weights);
        const bool joined = k > 0 && interior[k - 1].multiplicity <= p;
        out.points.insert(out.points.end(), reduced.begin() + (joined ? 1 : 0), reduced.end());
        if (k + 1 < pieces) {
            const KnotRun& next = interior[k];
            breaks.push_back(next.value);
            out.knots.insert(out.knots.end(), next.multiplicity > p ? p : q, next.value);
            start += next.multiplicity > p ? p + 1 : p;
        }
    }
    breaks.push_back(b);
    out.knots.insert(out.knots.end(), q + 1, b);

    // Back to the original continuity, one multiplicity less (A5.8); every removal adds its
    // bound to the spans it can move.
    std::vector<std::pair<double, int>> removals;
    for (const KnotRun& run : interior)
        if (run.multiplicity <= p) removals.emplace_back(run.value, p - run.multiplicity);
    remove_knots_in_order(q, out, removals, with_weights, [&](const OneKnotRemoval& one) {
        const auto from = std::upper_bound(breaks.begin(), breaks.end(), one.moved_from);
        for (size_t s = from == breaks.begin() ? 0 : (from - breaks.begin()) - 1;
             s < pieces && breaks[s] < one.moved_to; ++s)
            if (breaks[s + 1] > one.moved_from) piece_bound[s] += one.distance;
    });
    out.bound = *std::max_element(piece_bound.begin(), piece_bound.end());
    return out;
}

Status check_tolerance(double tolerance) {
    if (std::isfinite(tolerance) && tolerance >= 0.0) return Ok{};
    return make_error(ErrorCode::schema,
                      "tolerance must be a finite number >= 0, got " + format_number(tolerance),
                      "/tolerance");
}

Status check_degree(int p, const std::string& path) {
    if (p >= 2) return Ok{};
    return make_error(ErrorCode::degree, "a degree-1 curve or direction cannot be reduced", path);
}

// The reduced line and its bound in model units.
Expected<CurveDegreeReduction> reduce_line(const Curve& line) {
    Expected<Curve> clamped = clamp(line);
    if (!clamped) return clamped.error();
    const bool rational = is_rational(line.type);
    ReducedHomogeneous r =
        reduce_homogeneous(line.degree, clamped->knots, homogeneous_points(*clamped), rational);
    Expected<Curve> reduced =
        curve_from_homogeneous(line, line.degree - 1, std::move(r.knots), r.points, nullptr);
    if (!reduced) return reduced.error();
    return CurveDegreeReduction{
        std::move(reduced).value(),
        cartesian_bound(r.bound, clamped->points, clamped->weights, rational)};
}

Status check_bound(double bound, double tolerance, int p, bool rational, const char* what,
                   const std::string& path) {
    if (bound <= tolerance) return Ok{};
    const std::string reduction = "reducing the degree of the " + std::string(what) + " from " +
                                  std::to_string(p) + " to " + std::to_string(p - 1);
    if (!std::isfinite(bound)) {
        const std::string why = rational ? " (a weight <= 0, or a bound in 4D above the smallest "
                                           "weight, leaves none in model units)"
                                         : " (it overflows: the curve is far from any of degree " +
                                               std::to_string(p - 1) + ")";
        return make_error(ErrorCode::geometry,
                          reduction + " has no finite error bound" + why + ", so the tolerance " +
                              format_number(tolerance) + " cannot be met",
                          path);
    }
    return make_error(ErrorCode::geometry,
                      reduction + " may move it by up to " + format_number(bound) +
                          " (the error bound of A5.11), more than the tolerance " +
                          format_number(tolerance),
                      path);
}

} // namespace

Expected<CurveDegreeReduction> reduce_degree(const Curve& c, double tolerance) {
    if (Status ok = check_tolerance(tolerance); !ok) return ok.error();
    if (Status ok = check_degree(c.degree, "/curve/degree"); !ok) return ok.error();
    Expected<CurveDegreeReduction> r = reduce_line(c);
    if (!r) return r.error().under("/curve");
    if (Status ok =
            check_bound(r->max_error, tolerance, c.degree, is_rational(c.type), "curve", "/curve");
        !ok)
        return ok.error();
    return r;
}

Expected<SurfaceDegreeReduction> reduce_degree(const Surface& s, Dir dir, double tolerance) {
    if (Status ok = check_tolerance(tolerance); !ok) return ok.error();
    const std::string degree_path = dir == Dir::u ? "/surface/degree/0" : "/surface/degree/1";
    if (Status ok = check_degree(s.degree(dir), degree_path); !ok) return ok.error();
    const int across = s.count(dir == Dir::u ? Dir::v : Dir::u);
    std::vector<Curve> lines;
    double bound = 0.0;
    for (int l = 0; l < across; ++l) {
        Expected<CurveDegreeReduction> r = reduce_line(surface_line(s, dir, l));
        if (!r) return r.error().under("/surface");
        bound = std::max(bound, r->max_error);
        lines.push_back(std::move(r->curve));
    }
    if (Status ok = check_bound(bound, tolerance, s.degree(dir), is_rational(s.type), "surface",
                                "/surface");
        !ok)
        return ok.error();
    return SurfaceDegreeReduction{surface_from_lines(s, dir, lines), bound};
}

namespace {

// What each piece costs besides its arithmetic (allocations of its windows; measured: a
// 2000 x 400 bicubic surface, 800,000 pieces, in 2.8 s).
constexpr double steps_per_piece = 200;

} // namespace

WorkEstimate degree_reduction_cost(const Curve& c) {
    WorkEstimate e;
    const double pieces = static_cast<double>(knot_runs(c.knots).size());
    e.steps = pieces * (4 * (c.degree + 1.0) * (c.degree + 1.0) + steps_per_piece);
    e.answer_numbers = 4.0 * c.count() + c.knots.size();
    e.steps += e.answer_numbers * steps_per_answer_number;
    return e;
}

WorkEstimate degree_reduction_cost(const Surface& s, Dir dir) {
    WorkEstimate e;
    const int p = s.degree(dir);
    const double pieces = static_cast<double>(knot_runs(s.knots(dir)).size());
    const double lines = s.count(dir == Dir::u ? Dir::v : Dir::u);
    e.steps = lines * pieces * (4 * (p + 1.0) * (p + 1.0) + steps_per_piece);
    e.answer_numbers = 4.0 * s.n_u * s.n_v + s.knots_u.size() + s.knots_v.size();
    e.steps += e.answer_numbers * steps_per_answer_number;
    return e;
}

} // namespace isoparm::geom
