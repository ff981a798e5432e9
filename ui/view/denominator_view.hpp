// What the tracing square shows of a rational surface's denominator w(u, v): its sign on a
// grid of cells and its zero set (where the surface goes to infinity), kept until the weights,
// knots or degrees change. w does not depend on the control points' positions, so dragging a
// point never recomputes it.
#pragma once

#include <vector>

#include "core/geom/rational_picture.hpp"
#include "core/geom/types.hpp"

namespace isoparm::ui {

class DenominatorView {
public:
    static constexpr int sign_cells = 48; // per direction
    static constexpr int zero_set_cells = 64;

    // Recomputes only when s's denominator differs from the one shown (weights, knots,
    // degrees, counts or type); true when it did.
    bool update(const geom::Surface& s);

    // geom::denominator_signs over the surface's domain, u-major, sign_cells^2 entries.
    const std::vector<signed char>& signs() const { return signs_; }
    const std::vector<geom::ParamSegment>& zero_set() const { return zero_set_; }
    bool has_negative() const { return negative_; }

private:
    bool same_denominator(const geom::Surface& s) const;

    bool valid_ = false;
    geom::Surface key_; // the denominator's data only: points are left empty
    std::vector<signed char> signs_;
    std::vector<geom::ParamSegment> zero_set_;
    bool negative_ = false;
};

} // namespace isoparm::ui
