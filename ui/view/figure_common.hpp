// What the teaching figures (figures.hpp) share: print colours, number format, the map from
// data to the page, and point labels placed so that none covers another. Internal to ui/view.
#pragma once

#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include "ui/view/drawing.hpp"
#include "ui/view/figures.hpp"

namespace isoparm::ui::figure_detail {

// Dark on white: figures go on paper and slides.
struct Palette {
    static constexpr DrawColor ink{0.10f, 0.10f, 0.12f, 1};
    static constexpr DrawColor muted{0.40f, 0.40f, 0.44f, 1};
    static constexpr DrawColor faint{0.62f, 0.62f, 0.66f, 1};
    static constexpr DrawColor grid{0.80f, 0.80f, 0.84f, 1};
    static constexpr DrawColor curve{0.05f, 0.30f, 0.70f, 1};
    static constexpr DrawColor selected{0.85f, 0.33f, 0.05f, 1};
    static constexpr DrawColor indicator{0.85f, 0.10f, 0.10f, 1};
    static constexpr DrawColor comb{0.15f, 0.55f, 0.25f, 1};
    static constexpr DrawColor white{1, 1, 1, 1};
};

DrawStroke stroke(DrawColor c, double width, std::vector<double> dash = {});

// A number as the UI shows it: about 4 significant digits, no exponent for ordinary sizes.
std::string number(double x);

// A rectangle on the page, in points, y downward.
struct PageBox {
    double x = 0, y = 0, w = 0, h = 0;
};

// Data (x to the right, y upward) onto a box of the page.
struct DataMap {
    PageBox box;
    double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
    glm::dvec2 operator()(double x, double y) const;
    glm::dvec2 operator()(const glm::dvec2& p) const { return (*this)(p.x, p.y); }
};
// The data box [lo, hi] in `box` at one scale for both axes, centred.
DataMap fit_equal(const PageBox& box, glm::dvec2 lo, glm::dvec2 hi);

// A page with its background and title line; returns the area left for the picture.
PageBox start_page(Drawing& d, const FigureOptions& o, const std::string& title);

// Labels beside points (anchors on the page), placed so that none overlaps another or a
// label placed before (ui::place_labels with the labels' approximate sizes).
void point_labels(Drawing& d, const std::vector<glm::dvec2>& anchors,
                  const std::vector<std::string>& texts, double size, DrawColor color,
                  const std::string& role);

// The figures of each view (figure_*.cpp).
geom::Expected<Drawing> tracing_figure(const doc::Document& d, const FigureOptions& o);
geom::Expected<Drawing> basis_figure(const doc::Document& d, const FigureOptions& o);
geom::Expected<Drawing> curve_figure(const doc::Document& d, const FigureOptions& o, bool deboor);
geom::Expected<Drawing> homogeneous_figure(const doc::Document& d, const FigureOptions& o);
geom::Expected<Drawing> blossom_figure(const doc::Document& d, const FigureOptions& o);

} // namespace isoparm::ui::figure_detail
