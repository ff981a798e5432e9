// The one label placer: no two placed labels overlap, nothing leaves the view, lower priority
// is dropped first and counted, fixed labels stay where they are asked to be.
#include <gtest/gtest.h>

#include <random>

#include "ui/view/label_placer.hpp"
#include "ui/view/picture.hpp"

using namespace isoparm::ui;

namespace {

// 7 px a character, 12 px a line: a stand-in for a font.
const MeasureText mono = [](std::string_view s) {
    return glm::vec2(7.f * static_cast<float>(s.size()), 12.f);
};

bool inside(const Rect& r, const Rect& b) {
    return r.x >= b.x && r.y >= b.y && r.x + r.w <= b.x + b.w && r.y + r.h <= b.y + b.h;
}

void expect_no_overlaps(const LabelPlacement& p, const Rect& bounds) {
    for (std::size_t a = 0; a < p.placed.size(); ++a) {
        EXPECT_TRUE(inside(p.placed[a].rect, bounds)) << "label " << a << " leaves the view";
        for (std::size_t b = a + 1; b < p.placed.size(); ++b)
            EXPECT_FALSE(rects_overlap(p.placed[a].rect, p.placed[b].rect))
                << "labels " << p.placed[a].request << " and " << p.placed[b].request;
        if (p.more) {
            EXPECT_FALSE(rects_overlap(p.placed[a].rect, *p.more));
        }
    }
    if (p.more) {
        EXPECT_TRUE(inside(*p.more, bounds));
    }
}

LabelRequest at(float x, float y, std::string text, int priority = 0) {
    LabelRequest r;
    r.anchor = {x, y};
    r.text = std::move(text);
    r.priority = priority;
    return r;
}

} // namespace

TEST(LabelPlacer, ALoneLabelSitsRightOfItsPointWithoutLeader) {
    const Rect view{0, 0, 200, 200};
    const LabelPlacement p = place_labels({at(50, 100, "P22")}, view, mono);
    ASSERT_EQ(p.placed.size(), 1u);
    const Rect r = p.placed[0].rect;
    EXPECT_FLOAT_EQ(r.x, 56); // the offset (6) to the right
    EXPECT_FLOAT_EQ(r.y + r.h / 2, 100);
    EXPECT_FALSE(p.placed[0].leader);
    EXPECT_TRUE(p.dropped.empty());
    EXPECT_FALSE(p.more);
}

TEST(LabelPlacer, ALabelAtTheRightEdgeGoesLeftRatherThanOutside) {
    const Rect view{0, 0, 100, 100};
    const LabelPlacement p = place_labels({at(98, 50, "w=0.707")}, view, mono);
    ASSERT_EQ(p.placed.size(), 1u);
    EXPECT_TRUE(inside(p.placed[0].rect, view));
    EXPECT_LT(p.placed[0].rect.x + p.placed[0].rect.w, 98.f);
}

TEST(LabelPlacer, APileOfLabelsOnOnePointSpreadsWithLeadersAndNeverOverlaps) {
    // The Homogeneous tab's blob: many weights at nearly one place.
    const Rect view{0, 0, 400, 300};
    std::vector<LabelRequest> r;
    for (int k = 0; k < 9; ++k) r.push_back(at(200.f + 0.3f * k, 150.f, "w=0.707"));
    const LabelPlacement p = place_labels(r, view, mono);
    expect_no_overlaps(p, view);
    EXPECT_EQ(p.placed.size(), 9u);
    int leaders = 0;
    for (const PlacedLabel& l : p.placed) leaders += l.leader.has_value();
    EXPECT_GT(leaders, 0) << "labels moved away from their point are joined to it";
}

TEST(LabelPlacer, WhatDoesNotFitIsDroppedLowestPriorityFirstAndCounted) {
    const Rect view{0, 0, 80, 60};
    std::vector<LabelRequest> r;
    for (int k = 0; k < 12; ++k)
        r.push_back(at(40, 30, "label" + std::to_string(k), k == 5 ? 9 : 0));
    const LabelPlacement p = place_labels(r, view, mono);
    expect_no_overlaps(p, view);
    ASSERT_FALSE(p.dropped.empty());
    ASSERT_TRUE(p.more);
    EXPECT_EQ(p.more_text, "+" + std::to_string(p.dropped.size()));
    EXPECT_EQ(p.placed.size() + p.dropped.size(), r.size());
    // The important one is placed.
    bool five = false;
    for (const PlacedLabel& l : p.placed) five |= l.request == 5;
    EXPECT_TRUE(five);
}

TEST(LabelPlacer, FixedLabelsStayAndShiftInsideTheView) {
    const Rect view{10, 10, 100, 100};
    LabelRequest axis = at(110, 110, "x");
    axis.mode = LabelMode::fixed;
    axis.align = LabelAlign::bottom_right;
    LabelRequest title = at(60, 5, "xy plane"); // above the view: shifted in
    title.mode = LabelMode::fixed;
    title.align = LabelAlign::top_center;
    const LabelPlacement p = place_labels({axis, title}, view, mono);
    ASSERT_EQ(p.placed.size(), 2u);
    const Rect& x = p.placed[0].rect;
    EXPECT_FLOAT_EQ(x.x + x.w, 110);
    EXPECT_FLOAT_EQ(x.y + x.h, 110);
    EXPECT_FLOAT_EQ(p.placed[1].rect.y, 10);
}

TEST(LabelPlacer, TwoFixedLabelsOnOneSpotKeepTheFirstAndDropTheOther) {
    // The tracing square's "0.75" and "1" that merged into "0.751".
    const Rect view{0, 0, 200, 50};
    LabelRequest a = at(100, 10, "0.75"), b = at(104, 10, "1");
    for (LabelRequest* r : {&a, &b}) {
        r->mode = LabelMode::fixed;
        r->align = LabelAlign::top_center;
    }
    b.priority = 5; // the domain's end matters more
    const LabelPlacement p = place_labels({a, b}, view, mono);
    ASSERT_EQ(p.placed.size(), 1u);
    EXPECT_EQ(p.placed[0].request, 1u);
    EXPECT_EQ(p.dropped, std::vector<std::size_t>{0});
}

TEST(LabelPlacer, LabelsKeepClearOfHandles) {
    const Rect view{0, 0, 200, 200};
    const Rect disk{54, 90, 20, 20}; // right of the point: the label goes elsewhere
    const LabelPlacement p = place_labels({at(50, 100, "P22")}, view, mono, {}, {disk});
    ASSERT_EQ(p.placed.size(), 1u);
    EXPECT_FALSE(rects_overlap(p.placed[0].rect, disk));
}

TEST(LabelPlacer, RandomCrowdsNeverOverlapOrLeave) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> xy(0, 1);
    for (int trial = 0; trial < 40; ++trial) {
        const Rect view{5, 5, 150 + 300 * xy(rng), 100 + 200 * xy(rng)};
        std::vector<LabelRequest> r;
        const int n = 5 + trial * 2;
        for (int k = 0; k < n; ++k) {
            LabelRequest q = at(view.x + view.w * xy(rng), view.y + view.h * xy(rng),
                                std::string(1 + k % 7, 'a'), k % 3);
            if (k % 5 == 0) {
                q.mode = LabelMode::fixed;
                q.align = static_cast<LabelAlign>(k % 9);
            }
            r.push_back(q);
        }
        const LabelPlacement p = place_labels(r, view, mono);
        expect_no_overlaps(p, view);
        EXPECT_EQ(p.placed.size() + p.dropped.size(), r.size());
        EXPECT_EQ(p.more.has_value(), !p.dropped.empty()) << "dropped labels are counted";
    }
}

TEST(Picture, PlacesItsLabelsInItsFrame) {
    Picture pic;
    pic.view = "test";
    pic.frame = {0, 0, 120, 80};
    pic.line({0, 0}, {120, 80}, rgba8(255, 0, 0));
    pic.label({60, 40}, "C(0.5)", rgba8(0, 0, 0));
    pic.fixed_label({120, 80}, "u", rgba8(0, 0, 0), LabelAlign::bottom_right);
    const LabelPlacement p = place(pic, mono);
    EXPECT_EQ(p.placed.size(), 2u);
    expect_no_overlaps(p, pic.frame);
    EXPECT_EQ(red_of(rgba8(1, 2, 3, 4)), 1u);
    EXPECT_EQ(alpha_of(rgba8(1, 2, 3, 4)), 4u);
}
