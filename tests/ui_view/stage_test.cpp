// The stage's names, the four-view cells and a staged canvas's zoom and pan.
#include <gtest/gtest.h>

#include "ui/view/stage.hpp"

using namespace isoparm::ui;

TEST(Stage, EveryViewHasAUniqueNameThatReadsBack) {
    for (const StageViewInfo& i : stage_views) {
        ASSERT_TRUE(stage_view_named(i.name));
        EXPECT_EQ(*stage_view_named(i.name), i.view);
        EXPECT_EQ(stage_info(i.view), &i);
    }
    EXPECT_FALSE(stage_view_named("tracing-square"));
    EXPECT_EQ(stage_view_names().substr(0, 15), "tracing, basis,");
    EXPECT_EQ(stage_plane(StageView::plane_xz), 1);
    EXPECT_EQ(stage_plane(StageView::tracing), -1);
}

TEST(Stage, FourViewsAreEqualAndFillTheArea) {
    const Rect area{0, 30, 921, 631};
    const FourViews f = four_view_cells(area, 4);
    EXPECT_FLOAT_EQ(f.xy.w, f.view3d.w);
    EXPECT_FLOAT_EQ(f.xz.h, f.xy.h);
    EXPECT_FLOAT_EQ(f.yz.x + f.yz.w, 921);
    EXPECT_FLOAT_EQ(f.yz.y + f.yz.h, 661);
    EXPECT_FLOAT_EQ(f.view3d.x, f.xy.x + f.xy.w + 4);
}

TEST(Stage, ZoomKeepsThePointUnderThePointer) {
    const Rect canvas{100, 50, 400, 300};
    CanvasView v;
    const glm::dvec2 fitted(180, 120);
    const glm::dvec2 before = view_pixel(v, canvas, fitted);
    zoom_at(v, canvas, before, 2.5);
    const glm::dvec2 after = view_pixel(v, canvas, fitted);
    EXPECT_NEAR(after.x, before.x, 1e-9);
    EXPECT_NEAR(after.y, before.y, 1e-9);
    EXPECT_DOUBLE_EQ(v.zoom, 2.5);
    zoom_at(v, canvas, {0, 0}, 1e6);
    EXPECT_DOUBLE_EQ(v.zoom, canvas_zoom_max);
}

TEST(Stage, PlaneMapThroughTheViewMatchesThePixelTransform) {
    const Rect canvas{10, 20, 300, 200};
    const PlaneMap fitted = fit_plane(canvas, {-1, -1}, {1, 1}, 10);
    CanvasView v{3.0, {25, -40}};
    const PlaneMap m = view_map(v, fitted);
    for (const glm::dvec2 ab : {glm::dvec2(0, 0), glm::dvec2(0.5, -0.25), glm::dvec2(-1, 1)}) {
        const glm::dvec2 want = view_pixel(v, canvas, plane_to_pixel(fitted, ab));
        const glm::dvec2 got = plane_to_pixel(m, ab);
        EXPECT_NEAR(got.x, want.x, 1e-9);
        EXPECT_NEAR(got.y, want.y, 1e-9);
    }
    const Rect sq = view_rect(v, canvas, {60, 30, 100, 100});
    const glm::dvec2 lo = view_pixel(v, canvas, {60, 30});
    EXPECT_NEAR(sq.x, lo.x, 1e-4);
    EXPECT_NEAR(sq.w, 300, 1e-4);
}
