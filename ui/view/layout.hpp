// Window layout maths (pure): left column, 3D view, right column, with draggable splitters.
#pragma once

#include <vector>

namespace isoparm::ui {

struct Rect {
    float x = 0, y = 0, w = 0, h = 0;
    bool contains(float px, float py) const {
        return px >= x && px < x + w && py >= y && py < y + h;
    }
    bool operator==(const Rect&) const = default;
};

// What the user chose by dragging splitters; remembered between runs. Widths are in
// unscaled points (multiplied by the UI scale when laid out), stacks are relative shares.
struct LayoutPrefs {
    float left_width = 330;
    float right_width = 360;
    std::vector<float> left_shares{0.56f, 0.44f};  // tracing, basis functions
    std::vector<float> right_shares{0.62f, 0.38f}; // control point, control panel
    // Presentation mode's columns once dragged, as shares of the width (0: not dragged, the
    // 3D view keeps min_center_fraction); a projector and a laptop differ, so not in pixels.
    float presentation_left = 0, presentation_right = 0;
    bool operator==(const LayoutPrefs&) const = default;
};

struct LayoutInput {
    float width = 1280, height = 800; // the window, in ImGui units
    float top = 0;                    // menu bar height
    float bottom = 0;                 // status bar height
    float scale = 1;                  // HiDPI times presentation scale
    float splitter = 6;               // splitter thickness (already scaled)
    float min_center_fraction = 0;    // the centre keeps at least this share of the width
                                      // (presentation mode favours the 3D view)
    bool presentation = false;        // presentation mode: its own column widths, once dragged
};

struct Layout {
    Rect center;
    std::vector<Rect> left, right;                             // stacked panels, top to bottom
    Rect left_splitter, right_splitter;                        // vertical bars beside the centre
    std::vector<Rect> left_row_splitters, right_row_splitters; // between stacked panels
};

// Minimum sizes (unscaled points) the layout keeps while the window allows it.
constexpr float min_side_width = 200;
constexpr float min_center_width = 260;
constexpr float min_row_height = 80;

// Lays the panels out to fill the window exactly (no gaps, no overlaps). Side columns
// shrink proportionally before the centre drops below its minimum; in a window too small
// for the minimums everything shrinks proportionally.
Layout compute_layout(const LayoutPrefs& prefs, const LayoutInput& in);

enum class Side { left, right };

// A column splitter moved by dx pixels: the column takes its laid-out width plus the move,
// stored unscaled and kept at least min_side_width wide. In presentation mode both columns are
// stored as shares of the width (presentation_left / _right), the centre kept at least
// min_center_width.
void drag_column_splitter(LayoutPrefs& prefs, const Layout& layout, const LayoutInput& in,
                          Side side, float dx);
// The splitter under stacked panel `index` (between index and index + 1) moved by dy pixels:
// the two panels trade height, each keeping at least min_row_height (scaled).
void drag_row_splitter(LayoutPrefs& prefs, const Layout& layout, const LayoutInput& in, Side side,
                       int index, float dy);

// Restores defaults for values a settings file got wrong (negative, NaN, wrong count).
LayoutPrefs sanitize(const LayoutPrefs& prefs);

} // namespace isoparm::ui
