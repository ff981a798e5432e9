// The window's state for lessons and exercises (ui/course_actions.hpp): the lesson editor's
// draft, the exercise being worked on and its last Check, the authoring dialogs, and where
// the caption box was put. None of it is document data.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/scene/exercise.hpp"
#include "core/scene/facts.hpp"
#include "core/scene/lesson_draft.hpp"
#include "ui/view/layout.hpp"

namespace isoparm::ui {

// The lesson editor panel: a lesson's title, summary and stops, edited in place.
struct LessonEditorState {
    bool open = false;
    std::optional<scene::LessonDraft> draft;
    std::string path;     // the file it came from or was saved to ("" not saved yet)
    std::string base_dir; // where a relative "scene" path starts from
    int selected = 0;     // the stop shown below the list
    std::string caption;  // the selected stop's caption as it is being typed
    int caption_of = -1;  // the stop `caption` was filled from
    std::string problem;  // why the draft does not replay (the step and the reason), or ""
    std::string note;     // the last save or play, for the user
    bool dirty = false;   // changed since it was read or saved
};

// An exercise being worked on (Lessons > Exercises): its task and the last Check's answer.
struct ExerciseState {
    std::string path;
    std::optional<scene::Exercise> exercise;
    std::optional<scene::Grade> grade;
    int hints_shown = 0; // general hints revealed so far
    // The history when Check ran: the panel says so when the document changed since.
    std::size_t history_at_check = 0;
    const void* top_at_check = nullptr;
    // The panel's place: chosen off the object (as the caption box), again when its height
    // changes, until the user drags it.
    Rect placed{};
    bool placed_once = false, user_moved = false;
    float last_height = 0;
};

// Where the caption box is: placed by the stop it shows, then the user's if dragged.
struct CaptionBoxState {
    std::size_t placed_for = static_cast<std::size_t>(-1); // the stop it was placed for
    Rect placed{}; // where it was put (the user moved it when it is elsewhere)
    bool user_moved = false;
    float last_height = 0; // the box's height last frame
    // Frames in a row in which the box was placed again (its real height known, the camera
    // framed, the point clear): the window draws only on input, so it asks for the next frame
    // until the box stays put (at most a few).
    int settling = 0;
};

struct CourseState {
    LessonEditorState editor;
    ExerciseState exercise;
    bool exercise_open = false;
    // Lessons > Add stop here... (while recording): the caption typed.
    bool add_stop_request = false;
    std::string stop_caption;
    // Lessons > Add expectation... (while recording): the facts offered and which are ticked.
    bool add_expectation_request = false;
    std::vector<scene::Fact> facts;
    std::vector<char> chosen;
    CaptionBoxState caption_box;
    // Where the lesson editor and the Exercise panel were last frame (the caption box keeps
    // clear of them).
    std::vector<Rect> floating;
};

} // namespace isoparm::ui
