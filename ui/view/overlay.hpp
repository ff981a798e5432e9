// What the 3D view draws besides surface meshes, rebuilt every frame from the document:
// control nets, control points, the indicator, knot curves, de Boor levels (pure data).
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

namespace isoparm::ui {

struct OverlayVertex {
    glm::vec3 position;
    glm::vec4 color;
    bool operator==(const OverlayVertex&) const = default;
};

struct LineBatch {
    std::vector<OverlayVertex> vertices; // pairs: one segment per two vertices
    float width_px = 1.5f;
    bool faint_when_hidden = true; // parts behind surfaces drawn faintly instead of vanishing
    bool operator==(const LineBatch&) const = default;
};

struct PointBatch {
    std::vector<OverlayVertex> points;
    float size_px = 9.f;
    bool sphere = false; // shaded as a small sphere (S(u,v), de Boor results)
    bool on_top = false; // ignore depth (always visible)
    bool operator==(const PointBatch&) const = default;
};

struct Overlay {
    std::vector<LineBatch> lines;
    std::vector<PointBatch> points;
    bool operator==(const Overlay&) const = default;

    // A polyline as segments (consecutive points joined).
    static void add_polyline(LineBatch& b, const std::vector<glm::vec3>& pts,
                             const glm::vec4& color) {
        for (std::size_t k = 1; k < pts.size(); ++k) {
            b.vertices.push_back({pts[k - 1], color});
            b.vertices.push_back({pts[k], color});
        }
    }
};

} // namespace isoparm::ui
