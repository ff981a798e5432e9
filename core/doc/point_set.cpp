// Point sets of one object and the affine maps a selection is moved by.
#include "core/doc/point_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

namespace isoparm::doc {

std::vector<PointIndex> all_points(const Shape& shape) {
    std::vector<PointIndex> out;
    std::visit(overloaded{
                   [&](const SurfaceObject& so) {
                       for (int i = 0; i < so.surface.n_u; ++i)
                           for (int j = 0; j < so.surface.n_v; ++j) out.push_back({i, j});
                   },
                   [&](const CurveObject& c) {
                       for (int i = 0; i < c.curve.count(); ++i) out.push_back({i, -1});
                   },
                   [](const ImplicitObject&) {},
                   [&](const TriangleObject& t) {
                       for (int i = t.patch.degree; i >= 0; --i)
                           for (int j = t.patch.degree - i; j >= 0; --j) out.push_back({i, j});
                   },
               },
               shape);
    return out;
}

namespace {

// The points whose first index (`row`) or second is `k`, in the order the other index runs:
// a surface's row or column, a triangle's line of constant i or j (b_i,j,k for j = n - i .. 0),
// a curve's every point.
std::vector<PointIndex> line_points(const Shape& shape, bool row, int k) {
    std::vector<PointIndex> out;
    auto at = [row, k](int other) { return row ? PointIndex{k, other} : PointIndex{other, k}; };
    std::visit(overloaded{
                   [&](const SurfaceObject& so) {
                       const geom::Surface& s = so.surface;
                       const int fixed_count = row ? s.n_u : s.n_v;
                       const int other_count = row ? s.n_v : s.n_u;
                       if (k >= 0 && k < fixed_count)
                           for (int o = 0; o < other_count; ++o) out.push_back(at(o));
                   },
                   [&](const CurveObject&) { out = all_points(shape); },
                   [](const ImplicitObject&) {},
                   [&](const TriangleObject& t) {
                       if (k >= 0 && k <= t.patch.degree)
                           for (int o = t.patch.degree - k; o >= 0; --o) out.push_back(at(o));
                   },
               },
               shape);
    return out;
}

} // namespace

std::vector<PointIndex> row_points(const Shape& shape, int i) {
    return line_points(shape, true, i);
}

std::vector<PointIndex> column_points(const Shape& shape, int j) {
    return line_points(shape, false, j);
}

glm::dvec3 position_of(const Shape& shape, PointIndex p) {
    // Callers pass a point the shape has (has_control_point); an implicit surface has none.
    return std::visit(
        overloaded{
            [&](const SurfaceObject& s) { return s.surface.point(p.i, p.j); },
            [&](const CurveObject& c) { return c.curve.points[static_cast<std::size_t>(p.i)]; },
            [](const ImplicitObject&) { return glm::dvec3(0); },
            [&](const TriangleObject& t) {
                return t.patch.points[static_cast<std::size_t>(
                    geom::TrianglePatch::index(t.patch.degree, p.i, p.j))];
            },
        },
        shape);
}

glm::dvec3 centroid(const Shape& shape, const std::vector<PointIndex>& points) {
    glm::dvec3 sum(0);
    for (PointIndex p : points) sum += position_of(shape, p);
    return points.empty() ? sum : sum / static_cast<double>(points.size());
}

glm::dmat4 translation(const glm::dvec3& d) {
    glm::dmat4 m(1.0);
    m[3] = glm::dvec4(d, 1.0);
    return m;
}

glm::dmat4 about(const glm::dmat4& m, const glm::dvec3& pivot) {
    return translation(pivot) * m * translation(-pivot);
}

glm::dmat4 scaling(const glm::dvec3& f) {
    glm::dmat4 m(1.0);
    m[0][0] = f.x;
    m[1][1] = f.y;
    m[2][2] = f.z;
    return m;
}

glm::dmat4 rotation(int axis, double degrees) {
    double c = 0, s = 0;
    const double quarter = degrees / 90.0;
    if (quarter == std::floor(quarter) && std::abs(quarter) < 1e15) {
        const long q = ((static_cast<long>(quarter) % 4) + 4) % 4;
        const double cs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
        c = cs[q][0];
        s = cs[q][1];
    } else {
        const double r = degrees * std::acos(-1.0) / 180.0;
        c = std::cos(r);
        s = std::sin(r);
    }
    const int a = (axis + 1) % 3, b = (axis + 2) % 3; // the turned plane, a towards b
    glm::dmat4 m(1.0);
    m[a][a] = c;
    m[a][b] = s; // column a (the image of e_a) has s in row b
    m[b][a] = -s;
    m[b][b] = c;
    return m;
}

glm::dmat4 mirror(int axis) {
    glm::dvec3 f(1);
    f[axis] = -1;
    return scaling(f);
}

glm::dvec3 apply_affine(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

std::optional<PointIndex> mirror_partner(const Shape& shape, PointIndex p, int axis,
                                         double tolerance) {
    const std::vector<PointIndex> points = all_points(shape);
    if (points.empty()) return std::nullopt;
    double size = 0;
    for (PointIndex q : points) {
        const glm::dvec3 x = position_of(shape, q);
        size = std::max({size, std::abs(x.x), std::abs(x.y), std::abs(x.z)});
    }
    glm::dvec3 image = position_of(shape, p);
    image[axis] = -image[axis];
    const double limit = tolerance * std::max(size, 1.0);
    std::optional<PointIndex> best;
    double best_d = std::numeric_limits<double>::infinity();
    for (PointIndex q : points) {
        const glm::dvec3 d = position_of(shape, q) - image;
        const double e = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
        if (e <= limit && e < best_d) {
            best = q;
            best_d = e;
        }
    }
    return best;
}

SymmetricMove symmetric_move(const Shape& shape, const std::vector<PointIndex>& points,
                             const std::vector<glm::dvec3>& positions, int axis, double tolerance) {
    SymmetricMove out{points, positions, 0};
    for (std::size_t k = 0; k < points.size(); ++k) {
        const std::optional<PointIndex> partner = mirror_partner(shape, points[k], axis, tolerance);
        if (!partner) continue;
        if (*partner == points[k]) {
            out.positions[k][axis] = 0; // on the mirror plane: it stays there
            continue;
        }
        if (std::find(out.points.begin(), out.points.end(), *partner) != out.points.end()) continue;
        glm::dvec3 image = positions[k];
        image[axis] = -image[axis];
        out.points.push_back(*partner);
        out.positions.push_back(image);
        ++out.partners;
    }
    return out;
}

} // namespace isoparm::doc
