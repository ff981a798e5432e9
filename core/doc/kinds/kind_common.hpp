// Pieces the kinds' files share: exact (bit for bit) comparison, finite control points, the
// names of control points in messages.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/doc/kinds/kind_facts.hpp"
#include "core/geom/status.hpp"

namespace isoparm::doc::detail {

// Bit for bit: 0.0 and -0.0 differ, a NaN equals the same NaN. Undo must restore exactly the
// numbers it found, so `==` on doubles (which merges the zeros) is not enough.
inline bool bit_equal(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
inline bool bit_equal(float a, float b) {
    return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}
inline bool bit_equal(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}
inline bool bit_equal(const glm::dvec3& a, const glm::dvec3& b) {
    return bit_equal(a.x, b.x) && bit_equal(a.y, b.y) && bit_equal(a.z, b.z);
}
inline bool bit_equal(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (!bit_equal(a[k], b[k])) return false;
    return true;
}
inline bool same_curve_bits(const geom::Curve& a, const geom::Curve& b) {
    return a.type == b.type && a.degree == b.degree && bit_equal(a.knots, b.knots) &&
           bit_equal(a.points, b.points) && bit_equal(a.weights, b.weights);
}

// Every coordinate finite (`schema`); point_path(k) is the JSON Pointer of point k, to which
// the coordinate's index is appended.
template <typename PointPath>
geom::Status finite_points(const std::vector<glm::dvec3>& points, PointPath point_path) {
    for (std::size_t k = 0; k < points.size(); ++k)
        for (int a = 0; a < 3; ++a)
            if (!std::isfinite(points[k][a]))
                return geom::make_error(geom::ErrorCode::schema,
                                        "control point coordinates must be finite numbers, got " +
                                            geom::format_number(points[k][a]),
                                        point_path(k) + "/" + std::to_string(a));
    return geom::Ok{};
}

// The kind K's geometry, member `name` of the object or shape j, read by `read` (its errors
// under at/name).
template <class K, class Read>
geom::Expected<K> read_geometry(const nlohmann::json& j, const std::string& at, const char* name,
                                Read read) {
    auto g = read(j.at(name));
    if (!g) return g.error().under(at + "/" + name);
    return K{std::move(g).value()};
}

// The control points and weights of a kind whose geometry (member `net`) keeps them as
// `points` and `weights`: the four control_points / control_weights facts, defined.
#define ISOPARM_NET_FACTS(K, net)                                                                  \
    std::span<glm::dvec3> control_points(K& k) {                                                   \
        return k.net.points;                                                                       \
    }                                                                                              \
    std::span<const glm::dvec3> control_points(const K& k) {                                       \
        return k.net.points;                                                                       \
    }                                                                                              \
    std::span<double> control_weights(K& k) {                                                      \
        return k.net.weights;                                                                      \
    }                                                                                              \
    std::span<const double> control_weights(const K& k) {                                          \
        return k.net.weights;                                                                      \
    }

// A selected point [i, j] (`what` names the form in the refusal), i in 0..max_i and j in
// 0..max_j.
geom::Expected<std::pair<int, int>> point_pair_from_json(const nlohmann::json& point,
                                                         const std::string& at, const char* what,
                                                         int max_i, int max_j);

// The box of some points; nothing when there are none.
std::optional<Box> box_of(std::span<const glm::dvec3> points);

// A control point index outside 0..count-1 (`schema` at path).
geom::Error index_out_of_range(const char* name, int value, int count, const char* path);

// Labels: "P23" (surface, both indices < 10), "P12,3" (otherwise), "P4" (curve, j < 0).
std::string point_label(char letter, int i, int j);
// "P2,3" (j >= 0), "P4" (j < 0): indices always apart.
std::string indexed_label(char letter, int i, int j);
// Triangles: "b210" (every index < 10), "b12,3,0" otherwise; k = n - i - j.
std::string triangle_point_label(char letter, int n, int i, int j);

} // namespace isoparm::doc::detail
