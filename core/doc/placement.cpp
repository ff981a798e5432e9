// Placement of new objects (see placement.hpp).
#include "core/doc/placement.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

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

std::string unique_name(const Document& doc, const std::string& wanted, std::uint64_t except) {
    auto taken = [&](const std::string& n) {
        return std::any_of(doc.objects.begin(), doc.objects.end(),
                           [&](const Object& o) { return o.id != except && o.name == n; });
    };
    if (!taken(wanted)) return wanted;
    for (int n = 2;; ++n) {
        const std::string name = wanted + " (" + std::to_string(n) + ")";
        if (!taken(name)) return name;
    }
}

void place_beside_scene(const Document& doc, Shape& shape) {
    const std::optional<Box> scene = scene_bounds(doc);
    const std::optional<Box> own = bounds_of(shape);
    if (!scene || !own) return;
    const double width = own->hi.x - own->lo.x;
    const double gap = std::max(0.25 * width, 0.5);
    glm::dvec3 d{scene->hi.x + gap - own->lo.x, 0, 0};
    d.y = 0.5 * (scene->lo.y + scene->hi.y) - 0.5 * (own->lo.y + own->hi.y);
    // Each kind moves as it is drawn: control points, or an implicit surface's formula.
    std::visit([&](auto& k) { translate(k, d); }, shape);
}

} // namespace isoparm::doc
