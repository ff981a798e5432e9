// The curve kind: a designed curve (the curve designer's, or one a construction takes), with
// the plane it is drawn in and the rule that chooses its knots, and every fact the document
// asks of it (kind_facts.hpp).
#pragma once

#include <array>

#include "core/doc/kinds/kind_facts.hpp"

namespace isoparm::doc {

// Which plane a designed curve lives in (the curve designer edits it there).
enum class CurvePlane { xy, xz, yz, free3d };
inline constexpr geom::EnumName<CurvePlane> curve_plane_names[] = {
    {CurvePlane::xy, "xy"},
    {CurvePlane::xz, "xz"},
    {CurvePlane::yz, "yz"},
    {CurvePlane::free3d, "free3d", "3D"},
};
static_assert(geom::in_declaration_order(curve_plane_names));
constexpr std::span<const geom::EnumName<CurvePlane>> enum_names(CurvePlane) {
    return curve_plane_names;
}

// How the curve designer chooses the knots when control points are inserted or deleted or
// the degree changes (docs/constructions.md): clamped uniform, averaged from the chord /
// centripetal parameters of the control polygon (Piegl & Tiller eq. 9.8), or custom: the
// user's own knots, kept as they are and dragged with set_knot.
// closed: DesignMentor's third mode, the periodic curve of the polygon (geom::close_periodic):
// the stored curve holds the polygon's n points and then its first p again.
enum class CurveKnotMode { clamped_uniform, chord, centripetal, custom, closed };
inline constexpr geom::EnumName<CurveKnotMode> curve_knot_mode_names[] = {
    {CurveKnotMode::clamped_uniform, "clamped_uniform", "clamped uniform"},
    {CurveKnotMode::chord, "chord", "chord length"},
    {CurveKnotMode::centripetal, "centripetal"},
    {CurveKnotMode::custom, "custom"},
    {CurveKnotMode::closed, "closed", "closed (periodic)"},
};
static_assert(geom::in_declaration_order(curve_knot_mode_names));
constexpr std::span<const geom::EnumName<CurveKnotMode>> enum_names(CurveKnotMode) {
    return curve_knot_mode_names;
}

struct CurveObject {
    geom::Curve curve;
    CurvePlane plane = CurvePlane::xy;
    // Custom by default, so curves from old scenes and constructions keep their knots.
    CurveKnotMode knot_mode = CurveKnotMode::custom;

    static constexpr ObjectKind kind = ObjectKind::curve;
    static constexpr std::array<std::string_view, 3> shape_members{"plane", "knot_mode", "curve"};
    static constexpr bool in_patch_groups = false;
    static constexpr bool constructed = true; // a recipe builds curves (isocurves)
};

ISOPARM_KIND_FACTS(CurveObject);

} // namespace isoparm::doc
