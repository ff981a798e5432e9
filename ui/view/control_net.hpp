// An object's control net as the plane canvases (the Control point panel, the four-view
// layout's planes) draw and pick it: the points with their (i, j) and the net's lines.
#pragma once

#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "core/doc/document.hpp"

namespace isoparm::ui {

struct ControlNet {
    std::vector<std::pair<int, int>> ids; // (i, j) of each point; a triangle's b_ijk, k = n - i - j
    std::vector<glm::dvec3> points;
    std::vector<std::vector<int>> lines; // polylines, as indices into points
    int find(int i, int j) const;        // the point (i, j), or -1
};

// A surface: its rows and columns. A triangle of degree n: the lines i, j and k = const of
// its triangular net (together its 3 n (n + 1) / 2 edges). A curve: its control polygon, the
// points' ids (i, -1). Empty for implicit surfaces.
// Each kind's own in its view file (ui/view/kinds/); the dispatch is in kinds/kind_view.cpp.
ControlNet control_net_of(const doc::Object& o);

} // namespace isoparm::ui
