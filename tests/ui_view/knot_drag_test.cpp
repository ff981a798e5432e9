// A knot run dragged on the tracing panel's strip stays strictly between its neighbours.
#include <gtest/gtest.h>

#include "ui/view/knot_drag.hpp"

namespace isoparm::ui {
namespace {

const geom::Knots U{0, 0, 0, 0, 0.25, 0.5, 0.5, 0.75, 1, 1, 1, 1};

TEST(KnotDrag, ARunIsInnerWhileItsCopiesAreEqualAndItsNeighboursDiffer) {
    EXPECT_TRUE(is_inner_knot_run(U, 4, 1));
    EXPECT_TRUE(is_inner_knot_run(U, 5, 2));
    EXPECT_FALSE(is_inner_knot_run(U, 5, 1));  // the next knot equals it: not the whole run
    EXPECT_FALSE(is_inner_knot_run(U, 3, 1));  // 0 is a domain end with equal neighbours
    EXPECT_FALSE(is_inner_knot_run(U, 0, 1));  // no knot before it
    EXPECT_FALSE(is_inner_knot_run(U, 10, 2)); // no knot after it
    EXPECT_FALSE(is_inner_knot_run(U, 4, 2));  // 0.25 and 0.5 are not one run
}

TEST(KnotDrag, ThePointerPicksTheValueKeptOffTheNeighbours) {
    const geom::Interval domain{0, 1};
    EXPECT_DOUBLE_EQ(dragged_knot_value(U, 5, 2, domain, 0.6), 0.6);
    // Past a neighbour: a thousandth of the gap short of it.
    EXPECT_DOUBLE_EQ(dragged_knot_value(U, 5, 2, domain, 0.9), 0.75 - 0.5 * 1e-3);
    EXPECT_DOUBLE_EQ(dragged_knot_value(U, 5, 2, domain, -3.0), 0.25 + 0.5 * 1e-3);
    // The fraction is of the whole square's range (a patch group's domain).
    EXPECT_DOUBLE_EQ(dragged_knot_value(U, 4, 1, {0, 0.5}, 0.6), 0.3);
}

} // namespace
} // namespace isoparm::ui
