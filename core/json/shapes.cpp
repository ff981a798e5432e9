// Geometry objects <-> JSON: structural checks with precise paths, then geom validation.
#include "core/json/shapes.hpp"

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "core/geom/knots.hpp"
#include "core/geom/validate.hpp"
#include "core/json/fields.hpp"
#include "core/json/reader.hpp"

namespace isoparm::json_io {

using geom::Error;
using geom::ErrorCode;
using geom::Expected;
using geom::make_error;
using nlohmann::json;

namespace {

std::string at(long i) {
    return "/" + std::to_string(i);
}

Error weights_error(std::string message, std::string path) {
    return make_error(ErrorCode::weights, std::move(message), std::move(path));
}

// Members a geometry object may have; anything else is a typo and is refused.
geom::Status check_geometry_members(const json& j, const char* what) {
    return check_members(j, "", what, {"type", "degree", "knots", "points", "weights"});
}

// `type`: one of the four names; default nurbs with weights, else bspline.
Expected<geom::SplineType> read_type(const json& j) {
    const auto it = j.find("type");
    if (it == j.end()) {
        return j.contains("weights") ? geom::SplineType::nurbs : geom::SplineType::bspline;
    }
    const std::optional<geom::SplineType> t = enum_value<geom::SplineType>(*it);
    if (!t)
        return schema_error("type must be one of " + geom::names_list<geom::SplineType>(", "),
                            "/type");
    return *t;
}

// One degree: an integer (integral floats accepted) >= 1. Saturated to int64 so that a huge
// degree is reported as a `degree` error later instead of overflowing.
Expected<std::int64_t> read_one_degree(const json& v, const std::string& path) {
    const std::optional<std::int64_t> d = integer_value(v);
    if (!d) return schema_error("the degree is an integer", path);
    if (*d < 1) return make_error(ErrorCode::degree, "the degree must be at least 1", path);
    return *d;
}

// A flat array of finite numbers (knots).
Expected<geom::Knots> read_knot_vector(const json& v, const std::string& path) {
    if (!v.is_array()) return schema_error("a knot vector is an array of numbers", path);
    geom::Knots U;
    U.reserve(v.size());
    for (std::size_t k = 0; k < v.size(); ++k) {
        if (!is_finite_number(v[k]))
            return read_finite(v[k], path + at(static_cast<long>(k)), "a knot").error();
        U.push_back(v[k].get<double>());
    }
    return U;
}

// A flat array of n finite weights (code `weights` for every problem: shape or value).
Expected<std::vector<double>> read_weight_row(const json& v, std::size_t n, const std::string& path,
                                              const char* what) {
    if (!v.is_array())
        return weights_error(
            std::string(what) + " is an array of " + std::to_string(n) + " numbers", path);
    if (v.size() != n)
        return weights_error(
            "expected " + std::to_string(n) + " weights, got " + std::to_string(v.size()), path);
    std::vector<double> w(n);
    for (std::size_t k = 0; k < n; ++k) {
        const json& x = v[k];
        if (!x.is_number())
            return weights_error("a weight must be a number", path + at(static_cast<long>(k)));
        const double value = x.get<double>();
        if (!std::isfinite(value))
            return weights_error("a weight must be a finite number",
                                 path + at(static_cast<long>(k)));
        w[k] = value;
    }
    return w;
}

std::string degree_message(std::int64_t p, long n, const char* dir_name) {
    if (p > (std::int64_t{1} << 31)) {
        return std::string("the degree") + dir_name + " is far too large for " + std::to_string(n) +
               " control points (degree + 1 points are needed)";
    }
    return "degree " + std::to_string(p) + dir_name + " needs at least " + std::to_string(p + 1) +
           " control points, got " + std::to_string(n);
}

// Checks that depend on the degree but must not reach validate with an out-of-range int:
// a degree beyond any possible point count, and an omitted Bezier knot vector, which only
// fits n = p + 1 points.
std::optional<Error> check_degree_fits(std::int64_t p, long n, bool bezier_default_knots,
                                       const std::string& path, const char* dir_name,
                                       const char* what) {
    if (p >= n) return make_error(ErrorCode::degree, degree_message(p, n, dir_name), path);
    if (bezier_default_knots && n != p + 1) {
        return make_error(ErrorCode::degree,
                          std::string("a Bezier ") + what + " of degree " + std::to_string(p) +
                              " has exactly " + std::to_string(p + 1) + " control points, got " +
                              std::to_string(n),
                          path);
    }
    return std::nullopt;
}

} // namespace

Expected<geom::Curve> curve_from_json(const json& j) {
    if (!j.is_object()) return schema_error("a curve is a JSON object", "");
    if (auto st = check_geometry_members(j, "a curve"); !st) return st.error();
    Expected<geom::SplineType> type = read_type(j);
    if (!type) return type.error();

    const auto degree_it = j.find("degree");
    if (degree_it == j.end()) return missing_member("", "degree");
    if (degree_it->is_array()) return schema_error("a curve's degree is one integer", "/degree");
    Expected<std::int64_t> degree = read_one_degree(*degree_it, "/degree");
    if (!degree) return degree.error();

    const auto points_it = j.find("points");
    if (points_it == j.end()) return missing_member("", "points");
    const json& P = *points_it;
    if (!P.is_array()) return schema_error("points is an array of [x, y] or [x, y, z]", "/points");
    if (P.size() > static_cast<std::size_t>(geom::max_points_per_direction)) {
        return make_error(ErrorCode::limit,
                          "too many control points (" + std::to_string(P.size()) + " > " +
                              std::to_string(geom::max_points_per_direction) + ")",
                          "/points");
    }
    geom::Curve c;
    c.type = *type;
    c.points.reserve(P.size());
    for (std::size_t i = 0; i < P.size(); ++i) {
        Expected<glm::dvec3> p = read_point(P[i], "/points" + at(static_cast<long>(i)));
        if (!p) return p.error();
        c.points.push_back(*p);
    }
    const long n = static_cast<long>(c.points.size());

    const auto knots_it = j.find("knots");
    const bool default_knots = knots_it == j.end();
    if (default_knots && !geom::is_bezier(c.type)) return missing_member("", "knots");
    if (!default_knots) {
        Expected<geom::Knots> U = read_knot_vector(*knots_it, "/knots");
        if (!U) return U.error();
        c.knots = std::move(U).value();
    }

    const auto weights_it = j.find("weights");
    if (weights_it != j.end()) {
        if (!geom::is_rational(c.type)) {
            return schema_error(std::string("a ") + geom::name_of(c.type) +
                                    " curve takes no weights (use rational_bezier or nurbs)",
                                "/weights");
        }
        Expected<std::vector<double>> w =
            read_weight_row(*weights_it, c.points.size(), "/weights", "weights");
        if (!w) return w.error();
        c.weights = std::move(w).value();
    } else {
        c.weights.assign(c.points.size(), 1.0);
    }

    if (auto e = check_degree_fits(*degree, n, default_knots && geom::is_bezier(c.type), "/degree",
                                   "", "curve"))
        return *e;
    c.degree = static_cast<int>(*degree);
    if (default_knots) c.knots = geom::bezier_knots(c.degree);
    if (geom::Status s = geom::validate_curve(c); !s) return s.error();
    return c;
}

namespace {

// A surface's control points: n_u rows of n_v points; the shape first (cheap), then the size
// caps, then the coordinates.
geom::Status read_surface_points(const json& P, geom::Surface& s) {
    if (!P.is_array())
        return schema_error("a surface's points are n_u rows of n_v points [x, y, z]", "/points");
    const long max_dir = geom::max_points_per_direction;
    if (static_cast<long>(P.size()) > max_dir)
        return make_error(ErrorCode::limit, "too many points along u", "/points");
    long n_v = -1;
    for (std::size_t i = 0; i < P.size(); ++i) {
        const std::string row = "/points" + at(static_cast<long>(i));
        if (!P[i].is_array())
            return schema_error("a surface's points are rows (arrays) of points", row);
        const long len = static_cast<long>(P[i].size());
        if (len > max_dir)
            return make_error(ErrorCode::limit, "too many points along v", "/points");
        if (n_v < 0) n_v = len;
        if (len != n_v) {
            return schema_error("every row of points must have the same length: row " +
                                    std::to_string(i) + " has " + std::to_string(len) +
                                    ", row 0 has " + std::to_string(n_v),
                                row);
        }
    }
    if (n_v < 0) n_v = 0;
    const long n_u = static_cast<long>(P.size());
    if (n_u * n_v > geom::max_points_per_surface) {
        return make_error(ErrorCode::limit,
                          "too many control points in the surface (" + std::to_string(n_u) + " x " +
                              std::to_string(n_v) + " > " +
                              std::to_string(geom::max_points_per_surface) + ")",
                          "/points");
    }
    s.n_u = static_cast<int>(n_u);
    s.n_v = static_cast<int>(n_v);
    s.points.reserve(static_cast<std::size_t>(n_u * n_v));
    for (long i = 0; i < n_u; ++i) {
        for (long k = 0; k < n_v; ++k) {
            Expected<glm::dvec3> p =
                read_point(P[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)],
                           "/points" + at(i) + at(k));
            if (!p) return p.error();
            s.points.push_back(*p);
        }
    }
    return geom::Ok{};
}

// A surface's weights (rational types only): n_u rows of n_v numbers; unit weights when absent.
geom::Status read_surface_weights(const json& j, geom::Surface& s) {
    const long n_u = s.n_u, n_v = s.n_v;
    const auto weights_it = j.find("weights");
    if (weights_it == j.end()) {
        s.weights.assign(s.points.size(), 1.0);
        return geom::Ok{};
    }
    if (!geom::is_rational(s.type)) {
        return schema_error(std::string("a ") + geom::name_of(s.type) +
                                " surface takes no weights (use rational_bezier or nurbs)",
                            "/weights");
    }
    const json& W = *weights_it;
    if (!W.is_array()) return weights_error("weights are n_u rows of n_v numbers", "/weights");
    if (static_cast<long>(W.size()) != n_u) {
        return weights_error("expected " + std::to_string(n_u) + " rows of weights, got " +
                                 std::to_string(W.size()),
                             "/weights");
    }
    s.weights.reserve(s.points.size());
    for (long i = 0; i < n_u; ++i) {
        Expected<std::vector<double>> row =
            read_weight_row(W[static_cast<std::size_t>(i)], static_cast<std::size_t>(n_v),
                            "/weights" + at(i), "a row of weights");
        if (!row) return row.error();
        s.weights.insert(s.weights.end(), row->begin(), row->end());
    }
    return geom::Ok{};
}

} // namespace

Expected<geom::Surface> surface_from_json(const json& j) {
    if (!j.is_object()) return schema_error("a surface is a JSON object", "");
    if (auto st = check_geometry_members(j, "a surface"); !st) return st.error();
    Expected<geom::SplineType> type = read_type(j);
    if (!type) return type.error();

    const auto degree_it = j.find("degree");
    if (degree_it == j.end()) return missing_member("", "degree");
    if (!degree_it->is_array() || degree_it->size() != 2)
        return schema_error("a surface's degree is [degree_u, degree_v]", "/degree");
    std::int64_t degree[2];
    for (int d = 0; d < 2; ++d) {
        Expected<std::int64_t> p = read_one_degree((*degree_it)[d], "/degree" + at(d));
        if (!p) return p.error();
        degree[d] = *p;
    }

    const auto points_it = j.find("points");
    if (points_it == j.end()) return missing_member("", "points");
    geom::Surface s;
    s.type = *type;
    if (auto st = read_surface_points(*points_it, s); !st) return st.error();
    const long n_u = s.n_u, n_v = s.n_v;

    const auto knots_it = j.find("knots");
    const bool default_knots = knots_it == j.end();
    if (default_knots && !geom::is_bezier(s.type)) return missing_member("", "knots");
    if (!default_knots) {
        const json& K = *knots_it;
        if (!K.is_array() || K.size() != 2)
            return schema_error("a surface's knots are [knots_u, knots_v]", "/knots");
        for (int d = 0; d < 2; ++d) {
            Expected<geom::Knots> U =
                read_knot_vector(K[static_cast<std::size_t>(d)], "/knots" + at(d));
            if (!U) return U.error();
            (d == 0 ? s.knots_u : s.knots_v) = std::move(U).value();
        }
    }

    if (auto st = read_surface_weights(j, s); !st) return st.error();

    const bool bezier_default = default_knots && geom::is_bezier(s.type);
    if (auto e = check_degree_fits(degree[0], n_u, bezier_default, "/degree/0", " in u", "surface"))
        return *e;
    if (auto e = check_degree_fits(degree[1], n_v, bezier_default, "/degree/1", " in v", "surface"))
        return *e;
    s.degree_u = static_cast<int>(degree[0]);
    s.degree_v = static_cast<int>(degree[1]);
    if (default_knots) {
        s.knots_u = geom::bezier_knots(s.degree_u);
        s.knots_v = geom::bezier_knots(s.degree_v);
    }
    if (geom::Status st = geom::validate_surface(s); !st) return st.error();
    return s;
}

Expected<glm::dvec3> read_point(const json& v, const std::string& path, std::string_view what) {
    if (!v.is_array() || v.size() < 2 || v.size() > 3)
        return schema_error(std::string(what) + " is [x, y] or [x, y, z]", path);
    glm::dvec3 p(0.0);
    for (std::size_t k = 0; k < v.size(); ++k) {
        // The message's path is built only for a value that fails (millions of points pass).
        if (!is_finite_number(v[k]))
            return read_finite(v[k], path + at(static_cast<long>(k)), "a coordinate").error();
        p[static_cast<int>(k)] = v[k].get<double>();
    }
    return p;
}

json point_to_json(const glm::dvec3& p) {
    // A point beyond the range of doubles (a denominator that is tiny but not zero) cannot
    // be written either: like a point that does not exist, it is null, never inf or NaN.
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return nullptr;
    return json::array({p.x, p.y, p.z});
}

namespace {

json numbers(const std::vector<double>& v) {
    json a = json::array();
    a.get_ref<json::array_t&>().reserve(v.size());
    for (double x : v) a.push_back(x);
    return a;
}

} // namespace

json curve_to_json(const geom::Curve& c) {
    json j = json::object();
    j["type"] = geom::name_of(c.type);
    j["degree"] = c.degree;
    j["knots"] = numbers(c.knots);
    json pts = json::array();
    for (const glm::dvec3& p : c.points) pts.push_back(point_to_json(p));
    j["points"] = std::move(pts);
    if (geom::is_rational(c.type)) j["weights"] = numbers(c.weights);
    return j;
}

json surface_to_json(const geom::Surface& s) {
    json j = json::object();
    j["type"] = geom::name_of(s.type);
    j["degree"] = json::array({s.degree_u, s.degree_v});
    j["knots"] = json::array({numbers(s.knots_u), numbers(s.knots_v)});
    json rows = json::array();
    json wrows = json::array();
    for (int i = 0; i < s.n_u; ++i) {
        json row = json::array();
        json wrow = json::array();
        for (int k = 0; k < s.n_v; ++k) {
            row.push_back(point_to_json(s.point(i, k)));
            wrow.push_back(s.weight(i, k));
        }
        rows.push_back(std::move(row));
        wrows.push_back(std::move(wrow));
    }
    j["points"] = std::move(rows);
    if (geom::is_rational(s.type)) j["weights"] = std::move(wrows);
    return j;
}

Expected<geom::TrianglePatch> triangle_from_json(const json& j) {
    if (!j.is_object()) return schema_error("a triangle is a JSON object", "");
    if (auto st = check_members(j, "", "a triangle", {"type", "degree", "points", "weights"}); !st)
        return st.error();
    const json* type = find_member(j, "type");
    if (!type) return missing_member("", "type");
    geom::TrianglePatch t;
    if (*type == "rational_triangle_bezier")
        t.rational = true;
    else if (*type != "triangle_bezier")
        return schema_error("type must be triangle_bezier or rational_triangle_bezier", "/type");
    const json* degree = find_member(j, "degree");
    if (!degree) return missing_member("", "degree");
    Expected<std::int64_t> n = read_one_degree(*degree, "/degree");
    if (!n) return n.error();
    if (*n > geom::max_triangle_degree)
        return make_error(ErrorCode::limit,
                          "degree " + std::to_string(*n) + " is above the cap of " +
                              std::to_string(geom::max_triangle_degree),
                          "/degree");
    t.degree = static_cast<int>(*n);
    const json* points = find_member(j, "points");
    if (!points) return missing_member("", "points");
    const std::size_t want = static_cast<std::size_t>(geom::TrianglePatch::count_for(t.degree));
    if (!points->is_array() || points->size() != want)
        return schema_error("a triangle of degree " + std::to_string(t.degree) + " has " +
                                std::to_string(want) + " control points [x, y] or [x, y, z]",
                            "/points");
    for (std::size_t k = 0; k < want; ++k) {
        Expected<glm::dvec3> p = read_point((*points)[k], "/points" + at(static_cast<long>(k)));
        if (!p) return p.error();
        t.points.push_back(*p);
    }
    if (const json* w = find_member(j, "weights")) {
        if (!t.rational)
            return schema_error("a triangle_bezier takes no weights (use rational_triangle_bezier)",
                                "/weights");
        Expected<std::vector<double>> weights = read_weight_row(*w, want, "/weights", "weights");
        if (!weights) return weights.error();
        t.weights = std::move(weights).value();
    } else {
        t.weights.assign(want, 1.0);
    }
    if (geom::Status st = geom::validate_triangle(t); !st) return st.error();
    return t;
}

Expected<geom::Barycentric> triangle_param_from_json(const json& v, const std::string& path) {
    if (!v.is_array() || v.size() != 3)
        return schema_error("a triangle parameter is [r, s, t]", path);
    geom::Barycentric p{};
    for (std::size_t k = 0; k < 3; ++k) {
        Expected<double> x =
            read_finite(v[k], path + "/" + std::to_string(k), "a barycentric coordinate");
        if (!x) return x.error();
        p[k] = *x;
    }
    return p;
}

json triangle_to_json(const geom::TrianglePatch& t) {
    json j = json::object();
    j["type"] = t.rational ? "rational_triangle_bezier" : "triangle_bezier";
    j["degree"] = t.degree;
    json pts = json::array();
    for (const glm::dvec3& p : t.points) pts.push_back(point_to_json(p));
    j["points"] = std::move(pts);
    if (t.rational) j["weights"] = numbers(t.weights);
    return j;
}

} // namespace isoparm::json_io
