// The teaching figures as primitive lists and their writers: what each view draws (counted
// from the document), the text markup, and the files (SVG text, TikZ, PDF header, PNG pixels).
#include <algorithm>
#include <filesystem>
#include <gtest/gtest.h>
#include <unistd.h>

#include "core/scene/scene_io.hpp"
#include "ui/figure/drawing_files.hpp"
#include "ui/image/png_compare.hpp"
#include "ui/view/drawing_picture.hpp"
#include "ui/view/figures.hpp"

namespace isoparm::ui {
namespace {

doc::Document scene(const std::string& name) {
    auto d = scene::load_scene(std::string(ISOPARM_SOURCE_DIR) + "/assets/scenes/" + name);
    EXPECT_TRUE(d.ok());
    return d.ok() ? std::move(d).value() : doc::Document{};
}

template <class T> std::vector<const T*> items(const Drawing& d, const std::string& role) {
    std::vector<const T*> out;
    for (const DrawItem& item : d.items)
        if (const T* t = std::get_if<T>(&item); t && t->role == role) out.push_back(t);
    return out;
}

TEST(DrawingText, RunsOfScripts) {
    const std::vector<TextRun> r = text_runs("N_{2,3}(u)");
    ASSERT_EQ(r.size(), 3u);
    EXPECT_EQ(r[0].kind, TextRun::plain);
    EXPECT_EQ(r[0].text, "N");
    EXPECT_EQ(r[1].kind, TextRun::sub);
    EXPECT_EQ(r[1].text, "2,3");
    EXPECT_EQ(r[2].text, "(u)");
    const std::vector<TextRun> d = text_runs("d^{1}_4");
    ASSERT_EQ(d.size(), 3u);
    EXPECT_EQ(d[1].kind, TextRun::sup);
    EXPECT_EQ(d[2].kind, TextRun::sub);
    EXPECT_EQ(d[2].text, "4");
    EXPECT_EQ(plain_text("a\\_b^{(2)}"), "a_b(2)");
}

TEST(Figures, BasisHasOnePathPerFunctionAndAFlatPartitionOfUnity) {
    const doc::Document d = scene("fig3a-bspline.json");
    const auto fig = make_figure(d, FigureView::basis, {});
    ASSERT_TRUE(fig.ok()) << fig.error().message;
    const geom::Surface* s = d.objects.front().surface();
    ASSERT_NE(s, nullptr);
    EXPECT_EQ(items<DrawPath>(*fig, "basis").size(), static_cast<std::size_t>(s->n_u));
    const auto labels = items<DrawText>(*fig, "basis-label");
    ASSERT_EQ(labels.size(), static_cast<std::size_t>(s->n_u));
    EXPECT_EQ(labels.front()->text, "N_{0," + std::to_string(s->degree_u) + "}");
    // The sum of all functions is 1 everywhere: its path is one horizontal line.
    const auto sum = items<DrawPath>(*fig, "partition-of-unity");
    ASSERT_EQ(sum.size(), 1u);
    for (const glm::dvec2& p : sum[0]->points) EXPECT_NEAR(p.y, sum[0]->points[0].y, 1e-9);
    // ... at the height of the axis label "1".
    for (const DrawText* t : items<DrawText>(*fig, "axis-label")) {
        if (t->text == "1") {
            EXPECT_NEAR(t->anchor.y, sum[0]->points[0].y, 1e-9);
        }
    }
    // The v direction has its own functions.
    FigureOptions o;
    o.direction = geom::Dir::v;
    const auto v = make_figure(d, FigureView::basis, o);
    ASSERT_TRUE(v.ok());
    EXPECT_EQ(items<DrawPath>(*v, "basis").size(), static_cast<std::size_t>(s->n_v));
}

TEST(Figures, TracingSquareShowsEveryKnotAndTheIndicator) {
    doc::Document d = scene("fig5b-knot-inserted.json");
    const auto fig = make_figure(d, FigureView::tracing, {});
    ASSERT_TRUE(fig.ok()) << fig.error().message;
    const auto labels = items<DrawText>(*fig, "knot-label");
    EXPECT_GE(labels.size(), 4u);
    const auto domain = items<DrawPath>(*fig, "domain");
    ASSERT_EQ(domain.size(), 1u);
    const auto dot = items<DrawCircle>(*fig, "indicator");
    ASSERT_EQ(dot.size(), 1u);
    // The indicator lies inside the square, where (u, v) puts it.
    const auto& sq = domain[0]->points; // (lo, lo), (hi, lo), (hi, hi), (lo, hi) on the page
    const double fx = (dot[0]->center.x - sq[0].x) / (sq[1].x - sq[0].x);
    const double fy = (sq[0].y - dot[0]->center.y) / (sq[0].y - sq[3].y);
    EXPECT_NEAR(fx, d.view.indicator.x, 1e-9);
    EXPECT_NEAR(fy, d.view.indicator.y, 1e-9);
    EXPECT_EQ(items<DrawText>(*fig, "indicator-label").size(), 1u);
}

TEST(Figures, DeBoorLabelsEveryIntermediatePoint) {
    const doc::Document d = scene("curve-designer.json");
    const auto fig = make_figure(d, FigureView::deboor, {});
    ASSERT_TRUE(fig.ok()) << fig.error().message;
    // A cubic: levels of 3, 2 and 1 points.
    EXPECT_EQ(items<DrawCircle>(*fig, "deboor-point").size(), 6u);
    EXPECT_EQ(items<DrawPath>(*fig, "deboor-level").size(), 2u); // one point has no polygon
    const auto blossom = make_figure(d, FigureView::blossom, {});
    ASSERT_TRUE(blossom.ok());
    EXPECT_EQ(items<DrawText>(*blossom, "blossom-label").size(), 10u); // 4 + 3 + 2 + 1
}

TEST(Figures, ViewsSayWhatTheyNeed) {
    doc::Document empty;
    for (FigureView v :
         {FigureView::tracing, FigureView::basis, FigureView::curve, FigureView::homogeneous}) {
        const auto fig = make_figure(empty, v, {});
        ASSERT_FALSE(fig.ok());
        EXPECT_NE(fig.error().message.find("needs"), std::string::npos);
    }
}

TEST(DrawingFiles, SvgKeepsTextAsTextAndEscapesIt) {
    Drawing d;
    d.text({10, 20}, "P_{1} & <q>", 9, {}, HAlign::left, VAlign::baseline, "label");
    d.line({0, 0}, {10, 10}, {}, "net");
    const std::string svg = svg_document(d);
    EXPECT_NE(svg.find("<text class=\"label\""), std::string::npos);
    EXPECT_NE(svg.find("P<tspan"), std::string::npos);
    EXPECT_NE(svg.find("&amp; &lt;q&gt;"), std::string::npos);
    EXPECT_NE(svg.find("<path class=\"net\" d=\"M0 0 L10 10\""), std::string::npos);
    const std::string tex = tikz_picture(d, {});
    EXPECT_NE(tex.find("\\begin{tikzpicture}"), std::string::npos);
    EXPECT_NE(tex.find("P\\textsubscript{1} \\& <q>"), std::string::npos);
}

TEST(DrawingFiles, PdfAndPngThroughCairo) {
    Drawing d;
    d.width = 40;
    d.height = 30;
    d.background = DrawColor{1, 1, 1, 1};
    d.polygon({{10, 10}, {30, 10}, {30, 20}, {10, 20}}, std::nullopt, DrawColor{1, 0, 0, 1});
    d.text({2, 28}, "N_{0}", 6, {}, HAlign::left, VAlign::baseline);
    std::string error;
    const auto pdf = cairo_pdf(d, error);
    ASSERT_TRUE(pdf) << error;
    EXPECT_EQ(pdf->substr(0, 5), "%PDF-");
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("isoparm-figure-" + std::to_string(::getpid()) + ".png"))
                                 .string();
    ASSERT_EQ(write_drawing(d, path, 2), "");
    const auto image = read_image(path, error);
    std::filesystem::remove(path);
    ASSERT_TRUE(image) << error;
    EXPECT_EQ(image->width, 80);
    EXPECT_EQ(image->height, 60);
    const auto px = [&](int x, int y) {
        return &image->rgb[(static_cast<std::size_t>(y) * 80 + x) * 3];
    };
    EXPECT_EQ(px(40, 30)[0], 255); // inside the red rectangle
    EXPECT_EQ(px(40, 30)[1], 0);
    EXPECT_EQ(px(5, 5)[1], 255); // white outside
    EXPECT_NE(write_drawing(d, "x.odt"), "");
}

} // namespace
} // namespace isoparm::ui

namespace isoparm::ui {
namespace {

// A panel's Picture (shapes, a clip, label requests) through the vector path: every shape
// becomes a path or a disk in page coordinates (the frame's corner at the origin), each in
// its clip, and every placed label a text; the SVG holds them all.
TEST(DrawingOfPicture, ShapesClipsAndPlacedLabels) {
    Picture p;
    p.view = "tracing";
    p.frame = {100, 50, 200, 150};
    p.background = rgba8(255, 255, 255);
    p.line({110, 60}, {290, 190}, rgba8(0, 0, 0), 2);
    p.begin_clip({120, 70, 100, 100});
    p.box({130, 80}, {200, 150}, rgba8(200, 220, 255), rgba8(0, 0, 0));
    p.end_clip();
    p.disk({150, 100}, 4, rgba8(255, 0, 0));
    p.label({150, 100}, "(u, v)", rgba8(0, 0, 0));
    p.fixed_label({110, 195}, "u", rgba8(0, 0, 0), LabelAlign::bottom_left);
    const Drawing d = drawing_of(p, 9);
    EXPECT_EQ(d.width, 200);
    EXPECT_EQ(d.height, 150);
    int paths = 0, circles = 0, texts = 0, clips = 0;
    for (const DrawItem& item : d.items) {
        paths += std::holds_alternative<DrawPath>(item);
        circles += std::holds_alternative<DrawCircle>(item);
        texts += std::holds_alternative<DrawText>(item);
        clips += std::holds_alternative<DrawClip>(item);
    }
    EXPECT_EQ(paths, 2); // the segment and the box (no leader: the label sits beside it)
    EXPECT_EQ(circles, 1);
    EXPECT_EQ(texts, 2);
    EXPECT_EQ(clips, 4); // frame, the box's clip, frame again, none for the labels
    const auto& seg = std::get<DrawPath>(d.items[1]);
    EXPECT_EQ(seg.points[0], glm::dvec2(10, 10)); // page coordinates
    const auto& box_clip = std::get<DrawClip>(d.items[2]);
    EXPECT_EQ(box_clip.origin, glm::dvec2(20, 20));
    const std::string svg = svg_document(d);
    EXPECT_NE(svg.find(">(u, v)</text>"), std::string::npos);
    EXPECT_NE(svg.find("clip-path"), std::string::npos);
}

} // namespace
} // namespace isoparm::ui

#include "ui/view/picture_tap.hpp"

namespace isoparm::ui {
namespace {

// What a backend offers while a tap is open is kept, the last of each view; nothing outside a
// tap; nested taps give the pictures to the innermost.
TEST(PictureTap, KeepsTheLastPictureOfEachViewWhileOpen) {
    Picture a;
    a.view = "tracing";
    a.frame = {0, 0, 10, 10};
    offer_picture(a); // no tap: dropped
    PictureTap outer;
    EXPECT_EQ(outer.size(), 0u);
    offer_picture(a);
    a.frame.w = 20;
    offer_picture(a);
    ASSERT_NE(outer.find("tracing"), nullptr);
    EXPECT_EQ(outer.find("tracing")->frame.w, 20);
    {
        PictureTap inner;
        Picture b;
        b.view = "basis_u";
        offer_picture(b);
        EXPECT_NE(inner.find("basis_u"), nullptr);
        EXPECT_EQ(outer.find("basis_u"), nullptr);
    }
    Picture c;
    c.view = "curve";
    offer_picture(c);
    EXPECT_NE(outer.find("curve"), nullptr);
    EXPECT_STREQ(picture_view_name(static_cast<int>(FigureView::basis)), "basis_u");
}

} // namespace
} // namespace isoparm::ui
