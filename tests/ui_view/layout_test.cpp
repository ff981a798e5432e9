// Layout maths: panels fill the window without gaps, adapt to its size, splitters move them.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>

#include "ui/view/layout.hpp"

using namespace isoparm::ui;

namespace {

LayoutInput input(float w, float h, float scale = 1) {
    LayoutInput in;
    in.width = w;
    in.height = h;
    in.top = 20;
    in.bottom = 22;
    in.scale = scale;
    in.splitter = 6;
    return in;
}

// Columns tile the width exactly; stacks tile the height exactly.
void expect_tiles(const Layout& l, const LayoutInput& in) {
    EXPECT_FLOAT_EQ(l.left[0].x, 0);
    EXPECT_FLOAT_EQ(l.left_splitter.x, l.left[0].w);
    EXPECT_FLOAT_EQ(l.center.x, l.left_splitter.x + l.left_splitter.w);
    EXPECT_FLOAT_EQ(l.right_splitter.x, l.center.x + l.center.w);
    EXPECT_FLOAT_EQ(l.right[0].x, l.right_splitter.x + l.right_splitter.w);
    EXPECT_NEAR(l.right[0].x + l.right[0].w, in.width, 1e-3);
    for (const auto* col : {&l.left, &l.right}) {
        float y = in.top;
        for (std::size_t k = 0; k < col->size(); ++k) {
            EXPECT_NEAR((*col)[k].y, y, 1e-3);
            y += (*col)[k].h + (k + 1 < col->size() ? in.splitter : 0);
        }
        EXPECT_NEAR(y, in.height - in.bottom, 1e-3);
    }
    EXPECT_FLOAT_EQ(l.center.y, in.top);
    EXPECT_NEAR(l.center.h, in.height - in.top - in.bottom, 1e-3);
}

} // namespace

TEST(Layout, DefaultWindowKeepsPreferredWidths) {
    const LayoutPrefs prefs;
    const LayoutInput in = input(1600, 1000);
    const Layout l = compute_layout(prefs, in);
    expect_tiles(l, in);
    EXPECT_FLOAT_EQ(l.left[0].w, prefs.left_width);
    EXPECT_FLOAT_EQ(l.right[0].w, prefs.right_width);
    EXPECT_EQ(l.left.size(), 2u);
    EXPECT_EQ(l.right.size(), 2u);
    EXPECT_EQ(l.left_row_splitters.size(), 1u);
}

TEST(Layout, ScaleMultipliesWidths) {
    const LayoutPrefs prefs;
    const LayoutInput in = input(3000, 1600, 1.5f);
    const Layout l = compute_layout(prefs, in);
    expect_tiles(l, in);
    EXPECT_FLOAT_EQ(l.left[0].w, prefs.left_width * 1.5f);
}

TEST(Layout, NarrowWindowShrinksSidesBeforeCentre) {
    LayoutPrefs prefs;
    prefs.left_width = 500;
    prefs.right_width = 300;
    const LayoutInput in = input(1000, 700);
    const Layout l = compute_layout(prefs, in);
    expect_tiles(l, in);
    EXPECT_NEAR(l.center.w, min_center_width, 1e-3);
    EXPECT_GE(l.left[0].w, min_side_width);
    EXPECT_GE(l.right[0].w, min_side_width);
    // The extra width above the minimum shrank in proportion (300 : 100).
    EXPECT_NEAR((l.left[0].w - min_side_width) / (l.right[0].w - min_side_width), 3.0, 1e-3);
}

TEST(Layout, TinyWindowStillTilesWithoutNegativeSizes) {
    const LayoutInput in = input(300, 200);
    const Layout l = compute_layout(LayoutPrefs{}, in);
    expect_tiles(l, in);
    for (const Rect& r : {l.center, l.left[0], l.left[1], l.right[0], l.right[1]}) {
        EXPECT_GE(r.w, 0);
        EXPECT_GE(r.h, 0);
    }
}

TEST(Layout, RowsKeepMinimumHeight) {
    LayoutPrefs prefs;
    prefs.left_shares = {0.99f, 0.01f};
    const LayoutInput in = input(1600, 1000);
    const Layout l = compute_layout(prefs, in);
    expect_tiles(l, in);
    EXPECT_NEAR(l.left[1].h, min_row_height, 1e-3);
}

TEST(Layout, ColumnSplitterFollowsTheMouse) {
    LayoutPrefs prefs;
    const LayoutInput in = input(1600, 1000);
    Layout l = compute_layout(prefs, in);
    drag_column_splitter(prefs, l, in, Side::left, 40);
    EXPECT_FLOAT_EQ(compute_layout(prefs, in).left[0].w, 370);
    l = compute_layout(prefs, in);
    drag_column_splitter(prefs, l, in, Side::right, 40); // moving right narrows the right column
    EXPECT_FLOAT_EQ(compute_layout(prefs, in).right[0].w, LayoutPrefs{}.right_width - 40);
    drag_column_splitter(prefs, compute_layout(prefs, in), in, Side::left, -1000);
    EXPECT_FLOAT_EQ(prefs.left_width, min_side_width);
}

TEST(Layout, RowSplitterTradesHeightBetweenNeighbours) {
    LayoutPrefs prefs;
    const LayoutInput in = input(1600, 1000);
    const Layout before = compute_layout(prefs, in);
    drag_row_splitter(prefs, before, in, Side::right, 0, 50);
    const Layout after = compute_layout(prefs, in);
    EXPECT_NEAR(after.right[0].h, before.right[0].h + 50, 1e-2);
    EXPECT_NEAR(after.right[1].h, before.right[1].h - 50, 1e-2);
    // Clamped at the minimum of the lower panel.
    drag_row_splitter(prefs, after, in, Side::right, 0, 5000);
    EXPECT_NEAR(compute_layout(prefs, in).right[1].h, min_row_height, 1e-2);
    // A bad index is ignored.
    const LayoutPrefs copy = prefs;
    drag_row_splitter(prefs, after, in, Side::right, 3, 10);
    EXPECT_EQ(prefs, copy);
}

TEST(Layout, SanitizeRepairsBadValues) {
    LayoutPrefs p;
    p.left_width = -5;
    p.right_width = std::nanf("");
    p.left_shares = {1, 2, 3};
    p.right_shares = {0.5f, -1};
    const LayoutPrefs s = sanitize(p);
    EXPECT_EQ(s, LayoutPrefs{});
}

TEST(Layout, CentreFractionWinsOverSideWidths) {
    LayoutInput in = input(1440, 900, 1.5f);
    in.min_center_fraction = 0.45f;
    const Layout l = compute_layout(LayoutPrefs{}, in);
    expect_tiles(l, in);
    EXPECT_NEAR(l.center.w, 0.45f * (1440 - 2 * in.splitter), 1e-2);
    EXPECT_GE(l.left[0].w, min_side_width * 1.5f);
}

TEST(Layout, SmallWindowKeepsTheCentreShareBeforeSideMinimums) {
    // A projector's 1024x768 leaves a 921x691 window; presentation scale 1.5.
    LayoutInput in = input(921, 691, 1.5f);
    in.min_center_fraction = 0.5f;
    const Layout l = compute_layout(LayoutPrefs{}, in);
    expect_tiles(l, in);
    EXPECT_NEAR(l.center.w, 0.5f * (921 - 2 * in.splitter), 1e-2);
    EXPECT_GT(l.left[0].w, 0.f);
    EXPECT_GT(l.right[0].w, l.left[0].w); // the default proportions of the columns
}

TEST(Layout, PresentationColumnsMoveWithTheirSplitters) {
    // A projector's 921 x 691 window at presentation scale: the 3D view starts at half the
    // width; dragging the left splitter right widens the left column (it used to narrow it).
    LayoutPrefs prefs;
    LayoutInput in;
    in.width = 921;
    in.height = 691;
    in.scale = 1.25f;
    in.splitter = 6;
    in.min_center_fraction = 0.5f;
    in.presentation = true;
    const Layout before = compute_layout(prefs, in);
    EXPECT_GE(before.center.w, 0.5f * (921 - 12) - 1);
    drag_column_splitter(prefs, before, in, Side::left, 80);
    const Layout after = compute_layout(prefs, in);
    EXPECT_NEAR(after.left[0].w, before.left[0].w + 80, 0.5);
    EXPECT_NEAR(after.right[0].w, before.right[0].w, 0.5);
    EXPECT_NEAR(after.center.w, before.center.w - 80, 0.5);
    // Far right: the centre keeps its minimum (on a projector, 30% of the width).
    drag_column_splitter(prefs, after, in, Side::left, 2000);
    const Layout squeezed = compute_layout(prefs, in);
    EXPECT_GE(squeezed.center.w, std::min(min_center_width * 1.25f, 0.3f * (921 - 12)) - 0.5f);
    EXPECT_GT(squeezed.left[0].w, after.left[0].w);
    // The normal mode's columns are not touched by presentation drags.
    EXPECT_FLOAT_EQ(prefs.left_width, LayoutPrefs{}.left_width);
    // Saved shares that make no sense are dropped.
    LayoutPrefs bad;
    bad.presentation_left = 0.7f;
    bad.presentation_right = 0.5f;
    EXPECT_FLOAT_EQ(sanitize(bad).presentation_left, 0);
}
