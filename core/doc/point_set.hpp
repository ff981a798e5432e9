// Sets of control points of one object (a selection of many points) and the maps they are
// moved by: rows, columns and all, the centroid, affine maps about a pivot with exact
// quarter turns, mirrors, and the mirror partner that symmetric editing moves along.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include "core/doc/document.hpp"

namespace isoparm::doc {

// A control point as a selection names it: a surface's P_ij, a curve's P_i (j = -1), a
// triangle's b_ijk (k = n - i - j).
struct PointIndex {
    int i = 0, j = -1;
    bool operator==(const PointIndex&) const = default;
    auto operator<=>(const PointIndex&) const = default;
};

// Every control point of the shape, in its own order (none for an implicit surface).
std::vector<PointIndex> all_points(const Shape& shape);
// A surface's row i (P_i0 .. P_i,n_v-1: the points along v at one u index) and column j
// (P_0j .. P_n_u-1,j); a curve's row is all its points. Empty where the index is outside.
std::vector<PointIndex> row_points(const Shape& shape, int i);
std::vector<PointIndex> column_points(const Shape& shape, int j);
// The position of point p (which has_control_point says the shape has).
glm::dvec3 position_of(const Shape& shape, PointIndex p);
// The mean of the points' positions (the pivot a selection turns and scales about).
glm::dvec3 centroid(const Shape& shape, const std::vector<PointIndex>& points);

// Affine maps for a selection. `m` about `pivot`: T(pivot) m T(-pivot).
glm::dmat4 about(const glm::dmat4& m, const glm::dvec3& pivot);
glm::dmat4 translation(const glm::dvec3& d);
glm::dmat4 scaling(const glm::dvec3& factors);
// A turn by `degrees` about coordinate axis `axis` (0 x, 1 y, 2 z), counter-clockwise seen
// from the axis's positive end; multiples of 90 degrees are exact (0, 1 and -1, no 6e-17).
glm::dmat4 rotation(int axis, double degrees);
// The mirror in the plane through the origin perpendicular to `axis` (x -> -x for axis 0).
glm::dmat4 mirror(int axis);
// The point m maps p to.
glm::dvec3 apply_affine(const glm::dmat4& m, const glm::dvec3& p);

// Symmetric editing about the plane coordinate `axis` = 0: the control point whose position is
// p's mirror image (within `tolerance`, relative to the net's size; the nearest if several),
// which is p itself for a point on the plane. None when the net is not symmetric there.
std::optional<PointIndex> mirror_partner(const Shape& shape, PointIndex p, int axis,
                                         double tolerance = 1e-9);

// A move made symmetric about the plane coordinate `axis` = 0: each moved point's mirror
// partner (found before the move) goes to the mirror image of the point's new position, and a
// point on the plane (its own partner) stays on it (that coordinate 0). Partners already in
// the move keep their own positions; points without a partner move alone. The points and
// positions to give move_points.
struct SymmetricMove {
    std::vector<PointIndex> points;
    std::vector<glm::dvec3> positions;
    int partners = 0; // how many mirror partners were added
};
SymmetricMove symmetric_move(const Shape& shape, const std::vector<PointIndex>& points,
                             const std::vector<glm::dvec3>& positions, int axis,
                             double tolerance = 1e-9);

} // namespace isoparm::doc
