// Many selected control points (pure): the set beside the document's selected point (Shift+click
// adds or removes, a box drag selects what lies inside, keys take the row, the column or all),
// and the handle that moves, turns and scales them about a pivot in the 3D view and the planes.
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include "core/doc/document.hpp"
#include "core/doc/point_set.hpp"
#include "ui/view/camera.hpp"
#include "ui/view/canvas_map.hpp"

namespace isoparm::ui {

using doc::PointIndex;

// The selected points of one object, sorted and unique. The document's selected point (the
// one the Control point panel edits) is always among them; one point is the usual selection.
struct PointSelection {
    std::uint64_t object = 0;
    std::vector<PointIndex> points;

    bool contains(PointIndex p) const;
    // Adds p, or takes it out when it is there (Shift+click).
    void toggle(PointIndex p);
    void add(const std::vector<PointIndex>& more);
    void set(std::uint64_t id, std::vector<PointIndex> points);
    std::size_t size() const { return points.size(); }
};
// Keeps the set in step with the document: another object (or none) selected starts over from
// the selected point; points the shape no longer has are dropped; the selected point is in it.
void sync_selection(PointSelection& s, const doc::Document& doc);
// Where the selected point goes after a toggle: p when it was added; another point of the set
// when p (the selected point) was taken out; nothing when the set is empty.
std::optional<PointIndex> primary_after_toggle(const PointSelection& s, PointIndex p,
                                               PointIndex primary);

// The indices of the pixels inside the rectangle with corners a and b (any order).
std::vector<std::size_t> inside_box(const std::vector<glm::dvec2>& pixels, const glm::dvec2& a,
                                    const glm::dvec2& b);

// The handle drawn at a selection's pivot: a centre disk (moves in the view's plane), an arrow
// per axis (moves along it), a ring per axis (turns about it) and a square (scales about the
// pivot). In a plane canvas: the plane's two arrows, the ring about its normal and the square.
enum class HandlePart { none, centre, arrow_x, arrow_y, arrow_z, ring_x, ring_y, ring_z, scale };
struct HandleLayout {
    glm::dvec2 centre{0};
    double centre_radius = 7;
    bool axis_shown[3] = {false, false, false};
    glm::dvec2 tip[3]{};             // arrow ends, pixels
    std::vector<glm::dvec2> ring[3]; // closed polylines, pixels (empty when not shown)
    glm::dvec2 scale_box{0};         // the square's centre
    double box_half = 5;
};
// In the 3D view: arrows `size_px` long along x, y and z (an axis seen end-on has none), rings
// of radius 0.75 size in the planes through the pivot (seen edge-on: none).
HandleLayout handle_layout_3d(const Camera& c, const Viewport& vp, const glm::dvec3& pivot,
                              double size_px);
// In a plane canvas showing axes a (right) and b (up).
HandleLayout handle_layout_plane(const PlaneMap& m, int a, int b, const glm::dvec3& pivot,
                                 double size_px);
// The part under the pointer (centre and the square first, then arrow tips, then rings),
// within `radius` pixels; none.
HandlePart hit_handle(const HandleLayout& h, const glm::dvec2& mouse, double radius);
// The axis an arrow or a ring belongs to (0, 1, 2), -1 for the others.
int handle_axis(HandlePart p);

// What a handle drag from `press` to `now` (pixels) does about `pivot`, as an affine map:
// an arrow moves by the pointer's motion along the axis (move_along: the world motion along
// it, from the camera or the canvas), the centre by `move_free` (the world motion in the
// view's plane), a ring turns by the angle swept about the pivot's pixel (counter-clockwise on
// screen is positive when the axis points at the viewer: `axis_toward_viewer`), the square
// scales by |now - pivot| / |press - pivot|. Quarter-turn multiples are exact (doc::rotation).
glm::dmat4 ring_turn(int axis, const glm::dvec3& pivot, const glm::dvec2& pivot_px,
                     const glm::dvec2& press, const glm::dvec2& now, bool axis_toward_viewer,
                     double snap_degrees = 0);
glm::dmat4 box_scale(const glm::dvec3& pivot, const glm::dvec2& pivot_px, const glm::dvec2& press,
                     const glm::dvec2& now, double snap_step = 0);

} // namespace isoparm::ui
