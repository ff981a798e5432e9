// Placement of new objects (see placement.hpp).
#include "core/doc/placement.hpp"

#include <algorithm>

#include <glm/common.hpp>

namespace isoparm::doc {

namespace {

void grow(std::optional<Box>& box, const glm::dvec3& p) {
    if (!box) {
        box = Box{p, p};
        return;
    }
    box->lo = glm::min(box->lo, p);
    box->hi = glm::max(box->hi, p);
}

} // namespace

std::optional<Box> bounds_of(const Shape& shape) {
    return std::visit([](const auto& k) { return bounds(k); }, shape);
}

std::optional<Box> scene_bounds(const Document& doc) {
    std::optional<Box> box;
    for (const Object& o : doc.objects) {
        if (!o.visible) continue;
        if (const std::optional<Box> b = bounds_of(o.shape)) {
            grow(box, b->lo);
            grow(box, b->hi);
        }
    }
    return box;
}

void place_beside_scene(const Document& doc, Shape& shape) {
    // An object moves with its control points; one without them (an implicit surface, whose
    // expression is in absolute coordinates: moving its box alone would cut the field) stays
    // where its formula puts it.
    if (control_points_of(shape).empty()) return;
    const std::optional<Box> scene = scene_bounds(doc);
    const std::optional<Box> own = bounds_of(shape);
    if (!scene || !own) return;
    const double width = own->hi.x - own->lo.x;
    const double gap = std::max(0.25 * width, 0.5);
    glm::dvec3 d{scene->hi.x + gap - own->lo.x, 0, 0};
    d.y = 0.5 * (scene->lo.y + scene->hi.y) - 0.5 * (own->lo.y + own->hi.y);
    for (glm::dvec3& p : control_points_of(shape)) p += d;
}

} // namespace isoparm::doc
