// AppContext: executing commands with user-visible refusals, and the window title.
#include "ui/app_context.hpp"

#include <filesystem>

namespace isoparm::ui {

bool AppContext::execute(std::unique_ptr<doc::Command> cmd) {
    const std::string label = cmd->label();
    const geom::Status st = history.execute(doc, std::move(cmd));
    if (!st.ok()) {
        ui.status = label + " refused: " + st.error().message;
        return false;
    }
    ui.status.clear();
    return true;
}

std::string AppContext::title() const {
    const std::string name = file_path.empty()
                                 ? std::string("untitled")
                                 : std::filesystem::path(file_path).filename().string();
    return name + (dirty() ? " *" : "") + " - isoparm";
}

} // namespace isoparm::ui
