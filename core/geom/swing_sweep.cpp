// Swung (Piegl & Tiller 10.4) and translationally swept surfaces: exact tensor products.
#include <cmath>

#include "core/geom/construct.hpp"
#include "core/geom/construct_common.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::geom {

namespace {

// The tensor-product frame of a profile (u) x trajectory (v) surface; points filled by caller.
Surface tensor_frame(const Curve& profile, const Curve& trajectory) {
    Surface s;
    s.type =
        construct_detail::result_type(is_rational(profile.type) || is_rational(trajectory.type),
                                      is_bezier(profile.type) && is_bezier(trajectory.type));
    s.degree_u = profile.degree;
    s.degree_v = trajectory.degree;
    s.knots_u = profile.knots;
    s.knots_v = trajectory.knots;
    s.n_u = profile.count();
    s.n_v = trajectory.count();
    s.points.resize(static_cast<size_t>(s.n_u) * s.n_v);
    s.weights.resize(static_cast<size_t>(s.n_u) * s.n_v);
    return s;
}

// `geometry` at the first control point whose coordinate `axis` is not zero.
Status check_plane(const Curve& c, int axis, const std::string& name, const char* plane) {
    static const char* axis_names[] = {"x", "y", "z"};
    for (int i = 0; i < c.count(); ++i) {
        if (c.points[i][axis] != 0.0) {
            return make_error(ErrorCode::geometry,
                              "the " + name + " must lie in the " + plane +
                                  "-plane, but control point " + std::to_string(i) + " has " +
                                  axis_names[axis] + " = " + format_number(c.points[i][axis]),
                              "/" + name + "/points/" + std::to_string(i));
        }
    }
    return Ok{};
}

} // namespace

Expected<Surface> swing(const Curve& profile, const Curve& trajectory, double scale) {
    if (!std::isfinite(scale))
        return make_error(ErrorCode::schema, "scale must be a finite number", "/scale");
    if (Status s = check_plane(profile, 1, "profile", "xz"); !s) return s.error();
    if (Status s = check_plane(trajectory, 2, "trajectory", "xy"); !s) return s.error();
    if (Status s = construct_detail::check_result_size(profile.count(), trajectory.count()); !s)
        return s.error();
    // P&T eq. 10.9: Q_ij = (s Px_i Tx_j, s Px_i Ty_j, Pz_i), w_ij = w_i w_j. The product of the
    // two rational curves is exact: the x and y coordinates are products of the curves'
    // coordinates, and z does not depend on v (sum_j N_j w_j Pz_i / sum_j N_j w_j = Pz_i).
    Surface s = tensor_frame(profile, trajectory);
    for (int i = 0; i < s.n_u; ++i) {
        const glm::dvec3& P = profile.points[i];
        for (int j = 0; j < s.n_v; ++j) {
            const glm::dvec3& T = trajectory.points[j];
            s.point(i, j) = {scale * P.x * T.x, scale * P.x * T.y, P.z};
            s.weight(i, j) = profile.weights[i] * trajectory.weights[j];
        }
    }
    return s;
}

Expected<Surface> sweep(const Curve& profile, const Curve& trajectory) {
    const double a = trajectory.knots[trajectory.degree];
    const auto T0 = curve_point(trajectory, a);
    if (!T0) {
        return make_error(ErrorCode::weights,
                          "the trajectory has no point at its start " + format_number(a) +
                              " (its weights there sum to zero)",
                          "/trajectory/weights");
    }
    if (Status s = construct_detail::check_result_size(profile.count(), trajectory.count()); !s)
        return s.error();
    // The homogeneous tensor product w_i w_j (P_i + T_j - T0): projecting gives
    // [sum N_i w_i P_i / W_P] + [sum N_j w_j T_j / W_T] - T0 = P(u) + T(v) - T0 exactly, since
    // each factor's basis sums to one after division by its own weight function.
    Surface s = tensor_frame(profile, trajectory);
    for (int i = 0; i < s.n_u; ++i) {
        for (int j = 0; j < s.n_v; ++j) {
            s.point(i, j) = profile.points[i] + (trajectory.points[j] - *T0);
            s.weight(i, j) = profile.weights[i] * trajectory.weights[j];
        }
    }
    return s;
}

} // namespace isoparm::geom
