// The Fit panel: data points on a plane canvas, a curve or surface fitted through them
// (its entry points for menus and files: ui/fit_actions.hpp).
#pragma once

#include "ui/app_context.hpp"

namespace isoparm::ui {

void draw_fit_panel(AppContext& ctx);

} // namespace isoparm::ui
