// Whole-object validation of curves and surfaces, in the order the protocol reports errors.
#include "core/geom/validate.hpp"

#include <cmath>
#include <functional>

#include "core/geom/knots.hpp"

namespace isoparm::geom {

namespace {

std::string idx(long i) {
    return pointer_step(i);
}

Status check_degree(int p, int n, const std::string& path, const char* dir_name) {
    if (p < 1) return make_error(ErrorCode::degree, "the degree must be at least 1", path);
    if (n < p + 1) {
        return make_error(ErrorCode::degree,
                          std::string("degree ") + std::to_string(p) + dir_name +
                              " needs at least " + std::to_string(p + 1) + " control points, got " +
                              std::to_string(n),
                          path);
    }
    return Ok{};
}

// Runs after validate_knots, so the knots fit n and p: with n != p + 1 they make more than one
// span, and the knots are what is wrong (docs/protocol.md). A Bezier object read without
// knots gets a^(p+1) b^(p+1), which only fits p + 1 points; its reader refuses a wrong
// count as a `degree` error before this runs (there are no knots to blame).
Status check_bezier(const Knots& U, int p, int n, const std::string& knots_path, const char* what) {
    if (n != p + 1) {
        return make_error(ErrorCode::knots,
                          std::string("a Bezier ") + what +
                              " has one span: knots a^(p+1) b^(p+1) " + "and exactly " +
                              std::to_string(p + 1) + " control points for degree " +
                              std::to_string(p) + ", got " + std::to_string(n) + " control points",
                          knots_path);
    }
    for (int k = 0; k <= p; ++k) {
        if (U[k] != U[0] || U[p + 1 + k] != U.back()) {
            return make_error(ErrorCode::knots,
                              std::string("a Bezier ") + what +
                                  " has one span: knots a^(p+1) b^(p+1)",
                              knots_path);
        }
    }
    return Ok{};
}

Status check_weights(const std::vector<double>& w, size_t count, bool rational,
                     const std::function<std::string(size_t)>& path_of) {
    if (w.size() != count) {
        return make_error(ErrorCode::weights,
                          "expected " + std::to_string(count) + " weights, got " +
                              std::to_string(w.size()),
                          "/weights");
    }
    for (size_t k = 0; k < w.size(); ++k) {
        if (!std::isfinite(w[k]))
            return make_error(ErrorCode::weights, "weights must be finite numbers", path_of(k));
        if (!rational && w[k] != 1.0) {
            return make_error(ErrorCode::weights,
                              "a non-rational type has unit weights, got " + format_number(w[k]),
                              path_of(k));
        }
    }
    return Ok{};
}

Status check_points(const std::vector<glm::dvec3>& pts,
                    const std::function<std::string(size_t)>& path_of) {
    for (size_t k = 0; k < pts.size(); ++k) {
        const glm::dvec3& p = pts[k];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return make_error(ErrorCode::schema, "coordinates must be finite numbers", path_of(k));
    }
    return Ok{};
}

} // namespace

Status validate_curve(const Curve& c) {
    const int p = c.degree, n = c.count();
    if (n > max_points_per_direction) {
        return make_error(ErrorCode::limit,
                          "too many control points (" + std::to_string(n) + " > " +
                              std::to_string(max_points_per_direction) + ")",
                          "/points");
    }
    if (Status s = check_degree(p, n, "/degree", ""); !s) return s;
    if (Status s = check_points(c.points, [](size_t k) { return "/points" + idx(k); }); !s)
        return s;
    if (Status s = check_weights(c.weights, c.points.size(), is_rational(c.type),
                                 [](size_t k) { return "/weights" + idx(k); });
        !s)
        return s;
    if (Status s = validate_knots(c.knots, p, n); !s) return s.error().under("/knots");
    if (is_bezier(c.type)) return check_bezier(c.knots, p, n, "/knots", "curve");
    return Ok{};
}

Status validate_surface(const Surface& s) {
    if (s.n_u > max_points_per_direction)
        return make_error(ErrorCode::limit, "too many points along u", "/points");
    if (s.n_v > max_points_per_direction)
        return make_error(ErrorCode::limit, "too many points along v", "/points");
    if (static_cast<long>(s.n_u) * s.n_v > max_points_per_surface)
        return make_error(ErrorCode::limit, "too many control points in the surface", "/points");
    if (static_cast<long>(s.points.size()) != static_cast<long>(s.n_u) * s.n_v)
        return make_error(ErrorCode::schema, "the control net is not n_u x n_v", "/points");
    if (Status r = check_degree(s.degree_u, s.n_u, "/degree/0", " in u"); !r) return r;
    if (Status r = check_degree(s.degree_v, s.n_v, "/degree/1", " in v"); !r) return r;
    const int nv = s.n_v;
    auto grid_path = [nv](const char* field) {
        return [field, nv](size_t k) {
            return std::string(field) + idx(static_cast<long>(k) / nv) +
                   idx(static_cast<long>(k) % nv);
        };
    };
    if (Status r = check_points(s.points, grid_path("/points")); !r) return r;
    if (Status r =
            check_weights(s.weights, s.points.size(), is_rational(s.type), grid_path("/weights"));
        !r)
        return r;
    if (Status r = validate_knots(s.knots_u, s.degree_u, s.n_u); !r)
        return r.error().under("/knots/0");
    if (Status r = validate_knots(s.knots_v, s.degree_v, s.n_v); !r)
        return r.error().under("/knots/1");
    if (is_bezier(s.type)) {
        if (Status r = check_bezier(s.knots_u, s.degree_u, s.n_u, "/knots/0", "surface"); !r)
            return r;
        if (Status r = check_bezier(s.knots_v, s.degree_v, s.n_v, "/knots/1", "surface"); !r)
            return r;
    }
    return Ok{};
}

} // namespace isoparm::geom
