// The polygonizer's grid from its options: the options checked, then the grid laid out, its
// size checked before anything is allocated (protocol conventions 18 and 19).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/geom/implicit/polygonize_work.hpp"
#include "core/geom/validate.hpp"

namespace isoparm::geom::implicit::detail {

namespace {

// Coordinates lo + (hi - lo) i / n, exact at both ends.
std::vector<double> grid_coordinates(double lo, double hi, int n) {
    std::vector<double> c(n + 1);
    for (int i = 0; i < n; ++i) c[i] = lo + (hi - lo) * (static_cast<double>(i) / n);
    c[n] = hi;
    return c;
}

} // namespace

Status check_options(const Program& f, const PolygonizeOptions& o) {
    if (!std::isfinite(o.cell) || o.cell <= 0)
        return make_error(ErrorCode::schema,
                          "cell " + format_number(o.cell) + " must be a finite number > 0",
                          "/cell");
    static const char* axes = "xyz";
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(o.lo[a]) || !std::isfinite(o.hi[a]))
            return make_error(ErrorCode::schema,
                              std::string("bounds on ") + axes[a] + " must be finite numbers",
                              "/bounds");
        if (!(o.lo[a] < o.hi[a]))
            return make_error(ErrorCode::schema,
                              std::string("bounds on ") + axes[a] + " must have min < max, got " +
                                  format_number(o.lo[a]) + " and " + format_number(o.hi[a]),
                              "/bounds");
        if (!std::isfinite(o.hi[a] - o.lo[a]))
            return make_error(ErrorCode::schema,
                              std::string("bounds on ") + axes[a] + " span more than a double",
                              "/bounds");
    }
    const auto& names = f.parameter_names();
    if (o.parameters.size() != names.size())
        return make_error(ErrorCode::schema,
                          "expected " + std::to_string(names.size()) + " parameter values, got " +
                              std::to_string(o.parameters.size()),
                          "/parameters");
    for (std::size_t k = 0; k < o.parameters.size(); ++k)
        if (!std::isfinite(o.parameters[k]))
            return make_error(ErrorCode::schema,
                              "parameter '" + names[k] + "' must be a finite number, got " +
                                  format_number(o.parameters[k]),
                              "/parameters/" + std::to_string(k));
    return Ok{};
}

// The grid: ceil(extent / cell) cells per axis, the cell shrunk to fit (convention 18).
Expected<Grid> make_grid(const PolygonizeOptions& options) {
    // Counted in double first so a tiny cell cannot overflow an int before the check.
    double n[3], points = 1.0;
    for (int a = 0; a < 3; ++a) {
        n[a] = std::max(1.0, std::ceil((options.hi[a] - options.lo[a]) / options.cell));
        points *= n[a] + 1.0;
    }
    if (points > static_cast<double>(max_evaluation_points))
        return make_error(ErrorCode::limit,
                          "cell " + format_number(options.cell) + " gives a grid of " +
                              format_number(n[0] + 1) + " x " + format_number(n[1] + 1) + " x " +
                              format_number(n[2] + 1) + " points, more than the " +
                              std::to_string(max_evaluation_points) + " allowed",
                          "/cell");
    Grid grid;
    grid.nx = static_cast<int>(n[0]);
    grid.ny = static_cast<int>(n[1]);
    grid.nz = static_cast<int>(n[2]);
    grid.row = static_cast<std::size_t>(grid.nx) + 1;
    grid.plane = grid.row * (static_cast<std::size_t>(grid.ny) + 1);
    grid.xs = grid_coordinates(options.lo.x, options.hi.x, grid.nx);
    grid.ys = grid_coordinates(options.lo.y, options.hi.y, grid.ny);
    grid.zs = grid_coordinates(options.lo.z, options.hi.z, grid.nz);

    return grid;
}

} // namespace isoparm::geom::implicit::detail
