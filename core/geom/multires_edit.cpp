// Multiresolution edits: decompose to the level, change the coarse points or the detail,
// reconstruct (the filter bank is exact, so what was not edited comes back unchanged).
#include "core/geom/multires_edit.hpp"

#include <cmath>
#include <string>

#include "core/geom/multires.hpp"

namespace isoparm::geom {

namespace {

Status check_level(int level, int finest, const char* path, const std::string& what) {
    if (level >= 0 && level <= finest) return Ok{};
    return make_error(ErrorCode::schema,
                      "level " + std::to_string(level) + " is outside 0.." +
                          std::to_string(finest) + " for " + what + " (2^" +
                          std::to_string(finest) + " + 3 control points)",
                      path);
}

Status check_index(int index, int count, const char* path) {
    if (index >= 0 && index < count) return Ok{};
    return make_error(ErrorCode::schema,
                      std::string("coarse control point index ") + (path + 1) + " = " +
                          std::to_string(index) + " is outside 0.." + std::to_string(count - 1),
                      path);
}

Status check_factor(double factor) {
    if (std::isfinite(factor)) return Ok{};
    return make_error(ErrorCode::schema, "the detail scale must be a finite number",
                      "/detail_scale");
}

// The curve's decomposition at `level`, refusals included.
Expected<CurveDecomposition> curve_at_level(const Curve& c, int level) {
    auto J = multires_level(c);
    if (!J) return J.error();
    if (auto st = check_level(level, *J, "/level", "this curve"); !st) return st.error();
    return decompose(c.points, *J, level);
}

Expected<SurfaceDecomposition> surface_at_levels(const Surface& s, int level_u, int level_v) {
    auto J = multires_levels(s);
    if (!J) return J.error();
    if (auto st = check_level(level_u, J->first, "/level", "this surface in u"); !st)
        return st.error();
    if (auto st = check_level(level_v, J->second, "/level_v", "this surface in v"); !st)
        return st.error();
    return decompose(s.points, J->first, J->second, level_u, level_v);
}

} // namespace

Expected<std::vector<glm::dvec3>> multires_coarse_points(const Curve& c, int level) {
    auto d = curve_at_level(c, level);
    if (!d) return d.error();
    return std::move(d->coarse);
}

Expected<Curve> multires_move_coarse_point(const Curve& c, int level, int i,
                                           const glm::dvec3& position) {
    auto d = curve_at_level(c, level);
    if (!d) return d.error();
    if (auto st = check_index(i, static_cast<int>(d->coarse.size()), "/i"); !st) return st.error();
    d->coarse[i] = position;
    Curve out = c;
    out.points = reconstruct(*d);
    return out;
}

Expected<Curve> multires_scale_detail(const Curve& c, int level, double factor) {
    if (auto st = check_factor(factor); !st) return st.error();
    auto d = curve_at_level(c, level);
    if (!d) return d.error();
    for (auto& detail : d->details)
        for (glm::dvec3& x : detail) x *= factor;
    Curve out = c;
    out.points = reconstruct(*d);
    return out;
}

Expected<CoarseNet> multires_coarse_net(const Surface& s, int level_u, int level_v) {
    auto d = surface_at_levels(s, level_u, level_v);
    if (!d) return d.error();
    return CoarseNet{d->n_u, d->n_v, std::move(d->coarse)};
}

Expected<Surface> multires_move_coarse_point(const Surface& s, int level_u, int level_v, int i,
                                             int j, const glm::dvec3& position) {
    auto d = surface_at_levels(s, level_u, level_v);
    if (!d) return d.error();
    if (auto st = check_index(i, d->n_u, "/i"); !st) return st.error();
    if (auto st = check_index(j, d->n_v, "/j"); !st) return st.error();
    d->coarse[i * d->n_v + j] = position;
    Surface out = s;
    out.points = reconstruct(*d);
    return out;
}

Expected<Surface> multires_scale_detail(const Surface& s, int level_u, int level_v, double factor) {
    if (auto st = check_factor(factor); !st) return st.error();
    auto d = surface_at_levels(s, level_u, level_v);
    if (!d) return d.error();
    for (auto* lines : {&d->u_lines, &d->v_lines})
        for (CurveDecomposition& line : *lines)
            for (auto& detail : line.details)
                for (glm::dvec3& x : detail) x *= factor;
    Surface out = s;
    out.points = reconstruct(*d);
    return out;
}

} // namespace isoparm::geom
