// The teaching figures as primitive lists and their writers: what each view draws (counted
// from the document), the text markup, and the files (SVG text, TikZ, PDF header, PNG pixels).
#include <algorithm>
#include <filesystem>
#include <gtest/gtest.h>
#include <unistd.h>

#include "core/scene/scene_io.hpp"
#include "ui/figure/drawing_files.hpp"
#include "ui/image/png_compare.hpp"
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
    for (FigureView v : {FigureView::tracing, FigureView::basis, FigureView::curve,
                         FigureView::homogeneous}) {
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
    const auto px = [&](int x, int y) { return &image->rgb[(static_cast<std::size_t>(y) * 80 + x) * 3]; };
    EXPECT_EQ(px(40, 30)[0], 255); // inside the red rectangle
    EXPECT_EQ(px(40, 30)[1], 0);
    EXPECT_EQ(px(5, 5)[1], 255); // white outside
    EXPECT_NE(write_drawing(d, "x.odt"), "");
}

} // namespace
} // namespace isoparm::ui
