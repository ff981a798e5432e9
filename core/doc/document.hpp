// The document: the scene every panel and `isoparm geom` edit through commands.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/doc/kinds/curve_kind.hpp"
#include "core/doc/kinds/implicit_kind.hpp"
#include "core/doc/kinds/surface_kind.hpp"
#include "core/doc/kinds/triangle_kind.hpp"
#include "core/doc/recipe.hpp"
#include "core/geom/status.hpp"
#include "core/geom/triangle.hpp"
#include "core/geom/types.hpp"

namespace isoparm::doc {

// The kinds of object, each with its facts in its own file (kinds/kind_facts.hpp says what a
// kind answers and how the code asks).
using Shape = std::variant<SurfaceObject, CurveObject, ImplicitObject, TriangleObject>;

// Shape lists the kinds in ObjectKind's order, and every kind answers every fact.
template <std::size_t... I> constexpr bool kinds_in_order(std::index_sequence<I...>) {
    return ((std::variant_alternative_t<I, Shape>::kind == static_cast<ObjectKind>(I)) && ...);
}
static_assert(kinds_in_order(std::make_index_sequence<std::variant_size_v<Shape>>{}));
static_assert(std::variant_size_v<Shape> == std::size(object_kind_names));

ObjectKind kind_of(const Shape& shape);

// Calls f(std::type_identity<K>{}) for the kind K whose K::kind is `kind` (for code that knows a
// kind by name before it has a shape: reading one).
template <class F, std::size_t I = 0> decltype(auto) with_kind_type(ObjectKind kind, F&& f) {
    using K = std::variant_alternative_t<I, Shape>;
    if constexpr (I + 1 == std::variant_size_v<Shape>) {
        return f(std::type_identity<K>{});
    } else {
        if (K::kind == kind) return f(std::type_identity<K>{});
        return with_kind_type<F, I + 1>(kind, std::forward<F>(f));
    }
}

// The parts a kind may have; the accessors return nullptr for another kind (an allow-list:
// code for some kinds asks for those, and refuses the others with kind_refusal).
geom::Surface* surface_of(Shape& shape);
const geom::Surface* surface_of(const Shape& shape);
// A surface's trim loops (empty: untrimmed); nullptr for another kind.
const geom::Trim* trim_of(const Shape& shape);
CurveObject* curve_object_of(Shape& shape);
const CurveObject* curve_object_of(const Shape& shape);
geom::Curve* curve_of(Shape& shape);
const geom::Curve* curve_of(const Shape& shape);
ImplicitObject* implicit_of(Shape& shape);
const ImplicitObject* implicit_of(const Shape& shape);
geom::TrianglePatch* triangle_of(Shape& shape);
const geom::TrianglePatch* triangle_of(const Shape& shape);
// The control points of any kind (a surface's row-major, a curve's, a triangle's in
// TrianglePatch's order; none for an implicit surface), and their weights.
std::span<glm::dvec3> control_points_of(Shape& shape);
std::span<const glm::dvec3> control_points_of(const Shape& shape);
std::span<double> control_weights_of(Shape& shape);
std::span<const double> control_weights_of(const Shape& shape);
// Whether the shape has control point (i, j) as a selection names it: a surface's P_ij, a
// curve's P_i (j = -1), a triangle's b_ijk (i, j >= 0, i + j <= n).
bool has_control_point(const Shape& shape, int i, int j);
// "P23", "P4", "b210": control point (i, j) as messages and labels name it ("w23": its weight).
std::string point_label_of(const Shape& shape, PointName name, int i, int j);

struct Object {
    std::uint64_t id = 0; // stable across undo/redo; assigned by the document
    std::string name;
    Shape shape;
    bool visible = true;
    // Subpatches split from one surface share a group id (0: not a subpatch). They keep the
    // original parameters, so together they tile the original domain and the tracing square
    // shows that whole domain (core/doc/patches.hpp).
    std::uint64_t patch_group = 0;
    // What built the object, when it stays linked to its inputs (core/doc/associative.hpp): an
    // edit of an input rebuilds it in the same command; its own points are not edited until it
    // is detached.
    std::optional<Recipe> construction = std::nullopt;

    ObjectKind kind() const { return kind_of(shape); }
    geom::Surface* surface() { return surface_of(shape); }
    const geom::Surface* surface() const { return surface_of(shape); }
    CurveObject* curve_object() { return curve_object_of(shape); }
    const CurveObject* curve_object() const { return curve_object_of(shape); }
    geom::Curve* curve() { return curve_of(shape); }
    const geom::Curve* curve() const { return curve_of(shape); }
    ImplicitObject* implicit() { return implicit_of(shape); }
    const ImplicitObject* implicit() const { return implicit_of(shape); }
    geom::TrianglePatch* triangle() { return triangle_of(shape); }
    const geom::TrianglePatch* triangle() const { return triangle_of(shape); }
};

// "object 'T' is a triangular patch; <rest>" (`schema` at path): the refusal of code that serves
// other kinds, naming the object's real kind.
geom::Error kind_refusal(const Object& o, const std::string& rest, const std::string& path = "/id");
// Whether o is a surface with trim loops.
bool is_trimmed(const Object& o);

// Whether moving a control point of a subpatch also moves its neighbours' so the border stays
// closed (c0) and, where degrees and knots allow it, tangent-continuous (c1).
enum class Continuity { off, c0, c1 };
inline constexpr geom::EnumName<Continuity> continuity_names[] = {
    {Continuity::off, "off"}, {Continuity::c0, "C0"}, {Continuity::c1, "C1"}};
static_assert(geom::in_declaration_order(continuity_names));
constexpr std::span<const geom::EnumName<Continuity>> enum_names(Continuity) {
    return continuity_names;
}
// "off", "C0", "C1" (name_of), for callers that say it this way.
inline const char* continuity_name(Continuity c) {
    return geom::name_of(c);
}

struct Rgba {
    float r = 0, g = 0, b = 0, a = 1;
    bool operator==(const Rgba&) const = default;
};

// Saved with the scene, edited through commands (undoable).
struct Colors {
    Rgba background{0.13f, 0.14f, 0.17f, 1};
    Rgba surface{0.30f, 0.55f, 0.85f, 1};
    Rgba selected_surface{0.95f, 0.65f, 0.25f, 1};
    Rgba control_net{0.75f, 0.75f, 0.75f, 1};
    Rgba control_points{0.95f, 0.95f, 0.35f, 1};
    Rgba selected_point{1.0f, 0.25f, 0.25f, 1};
    Rgba knot_curves{0.20f, 0.85f, 0.45f, 1};
    Rgba indicator{1.0f, 0.2f, 0.2f, 1};
    bool operator==(const Colors&) const = default;
};

enum class DisplayStyle { shaded, wireframe, both };
inline constexpr geom::EnumName<DisplayStyle> display_style_names[] = {
    {DisplayStyle::shaded, "shaded"},
    {DisplayStyle::wireframe, "wireframe"},
    {DisplayStyle::both, "both"},
};
static_assert(geom::in_declaration_order(display_style_names));
constexpr std::span<const geom::EnumName<DisplayStyle>> enum_names(DisplayStyle) {
    return display_style_names;
}

// What is drawn and how (part of the view state below).
// The shaded surfaces' analysis colouring (Display > Analysis, `isoparm render --analysis`):
// false colour of a curvature from exact derivatives, or reflection lines.
enum class AnalysisMode { off, gaussian, mean, kmax, kmin, zebra, isophote };
inline constexpr geom::EnumName<AnalysisMode> analysis_mode_names[] = {
    {AnalysisMode::off, "off"},
    {AnalysisMode::gaussian, "gauss", "Gaussian curvature K"},
    {AnalysisMode::mean, "mean", "mean curvature H"},
    {AnalysisMode::kmax, "kmax", "largest principal curvature"},
    {AnalysisMode::kmin, "kmin", "smallest principal curvature"},
    {AnalysisMode::zebra, "zebra", "zebra stripes"},
    {AnalysisMode::isophote, "isophote", "isophotes"},
};
static_assert(geom::in_declaration_order(analysis_mode_names));
constexpr std::span<const geom::EnumName<AnalysisMode>> enum_names(AnalysisMode) {
    return analysis_mode_names;
}

struct DisplaySettings {
    DisplayStyle style = DisplayStyle::both;
    bool control_points = true;
    bool control_net = true;
    bool point_ids = false;
    bool knot_curves = false;
    bool indicator_point = true;
    bool deboor = false;
    int density = 32; // tessellation samples per knot span direction (default density)
    AnalysisMode analysis = AnalysisMode::off;
    // The colour bar's range for the curvature modes: automatic (the visible surfaces'
    // values; symmetric about zero for K and H) unless fixed.
    bool analysis_fixed = false;
    double analysis_lo = -1, analysis_hi = 1;
    int stripes = 12;       // zebra and isophote stripes across the view
    double zebra_angle = 0; // direction of the zebra stripes, degrees
    bool operator==(const DisplaySettings&) const = default;
};

struct Selection {
    std::uint64_t object = 0; // object id; 0 = none
    int i = -1, j = -1; // control point (surface: P_ij; curve: P_i with j = -1; triangle: b_ijk)
    bool has_point() const { return i >= 0; }
    bool operator==(const Selection&) const = default;
};

// What the user is looking at rather than what the scene is: saved with the scene, but not
// part of undo (an undo restores geometry and leaves the view where it is).
// One object's own display toggles (C, N, I, K with the object selected; Display > Selected
// object): control points, net, point names and knot curves. An object without its own takes
// the scene's DisplaySettings, which are the defaults for new objects, so hiding one object's
// points never hides the next new surface's.
struct ObjectDisplay {
    bool control_points = true;
    bool control_net = true;
    bool point_ids = false;
    bool knot_curves = false;
    bool operator==(const ObjectDisplay&) const = default;
};
ObjectDisplay defaults_of(const DisplaySettings& d);

struct ViewState {
    Selection selection;
    glm::dvec2 indicator{0.5, 0.5}; // (u, v) normalized to [0,1]^2 over the current domain
    // A triangle's indicator (r, s, t), barycentric: its own, since the square's (u, v) has
    // no meaning on a triangle and switching objects should keep both.
    geom::Barycentric barycentric{1.0 / 3, 1.0 / 3, 1.0 / 3};
    DisplaySettings display;                               // the defaults for every object
    std::map<std::uint64_t, ObjectDisplay> object_display; // objects with their own, by id
};

// What object `id` shows: its own toggles, else the scene's defaults.
ObjectDisplay display_of(const ViewState& view, std::uint64_t id);

struct Document {
    std::vector<Object> objects;
    Colors colors;
    ViewState view;
    Continuity continuity = Continuity::off; // a setting, saved with the scene; not undoable
    std::uint64_t next_id = 1;

    Object* find(std::uint64_t id);
    const Object* find(std::uint64_t id) const;
    int index_of(std::uint64_t id) const; // -1 if absent
    const Object* selected() const { return find(view.selection.object); }
    std::uint64_t allocate_id() { return next_id++; }
};

// Geometry that is bit-identical (undo tests compare with this): every object (id, name,
// visibility, shape with all its numbers compared bit for bit) in the same order, and colours.
bool same_geometry(const Document& a, const Document& b);
// One object, bit for bit (as same_geometry compares them), its recipe included.
bool same_object(const Object& a, const Object& b);
// Two shapes, bit for bit.
bool same_shape(const Shape& a, const Shape& b);
// The view state (selection, indicator, display settings), bit for bit.
bool same_view(const ViewState& a, const ViewState& b);
// same_geometry plus the view state and the continuity setting, bit for bit.
bool same_document(const Document& a, const Document& b);

// The welcoming default scene: a shaped 5x5 bicubic NURBS surface.
Document default_document();

// A planar grid in the xy-plane the user then shapes (Surface > New): rows x cols control
// points (rows along u, cols along v) evenly spaced on [-1, 1]^2, z = 0, unit weights, clamped
// uniform knots of the given degrees on [0, 1]. Precondition: the arguments pass
// make_planar_grid_checked (asserted).
geom::Surface make_planar_grid(int rows, int cols, int degree_u, int degree_v,
                               geom::SplineType type);
// The same for user input: `degree` errors ("/degree_u", "/degree_v": degree < 1; "/rows",
// "/cols": fewer points than degree + 1, or a Bezier type whose count is not degree + 1) and
// `limit` errors ("/rows", "/cols": more than 4096 per direction or 1,000,000 in all).
geom::Expected<geom::Surface> make_planar_grid_checked(int rows, int cols, int degree_u,
                                                       int degree_v, geom::SplineType type);

} // namespace isoparm::doc
