// The `convert` op (geom-protocol-2.md): an object as another spline type, split into its
// Bezier pieces when a Bezier type asks for it.
#include "core/geom/convert.hpp"
#include "core/json/shapes.hpp"
#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

OpResult op_convert(const json& request) {
    if (geom::Status s = check_fields(request, "convert", {"curve", "surface", "to"}); !s)
        return s.error();
    geom::Expected<Subject> subject = read_subject(request, true, true);
    if (!subject) return subject.error();
    const json* to = find_member(request, "to");
    if (!to) return missing_member("", "to");
    const std::optional<geom::SplineType> to_type = enum_value<geom::SplineType>(*to);
    if (!to_type)
        return schema_error("to must be one of " + geom::names_list<geom::SplineType>(", "), "/to");
    const geom::SplineType type = *to_type;
    json pieces = json::array();
    if (subject->is_surface) {
        auto converted = geom::convert(subject->surface, type);
        if (!converted) return converted.error().under("/surface");
        for (const geom::Surface& s : *converted) pieces.push_back(surface_to_json(s));
    } else {
        auto converted = geom::convert(subject->curve, type);
        if (!converted) return converted.error().under("/curve");
        for (const geom::Curve& c : *converted) pieces.push_back(curve_to_json(c));
    }
    json answer = json::object();
    answer["pieces"] = std::move(pieces);
    return answer;
}

} // namespace isoparm::protocol
