// The surface of revolution about the z-axis (Piegl & Tiller A8.1 MakeRevolvedSurf).
#include <cmath>

#include "core/geom/construct.hpp"
#include "core/geom/construct_common.hpp"
#include "core/geom/primitives.hpp"

namespace isoparm::geom {

namespace {

// The point rotated about the z-axis by the angle whose (cos, sin) is cs.
glm::dvec3 turned(const glm::dvec3& P, const glm::dvec2& cs) {
    return {P.x * cs.x - P.y * cs.y, P.x * cs.y + P.y * cs.x, P.z};
}

} // namespace

Expected<Surface> revolve(const Curve& profile, double degrees) {
    if (!std::isfinite(degrees) || !(degrees > 0.0 && degrees <= 360.0)) {
        return make_error(ErrorCode::schema,
                          "angle must lie in (0, 360] degrees, got " + format_number(degrees),
                          "/angle");
    }
    const ArcLayout arc = arc_layout(degrees);
    const int n_v = 2 * arc.arcs + 1;
    if (Status s = construct_detail::check_result_size(profile.count(), n_v); !s) return s.error();
    Surface s;
    s.type = SplineType::nurbs;
    s.degree_u = profile.degree;
    s.degree_v = 2;
    s.knots_u = profile.knots;
    s.knots_v = arc.knots;
    s.n_u = profile.count();
    s.n_v = n_v;
    s.points.resize(static_cast<size_t>(s.n_u) * n_v);
    s.weights.resize(static_cast<size_t>(s.n_u) * n_v);
    // Each profile control point sweeps the circle through it about the axis (A7.1 applied to
    // the point, a pole when it is on the axis); the weights multiply (w_i times the arc's), so
    // the homogeneous tensor product is exactly Rz(phi(v)) C(u): rotation is linear.
    for (int i = 0; i < s.n_u; ++i) {
        const glm::dvec3& P = profile.points[i];
        const double w = profile.weights[i];
        for (int a = 0; a <= arc.arcs; ++a) {
            // Arc joins on the circle; middle points where the joins' tangents meet: the join
            // plus tan(delta / 2) times its radius vector turned by 90 degrees (A8.1).
            const glm::dvec2 cs = cos_sin_degrees(a * arc.delta_degrees);
            const glm::dvec3 Q = turned(P, cs);
            s.point(i, 2 * a) = Q;
            s.weight(i, 2 * a) = w;
            if (a == arc.arcs) break;
            s.point(i, 2 * a + 1) = Q + arc.middle_reach * glm::dvec3(-Q.y, Q.x, 0.0);
            s.weight(i, 2 * a + 1) = w * arc.middle_weight;
        }
        // A full turn closes exactly: the last column is the first, not a rounded copy.
        if (degrees == 360.0) s.point(i, n_v - 1) = P;
    }
    // A point on the axis turned by 180 degrees is (-0, -0, z): zero has no sign here, as the
    // protocol and the scene files write it (a rebuilt vase equals the one saved).
    for (glm::dvec3& q : s.points) q += glm::dvec3(0.0);
    return s;
}

} // namespace isoparm::geom
