// The display budget counts surfaces, their displayed vertices and every control point.
#include <gtest/gtest.h>

#include "ui/view/scene_budget.hpp"

namespace isoparm::ui {
namespace {

TEST(SceneBudget, TheDefaultSceneFitsAndIsCounted) {
    doc::Document d = doc::default_document();
    const SceneDisplayCost one = estimate_scene_display(d);
    EXPECT_EQ(one.surfaces, 1);
    EXPECT_EQ(one.control_points, 25);
    EXPECT_GT(one.vertices, 0);
    EXPECT_EQ(scene_over_budget(d), "");
    // A curve adds its control points, no vertices.
    doc::Object c;
    c.id = d.allocate_id();
    c.shape = doc::CurveObject{
        geom::Curve{geom::SplineType::bspline, 1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}}, {1, 1}}};
    d.objects.push_back(c);
    const SceneDisplayCost two = estimate_scene_display(d);
    EXPECT_EQ(two.surfaces, 1);
    EXPECT_EQ(two.control_points, 27);
    EXPECT_EQ(two.vertices, one.vertices);
}

} // namespace
} // namespace isoparm::ui
