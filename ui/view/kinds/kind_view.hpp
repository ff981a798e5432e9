// What every kind of object answers on the workstation's side: the list a new kind's view
// file must fill in (the concept KindView below), the types its answers use, and the
// dispatchers the rest of ui/ and app/ call.
//
// One kind, one more place: beside its facts in core/doc/kinds, each kind has a view file here
// (surface_view.cpp, curve_view.cpp, implicit_view.cpp, triangle_view.cpp) with what it adds
// to the 3D view's scene, its control net (which the plane canvases draw and the 3D view
// picks), the editor it opens, how its control points are indexed and its Kind column label.
// Its mesh cache is its own file beside (surfaces: the renderer's tessellation; implicit_meshes,
// triangle_meshes). The dispatchers below visit doc::Shape with a generic lambda calling these
// functions, so a kind whose ISOPARM_KIND_VIEW line is missing stops the build there, and one
// whose functions are missing fails the link. Other ui/ code that decides by kind visits
// doc::Shape with doc::overloaded, listing every kind.
#pragma once

#include <concepts>
#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <utility>
#include <variant>
#include <vector>

#include "core/doc/command.hpp"
#include "core/doc/document.hpp"
#include "ui/view/control_net.hpp"
#include "ui/view/overlay.hpp"
#include "ui/view/scene_draw.hpp"

namespace isoparm::ui {

class ImplicitMeshes;
class TriangleMeshes;

// Which editor takes the right column's top slot while an object of the kind is selected.
enum class ObjectEditor { control_points, curve_designer, implicit_surface };

// How one object is drawn this frame (from build_scene's style and the document).
struct ObjectLook {
    std::uint64_t id = 0;
    bool selected = false;
    int point_i = -1, point_j = -1;      // the selected control point (drawn apart, larger)
    doc::ObjectDisplay own;              // the object's toggles (control points, net, knot curves)
    const doc::Colors* colors = nullptr; // kept readable on the background
    glm::vec3 background{0};
    float scale = 1; // line widths
    bool shaded = true, wire = true;
    int density = 32;             // the display's samples per knot span
    bool knot_continuity = false; // knot curves coloured by the continuity they carry
    const ImplicitMeshes* implicit_meshes = nullptr; // null: implicit surfaces draw no mesh
    const TriangleMeshes* triangle_meshes = nullptr; // null: triangles draw no mesh
};

// What the panels ask of a kind: the editor it opens in the right column, whether its control
// points are named (i, j) (true) or i alone, j = -1, or not at all (false), and the Objects
// tab's Kind column (label and note).
struct KindTraits {
    ObjectEditor editor = ObjectEditor::control_points;
    bool two_index = false;
    const char* label = "";
    const char* note = ""; // shown instead, the label in its tooltip: "trimmed" (trim loops)
};

// The batches every object adds to (build_scene draws them in its order).
struct SceneBatches {
    std::vector<SurfaceDraw>& surfaces;
    LineBatch &net, &knots, &knots_double, &knots_full, &curves, &box;
    PointBatch& points;
};

// Each kind's view functions (defined in its view file), declared by one line per kind.
#define ISOPARM_KIND_VIEW(K)                                                                       \
    void draw_kind(const K& k, const ObjectLook& look, SceneBatches& out);                         \
    ControlNet kind_net(const K& k);                                                               \
    KindTraits kind_traits(const K& k)

ISOPARM_KIND_VIEW(doc::SurfaceObject);
ISOPARM_KIND_VIEW(doc::CurveObject);
ISOPARM_KIND_VIEW(doc::ImplicitObject);
ISOPARM_KIND_VIEW(doc::TriangleObject);

// What a kind K answers here (each defined in its view file).
template <class K>
concept KindView = requires(const K& k, const ObjectLook& look, SceneBatches& out) {
    // Its shape, net, points and knot curves in the 3D view's batches.
    { draw_kind(k, look, out) } -> std::same_as<void>;
    // Its control net (empty: none).
    { kind_net(k) } -> std::same_as<ControlNet>;
    { kind_traits(k) } -> std::same_as<KindTraits>;
};

// Every kind of doc::Shape has its view: a kind without its ISOPARM_KIND_VIEW line stops here.
template <std::size_t... I> constexpr bool every_kind_viewed(std::index_sequence<I...>) {
    return (KindView<std::variant_alternative_t<I, doc::Shape>> && ...);
}
static_assert(every_kind_viewed(std::make_index_sequence<std::variant_size_v<doc::Shape>>{}),
              "a kind of doc::Shape lacks its view (ISOPARM_KIND_VIEW and its view file)");

// The dispatchers: the object's kind answers.
void draw_in_scene(const doc::Object& o, const ObjectLook& look, SceneBatches& out);
KindTraits traits_of(const doc::Shape& shape);
ObjectEditor editor_of(const doc::Object& o);
// Whether a control point of the shape is named by two indices (a surface's (i, j), a
// triangle's (i, j) of b_ijk) or by one (a curve's i, j = -1); a kind without control points
// names none (false).
bool two_index_points(const doc::Shape& shape);
// The Objects tab's Kind column: a surface by its spline type, else the kind as scene files
// name it.
const char* kind_label(const doc::Object& o);

// The command that moves control point (i, j) of o to p (a curve: point i).
std::unique_ptr<doc::Command> move_point_command(const doc::Object& o, int i, int j,
                                                 const glm::dvec3& p);

// Shared by the kinds' views: a spline patch's (surface or triangle) draw with its colours:
// the wireframe of the selected one in its own colour; over a shaded patch the lines are a
// darker shade of it so they read as grid, not as edges.
SurfaceDraw patch_draw(const ObjectLook& look);
// A control point in the points batch, unless it is the selected one (drawn larger apart).
void add_control_point(const ObjectLook& look, int i, int j, const glm::dvec3& p, PointBatch& out);

} // namespace isoparm::ui
