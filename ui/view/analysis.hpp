// The analysis colouring as the view shows it: the document's setting turned into what the
// renderer needs (the range found from the visible surfaces when automatic) and the colour
// bar's colours, the same maps as the mesh shader's.
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/doc/document.hpp"
#include "core/geom/curvature.hpp"
#include "core/geom/tessellate.hpp"
#include "ui/view/scene_draw.hpp"

namespace isoparm::ui {
class ImplicitMeshes;
}

namespace isoparm::ui {

AnalysisKind analysis_kind(doc::AnalysisMode mode);
// The curvature a curvature kind shows (K for the others: never asked).
geom::CurvatureKind curvature_kind(AnalysisKind kind);

// The display's analysis for the renderer. The automatic range is robust_range of the curvature
// of every visible spline surface sampled on a 17 x 17 grid of its domain (exact derivatives;
// undefined points left out) and of about 300 vertices of every visible implicit surface's
// mesh (when `implicit` is given), symmetric about zero for K and H (the diverging map); a fixed
// range is used as given. A range of width 0 (a flat grid) is widened to +-1e-12 so the bar
// still reads.
AnalysisView analysis_view(const doc::Document& doc, const ImplicitMeshes* implicit = nullptr);

// The curvature `kind` shows at each vertex of an implicit object's mesh, from f's gradient
// and Hessian (geom::implicit::implicit_curvature); NaN where undefined (a singular point) and
// everywhere when f does not compile. Every `stride`-th vertex only when stride > 1 (the
// automatic range's samples).
std::vector<double> implicit_vertex_curvature(const doc::ImplicitObject& o, const geom::Mesh& mesh,
                                              AnalysisKind kind, std::size_t stride = 1);

// The values' `tail` and 1 - `tail` percentiles (nearest rank), and their extremes: one pole
// or one outlying surface (a curvature of 165 among values near 1) no longer sets the range.
struct Range {
    double lo = 0, hi = 0;         // the robust range
    double all_lo = 0, all_hi = 0; // every value
};
Range robust_range(std::vector<double> values, double tail = 0.02);

// Under the colour bar when values lie beyond it: "all values -165 .. 3.2; the bar spans 96%
// of them" (empty when the bar covers them all).
std::string analysis_range_note(const AnalysisView& v);

// The colour of `value` under the view's map (the shader's formula).
glm::vec3 analysis_colour(const AnalysisView& view, double value);

// "K (Gaussian curvature)" for the colour bar's title.
std::string analysis_title(AnalysisKind kind);

} // namespace isoparm::ui
