// Where the workstation window opens (pure): inside the monitor's work area, at the size the
// user last left it on a monitor of that size, never larger than the work area, never
// off-screen.
#pragma once

#include <array>
#include <map>
#include <string>

namespace isoparm::ui {

struct ScreenRect {
    int x = 0, y = 0, width = 0, height = 0;
    bool operator==(const ScreenRect&) const = default;
};

// Window sizes remembered per monitor work-area size ("1024x768" -> {w, h}): a laptop screen
// and a classroom projector each keep their own.
using WindowSizes = std::map<std::string, std::array<int, 2>>;

constexpr int default_window_width = 1440, default_window_height = 900;
constexpr float first_window_fraction = 0.9f; // of the work area, at most, when nothing is kept
constexpr int min_window_width = 320, min_window_height = 240;

std::string work_area_key(const ScreenRect& work_area);

// The window's rectangle for `work_area`: the remembered size for this work-area size (clamped
// to the area), otherwise the default size shrunk to at most 90% of the area; centred.
ScreenRect place_window(const ScreenRect& work_area, const WindowSizes& remembered);

} // namespace isoparm::ui
