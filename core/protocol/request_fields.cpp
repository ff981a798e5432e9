// The protocol's shared field readers: precise `schema` errors, subjects, directions, domains.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/json/shapes.hpp"
#include "core/json/reader.hpp"
#include "core/json/fields.hpp"
#include "core/protocol/detail.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::protocol {

using geom::Error;
using geom::ErrorCode;
using geom::Expected;

geom::Status check_fields(const json& request, std::string_view op,
                          std::initializer_list<std::string_view> fields) {
    std::vector<std::string_view> allowed{"op"};
    allowed.insert(allowed.end(), fields.begin(), fields.end());
    return check_members(request, "", "op '" + short_name(op) + "'", allowed);
}

Expected<double> required_number(const json& request, std::string_view name) {
    const json* v = find_member(request, name);
    if (!v) return missing_member("", name);
    return read_finite(*v, member_path("", name), name);
}

Expected<std::int64_t> integer_option(const json& request, std::string_view name,
                                      std::int64_t fallback, std::int64_t lo, std::int64_t hi,
                                      const std::string& rule) {
    const json* v = find_member(request, name);
    if (!v) return fallback;
    const std::optional<std::int64_t> k = integer_value(*v);
    if (!k || *k < lo || *k > hi) return schema_error(rule, member_path("", name));
    return *k;
}

Expected<geom::Parametrization> read_parametrization(const json& request) {
    const json* m = find_member(request, "parametrization");
    if (!m) return geom::Parametrization::chord;
    if (const std::optional<geom::Parametrization> named = enum_value<geom::Parametrization>(*m))
        return *named;
    return schema_error("parametrization is \"chord\", \"centripetal\" or \"uniform\"",
                        "/parametrization");
}

Expected<int> read_int(const json& v, const std::string& path, std::string_view what) {
    const std::optional<std::int64_t> k = integer_value(v);
    if (!k) return schema_error(std::string(what) + " must be an integer", path);
    constexpr std::int64_t bound = std::numeric_limits<int>::max();
    return static_cast<int>(std::clamp<std::int64_t>(*k, -bound, bound));
}

Expected<Subject> read_subject(const json& request, bool allow_curve, bool allow_surface) {
    const json* curve = allow_curve ? find_member(request, "curve") : nullptr;
    const json* surface = allow_surface ? find_member(request, "surface") : nullptr;
    if (curve && surface) return schema_error("give exactly one of curve or surface", "/surface");
    if (!curve && !surface) {
        if (allow_curve && allow_surface)
            return schema_error("give exactly one of curve or surface", "/curve");
        return missing_member("", allow_curve ? "curve" : "surface");
    }
    Subject s;
    if (curve) {
        Expected<geom::Curve> c = curve_from_json(*curve);
        if (!c) return c.error().under("/curve");
        s.curve = std::move(c).value();
    } else {
        Expected<geom::Surface> f = surface_from_json(*surface);
        if (!f) return f.error().under("/surface");
        s.is_surface = true;
        s.surface = std::move(f).value();
    }
    return s;
}

Expected<geom::Dir> read_direction(const json& request, const Subject& subject) {
    const json* d = find_member(request, "direction");
    if (!subject.is_surface) {
        if (d)
            return schema_error("direction is for surfaces; a curve has one direction",
                                "/direction");
        return geom::Dir::u;
    }
    if (!d) return missing_member("", "direction");
    if (const std::optional<geom::Dir> dir = enum_value<geom::Dir>(*d)) return *dir;
    return schema_error("direction is \"u\" or \"v\"", "/direction");
}

Expected<DirectedSubject> read_directed_subject(const json& request, std::string_view op,
                                                std::initializer_list<std::string_view> fields) {
    if (geom::Status s = check_fields(request, op, fields); !s) return s.error();
    Expected<Subject> subject = read_subject(request, true, true);
    if (!subject) return subject.error();
    Expected<geom::Dir> dir = read_direction(request, *subject);
    if (!dir) return dir.error();
    return DirectedSubject{std::move(subject).value(), *dir};
}

Expected<std::int64_t> read_times(const json& request) {
    return integer_option(request, "times", 1, 1, std::numeric_limits<std::int64_t>::max(),
                          "times is an integer >= 1");
}

geom::Status check_in_domain(double t, const geom::Interval& domain, const std::string& path,
                             std::string_view what) {
    if (domain.contains(t)) return geom::Ok{};
    return geom::make_error(ErrorCode::domain,
                            std::string(what) + " " + geom::format_number(t) +
                                " outside the domain [" + geom::format_number(domain.lo) + ", " +
                                geom::format_number(domain.hi) + "]",
                            path);
}

json optional_point(const std::optional<glm::dvec3>& p) {
    return p ? point_to_json(*p) : json(nullptr);
}

namespace {

std::string param_path(std::size_t i) {
    return "/params/" + std::to_string(i);
}

} // namespace

Expected<std::vector<double>> read_curve_params(const json& params, const geom::Interval& dom) {
    std::vector<double> ts;
    ts.reserve(params.size());
    for (std::size_t i = 0; i < params.size(); ++i) {
        const std::string path = param_path(i);
        if (params[i].is_array()) return schema_error("a curve parameter is a number t", path);
        Expected<double> t = read_finite(params[i], path, "a curve parameter");
        if (!t) return t.error();
        if (geom::Status s = check_in_domain(*t, dom, path); !s) return s.error();
        ts.push_back(*t);
    }
    return ts;
}

Expected<std::vector<std::array<double, 2>>> read_surface_params(const json& params, const geom::Surface& s) {
    const geom::Interval dom[2] = {geom::domain(s, geom::Dir::u), geom::domain(s, geom::Dir::v)};
    std::vector<std::array<double, 2>> uv;
    uv.reserve(params.size());
    for (std::size_t i = 0; i < params.size(); ++i) {
        const std::string path = param_path(i);
        if (!params[i].is_array() || params[i].size() != 2)
            return schema_error("a surface parameter is [u, v]", path);
        std::array<double, 2> x{};
        for (int k = 0; k < 2; ++k) {
            const std::string sub = path + "/" + std::to_string(k);
            Expected<double> t =
                read_finite(params[i][static_cast<std::size_t>(k)], sub, k == 0 ? "u" : "v");
            if (!t) return t.error();
            if (geom::Status st = check_in_domain(*t, dom[k], sub, k == 0 ? "u" : "v"); !st)
                return st.error();
            x[static_cast<std::size_t>(k)] = *t;
        }
        uv.push_back(x);
    }
    return uv;
}

} // namespace isoparm::protocol
