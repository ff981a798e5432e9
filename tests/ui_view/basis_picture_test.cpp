// The Basis tab's drawings as data: one polyline a basis function, the selected one strong,
// the parameter's line, the title a label; the heat map's cells in the ramp's colours.
#include <gtest/gtest.h>

#include <cmath>
#include <variant>

#include "ui/view/basis_picture.hpp"

namespace isoparm::ui {
namespace {

TEST(BasisPicture, EveryFunctionAPolylineTheSelectedOneStrong) {
    const geom::Knots U{0, 0, 0, 0, 0.5, 1, 1, 1, 1};
    PlotColors c;
    const Picture pic = basis_curves_picture(U, 3, 5, 2, 0.25, "N2(u), degree 3", "basis_u",
                                             {0, 0, 300, 120}, CanvasView{}, 1, 15, c);
    EXPECT_EQ(pic.view, "basis_u");
    int faint = 0, strong = 0, lines = 0;
    for (const Shape& s : pic.shapes) {
        if (const auto* p = std::get_if<shape::Polyline>(&s)) {
            faint += p->color == c.faint;
            strong += p->color == c.strong;
            for (const glm::vec2& q : p->points) { // inside the box, below the title's line
                EXPECT_GE(q.y, 0 + 6 + 15 - 1e-3);
                EXPECT_LE(q.y, 120 - 4 + 1e-3);
            }
        }
        lines += std::holds_alternative<shape::Segment>(s);
    }
    EXPECT_EQ(faint, 4);
    EXPECT_EQ(strong, 1);
    EXPECT_EQ(lines, 1); // the parameter
    ASSERT_EQ(pic.labels.size(), 1u);
    EXPECT_EQ(pic.labels[0].text, "N2(u), degree 3");
}

TEST(BasisPicture, TheHeatRampRunsDarkToLightAndNegativeIsCyan) {
    const Rgba8 low = heat_rgba(0), high = heat_rgba(1), neg = heat_rgba(-1);
    EXPECT_LT(red_of(low) + green_of(low) + blue_of(low),
              red_of(high) + green_of(high) + blue_of(high));
    EXPECT_GT(blue_of(neg), red_of(neg));
    EXPECT_EQ(alpha_of(heat_rgba(0.3f)), 255u);
    const std::vector<float> values{0.f, 0.5f, std::nanf(""), 1.f};
    HeatInput in;
    in.canvas = in.square = {0, 0, 100, 100};
    in.values = &values;
    in.resolution = 2;
    in.max_value = 1;
    in.name = "R22";
    const Picture pic = heat_picture(in);
    ASSERT_GE(pic.shapes.size(), 4u);
    EXPECT_EQ(std::get<shape::Box>(pic.shapes[2]).fill, rgba8(90, 90, 90)); // undefined: grey
    EXPECT_EQ(std::get<shape::Box>(pic.shapes[3]).fill, heat_rgba(1));
    EXPECT_EQ(pic.labels.at(0).text, "R22");
}

} // namespace
} // namespace isoparm::ui
