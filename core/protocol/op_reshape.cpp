// The `close` and `split_knot` ops (geom-protocol-2.md): DesignMentor's closed curves and
// knot splitting, which change the shape on purpose.
#include "core/geom/reshape.hpp"
#include "core/json/shapes.hpp"
#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

namespace {

json shape_answer(const Subject& sub, const geom::Curve& c, const geom::Surface& s) {
    json answer = json::object();
    if (sub.is_surface)
        answer["surface"] = surface_to_json(s);
    else
        answer["curve"] = curve_to_json(c);
    return answer;
}

} // namespace

OpResult op_close(const json& request) {
    if (geom::Status s = check_fields(request, "close", {"curve", "surface", "direction", "mode"});
        !s)
        return s.error();
    geom::Expected<Subject> subject = read_subject(request, true, true);
    if (!subject) return subject.error();
    geom::Expected<geom::Dir> dir = read_direction(request, *subject);
    if (!dir) return dir.error();
    const json* mode = find_member(request, "mode");
    if (!mode) return missing_member("", "mode");
    if (!mode->is_string() || mode->get<std::string>() != "periodic")
        return schema_error("mode must be \"periodic\"", "/mode");
    if (subject->is_surface)
        return shape_answer(*subject, {}, geom::close_periodic(subject->surface, *dir));
    return shape_answer(*subject, geom::close_periodic(subject->curve), {});
}

OpResult op_split_knot(const json& request) {
    if (geom::Status s =
            check_fields(request, "split_knot", {"curve", "surface", "direction", "knot", "delta"});
        !s)
        return s.error();
    geom::Expected<Subject> subject = read_subject(request, true, true);
    if (!subject) return subject.error();
    geom::Expected<geom::Dir> dir = read_direction(request, *subject);
    if (!dir) return dir.error();
    geom::Expected<double> knot = required_number(request, "knot");
    if (!knot) return knot.error();
    std::optional<double> delta;
    if (const json* d = find_member(request, "delta")) {
        geom::Expected<double> x = read_finite(*d, "/delta", "delta");
        if (!x) return x.error();
        delta = *x;
    }
    json answer;
    if (subject->is_surface) {
        auto split = geom::split_knot(subject->surface, *dir, *knot, delta, "/surface");
        if (!split) return split.error();
        answer = shape_answer(*subject, {}, split->result);
        answer["max_change"] = split->max_change;
    } else {
        auto split = geom::split_knot(subject->curve, *knot, delta, "/curve");
        if (!split) return split.error();
        answer = shape_answer(*subject, split->result, {});
        answer["max_change"] = split->max_change;
    }
    return answer;
}

} // namespace isoparm::protocol
