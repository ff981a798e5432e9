// Global surface interpolation through a grid of points (Piegl & Tiller A9.4).
#include <vector>

#include "core/geom/fitting.hpp"

namespace isoparm::geom {

namespace {

// The degree along one direction of `count` points: 1..count - 1 (`degree`, "/degree/axis").
Status check_degree(int degree, int count, int axis, const char* dir_name) {
    if (degree >= 1 && degree <= count - 1) return Ok{};
    return make_error(ErrorCode::degree,
                      std::string("the degree in ") + dir_name +
                          " must lie between 1 and the number of points along " + dir_name +
                          " - 1 = " + std::to_string(count - 1) + ", got " + std::to_string(degree),
                      "/degree" + pointer_step(axis));
}

} // namespace

Expected<GridParams> grid_params(const std::vector<glm::dvec3>& grid, int rows, int columns, int p,
                                 int q, Parametrization mode) {
    if (rows < 2)
        return make_error(ErrorCode::schema,
                          "the grid needs at least 2 rows, got " + std::to_string(rows), "/grid");
    if (columns < 2) {
        return make_error(ErrorCode::schema,
                          "every row of the grid needs at least 2 points, got " +
                              std::to_string(columns),
                          "/grid/0");
    }
    if (Status s = check_degree(p, rows, 0, "u"); !s) return s.error();
    if (Status s = check_degree(q, columns, 1, "v"); !s) return s.error();
    auto at = [&](int k, int l) { return grid[static_cast<size_t>(k) * columns + l]; };

    // Eq. 9.16-9.18: u_k averaged over the columns, v_l over the rows.
    NetParams u = averaged_net_params(
        rows - 1, columns, [&](int k, int l) { return at(k, l); }, mode, true);
    NetParams v = averaged_net_params(
        columns - 1, rows, [&](int l, int k) { return at(k, l); }, mode, true);
    if (u.all_degenerate && v.all_degenerate) {
        return make_error(ErrorCode::geometry,
                          "all points of the grid coincide, so they cannot be parametrized",
                          "/grid");
    }
    // Every column collapsed to a point means every row equals the first (and likewise).
    const int row = u.all_degenerate ? 1 : u.coincident;
    const int column = v.all_degenerate ? 1 : v.coincident;
    if (row >= 0) {
        return make_error(ErrorCode::geometry,
                          "row " + std::to_string(row) + " of the grid coincides with row " +
                              std::to_string(row - 1) + ", which gives two equal parameters u",
                          "/grid" + pointer_step(row));
    }
    if (column >= 0) {
        return make_error(ErrorCode::geometry,
                          "column " + std::to_string(column) +
                              " of the grid coincides with column " + std::to_string(column - 1) +
                              ", which gives two equal parameters v",
                          "/grid/0" + pointer_step(column));
    }
    return GridParams{std::move(u.params), std::move(v.params)};
}

Expected<InterpolatedSurface> interpolate_surface(const std::vector<glm::dvec3>& grid, int rows,
                                                  int columns, int p, int q, Parametrization mode) {
    auto params = grid_params(grid, rows, columns, p, q, mode);
    if (!params) return params.error();
    InterpolatedSurface out;
    out.u_params = std::move(params->u);
    out.v_params = std::move(params->v);
    Surface& s = out.surface;
    s.type = SplineType::bspline;
    s.degree_u = p;
    s.degree_v = q;
    s.knots_u = averaged_knots(out.u_params, p);
    s.knots_v = averaged_knots(out.v_params, q);
    s.n_u = rows;
    s.n_v = columns;

    // A9.4: every column through its u_k at once (row k of the data holds row k of the grid),
    // giving R_(i,l); then every row of R through its v_l (row l of the data holds column l).
    std::vector<double> data = points_as_rows(grid);
    const auto singular = [] {
        return make_error(ErrorCode::geometry, "the interpolation system is singular", "/grid");
    };
    if (!solve_collocation(s.knots_u, p, out.u_params, data, columns * 3)) return singular();
    std::vector<double> across(data.size());
    for (int i = 0; i < rows; ++i)
        for (int l = 0; l < columns; ++l)
            for (int a = 0; a < 3; ++a)
                across[(static_cast<size_t>(l) * rows + i) * 3 + a] =
                    data[(static_cast<size_t>(i) * columns + l) * 3 + a];
    if (!solve_collocation(s.knots_v, q, out.v_params, across, rows * 3)) return singular();
    const std::vector<glm::dvec3> transposed = rows_as_points(across);
    s.points.resize(grid.size());
    s.weights.assign(grid.size(), 1.0);
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < columns; ++j)
            s.point(i, j) = transposed[static_cast<size_t>(j) * rows + i];
    return out;
}

} // namespace isoparm::geom
