// Fitting for the Fit panel: the geometry of geom/interpolate.hpp and geom/fitting.hpp, and the
// distance of the result from every data point, measured by evaluating it.
#include "core/doc/fit.hpp"

#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/fitting.hpp"

namespace isoparm::doc {

namespace {

// Distances measured, not taken from the fit: what the panel shows is what the curve does.
void measure(Fit& fit, const std::vector<glm::dvec3>& data,
             const std::vector<glm::dvec3>& reached) {
    fit.on_result = reached;
    fit.errors.clear();
    double sum = 0;
    for (std::size_t k = 0; k < data.size(); ++k) {
        const double e = glm::distance(data[k], reached[k]);
        fit.errors.push_back(e);
        fit.max_error = std::max(fit.max_error, e);
        sum += e * e;
    }
    fit.rms_error = data.empty() ? 0 : std::sqrt(sum / static_cast<double>(data.size()));
}

} // namespace

geom::Expected<Fit> fit_curve(const std::vector<glm::dvec3>& points, const FitSettings& settings,
                              const std::string& name, CurvePlane plane) {
    geom::Curve curve;
    Fit fit;
    if (settings.method == FitMethod::interpolate) {
        auto r = geom::interpolate_curve(points, settings.degree, settings.parametrization);
        if (!r) return r.error();
        curve = std::move(r->curve);
        fit.params = std::move(r->params);
    } else {
        auto r = geom::approximate_curve(points, settings.degree, settings.count,
                                         settings.parametrization);
        if (!r) return r.error();
        curve = std::move(r->curve);
        fit.params = std::move(r->params);
    }
    std::vector<glm::dvec3> reached;
    for (double t : fit.params) {
        const auto p = geom::curve_point(curve, t);
        if (!p)
            return geom::make_error(geom::ErrorCode::internal,
                                    "the fitted curve has no point at t");
        reached.push_back(*p);
    }
    measure(fit, points, reached);
    fit.object.name = name;
    fit.object.shape = CurveObject{std::move(curve), plane, CurveKnotMode::custom};
    return fit;
}

geom::Expected<Fit> fit_grid(const std::vector<glm::dvec3>& grid, int rows, int columns,
                             const FitSettings& settings, const std::string& name) {
    geom::Surface surface;
    std::vector<double> u_params, v_params;
    if (settings.method == FitMethod::interpolate) {
        auto r = geom::interpolate_surface(grid, rows, columns, settings.degree, settings.degree_v,
                                           settings.parametrization);
        if (!r) return r.error();
        surface = std::move(r->surface);
        u_params = std::move(r->u_params);
        v_params = std::move(r->v_params);
    } else {
        auto r =
            geom::approximate_surface(grid, rows, columns, settings.degree, settings.degree_v,
                                      settings.count, settings.count_v, settings.parametrization);
        if (!r) return r.error();
        surface = std::move(r->surface);
        u_params = std::move(r->u_params);
        v_params = std::move(r->v_params);
    }
    Fit fit;
    std::vector<glm::dvec3> reached;
    for (int k = 0; k < rows; ++k)
        for (int l = 0; l < columns; ++l) {
            const auto p = geom::surface_point(surface, u_params[k], v_params[l]);
            if (!p)
                return geom::make_error(geom::ErrorCode::internal,
                                        "the fitted surface has no point at (u_k, v_l)");
            reached.push_back(*p);
        }
    fit.params = std::move(u_params);
    fit.params.insert(fit.params.end(), v_params.begin(), v_params.end());
    measure(fit, grid, reached);
    fit.object.name = name;
    fit.object.shape = SurfaceObject{std::move(surface)};
    return fit;
}

} // namespace isoparm::doc
