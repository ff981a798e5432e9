// Orbit camera maths for the 3D view (pure: no GL), z up, plus the rays a drag needs.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

namespace isoparm::ui {

// A rectangle in pixels, y growing downward (ImGui's screen coordinates).
struct Viewport {
    double x = 0, y = 0, w = 1, h = 1;
    double aspect() const { return h > 0 ? w / h : 1.0; }
};

// Looks at `target` from `distance`, at azimuth `yaw` (about +z) and elevation `pitch`.
struct Camera {
    glm::dvec3 target{0, 0, 0};
    double distance = 6.0;
    double yaw = -0.95;    // radians
    double pitch = 0.55;   // radians, kept inside (-pi/2, pi/2)
    double fov_y = 0.6109; // 35 degrees
    bool operator==(const Camera&) const = default;
};

glm::dvec3 camera_eye(const Camera& c);
glm::dvec3 camera_forward(const Camera& c); // unit, from the eye toward the target
glm::dvec3 camera_right(const Camera& c);   // unit, screen right
glm::dvec3 camera_up(const Camera& c);      // unit, screen up
glm::dmat4 view_matrix(const Camera& c);
glm::dmat4 projection_matrix(const Camera& c, double aspect);
// The farthest the near clipping rectangle reaches from the eye: nothing nearer is clipped.
double near_plane_reach(const Camera& c, double aspect);
glm::dmat4 view_projection(const Camera& c, double aspect);

// Mouse gestures: pixel deltas as ImGui reports them (y down).
void orbit(Camera& c, double dx_px, double dy_px);
void pan(Camera& c, double dx_px, double dy_px, double viewport_height_px);
void zoom(Camera& c, double factor); // distance *= factor, factor > 0

// Frames the points so they fill about 90% of the view, centred on screen; keeps the
// viewing angles. Falls back to the (looser) bounding-sphere fit if tightening would lose a
// point. No-op for an empty set.
void fit_to_points(Camera& c, const std::vector<glm::dvec3>& points, double aspect);

struct Projected {
    glm::dvec2 pixel{0, 0};
    double depth = 0;     // NDC z in [-1, 1] when visible
    bool visible = false; // in front of the eye (w > 0) and inside the depth range
};
Projected project(const glm::dmat4& view_proj, const Viewport& vp, const glm::dvec3& p);

struct Ray {
    glm::dvec3 origin{0, 0, 0};
    glm::dvec3 dir{0, 0, -1}; // unit
};
Ray pixel_ray(const Camera& c, const Viewport& vp, const glm::dvec2& pixel);

// Where the ray meets the plane through `point` with normal `n`; nullopt if parallel or
// behind the origin.
std::optional<glm::dvec3> intersect_plane(const Ray& r, const glm::dvec3& point,
                                          const glm::dvec3& n);
// The point of the line point + s * dir closest to the ray; nullopt when they are parallel.
std::optional<glm::dvec3> closest_on_line(const Ray& r, const glm::dvec3& point,
                                          const glm::dvec3& dir);

// Dragging a point: in the plane through `start` facing the camera, or along world axis
// `axis` (0 = x, 1 = y, 2 = z) through `start`. Returns `start` when undefined.
glm::dvec3 drag_in_view_plane(const Camera& c, const Viewport& vp, const glm::dvec3& start,
                              const glm::dvec2& pixel);
glm::dvec3 drag_along_axis(const Camera& c, const Viewport& vp, const glm::dvec3& start, int axis,
                           const glm::dvec2& pixel);
// The world axis whose on-screen direction at `p` best matches the drag `screen_delta`.
int dominant_axis(const Camera& c, const Viewport& vp, const glm::dvec3& p,
                  const glm::dvec2& screen_delta);

} // namespace isoparm::ui
