#include "core/geom/refine_within_limits.hpp"

#include "core/geom/refine.hpp"
#include "core/geom/validate.hpp"

namespace isoparm::geom {

namespace {

Status check_times(int times) {
    if (times < 1)
        return make_error(ErrorCode::schema,
                          "times must be at least 1, got " + std::to_string(times), "/times");
    return Ok{};
}

// On a clamped vector with `spans` non-empty spans, elevation by t adds exactly t * spans
// control points (each distinct knot's multiplicity rises by t; Piegl & Tiller A5.9); an
// unclamped vector is clamped first, which never adds points. So n + t * spans bounds the
// result, and the refusal comes before any allocation. `across` is the count of the other
// direction for a surface (1 for a curve).
Status check_elevation_size(const Knots& U, int p, int n, long long across, int times) {
    long long spans = 0;
    for (int k = p; k < n; ++k)
        if (U[k] < U[k + 1]) ++spans;
    const long long estimate = n + static_cast<long long>(times) * spans;
    auto too_many = [&](long long count, long long cap) {
        return make_error(ErrorCode::limit,
                          "elevating the degree " + std::to_string(times) +
                              " time(s) would give about " + std::to_string(count) +
                              " control points; at most " + std::to_string(cap) + " are allowed",
                          "/times");
    };
    if (times > max_points_per_direction || estimate > max_points_per_direction)
        return too_many(estimate, max_points_per_direction);
    if (across > 1 && estimate * across > max_points_per_surface)
        return too_many(estimate * across, max_points_per_surface);
    return Ok{};
}

template <class Shape> Expected<Shape> within_limits(Expected<Shape> refined) {
    if (!refined) return refined;
    if (Status st = check_net_size(*refined, "/times"); !st) return st.error();
    return refined;
}

} // namespace

Expected<Curve> insert_knot_within_limits(const Curve& c, double t, int times) {
    if (Status st = check_times(times); !st) return st.error();
    return within_limits(insert_knot(c, t, times));
}

Expected<Surface> insert_knot_within_limits(const Surface& s, Dir dir, double t, int times) {
    if (Status st = check_times(times); !st) return st.error();
    return within_limits(insert_knot(s, dir, t, times));
}

Expected<Curve> elevate_degree_within_limits(const Curve& c, int times) {
    if (Status st = check_times(times); !st) return st.error();
    if (Status st = check_elevation_size(c.knots, c.degree, c.count(), 1, times); !st)
        return st.error();
    return within_limits(elevate_degree(c, times));
}

Expected<Surface> elevate_degree_within_limits(const Surface& s, Dir dir, int times) {
    if (Status st = check_times(times); !st) return st.error();
    const Dir other = opposite(dir);
    if (Status st =
            check_elevation_size(s.knots(dir), s.degree(dir), s.count(dir), s.count(other), times);
        !st)
        return st.error();
    return within_limits(elevate_degree(s, dir, times));
}

Status check_net_size(const Curve& c, const std::string& path) {
    if (c.count() > max_points_per_direction)
        return make_error(ErrorCode::limit,
                          "the result would have " + std::to_string(c.count()) +
                              " control points; at most " +
                              std::to_string(max_points_per_direction) + " are allowed",
                          path);
    return Ok{};
}

Status check_net_size(const Surface& s, const std::string& path) {
    const std::string counts = std::to_string(s.n_u) + " x " + std::to_string(s.n_v);
    if (s.n_u > max_points_per_direction || s.n_v > max_points_per_direction)
        return make_error(ErrorCode::limit,
                          "the result would have " + counts + " control points; at most " +
                              std::to_string(max_points_per_direction) +
                              " per direction are allowed",
                          path);
    if (static_cast<long>(s.n_u) * s.n_v > max_points_per_surface)
        return make_error(ErrorCode::limit,
                          "the result would have " + counts + " control points; at most " +
                              std::to_string(max_points_per_surface) + " are allowed",
                          path);
    return Ok{};
}

} // namespace isoparm::geom
