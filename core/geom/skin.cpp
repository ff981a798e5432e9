// The skinned surface through compatible sections (Piegl & Tiller 10.3 with 9.2.5, A9.1).
#include <cmath>

#include "core/geom/construct.hpp"
#include "core/geom/construct_common.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::geom {

namespace {

// Convention 15: for each control-point index i the lengths (or their square roots) between
// consecutive sections' i-th Cartesian control points, normalized to total 1, then averaged
// over i (P&T 9.2.5, eq. 9.5 applied per index and averaged like A9.4: averaged_net_params).
Expected<std::vector<double>> section_params(const std::vector<Curve>& sections,
                                             Parametrization mode) {
    const int K = static_cast<int>(sections.size()) - 1;
    NetParams v = averaged_net_params(
        K, sections.front().count(), [&](int k, int i) { return sections[k].points[i]; }, mode,
        false);
    if (v.degenerate_line >= 0) {
        return make_error(ErrorCode::geometry,
                          "the sections coincide at control point " +
                              std::to_string(v.degenerate_line) +
                              " (the same point in every compatible curve), so the " +
                              name_of(mode) + " lengths between sections sum to zero",
                          "/curves");
    }
    if (v.coincident >= 0) {
        const int k = v.coincident;
        return make_error(ErrorCode::geometry,
                          "curve " + std::to_string(k) + " coincides with curve " +
                              std::to_string(k - 1) + " (equal parameters v = " +
                              format_number(v.params[k]) + "), so no surface can pass through both",
                          "/curves/" + std::to_string(k));
    }
    return std::move(v.params);
}

} // namespace

Expected<Skinned> skin(const std::vector<Curve>& curves, int degree, Parametrization mode) {
    const int count = static_cast<int>(curves.size());
    if (count < 2) {
        return make_error(ErrorCode::schema,
                          "skin needs at least 2 curves, got " + std::to_string(count), "/curves");
    }
    if (degree < 1 || degree > count - 1) {
        return make_error(ErrorCode::schema,
                          "the skin degree must lie between 1 and the curve count - 1 = " +
                              std::to_string(count - 1) + ", got " + std::to_string(degree),
                          "/degree");
    }
    auto compatible = make_compatible(curves);
    if (!compatible) return compatible.error();
    if (Status s = construct_detail::check_result_size(compatible->front().count(), count); !s)
        return s.error();
    auto params = section_params(*compatible, mode);
    if (!params) return params.error();
    return skin_compatible(*compatible, degree, *params);
}

Expected<Skinned> skin_through(const std::vector<Curve>& curves, int degree,
                               const std::vector<double>& params) {
    auto compatible = make_compatible(curves);
    if (!compatible) return compatible.error();
    if (Status s = construct_detail::check_result_size(compatible->front().count(),
                                                       static_cast<long>(curves.size()));
        !s)
        return s.error();
    return skin_compatible(*compatible, degree, params);
}

Expected<Skinned> skin_compatible(const std::vector<Curve>& C, int degree,
                                  const std::vector<double>& v) {
    const int count = static_cast<int>(C.size());
    const int n = C.front().count(), K = count - 1, q = degree;

    bool rational = false, bezier = true;
    for (const Curve& c : C) {
        rational = rational || is_rational(c.type);
        bezier = bezier && is_bezier(c.type);
    }
    Skinned out;
    out.params = v;
    Surface& s = out.surface;
    s.type = construct_detail::result_type(rational, bezier && q == K);
    s.degree_u = C.front().degree;
    s.degree_v = q;
    s.knots_u = C.front().knots;
    s.knots_v = averaged_knots(v, q); // eq. 9.8
    s.n_u = n;
    s.n_v = count;
    s.points.resize(static_cast<size_t>(n) * count);
    s.weights.assign(static_cast<size_t>(n) * count, 1.0);

    // One collocation matrix N_j(v_k) for every control-point index: the right-hand sides are
    // the i-th control points of the sections, homogeneous (w P, w) for rational curves, so the
    // column through them interpolates C_k^w and S(u, v_k) = C_k(u) after projection.
    const int dims = rational ? 4 : 3;
    const int columns = n * dims;
    std::vector<double> data(static_cast<size_t>(count) * columns);
    auto fill = [&](bool homogeneous) {
        for (int k = 0; k <= K; ++k)
            for (int i = 0; i < n; ++i) {
                const HPoint h = homogeneous ? C[k].hpoint(i) : HPoint(C[k].points[i], 1.0);
                for (int a = 0; a < dims; ++a)
                    data[static_cast<size_t>(k) * columns + i * dims + a] = h[a];
            }
    };
    auto at = [&](int k, int i, int a) {
        return data[static_cast<size_t>(k) * columns + i * dims + a];
    };
    fill(rational);
    if (!solve_collocation(s.knots_v, q, v, data, columns))
        return make_error(ErrorCode::geometry, "the skinning system is singular", "/curves");
    if (!rational) {
        for (int i = 0; i < n; ++i)
            for (int j = 0; j <= K; ++j) s.point(i, j) = {at(j, i, 0), at(j, i, 1), at(j, i, 2)};
        return out;
    }
    bool needs_fallback = false;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j <= K; ++j) {
            const HPoint h{at(j, i, 0), at(j, i, 1), at(j, i, 2), at(j, i, 3)};
            s.weight(i, j) = h.w;
            if (h.w != 0.0) {
                s.point(i, j) = glm::dvec3(h) / h.w;
            } else if (h.x == 0.0 && h.y == 0.0 && h.z == 0.0) {
                needs_fallback = true; // a zero homogeneous point: any position will do
            } else {
                return make_error_nopath(
                    ErrorCode::weights,
                    "the interpolated control point (" + std::to_string(i) + ", " +
                        std::to_string(j) +
                        ") would lie at infinity (weight 0 with non-zero weighted coordinates)");
            }
            const glm::dvec3& p = s.point(i, j);
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) ||
                !std::isfinite(h.w)) {
                return make_error_nopath(ErrorCode::weights,
                                         "the interpolated control point (" + std::to_string(i) +
                                             ", " + std::to_string(j) +
                                             ") is not finite (a weight is too close to zero)");
            }
        }
    }
    if (needs_fallback) {
        // Place zero-weight points where the same interpolation puts the Cartesian points.
        fill(false);
        solve_collocation(s.knots_v, q, v, data, columns);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j <= K; ++j)
                if (s.weight(i, j) == 0.0) s.point(i, j) = {at(j, i, 0), at(j, i, 1), at(j, i, 2)};
    }
    return out;
}

} // namespace isoparm::geom
