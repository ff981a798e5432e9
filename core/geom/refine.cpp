// Knot insertion (Boehm, A5.1), knot refinement (A5.4), degree elevation (A5.9) and splitting,
// shape unchanged.
#include "core/geom/refine.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/geom/binomial.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::geom {

namespace {

// A curve in homogeneous form: what the refinement algorithms act on (they are linear there).
struct HCurve {
    int p = 1;
    Knots U;
    std::vector<HPoint> Pw;
    int n() const { return static_cast<int>(Pw.size()); }
};

HCurve homogeneous_of(const Curve& c, bool unit_weights) {
    HCurve h{c.degree, c.knots, {}};
    h.Pw.resize(c.count());
    for (int i = 0; i < c.count(); ++i)
        h.Pw[i] = unit_weights ? HPoint(c.points[i], 1.0) : c.hpoint(i);
    return h;
}

// Boehm's single knot insertion (Piegl & Tiller eq. 5.15) on the span find_span gives: the
// right limit inside the domain, the left limit at its end, so t = U[n] needs no P_n.
void insert_once(HCurve& c, double t) {
    const int p = c.p, n = c.n();
    const int k = find_span(c.U, p, n, t);
    std::vector<HPoint> Q(n + 1);
    for (int i = 0; i <= k - p; ++i) Q[i] = c.Pw[i];
    for (int i = k - p + 1; i <= k; ++i) {
        const double a = (t - c.U[i]) / (c.U[i + p] - c.U[i]);
        Q[i] = a * c.Pw[i] + (1.0 - a) * c.Pw[i - 1];
    }
    for (int i = k + 1; i <= n; ++i) Q[i] = c.Pw[i - 1];
    c.U.insert(c.U.begin() + k + 1, t);
    c.Pw = std::move(Q);
}

void insert_to_multiplicity(HCurve& c, double t, int target) {
    for (int m = multiplicity(c.U, t); m < target; ++m) insert_once(c, t);
}

// With t at multiplicity >= p: the part before t and the part after it, each with t at
// multiplicity p + 1 (the general form of splitting; also clamps when t is a domain end).
HCurve part_before(const HCurve& c, double t) {
    const int p = c.p;
    const int f = static_cast<int>(std::lower_bound(c.U.begin(), c.U.end(), t) - c.U.begin());
    HCurve out{p, Knots(c.U.begin(), c.U.begin() + f), {}};
    out.U.insert(out.U.end(), p + 1, t);
    out.Pw.assign(c.Pw.begin(), c.Pw.begin() + f);
    return out;
}

HCurve part_after(const HCurve& c, double t) {
    const int p = c.p;
    const int f = static_cast<int>(std::lower_bound(c.U.begin(), c.U.end(), t) - c.U.begin());
    const int m = multiplicity(c.U, t);
    assert(m >= p);
    HCurve out{p, Knots(p + 1, t), {}};
    out.U.insert(out.U.end(), c.U.begin() + f + m, c.U.end());
    out.Pw.assign(c.Pw.begin() + (f + m - p - 1), c.Pw.end());
    return out;
}

HCurve clamp_homogeneous(HCurve c) {
    const double a = c.U[c.p], b = c.U[c.n()];
    if (is_clamped(c.U, c.p, c.n())) return c;
    insert_to_multiplicity(c, a, c.p);
    c = part_after(c, a);
    insert_to_multiplicity(c, b, c.p);
    return part_before(c, b);
}

// Piegl & Tiller A5.9 DegreeElevateCurve on a clamped curve (book indices: n and m are the
// last point and knot indices).
HCurve elevate_clamped(const HCurve& in, int t) {
    const int p = in.p, n = in.n() - 1, m = n + p + 1;
    const int ph = p + t, ph2 = ph / 2;
    const Knots& U = in.U;
    const std::vector<HPoint>& Pw = in.Pw;
    std::vector<std::vector<double>> bezalfs(ph + 1, std::vector<double>(p + 1, 0.0));
    bezalfs[0][0] = bezalfs[ph][p] = 1.0;
    // C(p, j) C(t, i - j) / C(ph, i): directly while the binomials fit a double comfortably,
    // through log-gamma beyond (C(ph, i) overflows near ph = 1030).
    auto log_binomial = [](int n, int k) {
        return std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0);
    };
    for (int i = 1; i <= ph2; ++i) {
        const double inv = 1.0 / binomial(ph, i);
        const int mpi = std::min(p, i);
        for (int j = std::max(0, i - t); j <= mpi; ++j)
            bezalfs[i][j] =
                ph <= 1000
                    ? inv * binomial(p, j) * binomial(t, i - j)
                    : std::exp(log_binomial(p, j) + log_binomial(t, i - j) - log_binomial(ph, i));
    }
    for (int i = ph2 + 1; i <= ph - 1; ++i) {
        const int mpi = std::min(p, i);
        for (int j = std::max(0, i - t); j <= mpi; ++j) bezalfs[i][j] = bezalfs[ph - i][p - j];
    }
    // Upper bounds: each distinct interior knot gains t copies, the ends too.
    const size_t distinct = knot_runs(U).size();
    std::vector<HPoint> Qw(Pw.size() + distinct * t + 1);
    Knots Uh(U.size() + (distinct + 1) * t + 1);
    std::vector<HPoint> bpts(p + 1), ebpts(ph + 1), Nextbpts(std::max(p - 1, 1));
    std::vector<double> alfs(std::max(p - 1, 1));

    int mh = ph, kind = ph + 1, r = -1, a = p, b = p + 1, cind = 1;
    double ua = U[0];
    Qw[0] = Pw[0];
    for (int i = 0; i <= ph; ++i) Uh[i] = ua;
    for (int i = 0; i <= p; ++i) bpts[i] = Pw[i];
    while (b < m) {
        const int i0 = b;
        while (b < m && U[b] == U[b + 1]) ++b;
        const int mul = b - i0 + 1;
        mh += mul + t;
        const double ub = U[b];
        const int oldr = r;
        r = p - mul;
        const int lbz = oldr > 0 ? (oldr + 2) / 2 : 1;
        const int rbz = r > 0 ? ph - (r + 1) / 2 : ph;
        if (r > 0) { // insert ub r times to get the Bezier segment
            const double numer = ub - ua;
            for (int k = p; k > mul; --k) alfs[k - mul - 1] = numer / (U[a + k] - ua);
            for (int j = 1; j <= r; ++j) {
                const int save = r - j, s = mul + j;
                for (int k = p; k >= s; --k)
                    bpts[k] = alfs[k - s] * bpts[k] + (1.0 - alfs[k - s]) * bpts[k - 1];
                Nextbpts[save] = bpts[p];
            }
        }
        for (int i = lbz; i <= ph; ++i) { // degree-elevate the Bezier segment
            ebpts[i] = HPoint(0.0);
            const int mpi = std::min(p, i);
            for (int j = std::max(0, i - t); j <= mpi; ++j) ebpts[i] += bezalfs[i][j] * bpts[j];
        }
        if (oldr > 1) { // remove knot ua oldr times
            int first = kind - 2, last = kind;
            const double den = ub - ua;
            const double bet = (ub - Uh[kind - 1]) / den;
            for (int tr = 1; tr < oldr; ++tr) {
                int i = first, j = last, kj = j - kind + 1;
                while (j - i > tr) {
                    if (i < cind) {
                        const double alf = (ub - Uh[i]) / (ua - Uh[i]);
                        Qw[i] = alf * Qw[i] + (1.0 - alf) * Qw[i - 1];
                    }
                    if (j >= lbz) {
                        if (j - tr <= kind - ph + oldr) {
                            const double gam = (ub - Uh[j - tr]) / den;
                            ebpts[kj] = gam * ebpts[kj] + (1.0 - gam) * ebpts[kj + 1];
                        } else {
                            ebpts[kj] = bet * ebpts[kj] + (1.0 - bet) * ebpts[kj + 1];
                        }
                    }
                    ++i;
                    --j;
                    --kj;
                }
                --first;
                ++last;
            }
        }
        if (a != p)
            for (int i = 0; i < ph - oldr; ++i) Uh[kind++] = ua;
        for (int j = lbz; j <= rbz; ++j) Qw[cind++] = ebpts[j];
        if (b < m) {
            for (int j = 0; j < r; ++j) bpts[j] = Nextbpts[j];
            for (int j = r; j <= p; ++j) bpts[j] = Pw[b - p + j];
            a = b;
            ++b;
            ua = ub;
        } else {
            for (int i = 0; i <= ph; ++i) Uh[kind + i] = ub;
        }
    }
    const int nh = mh - ph - 1; // last index of the new points
    HCurve out{ph, Knots(Uh.begin(), Uh.begin() + nh + ph + 2), {}};
    out.Pw.assign(Qw.begin(), Qw.begin() + nh + 1);
    return out;
}

// A5.9 needs interior multiplicities <= p. At a knot of multiplicity p + 1 (where the curve
// may jump) the curve is cut, the pieces are elevated alone and joined again with the knot at
// the new full multiplicity p + t + 1.
HCurve elevate_any(const HCurve& in, int t) {
    const int n = in.n();
    for (const KnotRun& run : knot_runs(in.U)) {
        const bool interior = run.value > in.U[in.p] && run.value < in.U[n];
        if (!interior || run.multiplicity <= in.p) continue;
        const HCurve left = elevate_any(part_before(in, run.value), t);
        const HCurve right = elevate_any(part_after(in, run.value), t);
        HCurve out = left;
        out.U.insert(out.U.end(), right.U.begin() + (right.p + 1), right.U.end());
        out.Pw.insert(out.Pw.end(), right.Pw.begin(), right.Pw.end());
        return out;
    }
    return elevate_clamped(in, t);
}

// Runs `algorithm` on the curve in homogeneous form and converts back; a zero homogeneous
// point takes its position from the same algorithm on unit weights.
template <class Algorithm> Expected<Curve> run_homogeneous(const Curve& c, Algorithm algorithm) {
    const bool rational = is_rational(c.type);
    HCurve h = algorithm(homogeneous_of(c, !rational));
    std::vector<HPoint> fallback;
    if (rational) {
        const bool needs_fallback = std::any_of(h.Pw.begin(), h.Pw.end(), [](const HPoint& q) {
            return q.w == 0.0 && q.x == 0.0 && q.y == 0.0 && q.z == 0.0;
        });
        if (needs_fallback) fallback = algorithm(homogeneous_of(c, true)).Pw;
    }
    return curve_from_homogeneous(c, h.p, std::move(h.U), h.Pw,
                                  fallback.empty() ? nullptr : &fallback);
}

// The surface form of a curve operation: applied to every line along dir.
template <class CurveOp>
Expected<Surface> per_line(const Surface& s, Dir dir, CurveOp op, SplineType result_type) {
    const int across = s.count(opposite(dir));
    std::vector<Curve> lines;
    lines.reserve(across);
    for (int l = 0; l < across; ++l) {
        Expected<Curve> r = op(surface_line(s, dir, l));
        if (!r) return r.error();
        lines.push_back(std::move(r).value());
    }
    Surface out = surface_from_lines(s, dir, lines);
    out.type = result_type;
    return out;
}

Status check_times(int times) {
    if (times < 1)
        return make_error(ErrorCode::schema,
                          "times must be at least 1, got " + std::to_string(times), "/times");
    return Ok{};
}

SplineType after_adding_span(SplineType t) {
    if (t == SplineType::bezier) return SplineType::bspline;
    if (t == SplineType::rational_bezier) return SplineType::nurbs;
    return t;
}

} // namespace

std::vector<HPoint> homogeneous_points(const Curve& c) {
    const bool rational = is_rational(c.type);
    std::vector<HPoint> Pw(c.count());
    for (int i = 0; i < c.count(); ++i) Pw[i] = rational ? c.hpoint(i) : HPoint(c.points[i], 1.0);
    return Pw;
}

Expected<Curve> curve_from_homogeneous(const Curve& like, int degree, Knots knots,
                                       const std::vector<HPoint>& Pw,
                                       const std::vector<HPoint>* fallback) {
    Curve c;
    c.type = like.type;
    c.degree = degree;
    c.knots = std::move(knots);
    c.points.resize(Pw.size());
    c.weights.assign(Pw.size(), 1.0);
    const bool rational = is_rational(like.type);
    for (size_t i = 0; i < Pw.size(); ++i) {
        const HPoint& q = Pw[i];
        if (!rational) {
            c.points[i] = glm::dvec3(q); // affine combinations of unit-weight points
        } else if (q.w != 0.0) {
            c.points[i] = glm::dvec3(q) / q.w;
            c.weights[i] = q.w;
        } else if (q.x == 0.0 && q.y == 0.0 && q.z == 0.0) {
            c.points[i] = fallback ? glm::dvec3((*fallback)[i]) : glm::dvec3(0.0);
            c.weights[i] = 0.0;
        } else {
            return make_error_nopath(ErrorCode::weights,
                                     "the result needs control point " + std::to_string(i) +
                                         " at infinity (weight 0 with non-zero weighted "
                                         "coordinates): the weights change sign there");
        }
        const glm::dvec3& p = c.points[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) ||
            !std::isfinite(c.weights[i])) {
            return make_error_nopath(ErrorCode::weights,
                                     "control point " + std::to_string(i) +
                                         " of the result is not finite (a weight is too close "
                                         "to zero)");
        }
    }
    return c;
}

void refine_knot_vector(int p, Knots& U, std::vector<HPoint>& Pw, const std::vector<double>& X) {
    const int n = static_cast<int>(Pw.size()) - 1, m = n + p + 1;
    const int r = static_cast<int>(X.size()) - 1;
    const int a = find_span(U, p, n + 1, X[0]);
    const int b = find_span(U, p, n + 1, X[r]) + 1;
    std::vector<HPoint> Qw(static_cast<size_t>(n) + r + 2);
    Knots Ubar(static_cast<size_t>(m) + r + 2);
    for (int j = 0; j <= a - p; ++j) Qw[j] = Pw[j];
    for (int j = b - 1; j <= n; ++j) Qw[j + r + 1] = Pw[j];
    for (int j = 0; j <= a; ++j) Ubar[j] = U[j];
    for (int j = b + p; j <= m; ++j) Ubar[j + r + 1] = U[j];
    int i = b + p - 1, k = b + p + r;
    for (int j = r; j >= 0; --j) {
        while (X[j] <= U[i] && i > a) {
            Qw[k - p - 1] = Pw[i - p - 1];
            Ubar[k] = U[i];
            --k;
            --i;
        }
        Qw[k - p - 1] = Qw[k - p];
        for (int l = 1; l <= p; ++l) {
            const int ind = k - p + l;
            double alfa = Ubar[k + l] - X[j];
            if (alfa == 0.0) {
                Qw[ind - 1] = Qw[ind];
            } else {
                alfa /= Ubar[k + l] - U[i - p + l];
                Qw[ind - 1] = alfa * Qw[ind - 1] + (1.0 - alfa) * Qw[ind];
            }
        }
        Ubar[k] = X[j];
        --k;
    }
    U = std::move(Ubar);
    Pw = std::move(Qw);
}

Expected<Curve> insert_knot(const Curve& c, double t, int times) {
    if (Status s = check_times(times); !s) return s.error();
    const int p = c.degree;
    const Interval dom = domain(c);
    if (!std::isfinite(t) || !dom.contains(t)) {
        return make_error(ErrorCode::domain,
                          "knot " + format_number(t) + " outside the domain [" +
                              format_number(dom.lo) + ", " + format_number(dom.hi) + "]",
                          "/knot");
    }
    const int m = multiplicity(c.knots, t);
    if (m + times > p) {
        return make_error(ErrorCode::multiplicity,
                          "inserting " + format_number(t) + " " + std::to_string(times) +
                              " time(s) would make its multiplicity exceed the degree " +
                              std::to_string(p),
                          "/times");
    }
    auto r = run_homogeneous(c, [&](HCurve h) {
        for (int k = 0; k < times; ++k) insert_once(h, t);
        return h;
    });
    if (r) r->type = after_adding_span(c.type);
    return r;
}

Expected<Surface> insert_knot(const Surface& s, Dir dir, double t, int times) {
    return per_line(
        s, dir, [&](const Curve& c) { return insert_knot(c, t, times); },
        after_adding_span(s.type));
}

Expected<Curve> clamp(const Curve& c) {
    return run_homogeneous(c, [](HCurve h) { return clamp_homogeneous(std::move(h)); });
}

Expected<Curve> elevate_degree(const Curve& c, int times) {
    if (Status s = check_times(times); !s) return s.error();
    return run_homogeneous(
        c, [&](HCurve h) { return elevate_any(clamp_homogeneous(std::move(h)), times); });
}

Expected<Surface> elevate_degree(const Surface& s, Dir dir, int times) {
    return per_line(
        s, dir, [&](const Curve& c) { return elevate_degree(c, times); }, s.type);
}

Expected<std::pair<Curve, Curve>> split(const Curve& c, double t) {
    const Interval dom = domain(c);
    if (!std::isfinite(t) || !(dom.lo < t && t < dom.hi)) {
        return make_error(ErrorCode::domain,
                          "split parameter " + format_number(t) +
                              " must lie strictly inside the domain (" + format_number(dom.lo) +
                              ", " + format_number(dom.hi) + ")",
                          "/param");
    }
    auto refined = [&](HCurve h) {
        insert_to_multiplicity(h, t, h.p);
        return h;
    };
    auto first = run_homogeneous(c, [&](HCurve h) { return part_before(refined(h), t); });
    if (!first) return first.error();
    auto second = run_homogeneous(c, [&](HCurve h) { return part_after(refined(h), t); });
    if (!second) return second.error();
    return std::pair<Curve, Curve>{std::move(first).value(), std::move(second).value()};
}

Expected<std::pair<Surface, Surface>> split(const Surface& s, Dir dir, double t) {
    std::vector<Curve> firsts, seconds;
    const int across = s.count(opposite(dir));
    for (int l = 0; l < across; ++l) {
        auto r = split(surface_line(s, dir, l), t);
        if (!r) return r.error();
        firsts.push_back(std::move(r->first));
        seconds.push_back(std::move(r->second));
    }
    return std::pair<Surface, Surface>{surface_from_lines(s, dir, firsts),
                                       surface_from_lines(s, dir, seconds)};
}

} // namespace isoparm::geom
