// The ruled surface between two curves (Piegl & Tiller 10.2): straight segments in v.
#include "core/geom/construct.hpp"
#include "core/geom/construct_common.hpp"

namespace isoparm::geom {

Expected<Surface> ruled(const Curve& c0, const Curve& c1) {
    auto compatible = make_compatible({c0, c1});
    if (!compatible) return compatible.error();
    const Curve& a = (*compatible)[0];
    const Curve& b = (*compatible)[1];
    if (Status s = construct_detail::check_result_size(a.count(), 2); !s) return s.error();
    // The homogeneous tensor product with a degree-1 v-direction: row i is the segment from
    // C0's i-th control point to C1's, so S(u, v) = [(1-v) C0^w(u) + v C1^w(u)] projected.
    Surface s;
    s.type = construct_detail::result_type(is_rational(a.type) || is_rational(b.type),
                                           is_bezier(a.type) && is_bezier(b.type));
    s.degree_u = a.degree;
    s.degree_v = 1;
    s.knots_u = a.knots;
    s.knots_v = {0.0, 0.0, 1.0, 1.0};
    s.n_u = a.count();
    s.n_v = 2;
    s.points.resize(static_cast<size_t>(s.n_u) * 2);
    s.weights.resize(static_cast<size_t>(s.n_u) * 2);
    for (int i = 0; i < s.n_u; ++i) {
        s.point(i, 0) = a.points[i];
        s.weight(i, 0) = a.weights[i];
        s.point(i, 1) = b.points[i];
        s.weight(i, 1) = b.weights[i];
    }
    return s;
}

} // namespace isoparm::geom
