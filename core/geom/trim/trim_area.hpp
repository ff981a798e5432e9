// The area of a trimmed surface: the integral of |S_u x S_v| over the kept region of the domain.
#pragma once

#include "core/geom/trim/trim.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// The kept region triangulated on a grid through every knot (each span cut in pieces, at least
// `pieces` per direction in all), the loops within 1e-9 of the domain's size, and a degree-5
// quadrature (Dunavant's 7 points) on every triangle. Untrimmed (an empty trim): the whole
// domain. Points that do not exist contribute nothing. Precondition: valid surface,
// validate_trim(trim, domain(s)) passed.
double trimmed_area(const Surface& s, const Trim& trim, int pieces = 96);

} // namespace isoparm::geom
