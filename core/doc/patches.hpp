// Subpatches that keep sharing their original domain: the group's domain, which
// patch holds a parameter, the borders patches share, and continuity kept across them.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/doc/document.hpp"
#include "core/geom/status.hpp"

namespace isoparm::doc {

// The surfaces of group `group`, in document order.
std::vector<const Object*> patch_members(const Document& doc, std::uint64_t group);

// The rectangle the tracing square shows for a surface object: the box its group's patches
// tile (the original surface's domain), or the surface's own domain outside a group.
geom::ParamRect tracing_domain(const Document& doc, const Object& surface_object);

// The patch of `group` whose domain holds (u, v) (group parameters). On a border shared by
// several patches `prefer` wins when it is one of them (so the current patch does not flicker
// while the indicator runs along a border), else the first in document order. 0: none.
std::uint64_t patch_at(const Document& doc, std::uint64_t group, glm::dvec2 uv,
                       std::uint64_t prefer = 0);

// A scene's groups hold surfaces only (error `schema` at "/objects/<k>/patch_group"). Domains
// that overlap (a hand-edited file) are allowed: the first patch in document order holds the
// shared part for the indicator, and a scene the workstation wrote always loads back.
std::optional<geom::Error> check_patch_groups(const Document& doc);

// Two patches of a group that touch: `low`'s high end in direction `across` meets `high`'s
// low end, over `along` (parameters of the other direction).
struct SharedBorder {
    std::uint64_t low = 0, high = 0;
    geom::Dir across = geom::Dir::u;
    geom::Interval along;
    // The border curves have the same degree and knots over `along` (each side's knots at
    // the ends of `along` reach the degree), so the border's control points pair up one to
    // one and C0 can be kept exactly. Otherwise `why_not` says what differs.
    bool conforming = false;
    // Both sides are clamped at the border, so C1 across it is a condition on one more row.
    bool c1_possible = false;
    std::string why_not;
    // The first control point index along the border on each side, and how many pair up.
    int low_first = 0, high_first = 0, count = 0;
};
std::vector<SharedBorder> shared_borders(const Document& doc, std::uint64_t group);

// A knot to insert (shape unchanged) into patch `object` along `dir`, `times` more copies.
struct KnotInsertion {
    std::uint64_t object = 0;
    geom::Dir dir = geom::Dir::u;
    double t = 0;
    int times = 1;
};

// The knot insertions that make the group's borders pair up control point for control point
// (SharedBorder::conforming), for the borders `wanted` accepts (all when empty): along each
// border both sides get every knot either side has inside it, to the larger multiplicity, and
// the border's ends to multiplicity p where they lie inside a side's domain (Boehm insertion,
// Piegl & Tiller A5.1 / A5.4: the shape does not change). Borders whose degrees along differ,
// or whose ends are unclamped domain ends of a side, cannot be fixed this way and are left out.
// One round: inserting may make another border of a refined patch need knots, so callers
// repeat until the answer is empty (it ends: only knots already in the group are inserted, up
// to the degree). At most one entry per (object, dir, t).
std::vector<KnotInsertion>
conforming_insertions(const Document& doc, std::uint64_t group,
                      const std::function<bool(const SharedBorder&)>& wanted = {});

// A control point's previous state, to restore on undo.
struct PointChange {
    std::uint64_t object = 0;
    int i = 0, j = 0;
    glm::dvec3 position{0};
    double weight = 1;
};

// After control point (i, j) of surface `id` changed (position or weight), moves the
// neighbouring patches' points so that the borders stay closed (C0: the border points
// coincide, weights included) and, for C1, the cross-border derivatives agree (in
// homogeneous space, the condition of Piegl & Tiller eq. 5.26 on the two rows at the join:
// Q_B1 = Q_0 + (p_A dB) / (p_B dA) (Q_0 - Q_A1)). Changes spread to the neighbours'
// neighbours (a corner shared by four patches), each patch adjusted once. Returns the
// previous values of every point it changed, in the order changed; nothing outside a group
// or with Continuity::off. Borders that do not conform are left alone.
std::vector<PointChange> keep_continuity(Document& doc, std::uint64_t id, int i, int j,
                                         Continuity mode);

// Restores points recorded by keep_continuity (latest first).
void restore_points(Document& doc, const std::vector<PointChange>& changes);

// Whether the group's conforming borders hold continuity `mode` within `tolerance` (relative
// to the control net's size): border points coincide (C0) and the C1 rows agree. For tests and
// the control panel's status line.
bool continuity_holds(const Document& doc, std::uint64_t group, Continuity mode,
                      double tolerance = 1e-12);

} // namespace isoparm::doc
