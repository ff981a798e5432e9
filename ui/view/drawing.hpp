// A picture as a list of primitives that any backend draws: paths, dots, text runs with sub-
// and superscripts, and raster images, in points (1/72 inch) with y downward. The teaching
// figures (ui/view/figures.hpp) are built as Drawings and written as SVG, PDF, PNG and TikZ
// (ui/figure); a panel can draw the same list with ImGui. Every item carries a role ("basis",
// "knot-label"...) that the SVG writer keeps as its class, so tests and style sheets can find
// what a figure shows.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/vec2.hpp>

namespace isoparm::ui {

struct DrawColor {
    float r = 0, g = 0, b = 0, a = 1;
};

struct DrawStroke {
    DrawColor color;
    double width = 1;         // points
    std::vector<double> dash; // on, off, on, ... lengths in points; empty: solid
};

// A polyline, or a polygon when closed; stroked, filled or both.
struct DrawPath {
    std::vector<glm::dvec2> points;
    bool closed = false;
    std::optional<DrawStroke> stroke;
    std::optional<DrawColor> fill;
    std::string role;
};

struct DrawCircle {
    glm::dvec2 center{0, 0};
    double radius = 2;
    std::optional<DrawStroke> stroke;
    std::optional<DrawColor> fill;
    std::string role;
};

enum class HAlign { left, center, right };
enum class VAlign { baseline, middle, top, bottom };

// One label. `text` may hold subscripts and superscripts as in TeX: "N_{2,3}(u)",
// "d^{1}_{4}", "P_3" (one character without braces); a backslash escapes _ ^ { } and itself.
struct DrawText {
    glm::dvec2 anchor{0, 0};
    std::string text;
    double size = 10; // points
    DrawColor color;
    HAlign h = HAlign::left;
    VAlign v = VAlign::baseline;
    bool italic = false;
    std::string role;
};

// RGBA pixels (first row at the top) stretched over [origin, origin + size].
struct DrawImage {
    glm::dvec2 origin{0, 0}, size{0, 0};
    int pixels_w = 0, pixels_h = 0;
    std::vector<std::uint8_t> rgba;
    std::string role;
};

// The items after this one are clipped to the rectangle [origin, origin + size] (until the
// next clip; an empty size ends clipping).
struct DrawClip {
    glm::dvec2 origin{0, 0}, size{0, 0};
    bool active() const { return size.x > 0 && size.y > 0; }
};

using DrawItem = std::variant<DrawPath, DrawCircle, DrawText, DrawImage, DrawClip>;

struct Drawing {
    double width = 400, height = 300;    // points
    std::optional<DrawColor> background; // none: transparent
    std::string title;                   // the document's title (SVG <title>, PDF metadata)
    std::vector<DrawItem> items;         // drawn in order

    void line(glm::dvec2 a, glm::dvec2 b, const DrawStroke& s, std::string role = {});
    void polyline(std::vector<glm::dvec2> points, const DrawStroke& s, std::string role = {});
    void polygon(std::vector<glm::dvec2> points, std::optional<DrawStroke> s,
                 std::optional<DrawColor> fill, std::string role = {});
    void dot(glm::dvec2 center, double radius, DrawColor fill, std::optional<DrawStroke> s,
             std::string role = {});
    void text(glm::dvec2 anchor, std::string text, double size, DrawColor color, HAlign h, VAlign v,
              std::string role = {});
};

// A label's text split into runs: plain, subscript or superscript.
struct TextRun {
    enum Kind { plain, sub, sup } kind = plain;
    std::string text;
};
std::vector<TextRun> text_runs(const std::string& marked_up);
// The text without markup ("N_{2,3}" -> "N2,3"), as a reader extracting it sees it.
std::string plain_text(const std::string& marked_up);

// Roughly how wide a label is in points (DejaVu Sans's average advance, scripts at 70%), for
// placing labels before a backend measures them exactly.
double approximate_text_width(const std::string& marked_up, double size);

} // namespace isoparm::ui
