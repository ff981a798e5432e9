// The analysis colouring as the view shows it: the document's setting turned into what the
// renderer needs (the range found from the visible surfaces when automatic) and the colour
// bar's colours, the same maps as the mesh shader's.
#pragma once

#include <glm/vec3.hpp>
#include <string>

#include "core/doc/document.hpp"
#include "core/geom/curvature.hpp"
#include "ui/view/scene_draw.hpp"

namespace isoparm::ui {

AnalysisKind analysis_kind(doc::AnalysisMode mode);
// The curvature a curvature kind shows (K for the others: never asked).
geom::CurvatureKind curvature_kind(AnalysisKind kind);

// The display's analysis for the renderer. The automatic range covers the curvature of every
// visible spline surface sampled on a 17 x 17 grid of its domain (exact derivatives; undefined
// points left out), symmetric about zero for K and H (the diverging map), [min, max] for the
// principal curvatures (the sequential map); a fixed range is used as given. A range of width
// 0 (a flat grid) is widened to +-1e-12 so the bar still reads.
AnalysisView analysis_view(const doc::Document& doc);

// The colour of `value` under the view's map (the shader's formula).
glm::vec3 analysis_colour(const AnalysisView& view, double value);

// "K (Gaussian curvature)" for the colour bar's title.
std::string analysis_title(AnalysisKind kind);

} // namespace isoparm::ui
