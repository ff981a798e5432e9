#include "core/geom/coons.hpp"

#include <algorithm>
#include <glm/geometric.hpp>

#include "core/geom/construct.hpp"
#include "core/geom/construct_common.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/surface_sum.hpp"

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

} // namespace

Expected<Surface> coons(const std::array<Curve, 4>& curves) {
    std::array<Curve, 4> c;
    for (int k = 0; k < 4; ++k) {
        auto p = polynomial(curves[k], k);
        if (!p) return p.error();
        c[k] = std::move(p).value();
    }
    // The result has at least as many points per direction as its longest boundary curve
    // (making curves compatible only adds points): the caps are checked before the work (a
    // degree-1500 boundary took 9 s to be refused at the end).
    if (Status st = construct_detail::check_result_size(std::max(c[0].count(), c[1].count()),
                                                        std::max(c[2].count(), c[3].count()));
        !st)
        return st.error();
    // Corners, each curve taken on its own domain's ends.
    auto end = [&](int k, bool last) {
        const Interval d = domain(c[k]);
        return *curve_point(c[k], last ? d.hi : d.lo);
    };
    double size = 0;
    for (const Curve& cv : c)
        for (const glm::dvec3& P : cv.points)
            size = std::max(size, glm::length(P - c[0].points[0]));
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

    auto sum = sum_of_surfaces({{1.0, *ru}, {1.0, rv}, {-1.0, bilinear}});
    if (!sum) return sum.error();
    Surface& s = *sum;
    const bool all_bezier = std::all_of(curves.begin(), curves.end(),
                                        [](const Curve& cv) { return is_bezier(cv.type); });
    s.type = construct_detail::result_type(false, all_bezier && s.n_u == s.degree_u + 1 &&
                                                      s.n_v == s.degree_v + 1);
    return s;
}

} // namespace isoparm::geom
