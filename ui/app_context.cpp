// AppContext: executing commands with user-visible refusals, and the window title.
#include "ui/app_context.hpp"

#include <filesystem>

#include "core/doc/associative.hpp"
#include "ui/animation_actions.hpp"
#include "ui/modeler_actions.hpp"

namespace isoparm::ui {

bool AppContext::execute(std::unique_ptr<doc::Command> cmd) {
    // An animation's preview is not the document: a person's edit wins over it.
    suspend_animation(*this);
    const std::string label = cmd->label();
    observe_for_recording(); // a point picked in the frame its drag begins comes first
    std::optional<doc::CommandSpec> spec = cmd->spec();
    const geom::Status st = history.execute(doc, std::move(cmd));
    if (!st.ok()) {
        ui.status = label + " refused: " + st.error().message;
        // An edit of a constructed object's own points: ask to detach it, then run the edit
        // (every path that edits points gets the question, not a refusal in the status bar).
        if (spec)
            if (auto edit = doc::constructed_object_edited(doc, *spec))
                ask_to_detach(*this, edit->object, std::move(spec), std::move(edit->label));
        return false;
    }
    if (recorder) recorder->executed(history, doc);
    ui.status.clear();
    return true;
}

void AppContext::observe_for_recording() {
    if (!recorder) return;
    constexpr double degrees = 180.0 / 3.14159265358979323846;
    recorder->observe(doc, std::pair{ui.camera.yaw * degrees, ui.camera.pitch * degrees});
}

std::string AppContext::title() const {
    const std::string name = file_path.empty()
                                 ? std::string("untitled")
                                 : std::filesystem::path(file_path).filename().string();
    return name + (dirty() ? " *" : "") + " - isoparm";
}

} // namespace isoparm::ui
