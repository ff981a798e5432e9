// Many selected points: Shift+click toggles, the set follows the document, a box selects what
// lies inside it, and the handle's parts are hit and map as they are drawn.
#include <gtest/gtest.h>

#include "core/doc/point_set.hpp"
#include "ui/view/point_selection.hpp"

using namespace isoparm;
using namespace isoparm::ui;

namespace {

TEST(PointSelection, ShiftClickTogglesAndTheSetFollowsTheDocument) {
    doc::Document doc = doc::default_document(); // hill (5 x 5), P22 selected
    PointSelection s;
    sync_selection(s, doc);
    EXPECT_EQ(s.object, 1u);
    EXPECT_EQ(s.points, (std::vector<PointIndex>{{2, 2}}));
    s.toggle({0, 4});
    s.toggle({1, 1});
    EXPECT_EQ(s.size(), 3u);
    s.toggle({0, 4});
    EXPECT_FALSE(s.contains({0, 4}));
    EXPECT_EQ(primary_after_toggle(s, {0, 4}, {2, 2}), (PointIndex{2, 2}));
    s.toggle({2, 2}); // the selected point itself taken out: another one takes its place
    EXPECT_EQ(primary_after_toggle(s, {2, 2}, {2, 2}), (PointIndex{1, 1}));
    // Row and column of the selected point, all points.
    s.set(1, doc::row_points(doc.objects[0].shape, 2));
    sync_selection(s, doc);
    EXPECT_EQ(s.size(), 5u);
    // Another object selected: the set starts over.
    doc.view.selection = {};
    sync_selection(s, doc);
    EXPECT_EQ(s.size(), 0u);
}

TEST(PointSelection, ABoxSelectsThePointsInsideItWhicheverWayItIsDrawn) {
    const std::vector<glm::dvec2> px{{10, 10}, {50, 50}, {90, 20}, {30, 80}};
    EXPECT_EQ(inside_box(px, {0, 0}, {60, 60}), (std::vector<std::size_t>{0, 1}));
    EXPECT_EQ(inside_box(px, {60, 60}, {0, 0}), (std::vector<std::size_t>{0, 1}));
    EXPECT_EQ(inside_box(px, {100, 0}, {20, 90}), (std::vector<std::size_t>{1, 2, 3}));
    EXPECT_TRUE(inside_box(px, {0, 0}, {5, 5}).empty());
}

TEST(PointSelection, ThePlaneHandleIsHitWhereItIsDrawn) {
    PlaneMap m;
    m.canvas = {0, 0, 200, 200};
    m.center = {0, 0};
    m.units_per_px = 0.01;
    const HandleLayout h = handle_layout_plane(m, 0, 2, {0.1, 5, -0.2}, 60);
    EXPECT_EQ(h.centre, glm::dvec2(110, 120));
    EXPECT_EQ(hit_handle(h, {111, 119}, 6), HandlePart::centre);
    EXPECT_EQ(hit_handle(h, {165, 121}, 6), HandlePart::arrow_x);
    EXPECT_EQ(hit_handle(h, {110, 70}, 6), HandlePart::arrow_z);
    EXPECT_EQ(hit_handle(h, {110 - 45, 120}, 6), HandlePart::ring_y); // the ring about y
    EXPECT_EQ(hit_handle(h, h.scale_box, 6), HandlePart::scale);
    EXPECT_EQ(hit_handle(h, {10, 10}, 6), HandlePart::none);
}

TEST(PointSelection, RingsTurnAndTheSquareScalesAboutThePivot) {
    const glm::dvec3 pivot(1, 1, 0);
    // A quarter turn on screen, counter-clockwise (y down), the axis toward the viewer: +90.
    const glm::dmat4 turn = ring_turn(2, pivot, {100, 100}, {150, 100}, {100, 50}, true);
    EXPECT_EQ(doc::apply_affine(turn, {2, 1, 0}), glm::dvec3(1, 2, 0));
    EXPECT_EQ(doc::apply_affine(turn, pivot), pivot);
    // Snapped to 15 degrees.
    const glm::dmat4 snapped = ring_turn(2, pivot, {100, 100}, {150, 100}, {100, 52}, true, 15);
    EXPECT_EQ(doc::apply_affine(snapped, {2, 1, 0}), glm::dvec3(1, 2, 0));
    const glm::dmat4 twice = box_scale(pivot, {100, 100}, {120, 100}, {140, 100});
    EXPECT_EQ(doc::apply_affine(twice, {2, 1, 0}), glm::dvec3(3, 1, 0));
    EXPECT_EQ(doc::apply_affine(twice, pivot), pivot);
}

TEST(PointSelection, The3DHandleShowsTheAxesNotSeenEndOn) {
    Camera c;
    c.yaw = 0;
    c.pitch = 0; // looking along an axis: one arrow is seen end-on
    Viewport vp{0, 0, 800, 600};
    const HandleLayout h = handle_layout_3d(c, vp, {0, 0, 0}, 80);
    int shown = 0;
    for (bool b : h.axis_shown) shown += b;
    EXPECT_EQ(shown, 2);
    c.yaw = -0.95;
    c.pitch = 0.55;
    const HandleLayout g = handle_layout_3d(c, vp, {0, 0, 0}, 80);
    EXPECT_TRUE(g.axis_shown[0] && g.axis_shown[1] && g.axis_shown[2]);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(glm::length(g.tip[a] - g.centre), 60, 25) << a;
}

} // namespace
