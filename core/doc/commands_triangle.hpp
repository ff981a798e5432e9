// Triangular Bezier patches in the document (the paper's future work; Farin ch. 17): a new
// patch, and the split at the indicator. Degree elevation is elevate_degree (commands.hpp),
// which takes triangles too; control points and weights are edit_point's (b_ijk as (i, j)).
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "core/doc/command.hpp"
#include "core/doc/command_spec.hpp"

namespace isoparm::doc {

// A flat triangle to shape (Surface > New triangular patch): b_ijk = (i A + j B + k C) / n
// over the corners A = (1, -1, 0), B = (0, 1, 0)... (an equilateral-looking triangle about the
// origin), unit weights. `degree` errors at "/degree" below 1 or above 20 (a net one can still
// see and pick; the protocol takes larger ones).
geom::Expected<geom::TrianglePatch> make_flat_triangle(int degree, bool rational);
constexpr int max_new_triangle_degree = 20;

// Replaces the triangle with the three patches meeting at `at` (geom::split_triangle; names
// "<name>.1" .. ".3", fresh ids, in the original's place; piece v has the point in place of
// vertex v). Refusals: not a triangle ("/id"), `at` not barycentric or not strictly inside
// ("/param/k", "/param"), a level point at infinity ("weights"). The selected control point
// follows into the piece whose domain holds it.
std::unique_ptr<Command> split_triangle(std::uint64_t id, geom::Barycentric at);
// The pieces' ids after a split_triangle applied (zeros before, or for another command).
std::array<std::uint64_t, 3> split_triangle_ids(const Command& split_command);

// Where control point (i, j) of a degree-n triangle sits in the domain: (i, j, n - i - j) / n.
geom::Barycentric control_point_domain(int n, int i, int j);
// The control point (i, j) of a degree-m triangle nearest to the domain point `q`.
std::pair<int, int> nearest_control_point(int m, const geom::Barycentric& q);

} // namespace isoparm::doc
