// User actions shared by menus, keyboard shortcuts and dialogs: files, undo/redo, view.
#pragma once

#include <string>

#include "ui/app_context.hpp"

namespace isoparm::ui {

// File. Actions that would lose unsaved changes ask first (the unsaved-changes dialog
// runs the action once the user has answered).
void request_new_document(AppContext& ctx);
void request_open_dialog(AppContext& ctx);
void request_open_file(AppContext& ctx, const std::string& path);
void request_quit(AppContext& ctx);
// Runs a pending action without asking (the user chose to discard changes).
void run_pending(AppContext& ctx);

// The document becomes `d` with a fresh history (a lesson's or an exercise's untitled copy
// when `path` is empty): a recording ends and is offered for saving, a playing lesson closes.
void adopt_document(AppContext& ctx, doc::Document d, const std::string& path);
// Loads a scene; on error shows the error dialog and keeps the current document.
bool open_file(AppContext& ctx, const std::string& path);
void new_document(AppContext& ctx);
// Saves to the current file, or opens the save dialog when untitled. When the file changed on
// disk since it was loaded or last saved, saves nothing and asks (overwrite_changed_dialog).
// Returns whether saved.
bool save(AppContext& ctx);
void request_save_as(AppContext& ctx);
bool save_as(AppContext& ctx, const std::string& path);

// File > Start recording / Stop recording: the journal of edits saved as a script
// (docs/script-format.md). Stopping asks where to save it; Cancel goes on recording. Opening
// or creating another scene ends a recording and asks the same.
// File > Open lesson: a script played in the window from pause to pause (ui/lesson.hpp) on a
// copy of its scene; unsaved changes are asked about first.
void request_open_lesson_dialog(AppContext& ctx);
// The file dialog for the Fit panel's data points (CSV or XYZ).
void request_load_points_dialog(AppContext& ctx);
void request_open_lesson(AppContext& ctx, const std::string& path);
bool open_lesson(AppContext& ctx, const std::string& path);
void restart_lesson(AppContext& ctx);

void start_recording(AppContext& ctx);
void request_stop_recording(AppContext& ctx);
bool save_recording(AppContext& ctx, const std::string& path);
void discard_recording(AppContext& ctx);

void undo(AppContext& ctx);
void redo(AppContext& ctx);

void fit_view(AppContext& ctx);
void toggle_presentation(AppContext& ctx);
void toggle_view_only(AppContext& ctx); // Shift+P: the 3D view alone fills the window

// Shows a modal error dialog.
void show_error(AppContext& ctx, const std::string& title, const std::string& message);

// Persists settings (layout, recent files) unless running headless.
void store_settings(AppContext& ctx);

} // namespace isoparm::ui
