// A 2D teaching view's drawing as data (pure): the shapes a canvas draws, in order, and the
// labels it asks for, which one placer lays out (label_placer.hpp). The window draws a Picture
// with ImGui (ui/panels/picture_draw.hpp); a vector backend (SVG, PDF, TikZ) can draw the same
// Picture, measuring text with its own font. Coordinates are pixels of the view, y downward.
#pragma once

#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <glm/vec2.hpp>

#include "ui/view/label_placer.hpp"
#include "ui/view/layout.hpp"

namespace isoparm::ui {

// 8-bit RGBA packed with r in the lowest byte: the layout of ImGui's IM_COL32, so a panel's
// colours pass through unchanged.
using Rgba8 = std::uint32_t;
constexpr Rgba8 rgba8(unsigned r, unsigned g, unsigned b, unsigned a = 255) {
    return (a << 24) | (b << 16) | (g << 8) | r;
}
constexpr unsigned red_of(Rgba8 c) {
    return c & 0xffu;
}
constexpr unsigned green_of(Rgba8 c) {
    return (c >> 8) & 0xffu;
}
constexpr unsigned blue_of(Rgba8 c) {
    return (c >> 16) & 0xffu;
}
constexpr unsigned alpha_of(Rgba8 c) {
    return c >> 24;
}

namespace shape {
struct Segment {
    glm::vec2 a{0}, b{0};
    Rgba8 color = 0;
    float width = 1;
};
struct Polyline {
    std::vector<glm::vec2> points;
    Rgba8 color = 0;
    float width = 1;
    bool closed = false;
};
// A filled convex polygon.
struct Polygon {
    std::vector<glm::vec2> points;
    Rgba8 fill = 0;
};
struct Box {
    glm::vec2 lo{0}, hi{0};
    Rgba8 fill = 0;    // 0: not filled
    Rgba8 outline = 0; // 0: no outline
    float width = 1;
    float rounding = 0;
};
struct Disk {
    glm::vec2 center{0};
    float radius = 1;
    Rgba8 fill = 0;
    Rgba8 outline = 0;
    float width = 1;
};
} // namespace shape

using Shape =
    std::variant<shape::Segment, shape::Polyline, shape::Polygon, shape::Box, shape::Disk>;

struct Picture {
    std::string view; // its name in the UI report: label/<view>/<n>
    Rect frame;       // the canvas: shapes are clipped to it, labels stay inside it
    Rgba8 background = 0;
    Rgba8 border = 0; // the frame's outline (0: none)
    float border_width = 1;
    // Drawn in order, under the labels. There is no free text: every text of a view is a
    // label, so the placer sees it (and the UI report lists it).
    std::vector<Shape> shapes;
    // Each shape's clip: an index into `clips`, or -1 for the frame (begin_clip / end_clip).
    std::vector<int> shape_clips;
    std::vector<Rect> clips;
    int clip = -1;
    std::vector<LabelRequest> labels; // placed over the shapes
    std::vector<Rect> keep_clear;     // handles labels must not cover (a dragged disk)
    PlacerStyle style;

    // Shapes added from here on are clipped to `r` (within the frame) until end_clip.
    void begin_clip(const Rect& r) {
        clips.push_back(r);
        clip = static_cast<int>(clips.size()) - 1;
    }
    void end_clip() { clip = -1; }
    // Built in place in the list: moving a Shape (a variant) through a temporary makes GCC 12
    // under the sanitizers warn of uninitialized bytes (-Wmaybe-uninitialized), falsely.
    template <class S> void add(S&& s) {
        shapes.emplace_back(std::in_place_type<std::decay_t<S>>, std::forward<S>(s));
        shape_clips.push_back(clip);
    }
    void line(glm::vec2 a, glm::vec2 b, Rgba8 color, float width = 1) {
        add(shape::Segment{a, b, color, width});
    }
    void polyline(std::vector<glm::vec2> points, Rgba8 color, float width = 1,
                  bool closed = false) {
        if (points.size() > 1) add(shape::Polyline{std::move(points), color, width, closed});
    }
    void polygon(std::vector<glm::vec2> points, Rgba8 fill) {
        if (points.size() > 2) add(shape::Polygon{std::move(points), fill});
    }
    void box(glm::vec2 lo, glm::vec2 hi, Rgba8 fill, Rgba8 outline = 0, float width = 1,
             float rounding = 0) {
        add(shape::Box{lo, hi, fill, outline, width, rounding});
    }
    void disk(glm::vec2 center, float radius, Rgba8 fill, Rgba8 outline = 0, float width = 1) {
        add(shape::Disk{center, radius, fill, outline, width});
    }
    // A label naming the point `anchor`, placed beside it (or further out, with a leader).
    LabelRequest& label(glm::vec2 anchor, std::string text, Rgba8 color, int priority = 0) {
        LabelRequest r;
        r.anchor = anchor;
        r.text = std::move(text);
        r.color = color;
        r.priority = priority;
        return labels.emplace_back(std::move(r));
    }
    // A text at a fixed spot (axis names, tick values, a title): `anchor` is the spot of
    // `align` on its rectangle; dropped rather than drawn over another label.
    LabelRequest& fixed_label(glm::vec2 anchor, std::string text, Rgba8 color, LabelAlign align,
                              int priority = 100) {
        LabelRequest& r = label(anchor, std::move(text), color, priority);
        r.mode = LabelMode::fixed;
        r.align = align;
        return r;
    }
};

// The picture's labels placed (place_labels with its frame, style and keep_clear).
LabelPlacement place(const Picture& p, const MeasureText& measure);

} // namespace isoparm::ui
