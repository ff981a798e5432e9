// De Boor's construction one step at a time: what each step of a bicubic patch shows.
#include <gtest/gtest.h>

#include "ui/view/deboor_overlay.hpp"

namespace isoparm::ui {
namespace {

TEST(DeBoorSteps, ControlPointsThenTheUStageThenTheVStage) {
    EXPECT_EQ(deboor_step_info(0, 3, 3).text, "the control points P_ij that act at (u, v)");
    const DeBoorStepInfo u2 = deboor_step_info(2, 3, 3);
    EXPECT_TRUE(u2.u_stage);
    EXPECT_EQ(u2.level, 2);
    EXPECT_EQ(u2.text, "u-stage, level 2 of 3: every row curve's level 2 at u");
    const DeBoorStepInfo column = deboor_step_info(4, 3, 3);
    EXPECT_FALSE(column.u_stage);
    EXPECT_EQ(column.level, 0);
    const DeBoorStepInfo v2 = deboor_step_info(6, 3, 3);
    EXPECT_EQ(v2.text, "v-stage, level 2 of 3 at v");
    EXPECT_EQ(deboor_step_info(7, 3, 3).text, "S(u, v): the last level of the v-stage");
    EXPECT_EQ(deboor_step_info(-1, 3, 3).text, "all levels");
}

TEST(DeBoorSteps, PointNamesMatchTheDeBoorTab) {
    EXPECT_EQ(deboor_point_name(true, 0, 2, 3), "P2,3");
    EXPECT_EQ(deboor_point_name(true, 2, 4, 1), "d^2_4,1");
    EXPECT_EQ(deboor_point_name(false, 0, 3, -1), "Q3");
    EXPECT_EQ(deboor_point_name(false, 1, 5, -1), "d^1_5");
}

TEST(DeBoorSteps, TheStagesHaveTheirOwnColours) {
    EXPECT_NE(deboor_level_color(true, 1), deboor_level_color(false, 1));
    EXPECT_NE(deboor_level_color(true, 1), deboor_level_color(true, 2));
}

} // namespace
} // namespace isoparm::ui
