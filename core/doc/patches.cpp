// Subpatches sharing their original domain: lookup by parameter, shared borders, continuity.
#include "core/doc/patches.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <set>
#include <tuple>

#include "core/geom/knots.hpp"

namespace isoparm::doc {

namespace {

using geom::Dir;

int multiplicity_of(const geom::Knots& U, double t) {
    return static_cast<int>(std::count(U.begin(), U.end(), t));
}

// The part of a line's control points and knots that describes it over [lo, hi]: when both
// ends are knots of multiplicity >= p, the curve restricted there has the control points
// first .. first + count - 1 and the interior knots U[L+1 .. g-1] (L: the last index of lo,
// g: the first index of hi). Piegl & Tiller sec. 5.2: a knot of multiplicity p makes the
// curve interpolate P_{L-p}, and the pieces on each side are independent.
struct Restriction {
    bool ok = false;
    int first = 0, count = 0;
    std::vector<double> interior;
};

Restriction restrict_line(const geom::Knots& U, int p, double lo, double hi) {
    Restriction r;
    if (multiplicity_of(U, lo) < p || multiplicity_of(U, hi) < p) return r;
    const int L = static_cast<int>(std::upper_bound(U.begin(), U.end(), lo) - U.begin()) - 1;
    const int g = static_cast<int>(std::lower_bound(U.begin(), U.end(), hi) - U.begin());
    r.first = L - p;
    r.count = g - 1 - r.first + 1;
    if (r.first < 0 || r.count < 1) return r;
    r.interior.assign(U.begin() + L + 1, U.begin() + g);
    r.ok = true;
    return r;
}

bool clamped_at(const geom::Knots& U, int p, bool at_end) {
    const double t = at_end ? U[U.size() - 1 - p] : U[p];
    return multiplicity_of(U, t) >= p + 1;
}

glm::dvec4 homogeneous(const geom::Surface& s, int i, int j) {
    const double w = s.weight(i, j);
    return {s.point(i, j) * w, w};
}

// (i, j) of the point with index `c` across the border and `k` along it.
std::pair<int, int> ij(Dir across, int c, int k) {
    return across == Dir::u ? std::pair{c, k} : std::pair{k, c};
}

// One side of a border: its surface, the border and next-inner indices across it, and the
// distance dt from the border knot to the next distinct knot inward (the denominator of the
// first derivative at a clamped end, Piegl & Tiller eq. 3.7 applied to rows).
struct BorderSide {
    const geom::Surface* s = nullptr;
    int border = 0, inner = 0, first = 0, p = 0;
    double dt = 1;
};

BorderSide border_side(const geom::Surface& s, const SharedBorder& b, bool low) {
    BorderSide bs;
    bs.s = &s;
    const Dir d = b.across;
    const geom::Knots& U = s.knots(d);
    const int n = s.count(d), p = s.degree(d);
    bs.p = p;
    bs.first = low ? b.low_first : b.high_first;
    if (low) {
        bs.border = n - 1;
        bs.inner = n - 2;
        bs.dt = U[n + p] - U[n - 1];
    } else {
        bs.border = 0;
        bs.inner = 1;
        bs.dt = U[p + 1] - U[0];
    }
    return bs;
}

// The C1 row of the side `to` given the border point Q0 and the other side's inner point:
// equal first derivatives across the border, p_a (Q0 - Qa1) / dt_a = p_b (Qb1 - Q0) / dt_b.
glm::dvec4 c1_inner(const BorderSide& from, const BorderSide& to, const glm::dvec4& Q0,
                    const glm::dvec4& Qfrom_inner) {
    const double r = (from.p * to.dt) / (to.p * from.dt);
    return Q0 + r * (Q0 - Qfrom_inner);
}

// Sets a C1 row point from its homogeneous value. A zero weight has no Cartesian point that
// stands for Q (Cartesian + weight 0 is the homogeneous origin): the point is left as it is and
// continuity_holds reports the border.
bool set_point(geom::Surface& s, int i, int j, const glm::dvec4& Q) {
    if (Q.w == 0) return false;
    const double w =
        s.type == geom::SplineType::bspline || s.type == geom::SplineType::bezier ? 1.0 : Q.w;
    const glm::dvec3 p = glm::dvec3(Q) / Q.w;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(w))
        return false;
    if (s.point(i, j) == p && s.weight(i, j) == w) return false;
    s.point(i, j) = p;
    s.weight(i, j) = w;
    return true;
}

} // namespace

std::vector<const Object*> patch_members(const Document& doc, std::uint64_t group) {
    std::vector<const Object*> out;
    if (group == 0) return out;
    for (const Object& o : doc.objects)
        if (o.patch_group == group && o.surface()) out.push_back(&o);
    return out;
}

geom::ParamRect tracing_domain(const Document& doc, const Object& surface_object) {
    const geom::Surface* s = surface_object.surface();
    geom::ParamRect r = s ? geom::domain(*s) : geom::ParamRect{};
    for (const Object* m : patch_members(doc, surface_object.patch_group)) {
        const geom::ParamRect d = geom::domain(*m->surface());
        r.u = {std::min(r.u.lo, d.u.lo), std::max(r.u.hi, d.u.hi)};
        r.v = {std::min(r.v.lo, d.v.lo), std::max(r.v.hi, d.v.hi)};
    }
    return r;
}

std::uint64_t patch_at(const Document& doc, std::uint64_t group, glm::dvec2 uv,
                       std::uint64_t prefer) {
    std::uint64_t first = 0;
    for (const Object* m : patch_members(doc, group)) {
        if (!geom::domain(*m->surface()).contains(uv)) continue;
        if (m->id == prefer) return prefer;
        if (first == 0) first = m->id;
    }
    return first;
}

std::optional<geom::Error> check_patch_groups(const Document& doc) {
    for (std::size_t a = 0; a < doc.objects.size(); ++a) {
        const Object& A = doc.objects[a];
        if (A.patch_group == 0) continue;
        const std::string at = "/objects/" + std::to_string(a) + "/patch_group";
        if (!A.surface())
            return geom::make_error(geom::ErrorCode::schema,
                                    "only surfaces can be subpatches; object '" + A.name +
                                        "' is a " + geom::label_of(A.kind()),
                                    at);
    }
    return std::nullopt;
}

std::vector<SharedBorder> shared_borders(const Document& doc, std::uint64_t group) {
    std::vector<SharedBorder> out;
    const std::vector<const Object*> members = patch_members(doc, group);
    for (const Object* A : members)
        for (const Object* B : members) {
            if (A == B) continue;
            const geom::Surface& sa = *A->surface();
            const geom::Surface& sb = *B->surface();
            const geom::ParamRect ra = geom::domain(sa), rb = geom::domain(sb);
            for (Dir d : {Dir::u, Dir::v}) {
                if (ra.interval(d).hi != rb.interval(d).lo) continue;
                const Dir e = geom::opposite(d);
                const double lo = std::max(ra.interval(e).lo, rb.interval(e).lo);
                const double hi = std::min(ra.interval(e).hi, rb.interval(e).hi);
                if (!(lo < hi)) continue;
                SharedBorder b;
                b.low = A->id;
                b.high = B->id;
                b.across = d;
                b.along = {lo, hi};
                const Restriction la = restrict_line(sa.knots(e), sa.degree(e), lo, hi);
                const Restriction lb = restrict_line(sb.knots(e), sb.degree(e), lo, hi);
                const char* along = geom::name_of(e);
                if (sa.degree(e) != sb.degree(e)) {
                    b.why_not = std::string("the degrees in ") + along + " differ (" +
                                std::to_string(sa.degree(e)) + " and " +
                                std::to_string(sb.degree(e)) + ")";
                } else if (!la.ok || !lb.ok) {
                    b.why_not = std::string("the border ends are not knots of full multiplicity "
                                            "in ") +
                                along + " on both sides (insert or split there first)";
                } else if (la.interior != lb.interior || la.count != lb.count) {
                    b.why_not = std::string("the knots in ") + along + " differ along the border";
                } else {
                    b.conforming = true;
                    b.low_first = la.first;
                    b.high_first = lb.first;
                    b.count = la.count;
                    b.c1_possible = clamped_at(sa.knots(d), sa.degree(d), true) &&
                                    clamped_at(sb.knots(d), sb.degree(d), false) &&
                                    sa.count(d) >= 2 && sb.count(d) >= 2;
                }
                out.push_back(std::move(b));
            }
        }
    return out;
}

std::vector<KnotInsertion>
conforming_insertions(const Document& doc, std::uint64_t group,
                      const std::function<bool(const SharedBorder&)>& wanted) {
    std::vector<KnotInsertion> out;
    // The largest number of copies any border asks of (object, dir, t).
    auto need = [&](std::uint64_t object, Dir dir, double t, int times) {
        if (times <= 0) return;
        for (KnotInsertion& k : out)
            if (k.object == object && k.dir == dir && k.t == t) {
                k.times = std::max(k.times, times);
                return;
            }
        out.push_back({object, dir, t, times});
    };
    for (const SharedBorder& b : shared_borders(doc, group)) {
        if (b.conforming || (wanted && !wanted(b))) continue;
        const Dir e = geom::opposite(b.across);
        const geom::Surface& sa = *doc.find(b.low)->surface();
        const geom::Surface& sb = *doc.find(b.high)->surface();
        const int p = sa.degree(e);
        if (sb.degree(e) != p) continue;
        const double lo = b.along.lo, hi = b.along.hi;
        // A border end on a side's own domain end must already be a knot of multiplicity p
        // there (clamped): insertion cannot add copies at the end of a domain.
        bool fixable = true;
        for (const geom::Surface* s : {&sa, &sb}) {
            const geom::Interval d = geom::domain(*s, e);
            for (double t : {lo, hi})
                if ((t == d.lo || t == d.hi) && multiplicity_of(s->knots(e), t) < p)
                    fixable = false;
        }
        if (!fixable) continue;
        // Every knot value inside the border (either side's) and the two ends.
        std::set<double> values{lo, hi};
        for (const geom::Surface* s : {&sa, &sb})
            for (double t : s->knots(e))
                if (lo < t && t < hi) values.insert(t);
        for (double t : values) {
            const int ma = multiplicity_of(sa.knots(e), t), mb = multiplicity_of(sb.knots(e), t);
            const int target = t == lo || t == hi ? std::max({ma, mb, p}) : std::max(ma, mb);
            // The ends count only up to p: a clamped end has p + 1 copies and needs none more.
            const int want = std::min(target, p);
            need(b.low, e, t, want - ma);
            need(b.high, e, t, want - mb);
        }
    }
    return out;
}

std::vector<PointChange> keep_continuity(Document& doc, std::uint64_t id, int i, int j,
                                         Continuity mode) {
    std::vector<PointChange> changes;
    const Object* start = doc.find(id);
    if (mode == Continuity::off || !start || start->patch_group == 0 || !start->surface())
        return changes;
    const std::vector<SharedBorder> borders = shared_borders(doc, start->patch_group);
    // Each point changes at most once and the moved patch never: the propagation ends even
    // where C1 conditions around a corner disagree.
    std::set<std::tuple<std::uint64_t, int, int>> changed;
    std::deque<std::tuple<std::uint64_t, int, int>> queue{{id, i, j}};
    while (!queue.empty()) {
        const auto [xid, xi, xj] = queue.front();
        queue.pop_front();
        for (const SharedBorder& b : borders) {
            if (!b.conforming || (b.low != xid && b.high != xid)) continue;
            const bool x_low = b.low == xid;
            const std::uint64_t yid = x_low ? b.high : b.low;
            if (yid == id) continue;
            Object* X = doc.find(xid);
            Object* Y = doc.find(yid);
            const geom::Surface& sx = *X->surface();
            geom::Surface& sy = *Y->surface();
            const BorderSide bx = border_side(sx, b, x_low);
            const BorderSide by = border_side(sy, b, !x_low);
            const int c = b.across == Dir::u ? xi : xj;
            const int k = (b.across == Dir::u ? xj : xi) - bx.first;
            if (k < 0 || k >= b.count) continue;
            const bool c1 = mode == Continuity::c1 && b.c1_possible;
            if (c != bx.border && !(c1 && c == bx.inner)) continue;

            const auto [x0i, x0j] = ij(b.across, bx.border, bx.first + k);
            const auto [x1i, x1j] = ij(b.across, bx.inner, bx.first + k);
            const auto [y0i, y0j] = ij(b.across, by.border, by.first + k);
            const auto [y1i, y1j] = ij(b.across, by.inner, by.first + k);
            // A point is claimed by the first path that reaches it, changed or not: a second
            // path through a corner (where C1 conditions can disagree) leaves it alone, so the
            // result does not depend on which values happened to be equal already.
            auto change = [&](int ci, int cj, const glm::dvec4& Q) {
                if (!changed.insert({yid, ci, cj}).second) return;
                const PointChange before{yid, ci, cj, sy.point(ci, cj), sy.weight(ci, cj)};
                if (!set_point(sy, ci, cj, Q)) return;
                changes.push_back(before);
                queue.emplace_back(yid, ci, cj);
            };
            const glm::dvec4 Q0 = homogeneous(sx, x0i, x0j);
            if (c == bx.border) {
                // C0: the same point, weight included (copied, not recomputed: exact).
                if (changed.insert({yid, y0i, y0j}).second &&
                    (sy.point(y0i, y0j) != sx.point(x0i, x0j) ||
                     sy.weight(y0i, y0j) != sx.weight(x0i, x0j))) {
                    changes.push_back({yid, y0i, y0j, sy.point(y0i, y0j), sy.weight(y0i, y0j)});
                    sy.point(y0i, y0j) = sx.point(x0i, x0j);
                    if (sy.type == sx.type) sy.weight(y0i, y0j) = sx.weight(x0i, x0j);
                    queue.emplace_back(yid, y0i, y0j);
                }
            }
            if (c1) change(y1i, y1j, c1_inner(bx, by, Q0, homogeneous(sx, x1i, x1j)));
        }
    }
    return changes;
}

void restore_points(Document& doc, const std::vector<PointChange>& changes) {
    for (auto it = changes.rbegin(); it != changes.rend(); ++it) {
        Object* o = doc.find(it->object);
        geom::Surface* s = o ? o->surface() : nullptr;
        if (!s) continue;
        s->point(it->i, it->j) = it->position;
        s->weight(it->i, it->j) = it->weight;
    }
}

bool continuity_holds(const Document& doc, std::uint64_t group, Continuity mode, double tolerance) {
    if (mode == Continuity::off) return true;
    double size = 1;
    for (const Object* m : patch_members(doc, group))
        for (const glm::dvec3& p : m->surface()->points)
            size = std::max({size, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    const double tol = tolerance * size;
    for (const SharedBorder& b : shared_borders(doc, group)) {
        if (!b.conforming) continue;
        const geom::Surface& sl = *doc.find(b.low)->surface();
        const geom::Surface& sh = *doc.find(b.high)->surface();
        const BorderSide bl = border_side(sl, b, true);
        const BorderSide bh = border_side(sh, b, false);
        for (int k = 0; k < b.count; ++k) {
            const auto [l0i, l0j] = ij(b.across, bl.border, bl.first + k);
            const auto [h0i, h0j] = ij(b.across, bh.border, bh.first + k);
            const glm::dvec4 Ql = homogeneous(sl, l0i, l0j), Qh = homogeneous(sh, h0i, h0j);
            for (int a = 0; a < 4; ++a)
                if (std::abs(Ql[a] - Qh[a]) > tol) return false;
            if (mode != Continuity::c1 || !b.c1_possible) continue;
            const auto [l1i, l1j] = ij(b.across, bl.inner, bl.first + k);
            const auto [h1i, h1j] = ij(b.across, bh.inner, bh.first + k);
            const glm::dvec4 want = c1_inner(bl, bh, Ql, homogeneous(sl, l1i, l1j));
            const glm::dvec4 have = homogeneous(sh, h1i, h1j);
            for (int a = 0; a < 4; ++a)
                if (std::abs(want[a] - have[a]) > tol) return false;
        }
    }
    return true;
}

} // namespace isoparm::doc
