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

// A curve is charged for the points the workstation evaluates on it at its degree, not only for
// its control points: a degree-4095 curve (108 s to render when only its 4,096 control points
// were counted) is over the budget, one of degree 3 with as many points is not.
TEST(SceneBudget, AHighDegreeCurveIsChargedForItsEvaluations) {
    auto curve_scene = [](int degree, int points) {
        doc::Document d;
        geom::Curve c;
        c.type = geom::SplineType::bspline;
        c.degree = degree;
        c.points.resize(static_cast<std::size_t>(points));
        for (int k = 0; k < points; ++k) c.points[static_cast<std::size_t>(k)] = {k, k % 2, 0};
        c.weights.assign(c.points.size(), 1.0);
        for (int k = 0; k <= degree; ++k) c.knots.push_back(0);
        for (int k = 1; k < points - degree; ++k) c.knots.push_back(k);
        for (int k = 0; k <= degree; ++k) c.knots.push_back(points - degree);
        doc::Object o;
        o.id = d.allocate_id();
        o.shape = doc::CurveObject{c};
        d.objects.push_back(o);
        return d;
    };
    const doc::Document high = curve_scene(4095, 4096);
    const std::string said = scene_over_budget(high);
    EXPECT_NE(said.find("4,096 control points"), std::string::npos) << said;
    EXPECT_NE(said.find("basis steps"), std::string::npos) << said;
    EXPECT_EQ(scene_over_budget(curve_scene(3, 4096)), "");
}

// After an import the display density is lowered until the scene fits (a 1,018-face part was
// written at 32 and then refused: "would need about 1,900 MiB"), never raised, and 0 says that
// nothing fits.
TEST(SceneBudget, TheDensityThatFitsIsTheLargestAtMostTheScenes) {
    auto grid = [](int surfaces) {
        doc::Document d;
        geom::Surface s;
        s.type = geom::SplineType::bspline;
        s.degree_u = s.degree_v = 1;
        s.n_u = s.n_v = 9;
        s.knots_u = s.knots_v = {0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 8};
        for (int i = 0; i < 9; ++i)
            for (int j = 0; j < 9; ++j) s.points.push_back({i, j, 0});
        s.weights.assign(s.points.size(), 1.0);
        for (int k = 0; k < surfaces; ++k) {
            doc::Object o;
            o.id = d.allocate_id();
            o.shape = doc::SurfaceObject{s};
            d.objects.push_back(o);
        }
        return d;
    };
    doc::Document few = grid(2);
    EXPECT_EQ(display_density_that_fits(few), few.view.display.density);
    doc::Document many = grid(1000);
    ASSERT_NE(scene_over_budget(many), "");
    const int density = display_density_that_fits(many);
    ASSERT_GT(density, 0);
    EXPECT_LT(density, many.view.display.density);
    many.view.display.density = density;
    EXPECT_EQ(scene_over_budget(many), "");
    // Twice the density that fits does not (the largest of the steps tried is taken).
    many.view.display.density = density * 2;
    EXPECT_NE(scene_over_budget(many), "");
    // 64 KiB a surface alone passes 1 GiB: nothing fits.
    EXPECT_EQ(display_density_that_fits(grid(20000)), 0);
}

} // namespace
} // namespace isoparm::ui
