// The tracing square's denominator picture: recomputed when w changes, never for a point drag.
#include <gtest/gtest.h>

#include "core/doc/placement.hpp"
#include "ui/view/denominator_view.hpp"

using namespace isoparm;
using namespace isoparm::ui;

TEST(DenominatorView, RecomputesForWeightsNotForPoints) {
    geom::Surface s = doc::make_planar_grid(4, 4, 2, 2, geom::SplineType::nurbs);
    DenominatorView view;
    EXPECT_TRUE(view.update(s));
    EXPECT_FALSE(view.has_negative());
    EXPECT_TRUE(view.zero_set().empty());
    EXPECT_EQ(view.signs().size(),
              static_cast<std::size_t>(DenominatorView::sign_cells * DenominatorView::sign_cells));
    s.point(1, 2).z += 3; // w does not read the points
    EXPECT_FALSE(view.update(s));
    // A negative corner weight: w changes sign near that corner and a zero set appears.
    s.weight(3, 3) = -4;
    EXPECT_TRUE(view.update(s));
    EXPECT_TRUE(view.has_negative());
    EXPECT_FALSE(view.zero_set().empty());
    for (const geom::ParamSegment& seg : view.zero_set())
        EXPECT_LT(std::abs(geom::surface_denominator(s, seg.a.x, seg.a.y)), 1e-13);
    EXPECT_FALSE(view.update(s));
}
