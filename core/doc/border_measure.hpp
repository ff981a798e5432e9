// How well two patches of a group actually join along a shared border, measured on the
// surfaces (not inferred from the control points): the Continuity panel's figures.
#pragma once

#include "core/doc/patches.hpp"

namespace isoparm::doc {

// Sampled at `samples` parameters along the border (both patches keep the group's parameters,
// so the two sides are evaluated at the same (u, v)); each figure is the largest over the
// samples where both sides exist:
// - gap: the distance between the two sides' points (C0 holds when it is ~0);
// - angle: between their unit normals, in degrees (G1, tangent planes agree);
// - derivative: |S_low,across - S_high,across|, the first derivatives across the border
//   (C1 holds when it is ~0; the group's parameters are shared, so no scaling is needed);
// - curvature: the jump of the mean curvature H across the border (G2 needs it ~0).
// `sampled` counts the samples where both sides had a point (0: nothing could be measured).
struct BorderMeasure {
    double gap = 0, angle_degrees = 0, derivative = 0, curvature = 0;
    int sampled = 0;
};
BorderMeasure measure_border(const Document& doc, const SharedBorder& border, int samples = 33);

// Which conditions the figures meet. Gap and derivative are lengths, held when below 1e-9 of
// `size` (a gap of 1e-12 on a unit patch is a join); the angle holds below 1e-6 degrees and
// the mean-curvature jump below 1e-6 (both already relative to nothing that scales).
struct BorderHolds {
    bool c0 = false, g1 = false, c1 = false, g2 = false;
};
BorderHolds border_holds(const BorderMeasure& m, double size);

// The best level a border shows, each needing the ones before it: what the 3D view colours it.
// `g2` means C1 with the mean curvature continuous as well.
enum class BorderLevel { broken, c0, g1, c1, g2 };
inline constexpr geom::EnumName<BorderLevel> border_level_names[] = {
    {BorderLevel::broken, "broken"},
    {BorderLevel::c0, "C0"},
    {BorderLevel::g1, "G1"},
    {BorderLevel::c1, "C1"},
    {BorderLevel::g2, "G2", "C1 + G2"},
};
static_assert(geom::in_declaration_order(border_level_names));
constexpr std::span<const geom::EnumName<BorderLevel>> enum_names(BorderLevel) {
    return border_level_names;
}
BorderLevel border_level(const BorderMeasure& m, double size);
// "broken", "C0", "G1", "C1", "C1 + G2" (label_of).
inline const char* border_level_name(BorderLevel level) {
    return geom::label_of(level);
}

// The size figures are relative to: the largest coordinate of the group's control points.
double group_size(const Document& doc, std::uint64_t group);

} // namespace isoparm::doc
