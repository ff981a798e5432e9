// Where a lesson's caption box goes over the 3D view: never on the point the stop is about
// (the selected control point, the indicator's point), and off the object it is about when
// the view has room (the selected object, else every visible one). Pure: the focus is
// projected with the view's camera, the box placed by scoring candidate positions.
#pragma once

#include <vector>

#include "core/doc/document.hpp"
#include "ui/view/camera.hpp"
#include "ui/view/layout.hpp"

namespace isoparm::ui {

struct CaptionFocus {
    std::vector<Rect> points;  // must stay uncovered: a small square around each point
    std::vector<Rect> objects; // stays uncovered where the view has room: screen boxes
    std::vector<Rect> windows; // other floating windows (the lesson editor): kept clear too
};

// The stop's subject on screen, in the pixels of `view` (the 3D image's rectangle).
// `point_radius` is the half side of a point's square (a control point's disk and a margin).
CaptionFocus caption_focus(const doc::Document& d, const Camera& camera, const Rect& view,
                           float point_radius);

// The world points the focus's object boxes come from (fit_camera_into frames them).
std::vector<glm::dvec3> focus_points(const doc::Document& d);

// Moves the camera (zoom and pan, keeping its angles) so that `points` lie inside `free`, a
// part of the view `view` (both in pixels): where a caption box cannot avoid the object, the
// object moves out from under it. Keeps the camera as it was when the points cannot be
// framed (behind the eye, or `free` too small).
void fit_camera_into(Camera& camera, const std::vector<glm::dvec3>& points, const Rect& view,
                     const Rect& free);

// The largest rectangle of `view` beside `box` (above, below, left or right of it).
Rect free_beside(const Rect& view, const Rect& box);

bool overlaps(const Rect& a, const Rect& b);
float overlap_area(const Rect& a, const Rect& b);

// The position of a w x h box inside `view` (inset by `margin`): the candidate that covers
// no point and the least of the objects; among equals, the one nearest the top centre (where
// a class looks for it), then the one nearest `previous` (the box does not jump for nothing).
// A box larger than the view goes to its top left.
Rect place_caption(const Rect& view, float w, float h, const CaptionFocus& focus, float margin,
                   const Rect* previous = nullptr);

} // namespace isoparm::ui
