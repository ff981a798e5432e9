// What the 3D view is asked to draw, built without GL (ui/view/scene_builder.hpp) and drawn
// by the OpenGL renderer (ui/render/renderer.hpp): surfaces seen through a camera; the lines
// and points around them are the overlay (overlay.hpp).
#pragma once

#include "core/doc/document.hpp"

#include <cstdint>

#include <glm/vec4.hpp>

#include "core/geom/tessellate.hpp"
#include "core/geom/types.hpp"
#include "ui/view/camera.hpp"

namespace isoparm::ui {

// One surface to draw. The renderer never owns geometry: it keeps only derived GPU buffers,
// keyed by object id, and re-tessellates when the surface or density differs from the cache.
struct SurfaceMesh;

struct SurfaceDraw {
    std::uint64_t id = 0;
    const geom::Surface* surface = nullptr;
    const geom::Trim* trim = nullptr; // the part of its domain kept (nullptr: all of it)
    int density = 32;
    // The surface's display mesh at `density` (surface_meshes.hpp fills it in before drawing;
    // its revision goes in mesh_revision).
    const SurfaceMesh* display = nullptr;
    bool shaded = true;
    bool wireframe = false;
    glm::vec4 fill{0.3f, 0.55f, 0.85f, 1};
    glm::vec4 wire{0.9f, 0.9f, 0.9f, 1};
    float wire_width = 1.0f;
    // A ready-made mesh instead of a surface (implicit objects): uploaded whenever
    // mesh_revision differs from the cached one; its wireframe is the triangle edges.
    const geom::Mesh* mesh = nullptr;
    std::uint64_t mesh_revision = 0;
    // The implicit object the mesh is of: under a curvature kind its vertices are coloured by
    // the curvature f's gradient and Hessian give (geom::implicit::implicit_curvature).
    const doc::ImplicitObject* implicit = nullptr;
    // A closed mesh inside the box [box_lo, box_hi] is seen from outside the box only from
    // this side (+1: where its triangles run counter-clockwise; -1: the other; 0: not closed,
    // any side may show). See face_culling.hpp.
    int seen_side = 0;
    glm::dvec3 box_lo{0.0}, box_hi{0.0};
};

// The shaded surfaces' analysis colouring (doc::AnalysisMode, without the document): the
// renderer computes the curvature kinds at the tessellation's vertices from exact derivatives
// (geom::curvature_grid) and colours them over [lo, hi]; zebra and isophote stripes come from
// the normals per pixel.
enum class AnalysisKind { off, gaussian, mean, kmax, kmin, zebra, isophote };
inline bool is_curvature(AnalysisKind k) {
    return k == AnalysisKind::gaussian || k == AnalysisKind::mean || k == AnalysisKind::kmax ||
           k == AnalysisKind::kmin;
}
struct AnalysisView {
    AnalysisKind kind = AnalysisKind::off;
    float lo = -1, hi = 1; // the colour bar's range (curvature kinds)
    bool diverging = true; // blue - white - red about zero, else a sequential map lo .. hi
    int stripes = 12;      // zebra / isophote stripes
    float zebra_angle = 0; // degrees, the stripes' direction on screen
    // The automatic range is robust: the values' 2nd to 98th percentiles, so that one pole or
    // outlier does not wash every other surface out. All the values span data_lo .. data_hi;
    // `clipped` when that is wider than the bar (values beyond take the end colours).
    bool fixed = false;
    float data_lo = 0, data_hi = 0;
    bool clipped = false;
    bool operator==(const AnalysisView&) const = default;
};

struct SceneView {
    Camera camera;
    AnalysisView analysis;
    int width = 1, height = 1; // framebuffer pixels
    glm::vec4 background{0.13f, 0.14f, 0.17f, 1};
    bool operator==(const SceneView&) const = default;
};

} // namespace isoparm::ui
