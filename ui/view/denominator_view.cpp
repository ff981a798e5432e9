// The tracing square's picture of w(u, v), cached by the data w depends on (see the header).
#include "ui/view/denominator_view.hpp"

#include <algorithm>

namespace isoparm::ui {

bool DenominatorView::same_denominator(const geom::Surface& s) const {
    return valid_ && s.type == key_.type && s.degree_u == key_.degree_u &&
           s.degree_v == key_.degree_v && s.n_u == key_.n_u && s.n_v == key_.n_v &&
           s.knots_u == key_.knots_u && s.knots_v == key_.knots_v && s.weights == key_.weights;
}

bool DenominatorView::update(const geom::Surface& s) {
    if (same_denominator(s)) return false;
    signs_ = geom::denominator_signs(s, sign_cells);
    zero_set_ = geom::denominator_zero_set(s, zero_set_cells);
    key_ = s;
    key_.points.clear(); // the key holds what w depends on, not the points
    negative_ = std::any_of(signs_.begin(), signs_.end(), [](signed char c) { return c < 0; });
    valid_ = true;
    return true;
}

} // namespace isoparm::ui
