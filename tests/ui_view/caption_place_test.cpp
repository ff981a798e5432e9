// The caption box never covers the stop's point, and keeps off its object where the view has
// room; the focus is where the 3D view draws the selected point and the object.
#include <gtest/gtest.h>

#include "ui/view/caption_place.hpp"

namespace isoparm::ui {
namespace {

const Rect view{100, 50, 800, 600};

TEST(CaptionPlace, TopCentreWhenNothingIsThere) {
    const Rect r = place_caption(view, 400, 100, {}, 10);
    EXPECT_FLOAT_EQ(r.x, 100 + 10 + (800 - 20 - 400) / 2.f);
    EXPECT_FLOAT_EQ(r.y, 60);
}

TEST(CaptionPlace, ThePointIsNeverCoveredAndTheObjectAvoidedWhereThereIsRoom) {
    CaptionFocus f;
    // A point right where the box would go, and an object filling the upper half.
    f.points.push_back({490, 80, 24, 24});
    f.objects.push_back({150, 60, 700, 280});
    const Rect r = place_caption(view, 400, 100, f, 10);
    EXPECT_FALSE(overlaps(r, f.points[0]));
    EXPECT_FALSE(overlaps(r, f.objects[0]));
    // The object fills the whole view: covered it must be, the point still not.
    f.objects = {{100, 50, 800, 600}};
    for (float px : {150.f, 480.f, 800.f})
        for (float py : {70.f, 330.f, 600.f}) {
            f.points = {{px, py, 24, 24}};
            const Rect s = place_caption(view, 400, 120, f, 10);
            EXPECT_FALSE(overlaps(s, f.points[0])) << px << " " << py;
            EXPECT_GE(s.x, view.x);
            EXPECT_LE(s.x + s.w, view.x + view.w);
            EXPECT_LE(s.y + s.h, view.y + view.h);
        }
}

TEST(CaptionPlace, TheFocusIsTheSelectedPointAndObjectOnScreen) {
    doc::Document d = doc::default_document(); // P2,2 of the hill selected
    d.view.display.indicator_point = false;
    d.view.display.deboor = false;
    Camera cam;
    fit_to_points(cam, focus_points(d), view.w / view.h);
    const CaptionFocus f = caption_focus(d, cam, view, 12);
    ASSERT_EQ(f.points.size(), 1u);
    ASSERT_EQ(f.objects.size(), 1u);
    // P2,2 (above the hill's top: a control point need not lie on its surface) and the hill's
    // screen box, both inside the view; the point above the box's middle.
    const Rect& p = f.points[0];
    const Rect& o = f.objects[0];
    EXPECT_TRUE(view.contains(p.x + 12, p.y + 12));
    EXPECT_TRUE(view.contains(o.x, o.y));
    EXPECT_TRUE(view.contains(o.x + o.w, o.y + o.h));
    EXPECT_GT(o.w, 100);
    EXPECT_LT(p.y + 12, o.y + o.h / 2);
    // With the indicator's point shown, it is a point to avoid too.
    d.view.display.indicator_point = true;
    EXPECT_EQ(caption_focus(d, cam, view, 12).points.size(), 2u);
    // Nothing selected: every visible object is the focus, and no point.
    d.view.selection = {};
    d.view.display.indicator_point = false;
    const CaptionFocus all = caption_focus(d, cam, view, 12);
    EXPECT_TRUE(all.points.empty());
    EXPECT_EQ(all.objects.size(), 1u);
}

TEST(CaptionPlace, WithoutRoomBesideTheObjectTheCameraMovesItFromUnderTheBox) {
    doc::Document d = doc::default_document();
    Camera cam;
    fit_to_points(cam, focus_points(d), view.w / view.h); // the hill fills the view
    const Rect box = place_caption(view, 700, 260, caption_focus(d, cam, view, 12), 10);
    ASSERT_GT(overlap_area(box, caption_focus(d, cam, view, 12).objects[0]), 0);
    const Rect free = free_beside(view, box);
    EXPECT_GT(free.h, 200); // above or below the box, the largest part left
    fit_camera_into(cam, focus_points(d), view, free);
    const CaptionFocus after = caption_focus(d, cam, view, 12);
    for (const Rect& o : after.objects) {
        EXPECT_FALSE(overlaps(box, o)) << o.x << " " << o.y << " " << o.w << " " << o.h;
        EXPECT_GE(o.y, free.y);
        EXPECT_LE(o.y + o.h, free.y + free.h);
    }
    for (const Rect& p : after.points) EXPECT_FALSE(overlaps(box, p));
}

} // namespace
} // namespace isoparm::ui
