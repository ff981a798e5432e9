#include "core/geom/coons.hpp"

#include <algorithm>
#include <glm/geometric.hpp>
#include <map>

#include "core/geom/construct.hpp"
#include "core/geom/construct_common.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/refine.hpp"

namespace isoparm::geom {

Surface transposed(const Surface& s) {
    Surface t = s;
    std::swap(t.degree_u, t.degree_v);
    std::swap(t.knots_u, t.knots_v);
    std::swap(t.n_u, t.n_v);
    for (int i = 0; i < s.n_u; ++i)
        for (int j = 0; j < s.n_v; ++j) {
            t.point(j, i) = s.point(i, j);
            t.weight(j, i) = s.weight(i, j);
        }
    return t;
}

namespace {

std::string curve_path(int k) {
    return "/curves/" + std::to_string(k);
}

// A polynomial copy: rational curves are accepted only with all weights equal (then the
// Cartesian control points already describe the curve).
Expected<Curve> polynomial(const Curve& c, int k) {
    for (double w : c.weights)
        if (w != c.weights.front())
            return make_error(ErrorCode::weights,
                              "a Coons patch blends polynomial boundaries: curve " +
                                  std::to_string(k) + " has weights that differ",
                              curve_path(k));
    Curve p = c;
    p.weights.assign(p.points.size(), 1.0);
    p.type = is_bezier(c.type) ? SplineType::bezier : SplineType::bspline;
    return p;
}

// Raises both directions to the given degrees and inserts knots so that the surface has
// exactly the knot vectors U and V (which contain its own, as multisets). Shape unchanged.
Expected<Surface> refine_to(Surface s, int p, int q, const Knots& U, const Knots& V) {
    if (s.degree_u < p) {
        auto e = elevate_degree(s, Dir::u, p - s.degree_u);
        if (!e) return e.error();
        s = std::move(e).value();
    }
    if (s.degree_v < q) {
        auto e = elevate_degree(s, Dir::v, q - s.degree_v);
        if (!e) return e.error();
        s = std::move(e).value();
    }
    for (Dir dir : {Dir::u, Dir::v}) {
        const Knots& target = dir == Dir::u ? U : V;
        std::map<double, int> missing;
        for (double t : target) ++missing[t];
        for (double t : s.knots(dir)) --missing[t];
        for (const auto& [t, times] : missing) {
            if (times <= 0) continue;
            auto r = insert_knot(s, dir, t, times);
            if (!r) return r.error();
            s = std::move(r).value();
        }
    }
    return s;
}

} // namespace

Expected<Surface> coons(const std::array<Curve, 4>& curves) {
    std::array<Curve, 4> c;
    for (int k = 0; k < 4; ++k) {
        auto p = polynomial(curves[k], k);
        if (!p) return p.error();
        c[k] = std::move(p).value();
    }
    // Corners, each curve taken on its own domain's ends.
    auto end = [&](int k, bool last) {
        const Interval d = domain(c[k]);
        return *curve_point(c[k], last ? d.hi : d.lo);
    };
    double size = 0;
    for (const Curve& cv : c)
        for (const glm::dvec3& P : cv.points) size = std::max(size, glm::length(P - c[0].points[0]));
    const double tolerance = 1e-9 * std::max(size, 1e-300);
    // (curve, its end) against (earlier curve, its end): C_0v starts at C_u0(0) and ends at
    // C_u1(0); C_1v starts at C_u0(1) and ends at C_u1(1).
    const struct {
        int curve;
        bool last;
        int other;
        bool other_last;
        const char* corner;
    } corners[] = {{2, false, 0, false, "S(0, 0)"},
                   {2, true, 1, false, "S(0, 1)"},
                   {3, false, 0, true, "S(1, 0)"},
                   {3, true, 1, true, "S(1, 1)"}};
    for (const auto& k : corners) {
        const double miss = glm::length(end(k.curve, k.last) - end(k.other, k.other_last));
        if (!(miss <= tolerance))
            return make_error(ErrorCode::geometry,
                              "the corner " + std::string(k.corner) + " is open: curve " +
                                  std::to_string(k.curve) + " ends " + format_number(miss) +
                                  " away from curve " + std::to_string(k.other),
                              curve_path(k.curve));
    }

    auto ru = ruled(c[0], c[1]); // S(u, 0) = C_u0, S(u, 1) = C_u1
    if (!ru) return ru.error();
    auto rv_transposed = ruled(c[2], c[3]); // along the curves first: transpose to (u, v)
    if (!rv_transposed) return rv_transposed.error();
    const Surface rv = transposed(*rv_transposed);
    // The bilinear patch of the corners, as the boundaries meet them (C_u0 and C_u1's ends).
    Surface bilinear;
    bilinear.type = SplineType::bspline;
    bilinear.degree_u = bilinear.degree_v = 1;
    bilinear.knots_u = bilinear.knots_v = {0, 0, 1, 1};
    bilinear.n_u = bilinear.n_v = 2;
    bilinear.points = {end(0, false), end(1, false), end(0, true), end(1, true)};
    bilinear.weights.assign(4, 1.0);

    const int p = ru->degree_u, q = rv.degree_v;
    // The ruled surfaces' degree-1 directions are raised to p (q) and take the other's knots.
    const Knots &U = ru->knots_u, &V = rv.knots_v;
    auto a = refine_to(*ru, p, q, U, V);
    if (!a) return a.error();
    auto b = refine_to(rv, p, q, U, V);
    if (!b) return b.error();
    auto t = refine_to(bilinear, p, q, U, V);
    if (!t) return t.error();
    if (Status st = construct_detail::check_result_size(a->n_u, a->n_v); !st) return st.error();
    Surface s = *a;
    for (std::size_t k = 0; k < s.points.size(); ++k)
        s.points[k] = a->points[k] + b->points[k] - t->points[k];
    const bool all_bezier = std::all_of(curves.begin(), curves.end(),
                                        [](const Curve& cv) { return is_bezier(cv.type); });
    s.type = construct_detail::result_type(false, all_bezier && s.n_u == p + 1 && s.n_v == q + 1);
    return s;
}

} // namespace isoparm::geom
