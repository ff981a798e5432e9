// A knot run dragged between its neighbours (see knot_drag.hpp).
#include "ui/view/knot_drag.hpp"

#include <algorithm>

#include "ui/view/canvas_map.hpp"

namespace isoparm::ui {

bool is_inner_knot_run(const geom::Knots& U, int first, int count) {
    const int knot_count = static_cast<int>(U.size());
    bool still = first >= 1 && first + count < knot_count;
    for (int q = first; still && q < first + count; ++q) still = U[q] == U[first];
    if (still) still = U[first - 1] < U[first] && U[first] < U[first + count];
    return still;
}

double dragged_knot_value(const geom::Knots& U, int first, int count, const geom::Interval& range,
                          double fraction) {
    const double lo = U[first - 1], hi = U[first + count];
    const double eps = (hi - lo) * 1e-3;
    return std::clamp(denormalize_param(range, fraction), lo + eps, hi - eps);
}

} // namespace isoparm::ui
