// Blossoms (polar forms) of curve and surface pieces: the arguments of every de Boor point.
#pragma once

#include <optional>
#include <vector>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// The piece a blossom is taken on: by default the span holding `t` by the right-limit rule
// (find_span), with t first brought into the domain (an argument beyond either end names the
// first or last piece).
int default_blossom_span(const Knots& U, int p, int n, double t);
// `schema` at `path` unless p <= span <= n - 1 and [U[span], U[span+1]) is not empty.
Status check_blossom_span(const Knots& U, int p, int n, int span, const std::string& path);

// f(args) on the piece `span`, in homogeneous space (rational pieces too): the Cartesian point,
// or nullopt where its weight is zero. Preconditions: args.size() == degree, span checked.
std::optional<glm::dvec3> curve_blossom(const Curve& c, int span, const std::vector<double>& args);
// The tensor-product blossom f(u_args; v_args) on the piece (span_u, span_v): each column's
// u-blossom, then the v-blossom of those.
std::optional<glm::dvec3> surface_blossom(const Surface& s, int span_u, int span_v,
                                          const std::vector<double>& u_args,
                                          const std::vector<double>& v_args);

// The blossom arguments of a point of de Boor's triangle at t (deboor.hpp's indexing: level k,
// index i = first_index + position + k, the span's triangle): d^k_i = f(t, ..., t, U[i+1], ...,
// U[i+p-k]) with t repeated k times (Ramshaw's labelling; Farin ch. 4). Level 0 is the
// control point f(U[i+1], ..., U[i+p]); level p is f(t, ..., t), the curve point. Each step
// of de Boor's algorithm replaces one knot argument by t (multi-affinity).
std::vector<double> deboor_point_arguments(const Knots& U, int p, int level, int index, double t);

} // namespace isoparm::geom
