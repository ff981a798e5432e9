// The protocol's shared field readers: precise `schema` errors, subjects, directions, domains.
#include <cmath>

#include "core/json/shapes.hpp"
#include "core/json/reader.hpp"
#include "core/json/values.hpp"
#include "core/protocol/detail.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::protocol {

using geom::Error;
using geom::ErrorCode;
using geom::Expected;

Error schema_error(std::string message, std::string path) {
    return geom::make_error(ErrorCode::schema, std::move(message), std::move(path));
}

std::string field_path(std::string_view name) {
    return "/" + escape_pointer_token(name);
}

Error missing_field(std::string_view name) {
    return schema_error("missing field '" + std::string(name) + "'", field_path(name));
}

geom::Status check_fields(const json& request, std::string_view op,
                          std::initializer_list<std::string_view> allowed) {
    for (const auto& [key, value] : request.items()) {
        (void)value;
        if (key == "op") continue;
        bool known = false;
        for (std::string_view a : allowed) known = known || key == a;
        if (known) continue;
        std::string list;
        for (std::string_view a : allowed) {
            if (!list.empty()) list += ", ";
            list += a;
        }
        return schema_error("unknown field '" + short_name(key) + "' for op '" + std::string(op) +
                                "' (it takes: " + list + ")",
                            field_path(key));
    }
    return geom::Ok{};
}

const json* find_field(const json& request, std::string_view name) {
    const auto it = request.find(std::string(name));
    return it == request.end() ? nullptr : &*it;
}

Expected<double> read_number(const json& value, const std::string& path, std::string_view what) {
    if (!value.is_number()) return schema_error(std::string(what) + " must be a number", path);
    const double x = value.get<double>();
    if (!std::isfinite(x))
        return schema_error(std::string(what) + " must be a finite number", path);
    return x;
}

Expected<double> required_number(const json& request, std::string_view name) {
    const json* v = find_field(request, name);
    if (!v) return missing_field(name);
    return read_number(*v, field_path(name), name);
}

Expected<std::int64_t> integer_option(const json& request, std::string_view name,
                                      std::int64_t fallback, std::int64_t lo, std::int64_t hi,
                                      const std::string& rule) {
    const json* v = find_field(request, name);
    if (!v) return fallback;
    const std::optional<std::int64_t> k = integer_value(*v);
    if (!k || *k < lo || *k > hi) return schema_error(rule, field_path(name));
    return *k;
}

Expected<Subject> read_subject(const json& request, bool allow_curve, bool allow_surface) {
    const json* curve = allow_curve ? find_field(request, "curve") : nullptr;
    const json* surface = allow_surface ? find_field(request, "surface") : nullptr;
    if (curve && surface) return schema_error("give exactly one of curve or surface", "/surface");
    if (!curve && !surface) {
        if (allow_curve && allow_surface)
            return schema_error("give exactly one of curve or surface", "/curve");
        return missing_field(allow_curve ? "curve" : "surface");
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
    const json* d = find_field(request, "direction");
    if (!subject.is_surface) {
        if (d)
            return schema_error("direction is for surfaces; a curve has one direction",
                                "/direction");
        return geom::Dir::u;
    }
    if (!d) return missing_field("direction");
    if (d->is_string() && d->get_ref<const std::string&>() == "u") return geom::Dir::u;
    if (d->is_string() && d->get_ref<const std::string&>() == "v") return geom::Dir::v;
    return schema_error("direction is \"u\" or \"v\"", "/direction");
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

geom::Interval curve_domain(const geom::Curve& c) {
    return geom::domain(c.knots, c.degree, c.count());
}

geom::Interval surface_domain(const geom::Surface& s, geom::Dir dir) {
    return geom::domain(s.knots(dir), s.degree(dir), s.count(dir));
}

json optional_point(const std::optional<glm::dvec3>& p) {
    return p ? point_to_json(*p) : json(nullptr);
}

} // namespace isoparm::protocol
