// From the document to what the renderer draws: surfaces with their colours and the
// overlay (control nets, points, indicator S(u,v), knot curves, drag guides). No GL here.
#pragma once

#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/doc/border_measure.hpp"
#include "core/doc/document.hpp"
#include "ui/view/curve_glyphs.hpp"
#include "ui/view/overlay.hpp"
#include "ui/view/scene_draw.hpp"

namespace isoparm::ui {

glm::vec4 to_vec4(const doc::Rgba& c);

struct SceneStyle {
    float scale = 1;     // line widths and point sizes (HiDPI, presentation)
    int guide_axis = -1; // an axis-constrained drag shows its axis through guide_point
    glm::dvec3 guide_point{0};
    int deboor_step = -1; // de Boor's construction up to this step (-1: all); deboor_overlay.hpp
    // Knot curves coloured by the continuity their knot leaves (knot_continuity_color).
    bool knot_continuity = false;
    // The current patch group's borders drawn thick in border_level_color.
    bool border_continuity = false;
    // The selected curve's comb, osculating circle and Frenet frame at curve_t (normalised to
    // [0, 1] over its domain), as the curve designer shows them on its canvas.
    CurveGlyphRequest curve_glyphs;
    double curve_t = 0.4;
    // The working plane z = 0 with its grid (Display > Grid): lines every grid_step out to
    // grid_lines steps either side of grid_centre (put on a grid line), every fifth brighter.
    bool working_grid = false;
    double grid_step = 1;
    int grid_lines = 20;
    glm::dvec2 grid_centre{0};
    // Points selected beside the selected one (many points selected): drawn as it is.
    std::vector<glm::dvec3> also_selected;
};

// A border's colour by the continuity measured on it (doc::border_level): red broken, orange
// C0, yellow G1, green C1, cyan C1 with the mean curvature continuous.
glm::vec4 border_level_color(doc::BorderLevel level);

// The colour of an interior knot curve of multiplicity m in degree p by the continuity
// C^(p - m) it carries: the scene's knot-curve colour from C2 up, yellow for C1, orange for
// C0, red where the surface need not be continuous (C-1).
glm::vec4 knot_continuity_color(int degree, int multiplicity, const glm::vec4& smooth);

struct BuiltScene {
    std::vector<SurfaceDraw> surfaces;
    Overlay overlay;
};
class ImplicitMeshes;
class TriangleMeshes;
// Implicit objects are drawn from `implicit`'s cached meshes (left out when it is null or
// has no mesh for them yet); the selected one also shows its bounds as a box. Triangular
// patches are drawn from `triangles`' meshes (their nets and points always).
BuiltScene build_scene(const doc::Document& d, const SceneStyle& style,
                       const ImplicitMeshes* implicit = nullptr,
                       const TriangleMeshes* triangles = nullptr);

// The points of the isoparametric curve with `fixed` direction held at t (S(t, v) for
// fixed = u), `samples` evenly spaced in the other direction; runs where the point does not
// exist (zero denominator) break the polyline into pieces.
std::vector<std::vector<glm::vec3>> iso_curve(const geom::Surface& s, geom::Dir fixed, double t,
                                              int samples);

// The control points of visible objects (corners of an implicit object's box): what "fit
// to view" frames.
std::vector<glm::dvec3> scene_points(const doc::Document& d);

} // namespace isoparm::ui
