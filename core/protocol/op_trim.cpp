// Trimmed surfaces in the protocol: the `trim` member `tessellate` and the ops below share
// (read, then checked against the surface's domain), `classify` (where points lie in the
// trimmed domain) and `area`.
#include <cmath>

#include "core/geom/knots.hpp"
#include "core/geom/trim/trim_area.hpp"
#include "core/geom/trim/trim_classify.hpp"
#include "core/geom/trim/trim_validate.hpp"
#include "core/geom/validate.hpp"
#include "core/json/trim_json.hpp"
#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

using geom::Expected;

Expected<std::optional<geom::Trim>> read_trim(const json& request, const geom::Surface& s) {
    const json* t = find_member(request, "trim");
    if (!t) return std::optional<geom::Trim>{};
    Expected<geom::Trim> trim = trim_from_json(*t);
    if (!trim) return trim.error().under("/trim");
    if (geom::Status st = geom::validate_trim(*trim, geom::domain(s)); !st)
        return st.error().under("/trim");
    return std::optional<geom::Trim>{std::move(*trim)};
}

OpResult op_classify(const json& request) {
    if (find_member(request, "curve"))
        return schema_error("classify takes a surface and its trim, not a curve", "/curve");
    if (geom::Status s = check_fields(request, "classify", {"surface", "trim", "params"}); !s)
        return s.error();
    Expected<Subject> subject = read_subject(request, false, true);
    if (!subject) return subject.error();
    Expected<std::optional<geom::Trim>> trim = read_trim(request, subject->surface);
    if (!trim) return trim.error();
    const json* params = find_member(request, "params");
    if (!params) return missing_member("", "params");
    if (!params->is_array()) return schema_error("params is an array of [u, v]", "/params");
    if (params->size() > static_cast<std::size_t>(geom::max_evaluation_points))
        return geom::make_error(geom::ErrorCode::limit,
                                "too many points (" + std::to_string(params->size()) + " > " +
                                    std::to_string(geom::max_evaluation_points) + ")",
                                "/params");
    std::vector<glm::dvec2> points;
    for (std::size_t k = 0; k < params->size(); ++k) {
        Expected<glm::dvec2> p =
            read_param((*params)[k], "/params" + geom::pointer_step(static_cast<long>(k)));
        if (!p) return p.error();
        points.push_back(*p);
    }
    const geom::TrimClassifier classifier(trim->value_or(geom::Trim{}),
                                          geom::domain(subject->surface));
    json sides = json::array();
    for (const glm::dvec2& p : points) sides.push_back(geom::name_of(classifier.classify(p)));
    return json{{"sides", std::move(sides)}};
}

OpResult op_area(const json& request) {
    if (find_member(request, "curve"))
        return schema_error("area takes a surface (and its trim), not a curve", "/curve");
    if (geom::Status s = check_fields(request, "area", {"surface", "trim"}); !s) return s.error();
    Expected<Subject> subject = read_subject(request, false, true);
    if (!subject) return subject.error();
    Expected<std::optional<geom::Trim>> trim = read_trim(request, subject->surface);
    if (!trim) return trim.error();
    const double area = geom::trimmed_area(subject->surface, trim->value_or(geom::Trim{}));
    if (!std::isfinite(area))
        return geom::make_error(geom::ErrorCode::geometry,
                                "the area is not finite (a zero denominator inside the domain)",
                                "/surface");
    return json{{"area", area}};
}

} // namespace isoparm::protocol
