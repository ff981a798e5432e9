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

} // namespace isoparm::geom
