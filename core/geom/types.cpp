// The curve <-> surface line slicing shared by all refinements.
#include "core/geom/types.hpp"

#include <cassert>

namespace isoparm::geom {

Curve surface_line(const Surface& s, Dir dir, int index) {
    Curve c;
    c.type = s.type;
    c.degree = s.degree(dir);
    c.knots = s.knots(dir);
    const int n = s.count(dir);
    c.points.resize(n);
    c.weights.resize(n);
    for (int k = 0; k < n; ++k) {
        const int id = dir == Dir::u ? s.index(k, index) : s.index(index, k);
        c.points[k] = s.points[id];
        c.weights[k] = s.weights[id];
    }
    return c;
}

Surface surface_from_lines(const Surface& like, Dir dir, const std::vector<Curve>& lines) {
    assert(!lines.empty());
    Surface s = like;
    const Curve& first = lines.front();
    const int along = first.count();
    const int across = static_cast<int>(lines.size());
    if (dir == Dir::u) {
        s.degree_u = first.degree;
        s.knots_u = first.knots;
        s.n_u = along;
        s.n_v = across;
    } else {
        s.degree_v = first.degree;
        s.knots_v = first.knots;
        s.n_v = along;
        s.n_u = across;
    }
    s.points.assign(static_cast<size_t>(s.n_u) * s.n_v, glm::dvec3(0));
    s.weights.assign(static_cast<size_t>(s.n_u) * s.n_v, 1.0);
    for (int l = 0; l < across; ++l) {
        assert(lines[l].count() == along);
        for (int k = 0; k < along; ++k) {
            const int id = dir == Dir::u ? s.index(k, l) : s.index(l, k);
            s.points[id] = lines[l].points[k];
            s.weights[id] = lines[l].weights[k];
        }
    }
    return s;
}

} // namespace isoparm::geom
