#include "core/geom/blossom.hpp"

#include <algorithm>

#include "core/geom/deboor.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::geom {

int default_blossom_span(const Knots& U, int p, int n, double t) {
    const Interval dom = domain(U, p, n);
    return find_span(U, p, n, std::clamp(t, dom.lo, dom.hi));
}

Status check_blossom_span(const Knots& U, int p, int n, int span, const std::string& path) {
    if (span < p || span > n - 1)
        return make_error(ErrorCode::schema,
                          "span " + std::to_string(span) + " is not a piece: it must be between " +
                              std::to_string(p) + " and " + std::to_string(n - 1),
                          path);
    if (!(U[span] < U[span + 1]))
        return make_error(ErrorCode::schema,
                          "span " + std::to_string(span) + " is empty: knots " +
                              std::to_string(span) + " and " + std::to_string(span + 1) +
                              " are both " + format_number(U[span]),
                          path);
    return Ok{};
}

namespace {

HPoint blossom_homogeneous(const Knots& U, int p, const std::vector<HPoint>& Pw, int span,
                           const std::vector<double>& args) {
    return deboor_polar(U, p, Pw, span, args).levels.back().front();
}

} // namespace

// A polynomial's blossom is an affine combination of its control points, whatever the
// arguments: its weight is exactly 1, but computed in homogeneous space it is a sum of large
// terms that cancel (the line from (0,0) to (1,1) at 1e16: 1 - 1e16 + 1e16 = 0 in floating
// point). So only a rational object divides by the computed weight.
namespace {
std::optional<glm::dvec3> cartesian_of(const HPoint& h, SplineType type) {
    if (!is_rational(type)) return glm::dvec3(h);
    return DeBoorTriangle::cartesian(h);
}
} // namespace

std::optional<glm::dvec3> curve_blossom(const Curve& c, int span, const std::vector<double>& args) {
    std::vector<HPoint> Pw(c.count());
    for (int i = 0; i < c.count(); ++i) Pw[i] = c.hpoint(i);
    return cartesian_of(blossom_homogeneous(c.knots, c.degree, Pw, span, args), c.type);
}

std::optional<glm::dvec3> surface_blossom(const Surface& s, int span_u, int span_v,
                                          const std::vector<double>& u_args,
                                          const std::vector<double>& v_args) {
    // Only the columns of the v-piece matter: j = span_v - q .. span_v.
    std::vector<HPoint> column(s.n_u), row(s.n_v);
    for (int j = span_v - s.degree_v; j <= span_v; ++j) {
        for (int i = 0; i < s.n_u; ++i) column[i] = s.hpoint(i, j);
        row[j] = blossom_homogeneous(s.knots_u, s.degree_u, column, span_u, u_args);
    }
    return cartesian_of(blossom_homogeneous(s.knots_v, s.degree_v, row, span_v, v_args), s.type);
}

std::vector<double> deboor_point_arguments(const Knots& U, int p, int level, int index, double t) {
    std::vector<double> args(static_cast<std::size_t>(level), t);
    for (int r = index + 1; r <= index + p - level; ++r) args.push_back(U[r]);
    return args;
}

} // namespace isoparm::geom
