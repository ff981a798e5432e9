// The Fit panel's edits that come from outside it: opening it, and data points from a file.
#include "ui/fit_actions.hpp"

#include <filesystem>

#include "core/scene/point_file.hpp"

namespace isoparm::ui {

bool load_fit_points(AppContext& ctx, const std::string& path, std::string& error) {
    auto data = scene::load_points(path);
    if (!data) {
        error = data.error().message;
        return false;
    }
    FitState& f = ctx.ui.fit;
    f.points = std::move(data->points);
    f.rows = data->rows;
    f.columns = data->columns;
    f.source = std::filesystem::path(path).filename().string();
    f.stale = true;
    f.open = true;
    f.drag = -1;
    f.frame_plane = -1; // frame the new data
    // Counts that no longer fit the data are the fit's refusal, shown; nothing is clamped.
    return true;
}

void open_fit_panel(AppContext& ctx) {
    ctx.ui.fit.open = true;
}

} // namespace isoparm::ui
