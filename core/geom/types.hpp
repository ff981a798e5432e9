// The one rational tensor-product representation behind all four spline types.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "core/geom/enum_names.hpp"

namespace isoparm::geom {

// The type is a tag: all four share one representation. Non-rational types keep unit
// weights; Bezier types keep a single span (knots a^(p+1) b^(p+1), n = p + 1).
enum class SplineType { bezier, rational_bezier, bspline, nurbs };
// Files and requests spell them bezier ... nurbs; menus and messages say them as the paper does.
inline constexpr EnumName<SplineType> spline_type_names[] = {
    {SplineType::bezier, "bezier", "Bezier"},
    {SplineType::rational_bezier, "rational_bezier", "rational Bezier"},
    {SplineType::bspline, "bspline", "B-spline"},
    {SplineType::nurbs, "nurbs", "NURBS"},
};
static_assert(in_declaration_order(spline_type_names));
constexpr std::span<const EnumName<SplineType>> enum_names(SplineType) {
    return spline_type_names;
}
// The file name (name_of), for callers that say it this way.
inline const char* spline_type_name(SplineType type) {
    return name_of(type);
}
inline bool is_rational(SplineType t) {
    return t == SplineType::rational_bezier || t == SplineType::nurbs;
}
inline bool is_bezier(SplineType t) {
    return t == SplineType::bezier || t == SplineType::rational_bezier;
}

enum class Dir { u, v };
inline constexpr EnumName<Dir> dir_names[] = {{Dir::u, "u"}, {Dir::v, "v"}};
static_assert(in_declaration_order(dir_names));
constexpr std::span<const EnumName<Dir>> enum_names(Dir) {
    return dir_names;
}
// The other parameter direction (u for v, v for u).
inline Dir opposite(Dir d) {
    return d == Dir::u ? Dir::v : Dir::u;
}

using Knots = std::vector<double>;

// Homogeneous point (w*x, w*y, w*z, w), the space where rational algorithms are linear.
using HPoint = glm::dvec4;
inline HPoint to_homogeneous(const glm::dvec3& p, double w) {
    return {p * w, w};
}

struct Curve {
    SplineType type = SplineType::bspline;
    int degree = 1;
    Knots knots;                    // n + p + 1 values, non-decreasing
    std::vector<glm::dvec3> points; // n Cartesian control points
    std::vector<double> weights;    // n weights, any finite real (zero and negative too)

    int count() const { return static_cast<int>(points.size()); }
    HPoint hpoint(int i) const { return to_homogeneous(points[i], weights[i]); }
};

struct Surface {
    SplineType type = SplineType::bspline;
    int degree_u = 1, degree_v = 1;
    Knots knots_u, knots_v;         // n_u + p + 1 and n_v + q + 1 values
    int n_u = 0, n_v = 0;           // control points along u (rows) and along v (columns)
    std::vector<glm::dvec3> points; // n_u * n_v, row-major: index i * n_v + j is P_ij
    std::vector<double> weights;    // n_u * n_v, same layout

    int index(int i, int j) const { return i * n_v + j; }
    glm::dvec3& point(int i, int j) { return points[index(i, j)]; }
    const glm::dvec3& point(int i, int j) const { return points[index(i, j)]; }
    double& weight(int i, int j) { return weights[index(i, j)]; }
    double weight(int i, int j) const { return weights[index(i, j)]; }
    HPoint hpoint(int i, int j) const { return to_homogeneous(point(i, j), weight(i, j)); }
    int degree(Dir d) const { return d == Dir::u ? degree_u : degree_v; }
    const Knots& knots(Dir d) const { return d == Dir::u ? knots_u : knots_v; }
    int count(Dir d) const { return d == Dir::u ? n_u : n_v; }
};

struct Interval {
    double lo = 0, hi = 1;
    bool contains(double t) const { return lo <= t && t <= hi; }
};

// A rectangle of parameters (u, v): a surface's domain, or the box a patch group tiles.
struct ParamRect {
    Interval u, v;
    bool contains(glm::dvec2 p) const { return u.contains(p.x) && v.contains(p.y); }
    const Interval& interval(Dir d) const { return d == Dir::u ? u : v; }
};

// Curve <-> surface slicing, so each curve algorithm has one implementation that surfaces
// apply row by row or column by column.
// The curve through P_{*,j} (dir u, index j) or through P_{i,*} (dir v, index i).
Curve surface_line(const Surface& s, Dir dir, int index);
// Rebuild a surface from lines that all share degree and knots: lines[j] runs along dir.
Surface surface_from_lines(const Surface& like, Dir dir, const std::vector<Curve>& lines);

} // namespace isoparm::geom
