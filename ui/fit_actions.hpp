// The Fit panel's entry points for the menus, the file dialog and the browser's uploads (the
// panel itself is ui/panels/fit_panel.cpp).
#pragma once

#include <string>

#include "ui/app_context.hpp"

namespace isoparm::ui {

void open_fit_panel(AppContext& ctx);
// Replaces the panel's points with a CSV / XYZ file's (a grid when it has blank-line rows) and
// opens the panel; false with the reason (naming the file and line) in `error`.
bool load_fit_points(AppContext& ctx, const std::string& path, std::string& error);

} // namespace isoparm::ui
