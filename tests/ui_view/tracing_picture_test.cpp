// The tracing square's drawing as data: the paper's Fig. 6 split square with its patch names,
// knot values and weights, every label apart and inside the frame, at the sizes the window uses.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/doc/commands.hpp"
#include "core/doc/commands_trim.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/trim/trim.hpp"
#include "ui/view/tracing_picture.hpp"

namespace isoparm::ui {
namespace {

const MeasureText mono = [](std::string_view s) {
    return glm::vec2(8.f * static_cast<float>(s.size()), 15.f);
};

doc::Document split_hill() {
    doc::Document d = doc::default_document();
    doc::History h;
    EXPECT_TRUE(h.execute(d, doc::split_object(d.objects[0].id, geom::Dir::u, 0.75)).ok());
    EXPECT_TRUE(h.execute(d, doc::split_object(d.objects[0].id, geom::Dir::v, 0.5)).ok());
    return d;
}

TracingInput input(float side) {
    TracingInput in;
    in.canvas = {60, 30, side, side};
    in.square = in.canvas;
    in.label_w = 50;
    in.label_h = 50;
    return in;
}

void expect_apart(const Picture& pic) {
    const LabelPlacement p = place(pic, mono);
    for (std::size_t a = 0; a < p.placed.size(); ++a) {
        const Rect& r = p.placed[a].rect;
        EXPECT_GE(r.x, pic.frame.x);
        EXPECT_GE(r.y, pic.frame.y);
        EXPECT_LE(r.x + r.w, pic.frame.x + pic.frame.w);
        EXPECT_LE(r.y + r.h, pic.frame.y + pic.frame.h);
        for (std::size_t b = a + 1; b < p.placed.size(); ++b)
            EXPECT_FALSE(rects_overlap(r, p.placed[b].rect)) << a << " " << b;
    }
}

TEST(TracingPicture, ThePapersSplitSquareNamesItsPatchesAndKnotsApart) {
    const doc::Document d = split_hill();
    for (float side : {90.f, 200.f, 520.f}) {
        const TracingPicture t = tracing_picture(d, d.objects[0], input(side));
        EXPECT_EQ(t.picture.view, "tracing");
        EXPECT_EQ(t.ticks_u.size(), t.px_u.size());
        // The frame holds the strips: the v values left of the canvas, the u values below.
        EXPECT_FLOAT_EQ(t.picture.frame.x, 10);
        EXPECT_FLOAT_EQ(t.picture.frame.y + t.picture.frame.h, 30 + side + 50);
        // Three patch names and the u, v letters at least, whatever the size.
        const auto named = std::count_if(t.picture.labels.begin(), t.picture.labels.end(),
                                         [](const LabelRequest& r) { return r.text == "u"; });
        EXPECT_EQ(named, 1);
        expect_apart(t.picture);
    }
}

TEST(TracingPicture, WeightsAndTheHeldKnotAreLabelled) {
    doc::Document d = doc::default_document();
    geom::Surface& s = *d.objects[0].surface();
    s.type = geom::SplineType::nurbs;
    s.weights[12] = 5;
    TracingInput in = input(300);
    in.weights = true;
    in.held = std::pair{geom::Dir::u, 4};
    const TracingPicture t = tracing_picture(d, d.objects[0], in);
    const auto five = std::find_if(t.picture.labels.begin(), t.picture.labels.end(),
                                   [](const LabelRequest& r) { return r.text == "5"; });
    ASSERT_NE(five, t.picture.labels.end());
    EXPECT_EQ(five->priority, 20); // unusual weights first
    EXPECT_EQ(five->tooltip, "w22 = 5");
    // The indicator at (0.5, 0.5) is in the middle of the canvas, and labels keep clear of it.
    EXPECT_FLOAT_EQ(t.indicator.x, 60 + 150);
    ASSERT_FALSE(t.picture.keep_clear.empty());
    expect_apart(t.picture);
}

// The default hill less a round hole in the middle of its domain.
doc::Document hill_with_hole() {
    doc::Document d = doc::default_document();
    const geom::ParamRect dom = geom::domain(*d.objects[0].surface());
    const glm::dvec2 mid{(dom.u.lo + dom.u.hi) / 2, (dom.v.lo + dom.v.hi) / 2};
    geom::Trim t;
    t.holes.push_back(
        geom::circle_loop(mid, 0.25 * (dom.u.hi - dom.u.lo), /*clockwise=*/true).value());
    doc::History h;
    EXPECT_TRUE(h.execute(d, doc::set_trim(d.objects[0].id, t)).ok());
    return d;
}

std::size_t trim_polylines(const Picture& pic, Rgba8 color) {
    return static_cast<std::size_t>(
        std::count_if(pic.shapes.begin(), pic.shapes.end(), [&](const Shape& s) {
            const auto* p = std::get_if<shape::Polyline>(&s);
            return p && p->closed && p->color == color && p->points.size() > 8;
        }));
}

TEST(TracingPicture, ATrimmedSurfaceShowsItsLoopsAndTheIndicatorInTheHoleIsCutAway) {
    doc::Document d = hill_with_hole();
    const TracingInput in = input(300);
    d.view.indicator = {0.5, 0.5}; // in the hole
    TracingPicture t = tracing_picture(d, d.objects[0], in);
    EXPECT_EQ(trim_polylines(t.picture, in.colors.trim), 1u);
    EXPECT_TRUE(t.indicator_cut);
    EXPECT_EQ(std::count_if(t.picture.labels.begin(), t.picture.labels.end(),
                            [](const LabelRequest& r) { return r.text == "cut away"; }),
              1);
    d.view.indicator = {0.1, 0.1}; // kept
    t = tracing_picture(d, d.objects[0], in);
    EXPECT_FALSE(t.indicator_cut);
    EXPECT_EQ(std::count_if(t.picture.labels.begin(), t.picture.labels.end(),
                            [](const LabelRequest& r) { return r.text == "cut away"; }),
              0);
    expect_apart(t.picture);
    // Untrimmed: no loop drawn.
    const doc::Document plain = doc::default_document();
    EXPECT_EQ(trim_polylines(tracing_picture(plain, plain.objects[0], in).picture, in.colors.trim),
              0u);
}

} // namespace
} // namespace isoparm::ui
