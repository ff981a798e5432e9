// Window placement: fits the work area, remembers per monitor size, never off-screen.
#include <gtest/gtest.h>

#include "ui/view/window_placement.hpp"

using namespace isoparm::ui;

TEST(WindowPlacement, FirstWindowOnASmallScreenTakesAtMostNinetyPercent) {
    const ScreenRect projector{0, 0, 1024, 768};
    const ScreenRect r = place_window(projector, {});
    EXPECT_LE(r.width, 0.9 * 1024);
    EXPECT_LE(r.height, 0.9 * 768);
    EXPECT_GE(r.x, 0);
    EXPECT_GE(r.y, 0);
    EXPECT_LE(r.x + r.width, 1024);
    EXPECT_LE(r.y + r.height, 768);
}

TEST(WindowPlacement, FirstWindowOnALargeScreenHasTheDefaultSizeCentred) {
    const ScreenRect area{0, 30, 1920, 1050}; // a panel takes the top 30 px
    const ScreenRect r = place_window(area, {});
    EXPECT_EQ(r.width, default_window_width);
    EXPECT_EQ(r.height, default_window_height);
    EXPECT_EQ(r.x, (1920 - default_window_width) / 2);
    EXPECT_EQ(r.y, 30 + (1050 - default_window_height) / 2);
}

TEST(WindowPlacement, RemembersTheSizePerWorkAreaAndClampsItToTheArea) {
    WindowSizes kept;
    kept[work_area_key({0, 0, 1920, 1080})] = {1800, 1000};
    kept[work_area_key({0, 0, 1024, 768})] = {3000, 2000}; // maximised once elsewhere
    EXPECT_EQ(place_window({0, 0, 1920, 1080}, kept), (ScreenRect{60, 40, 1800, 1000}));
    EXPECT_EQ(place_window({0, 0, 1024, 768}, kept), (ScreenRect{0, 0, 1024, 768}));
    // A monitor of another size starts from the default, not from either kept size.
    EXPECT_EQ(place_window({0, 0, 2560, 1440}, kept).width, default_window_width);
}

TEST(WindowPlacement, SecondMonitorOffsetIsKept) {
    const ScreenRect right{1920, 0, 1280, 1024};
    const ScreenRect r = place_window(right, {});
    EXPECT_GE(r.x, 1920);
    EXPECT_LE(r.x + r.width, 1920 + 1280);
}
