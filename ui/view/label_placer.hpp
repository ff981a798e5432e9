// The one label placer of every 2D canvas and of the 3D view's overlay (pure): labels ask to
// name an anchor point; each tries places around it, nearest first, then further out with a
// leader line back to the anchor; a label that finds no free place inside the view is dropped,
// lower priority first, and counted in a "+n" badge whose hover lists them. Nothing it places
// overlaps another placed label, and nothing lies outside the view.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "ui/view/layout.hpp"

namespace isoparm::ui {

// A label's size in pixels for its text: the backend's font (ImGui's CalcTextSize in the
// window; a vector backend measures with its own font).
using MeasureText = std::function<glm::vec2(std::string_view)>;

// How a label relates to its anchor.
enum class LabelMode {
    around, // the placer chooses among places around the anchor, then further out with a leader
    fixed   // the anchor is a fixed spot (axis names, ticks, titles): placed there, or dropped
};

// Where the anchor is on a fixed label's rectangle.
enum class LabelAlign {
    top_left,
    top_center,
    top_right,
    center_left,
    center,
    center_right,
    bottom_left,
    bottom_center,
    bottom_right
};

// One request: the anchor it names, its text and how much it matters.
struct LabelRequest {
    glm::vec2 anchor{0};
    std::string text;
    int priority = 0; // higher is placed first and dropped last
    LabelMode mode = LabelMode::around;
    LabelAlign align = LabelAlign::top_left; // fixed labels only
    std::uint32_t color = 0xffffffffu;       // text colour (8-bit RGBA, r in the lowest byte)
    std::uint32_t plate = 0;                 // a plate behind the text (0: none)
    std::uint32_t frame = 0;                 // the plate's outline (0: none)
    std::string tooltip;                     // the whole text, when `text` is shortened
};

struct PlacerStyle {
    float offset = 6;     // gap between the anchor and a label beside it
    float padding = 2;    // around the text, inside its rectangle (the plate)
    float margin = 1;     // kept free between two labels
    float leader_min = 0; // a leader line is drawn when the rectangle is further than this
                          // from the anchor (0: offset * 2)
    int rings = 4;        // how far out places are tried: 2 + 2 rings rows of labels either side
};

struct PlacedLabel {
    std::size_t request = 0; // index into the requests
    Rect rect;               // the label's rectangle, padding included
    glm::vec2 text_at{0};    // top-left of the text
    std::optional<std::pair<glm::vec2, glm::vec2>> leader; // from the anchor to the rectangle
};

struct LabelPlacement {
    std::vector<PlacedLabel> placed;  // in the order they were placed (priority, then request)
    std::vector<std::size_t> dropped; // requests that found no room, by priority
    std::optional<Rect> more;         // the "+n" badge when any were dropped
    std::string more_text;            // "+n"
    glm::vec2 more_text_at{0};
};

// Places the labels inside `bounds`, clear of every `obstacles` rectangle (handles the labels
// must not cover: a dragged disk, the indicator). Fixed labels first (by priority), then the
// others by priority; ties keep the request order. Deterministic.
LabelPlacement place_labels(const std::vector<LabelRequest>& requests, const Rect& bounds,
                            const MeasureText& measure, const PlacerStyle& style = {},
                            const std::vector<Rect>& obstacles = {});

// Whether two rectangles share any area (touching edges do not).
bool rects_overlap(const Rect& a, const Rect& b);

} // namespace isoparm::ui
