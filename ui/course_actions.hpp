// Lessons and exercises in the window (docs/lessons.md): exercises opened and checked, a
// lesson's stops played from any one, and lessons written while recording (stops with
// captions, expectations picked from the document's facts) and edited in the lesson editor.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "ui/app_context.hpp"

namespace isoparm::ui {

// Exercises: opened on an untitled copy of their starting scene (unsaved changes are asked
// about first); the Exercise panel stays open when another scene is opened, so a student can
// check a saved answer too.
void request_open_exercise_dialog(AppContext& ctx);
void request_open_exercise(AppContext& ctx, const std::string& path);
bool open_exercise(AppContext& ctx, const std::string& path);
// Grades the document as it is now (core/scene/exercise.hpp) into the Exercise panel.
void check_exercise(AppContext& ctx);
void close_exercise(AppContext& ctx);

// The playing lesson from its start up to stop `stop` (0 the first), on a fresh copy of its
// scene.
void lesson_goto(AppContext& ctx, std::size_t stop);

// While recording: a stop (its caption, then a pause) or expectations added to the journal.
void add_stop_here(AppContext& ctx, const std::string& caption);
void add_expectations(AppContext& ctx, const std::vector<scene::Fact>& facts);
// Opens the dialogs that ask for them (at the next frame).
void request_add_stop(AppContext& ctx);
void request_add_expectation(AppContext& ctx);

// Stops the recording and opens it in the lesson editor, with the save dialog in the user's
// lessons folder.
void save_recording_as_lesson(AppContext& ctx);
// The lesson editor on the playing lesson (as its file holds it), else empty.
void open_lesson_editor(AppContext& ctx);
// The save dialog for the editor's lesson: the user's lessons folder unless the lesson is
// already there.
void request_save_lesson_dialog(AppContext& ctx);
// Writes the editor's lesson to `path` (atomically; a relative starting scene is written
// inline when the folder changes, so the lesson opens wherever it goes). Errors go to the
// editor's note; returns whether written.
bool save_lesson(AppContext& ctx, const std::string& path);
// Plays the editor's lesson (as edited, not saved) from its start to stop `stop`, on a fresh
// copy of its scene: unsaved changes are asked about first (request_), or not.
void request_play_draft(AppContext& ctx, std::size_t stop);
void play_draft_from(AppContext& ctx, std::size_t stop);
// Whether the editor's lesson replays: "" or the first step that cannot be carried out.
std::string draft_problem(const LessonEditorState& editor);

} // namespace isoparm::ui
