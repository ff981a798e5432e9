// The options `isoparm render` and `isoparm figure` share: what the view shows (indicator,
// selection, style, camera, analysis, display toggles, de Boor's step), checked against the
// loaded scene and applied to a workstation's context.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ui/app_context.hpp"

namespace isoparm::app {

struct ViewOptions {
    std::string indicator, select, style, camera, analysis;
    // Display toggles: 0 = as the scene says, > 0 on, < 0 off (--x / --no-x).
    int points = 0, net = 0, ids = 0, knot_curves = 0, indicator_point = 0, deboor = 0;
    // De Boor's construction up to this step (-1: all); wide, so that any number typed is
    // checked against the scene rather than failing to convert.
    long long deboor_step = -1;
};

void add_view_options(CLI::App* sub, ViewOptions& o);
// Checks the options against the loaded scene and applies them; "" or the reason they fail.
std::string apply_view_options(const ViewOptions& o, ui::AppContext& ctx);

// "a,b[,c]" -> numbers; nullopt when the text is not min..max finite numbers. Each part may
// have spaces around it and a leading '+'.
std::optional<std::vector<double>> numbers(const std::string& text, size_t min, size_t max);
// "WxH" with 16 <= W, H <= 8192 (digits only); nullopt otherwise.
std::optional<std::pair<int, int>> picture_size(std::string_view text);

} // namespace isoparm::app
