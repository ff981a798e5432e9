// The construction ops: requests read into curves, geom/construct.hpp does the work, errors
// already carry request-relative paths ("/curves/1", "/profile/points/3", "/degree").
#include "core/protocol/op_construct.hpp"

#include <algorithm>
#include <vector>

#include "core/geom/construct.hpp"
#include "core/geom/coons.hpp"
#include "core/geom/gordon.hpp"
#include "core/json/shapes.hpp"

namespace isoparm::protocol {

using geom::Curve;
using geom::Expected;

namespace {

// An array of at least `min` (and at most `max`) curves at member `name` ("curves",
// "u_curves"), each parsed and validated, errors under "/<name>/k".
Expected<std::vector<Curve>> read_curve_list(const json& request, std::string_view name,
                                             std::string_view op, size_t min, size_t max) {
    const json* v = find_member(request, name);
    if (!v) return missing_member("", name);
    const std::string path = member_path("", name);
    if (!v->is_array())
        return schema_error(std::string(name) + " must be an array of curves", path);
    if (v->size() < min || v->size() > max) {
        const std::string want =
            min == max ? "exactly " + std::to_string(min) : "at least " + std::to_string(min);
        return schema_error(std::string(op) + " takes " + want + " " + std::string(name) +
                                ", got " + std::to_string(v->size()),
                            path);
    }
    std::vector<Curve> curves;
    curves.reserve(v->size());
    for (size_t k = 0; k < v->size(); ++k) {
        Expected<Curve> c = curve_from_json((*v)[k]);
        if (!c) return c.error().under(path + "/" + std::to_string(k));
        curves.push_back(std::move(c).value());
    }
    return curves;
}

Expected<std::vector<Curve>> read_curves(const json& request, std::string_view op, size_t min,
                                         size_t max) {
    return read_curve_list(request, "curves", op, min, max);
}

// A required curve field ("curve", "profile", "trajectory"), errors under its own path.
Expected<Curve> read_curve(const json& request, std::string_view name) {
    const json* v = find_member(request, name);
    if (!v) return missing_member("", name);
    Expected<Curve> c = curve_from_json(*v);
    if (!c) return c.error().under(member_path("", name));
    return c;
}

// An optional finite number with a default.
Expected<double> number_option(const json& request, std::string_view name, double fallback) {
    const json* v = find_member(request, name);
    if (!v) return fallback;
    return read_finite(*v, member_path("", name), name);
}

json curves_to_json(const std::vector<Curve>& curves) {
    json out = json::array();
    for (const Curve& c : curves) out.push_back(curve_to_json(c));
    return out;
}

constexpr size_t unbounded = static_cast<size_t>(-1);

} // namespace

OpResult op_make_compatible(const json& request) {
    if (geom::Status s = check_fields(request, "make_compatible", {"curves"}); !s) return s.error();
    auto curves = read_curves(request, "make_compatible", 2, unbounded);
    if (!curves) return curves.error();
    auto result = geom::make_compatible(*curves);
    if (!result) return result.error();
    return json{{"curves", curves_to_json(*result)}};
}

OpResult op_ruled(const json& request) {
    if (geom::Status s = check_fields(request, "ruled", {"curves"}); !s) return s.error();
    auto curves = read_curves(request, "ruled", 2, 2);
    if (!curves) return curves.error();
    auto s = geom::ruled((*curves)[0], (*curves)[1]);
    if (!s) return s.error();
    return json{{"surface", surface_to_json(*s)}};
}

OpResult op_revolve(const json& request) {
    if (geom::Status s = check_fields(request, "revolve", {"curve", "angle"}); !s) return s.error();
    auto curve = read_curve(request, "curve");
    if (!curve) return curve.error();
    auto angle = number_option(request, "angle", 360.0);
    if (!angle) return angle.error();
    auto s = geom::revolve(*curve, *angle); // `schema` at "/angle" outside (0, 360]
    if (!s) return s.error();
    return json{{"surface", surface_to_json(*s)}};
}

OpResult op_swing(const json& request) {
    if (geom::Status s = check_fields(request, "swing", {"profile", "trajectory", "scale"}); !s)
        return s.error();
    auto profile = read_curve(request, "profile");
    if (!profile) return profile.error();
    auto trajectory = read_curve(request, "trajectory");
    if (!trajectory) return trajectory.error();
    auto scale = number_option(request, "scale", 1.0);
    if (!scale) return scale.error();
    auto s = geom::swing(*profile, *trajectory, *scale);
    if (!s) return s.error();
    return json{{"surface", surface_to_json(*s)}};
}

OpResult op_sweep(const json& request) {
    if (geom::Status s = check_fields(request, "sweep", {"profile", "trajectory"}); !s)
        return s.error();
    auto profile = read_curve(request, "profile");
    if (!profile) return profile.error();
    auto trajectory = read_curve(request, "trajectory");
    if (!trajectory) return trajectory.error();
    auto s = geom::sweep(*profile, *trajectory);
    if (!s) return s.error();
    return json{{"surface", surface_to_json(*s)}};
}

OpResult op_skin(const json& request) {
    if (geom::Status s = check_fields(request, "skin", {"curves", "degree", "parametrization"}); !s)
        return s.error();
    auto curves = read_curves(request, "skin", 2, unbounded);
    if (!curves) return curves.error();
    const auto count = static_cast<std::int64_t>(curves->size());
    auto degree = integer_option(request, "degree",
                                 geom::default_skin_degree(static_cast<int>(count)), 1, count - 1,
                                 "degree (the v-degree) must be an integer from 1 to the curve "
                                 "count - 1 = " +
                                     std::to_string(count - 1));
    if (!degree) return degree.error();
    auto mode = read_parametrization(request);
    if (!mode) return mode.error();
    auto s = geom::skin(*curves, static_cast<int>(*degree), *mode);
    if (!s) return s.error();
    return json{{"surface", surface_to_json(s->surface)}, {"params", s->params}};
}

OpResult op_coons(const json& request) {
    if (geom::Status s = check_fields(request, "coons", {"curves"}); !s) return s.error();
    auto curves = read_curves(request, "coons", 4, 4);
    if (!curves) return curves.error();
    auto s = geom::coons({(*curves)[0], (*curves)[1], (*curves)[2], (*curves)[3]});
    if (!s) return s.error();
    json answer = json::object();
    answer["surface"] = surface_to_json(*s);
    return answer;
}

OpResult op_gordon(const json& request) {
    if (geom::Status s = check_fields(request, "gordon", {"u_curves", "v_curves"}); !s)
        return s.error();
    auto u_curves = read_curve_list(request, "u_curves", "gordon", 2, unbounded);
    if (!u_curves) return u_curves.error();
    auto v_curves = read_curve_list(request, "v_curves", "gordon", 2, unbounded);
    if (!v_curves) return v_curves.error();
    auto g = geom::gordon(*u_curves, *v_curves);
    if (!g) return g.error();
    json answer = json::object();
    answer["surface"] = surface_to_json(g->surface);
    answer["u_params"] = g->u_params;
    answer["v_params"] = g->v_params;
    return answer;
}

} // namespace isoparm::protocol
