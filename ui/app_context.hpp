// Everything a panel works with: the document and its history, the file, settings and UI
// state. Panels read the document and change it only through commands.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/doc/command.hpp"
#include "core/doc/document.hpp"
#include "core/json/input_file.hpp"
#include "core/scene/recorder.hpp"
#include "ui/ui_state.hpp"
#include "ui/view/settings.hpp"

namespace isoparm::ui {

class Renderer;
class ImplicitMeshes;

struct AppContext {
    doc::Document doc;
    doc::History history;
    std::string file_path; // empty: untitled
    // The file as it was on disk when loaded or last saved: Save asks before replacing a file
    // someone else wrote since (two windows on one scene).
    std::optional<json_io::FileStamp> file_stamp;
    Settings settings;
    bool remember_settings = false; // false in headless runs (deterministic, no side effects)
    UiState ui;
    Renderer* renderer = nullptr;
    ImplicitMeshes* implicit_meshes = nullptr; // owned by the workstation

    // File > Start recording: the journal of this session's edits (core/scene/recorder.hpp);
    // null when not recording.
    std::unique_ptr<scene::Recorder> recorder;

    // Runs a command through the history; a refusal shows in the status bar and changes
    // nothing. Returns whether it applied (and, while recording, records it).
    bool execute(std::unique_ptr<doc::Command> cmd);
    // The view as it is now, for the recording (once a frame, and before every edit).
    void observe_for_recording();
    // Ends the current gesture: the next command starts a new undo step.
    void seal() { history.seal(); }
    bool dirty() const { return !history.is_clean(); }
    std::string title() const; // "name.json * - isoparm"
};

} // namespace isoparm::ui
