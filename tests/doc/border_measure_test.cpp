// Border continuity measured on the surfaces: a split keeps every figure at zero, and a point
// moved with continuity off opens the gap the panel then shows.
#include <gtest/gtest.h>

#include "core/doc/border_measure.hpp"
#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::doc::testing;

namespace {

TEST(BorderMeasure, ASplitJoinsExactlyAndAMovedPointOpensTheGap) {
    Document doc = sample_document();
    History h;
    ASSERT_TRUE(h.execute(doc, split_object(hill_id, geom::Dir::u, 0.5)).ok());
    const std::uint64_t group = doc.objects[0].patch_group;
    auto borders = shared_borders(doc, group);
    ASSERT_EQ(borders.size(), 1u);
    BorderMeasure m = measure_border(doc, borders[0]);
    EXPECT_EQ(m.sampled, 33);
    EXPECT_LT(m.gap, 1e-12);
    EXPECT_LT(m.angle_degrees, 1e-9);
    EXPECT_LT(m.derivative, 1e-10);
    EXPECT_LT(m.curvature, 1e-8);
    const double size = group_size(doc, group);
    EXPECT_GT(size, 0.5);
    EXPECT_EQ(border_level(m, size), BorderLevel::g2); // a split is as smooth as the surface
    // Continuity off: the border row moves on one side only.
    doc.continuity = Continuity::off;
    const std::uint64_t left = borders[0].low;
    const geom::Surface& s = *doc.find(left)->surface();
    const int last = s.n_u - 1;
    ASSERT_TRUE(
        h.execute(doc, move_control_point(left, last, 2, s.point(last, 2) + glm::dvec3(0, 0, 0.5)))
            .ok());
    m = measure_border(doc, shared_borders(doc, group)[0]);
    EXPECT_GT(m.gap, 0.1);
    EXPECT_GT(m.angle_degrees, 1);
    EXPECT_EQ(border_level(m, size), BorderLevel::broken);
}

TEST(BorderMeasure, LevelsNeedTheOnesBelowThem) {
    BorderMeasure m;
    EXPECT_EQ(border_level(m, 1), BorderLevel::broken); // nothing sampled, nothing shown
    m.sampled = 5;
    EXPECT_EQ(border_level(m, 1), BorderLevel::g2);
    m.curvature = 0.3;
    EXPECT_EQ(border_level(m, 1), BorderLevel::c1);
    m.derivative = 0.2; // tangent planes agree, derivatives differ: G1 only
    EXPECT_EQ(border_level(m, 1), BorderLevel::g1);
    EXPECT_EQ(border_level(m, 1e9), BorderLevel::c1); // 0.2 is nothing on a huge group
    m.angle_degrees = 2;
    EXPECT_EQ(border_level(m, 1), BorderLevel::c0);
    m.gap = 1e-6;
    EXPECT_EQ(border_level(m, 1), BorderLevel::broken);
    EXPECT_STREQ(border_level_name(BorderLevel::g1), "G1");
}

} // namespace
