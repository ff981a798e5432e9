// Dragging a knot on the tracing panel's tick strip, without a window: whether the run held
// is still there after other edits, and where the pointer puts it.
#pragma once

#include "core/geom/types.hpp"

namespace isoparm::ui {

// Whether knots U[first .. first + count - 1] are still one run of equal values with a
// smaller knot before and a larger one after (an insertion, elevation or undo during the
// drag may have changed the vector; then the drag ends).
bool is_inner_knot_run(const geom::Knots& U, int first, int count);

// The value a dragged run takes for the pointer at `fraction` of the tracing square along the
// run's direction (0 at the domain's low end, 1 at the high end of `range`): the pointer's
// parameter, kept a thousandth of the gap away from the neighbouring knots so the knot stays
// strictly between them and the move is never refused. Precondition: is_inner_knot_run.
double dragged_knot_value(const geom::Knots& U, int first, int count, const geom::Interval& range,
                          double fraction);

} // namespace isoparm::ui
