// Border continuity measured by evaluating both sides (exact derivatives, geom::evaluate).
#include "core/doc/border_measure.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/curvature.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/tessellate.hpp"

namespace isoparm::doc {

BorderMeasure measure_border(const Document& doc, const SharedBorder& border, int samples) {
    BorderMeasure m;
    const Object* low = doc.find(border.low);
    const Object* high = doc.find(border.high);
    if (!low || !high || !low->surface() || !high->surface()) return m;
    const geom::Surface& a = *low->surface();
    const geom::Surface& b = *high->surface();
    const double at = geom::domain(a, border.across).hi; // == b's low end in `across`
    const bool across_u = border.across == geom::Dir::u;
    for (double s : geom::uniform_params(border.along.lo, border.along.hi, std::max(samples, 2))) {
        const double u = across_u ? at : s, v = across_u ? s : at;
        const auto da = geom::surface_derivatives(a, u, v, 2);
        const auto db = geom::surface_derivatives(b, u, v, 2);
        if (!da || !db) continue;
        ++m.sampled;
        m.gap = std::max(m.gap, glm::distance(da->D[0][0], db->D[0][0]));
        const glm::dvec3 sa = across_u ? da->D[1][0] : da->D[0][1];
        const glm::dvec3 sb = across_u ? db->D[1][0] : db->D[0][1];
        m.derivative = std::max(m.derivative, glm::distance(sa, sb));
        const auto na = geom::normal_from_derivatives(*da);
        const auto nb = geom::normal_from_derivatives(*db);
        if (na && nb) {
            // atan2 of sine and cosine: acos near 1 would turn rounding into 1e-6 degrees.
            const double angle = std::atan2(glm::length(glm::cross(*na, *nb)), glm::dot(*na, *nb));
            m.angle_degrees = std::max(m.angle_degrees, angle * 180.0 / 3.14159265358979323846);
        }
        const auto ka = geom::curvature_from_derivatives(*da);
        const auto kb = geom::curvature_from_derivatives(*db);
        if (ka && kb) m.curvature = std::max(m.curvature, std::abs(ka->mean - kb->mean));
    }
    return m;
}

namespace {
constexpr double length_tolerance = 1e-9; // relative to the group's size
constexpr double angle_tolerance = 1e-6;  // degrees
constexpr double curvature_tolerance = 1e-6;
} // namespace

BorderHolds border_holds(const BorderMeasure& m, double size) {
    BorderHolds h;
    if (m.sampled == 0) return h; // nothing measured: nothing shown to hold
    h.c0 = m.gap <= length_tolerance * size;
    h.g1 = m.angle_degrees <= angle_tolerance;
    h.c1 = m.derivative <= length_tolerance * size;
    h.g2 = m.curvature <= curvature_tolerance;
    return h;
}

BorderLevel border_level(const BorderMeasure& m, double size) {
    const BorderHolds h = border_holds(m, size);
    if (!h.c0) return BorderLevel::broken;
    if (!h.g1) return BorderLevel::c0;
    if (!h.c1) return BorderLevel::g1;
    return h.g2 ? BorderLevel::g2 : BorderLevel::c1;
}

double group_size(const Document& doc, std::uint64_t group) {
    double size = 0;
    for (const Object* p : patch_members(doc, group))
        if (const geom::Surface* s = p->surface())
            for (const glm::dvec3& q : s->points)
                size = std::max({size, std::abs(q.x), std::abs(q.y), std::abs(q.z)});
    return std::max(size, 1e-300);
}

} // namespace isoparm::doc
