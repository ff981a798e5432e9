// The fitting ops (geom-protocol-2.md, Fitting and refinement): `interpolate` (a curve through
// points, with or without end derivatives, or a surface through a grid) and `approximate`
// (least squares). The maths is in geom/interpolate.hpp and geom/fitting.hpp.
#include <algorithm>

#include "core/geom/fitting.hpp"
#include "core/geom/validate.hpp"
#include "core/geom/work_budget.hpp"
#include "core/json/shapes.hpp"
#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

using geom::ErrorCode;
using geom::Expected;

namespace {

geom::Error too_many(const std::string& what, std::size_t count, long cap,
                     const std::string& path) {
    return geom::make_error(ErrorCode::limit,
                            "too many " + what + " (" + std::to_string(count) + " > " +
                                std::to_string(cap) + ")",
                            path);
}

// `points`: an array of at most `cap` points [x, y] or [x, y, z] (`limit` above it).
Expected<const json*> points_array(const json& request, long cap) {
    const json* v = find_member(request, "points");
    if (!v) return missing_member("", "points");
    if (!v->is_array()) return schema_error("points is an array of [x, y] or [x, y, z]", "/points");
    if (v->size() > static_cast<std::size_t>(cap))
        return too_many("points", v->size(), cap, "/points");
    return v;
}

Expected<std::vector<glm::dvec3>> read_points(const json& array, const std::string& path) {
    std::vector<glm::dvec3> points;
    points.reserve(array.size());
    for (std::size_t k = 0; k < array.size(); ++k) {
        Expected<glm::dvec3> p =
            read_point(array[k], path + geom::pointer_step(static_cast<long>(k)), "a point");
        if (!p) return p.error();
        points.push_back(*p);
    }
    return points;
}

Expected<int> required_int(const json& request, std::string_view name) {
    const json* v = find_member(request, name);
    if (!v) return missing_member("", name);
    return read_int(*v, member_path("", name), name);
}

// The work of fitting `n` control points of degree p (clamped into its valid range: a degree
// out of range is refused by the fit itself, with its own code) to `rows` parameters.
geom::Status spend_fit(double rows, int n, int p, double columns, const std::string& path,
                       const std::string& what) {
    const int degree = std::clamp(p, 1, std::max(1, n - 1));
    return geom::spend_work(geom::estimate_banded_fit(rows, n, degree, columns), path, what);
}

std::string points_of_degree(std::size_t count, int p) {
    return geom::with_thousands(static_cast<double>(count)) + " points at degree " +
           std::to_string(p);
}

// `end_derivatives`: [D0, Dn], two vectors.
Expected<std::array<glm::dvec3, 2>> read_end_derivatives(const json& v) {
    if (!v.is_array() || v.size() != 2)
        return schema_error("end_derivatives is [D0, Dn], two vectors [x, y, z]",
                            "/end_derivatives");
    std::array<glm::dvec3, 2> out{};
    for (std::size_t k = 0; k < 2; ++k) {
        Expected<glm::dvec3> d =
            read_point(v[k], "/end_derivatives" + geom::pointer_step(static_cast<long>(k)),
                       "an end derivative");
        if (!d) return d.error();
        out[k] = *d;
    }
    return out;
}

OpResult interpolate_points(const json& request, geom::Parametrization mode) {
    Expected<int> degree = required_int(request, "degree");
    if (!degree) return degree.error();
    const json* ends = find_member(request, "end_derivatives");
    const int extra = ends ? 2 : 0; // control points beyond one per point
    Expected<const json*> array = points_array(request, geom::max_points_per_direction - extra);
    if (!array) return array.error();
    std::optional<std::array<glm::dvec3, 2>> derivatives;
    if (ends) {
        auto d = read_end_derivatives(*ends);
        if (!d) return d.error();
        derivatives = *d;
    }
    const std::size_t count = (*array)->size();
    if (geom::Status ok =
            spend_fit(static_cast<double>(count), static_cast<int>(count) + extra, *degree, 3,
                      "/points", "interpolating " + points_of_degree(count, *degree));
        !ok)
        return ok.error();
    auto points = read_points(**array, "/points");
    if (!points) return points.error();
    auto fit = derivatives ? geom::interpolate_curve_with_end_derivatives(
                                 *points, *degree, mode, (*derivatives)[0], (*derivatives)[1])
                           : geom::interpolate_curve(*points, *degree, mode);
    if (!fit) return fit.error();
    return json{{"curve", curve_to_json(fit->curve)}, {"params", fit->params}};
}

// `grid`: rows of points, all rows as long as the first, within the surface caps.
struct Grid {
    std::vector<glm::dvec3> points; // row-major
    int rows = 0, columns = 0;
};
Expected<Grid> read_grid(const json& v) {
    if (!v.is_array() || v.empty() || !v[0].is_array())
        return schema_error("grid is an array of rows, each an array of points [x, y, z]", "/grid");
    const std::size_t rows = v.size(), columns = v[0].size();
    if (rows > static_cast<std::size_t>(geom::max_points_per_direction))
        return too_many("rows in the grid", rows, geom::max_points_per_direction, "/grid");
    if (columns > static_cast<std::size_t>(geom::max_points_per_direction))
        return too_many("points in a row of the grid", columns, geom::max_points_per_direction,
                        "/grid/0");
    if (static_cast<long>(rows * columns) > geom::max_points_per_surface)
        return too_many("points in the grid", rows * columns, geom::max_points_per_surface,
                        "/grid");
    Grid g;
    g.rows = static_cast<int>(rows);
    g.columns = static_cast<int>(columns);
    g.points.reserve(rows * columns);
    for (std::size_t k = 0; k < rows; ++k) {
        const std::string row = "/grid" + geom::pointer_step(static_cast<long>(k));
        if (!v[k].is_array()) return schema_error("a row of the grid is an array of points", row);
        if (v[k].size() != columns) {
            return schema_error("every row of the grid must have as many points as the first (" +
                                    std::to_string(columns) + "), got " +
                                    std::to_string(v[k].size()),
                                row);
        }
        auto points = read_points(v[k], row);
        if (!points) return points.error();
        g.points.insert(g.points.end(), points->begin(), points->end());
    }
    return g;
}

// `degree` of a grid: [p, q].
Expected<std::array<int, 2>> read_degree_pair(const json& request) {
    const json* v = find_member(request, "degree");
    if (!v) return missing_member("", "degree");
    if (!v->is_array() || v->size() != 2)
        return schema_error("degree of a surface is [p, q], two integers", "/degree");
    std::array<int, 2> out{};
    for (std::size_t k = 0; k < 2; ++k) {
        Expected<int> d = read_int((*v)[k], "/degree" + geom::pointer_step(static_cast<long>(k)),
                                   k == 0 ? "the degree in u" : "the degree in v");
        if (!d) return d.error();
        out[k] = *d;
    }
    return out;
}

OpResult interpolate_grid(const json& request, geom::Parametrization mode) {
    if (find_member(request, "end_derivatives"))
        return schema_error("end_derivatives are for curves (points), not grids",
                            "/end_derivatives");
    Expected<std::array<int, 2>> degree = read_degree_pair(request);
    if (!degree) return degree.error();
    Expected<Grid> grid = read_grid(*find_member(request, "grid"));
    if (!grid) return grid.error();
    const auto [p, q] = *degree;
    const int rows = grid->rows, columns = grid->columns;
    // Columns first (3 numbers a point of a row for every column), then rows.
    if (geom::Status ok = spend_fit(rows, rows, p, 3.0 * columns, "/grid",
                                    "interpolating a " + std::to_string(rows) + " x " +
                                        std::to_string(columns) + " grid");
        !ok)
        return ok.error();
    if (geom::Status ok = spend_fit(columns, columns, q, 3.0 * rows, "/grid",
                                    "interpolating a " + std::to_string(rows) + " x " +
                                        std::to_string(columns) + " grid");
        !ok)
        return ok.error();
    auto fit = geom::interpolate_surface(grid->points, rows, columns, p, q, mode);
    if (!fit) return fit.error();
    return json{{"surface", surface_to_json(fit->surface)},
                {"params", json::array({fit->u_params, fit->v_params})}};
}

} // namespace

OpResult op_interpolate(const json& request) {
    if (geom::Status s =
            check_fields(request, "interpolate",
                         {"points", "grid", "degree", "parametrization", "end_derivatives"});
        !s)
        return s.error();
    const bool has_points = find_member(request, "points") != nullptr;
    const bool has_grid = find_member(request, "grid") != nullptr;
    if (has_points && has_grid)
        return schema_error("give exactly one of points (a curve) or grid (a surface)", "/grid");
    if (!has_points && !has_grid)
        return schema_error("give exactly one of points (a curve) or grid (a surface)", "/points");
    Expected<geom::Parametrization> mode = read_parametrization(request);
    if (!mode) return mode.error();
    return has_grid ? interpolate_grid(request, *mode) : interpolate_points(request, *mode);
}

OpResult op_approximate(const json& request) {
    if (geom::Status s =
            check_fields(request, "approximate", {"points", "degree", "count", "parametrization"});
        !s)
        return s.error();
    Expected<int> degree = required_int(request, "degree");
    if (!degree) return degree.error();
    Expected<int> count = required_int(request, "count");
    if (!count) return count.error();
    Expected<geom::Parametrization> mode = read_parametrization(request);
    if (!mode) return mode.error();
    if (*count > geom::max_points_per_direction) {
        return geom::make_error(ErrorCode::limit,
                                "too many control points (count " + std::to_string(*count) + " > " +
                                    std::to_string(geom::max_points_per_direction) + ")",
                                "/count");
    }
    Expected<const json*> array = points_array(request, geom::max_evaluation_points);
    if (!array) return array.error();
    const std::size_t total = (*array)->size();
    if (geom::Status ok = spend_fit(static_cast<double>(total), std::max(*count, 2), *degree, 3,
                                    "/points", "approximating " + points_of_degree(total, *degree));
        !ok)
        return ok.error();
    auto points = read_points(**array, "/points");
    if (!points) return points.error();
    auto fit = geom::approximate_curve(*points, *degree, *count, *mode);
    if (!fit) return fit.error();
    return json{{"curve", curve_to_json(fit->curve)},
                {"params", fit->params},
                {"max_error", fit->max_error},
                {"rms_error", fit->rms_error}};
}

} // namespace isoparm::protocol
