#include "ui/view/face_culling.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace isoparm::ui {

HiddenFaces hidden_faces(const SurfaceDraw& d, const glm::dvec3& eye, double near_reach) {
    if (d.seen_side == 0) return HiddenFaces::none;
    // The eye's distance to the box (0 inside it) must exceed what the near plane reaches.
    const glm::dvec3 nearest = glm::clamp(eye, d.box_lo, d.box_hi);
    if (!(glm::distance(eye, nearest) > near_reach)) return HiddenFaces::none;
    return d.seen_side > 0 ? HiddenFaces::clockwise : HiddenFaces::counter_clockwise;
}

} // namespace isoparm::ui
