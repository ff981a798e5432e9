// Window placement on the monitor (see window_placement.hpp).
#include "ui/view/window_placement.hpp"

#include <algorithm>

namespace isoparm::ui {

std::string work_area_key(const ScreenRect& a) {
    return std::to_string(a.width) + "x" + std::to_string(a.height);
}

ScreenRect place_window(const ScreenRect& area, const WindowSizes& remembered) {
    int w = default_window_width, h = default_window_height;
    if (const auto it = remembered.find(work_area_key(area)); it != remembered.end()) {
        w = it->second[0];
        h = it->second[1];
    } else {
        w = std::min(w, static_cast<int>(area.width * first_window_fraction));
        h = std::min(h, static_cast<int>(area.height * first_window_fraction));
    }
    // Never larger than the area (a remembered size may come from a maximised window), and no
    // smaller than usable unless the area itself is smaller.
    w = std::clamp(w, std::min(min_window_width, area.width), std::max(area.width, 1));
    h = std::clamp(h, std::min(min_window_height, area.height), std::max(area.height, 1));
    return {area.x + (area.width - w) / 2, area.y + (area.height - h) / 2, w, h};
}

} // namespace isoparm::ui
