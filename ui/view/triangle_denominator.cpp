#include "ui/view/triangle_denominator.hpp"

namespace isoparm::ui {

namespace {

geom::Barycentric mix(const geom::Barycentric& p, const geom::Barycentric& q, double f) {
    return {p[0] + f * (q[0] - p[0]), p[1] + f * (q[1] - p[1]), p[2] + f * (q[2] - p[2])};
}

// One small triangle: its tint and its piece of the zero set. A zero counts as positive, so
// exactly two edges or none change sign.
void march(const geom::TrianglePatch& t, const std::array<geom::Barycentric, 3>& p,
           const std::array<double, 3>& d, TriangleDenominatorView& v) {
    const geom::Barycentric centre = {(p[0][0] + p[1][0] + p[2][0]) / 3,
                                      (p[0][1] + p[1][1] + p[2][1]) / 3,
                                      (p[0][2] + p[1][2] + p[2][2]) / 3};
    if (geom::triangle_denominator(t, centre) < 0) v.negative.push_back(p);
    std::array<geom::Barycentric, 2> segment;
    int found = 0;
    for (int e = 0; e < 3; ++e) {
        const int a = e, b = (e + 1) % 3;
        if ((d[a] < 0) == (d[b] < 0)) continue;
        segment[static_cast<std::size_t>(found++)] = mix(p[a], p[b], d[a] / (d[a] - d[b]));
    }
    if (found == 2) v.zero_set.push_back(segment);
}

} // namespace

TriangleDenominatorView triangle_denominator_view(const geom::TrianglePatch& t, int subdivisions) {
    TriangleDenominatorView v;
    v.key = TriangleWeightsKey::of(t, subdivisions);
    v.valid = true;
    if (!t.rational) return v; // D = 1
    const int N = subdivisions;
    auto point = [N](int a, int b) { return triangle_grid_point(N, a, b); };
    std::vector<double> D(static_cast<std::size_t>(geom::TrianglePatch::count_for(N)));
    auto at = [&](int a, int b) -> double& {
        return D[static_cast<std::size_t>(geom::TrianglePatch::index(N, a, b))];
    };
    for (int a = 0; a <= N; ++a)
        for (int b = 0; a + b <= N; ++b) at(a, b) = geom::triangle_denominator(t, point(a, b));
    for (int a = 0; a < N; ++a)
        for (int b = 0; a + b < N; ++b) {
            march(t, {point(a, b), point(a + 1, b), point(a, b + 1)},
                  {at(a, b), at(a + 1, b), at(a, b + 1)}, v);
            if (a + b + 2 <= N)
                march(t, {point(a + 1, b), point(a + 1, b + 1), point(a, b + 1)},
                      {at(a + 1, b), at(a + 1, b + 1), at(a, b + 1)}, v);
        }
    return v;
}

bool same_denominator(const TriangleDenominatorView& v, const geom::TrianglePatch& t,
                      int subdivisions) {
    return v.valid && v.key.matches(t, subdivisions);
}

} // namespace isoparm::ui
