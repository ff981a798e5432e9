// A lesson as its author edits it in the window (the lesson editor, "Add stop here"): a title,
// a one-line summary, the starting scene and its stops. A stop is the stretch of steps a
// presenter's Next runs, ending where the lesson halts, with the caption shown there. It reads
// and writes the script format (docs/script-format.md) and nothing else, so a saved lesson
// replays with `isoparm script`, and every step it does not edit is written back as it was.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/geom/status.hpp"

namespace isoparm::scene {

struct LessonStop {
    // The steps from the previous stop to this one: commands, view changes, captions and
    // expectations, in order (the pause that ends the stop is not kept here).
    std::vector<nlohmann::json> steps;
    // Whether a pause ends it: every stop but possibly the last (the lesson's end).
    bool paused = true;
};

struct LessonDraft {
    std::string title, summary;
    // The starting scene as the script writes it: a path relative to the lesson's folder, a
    // scene object inline, or null (the default scene).
    nlohmann::json scene;
    std::vector<LessonStop> stops;

    std::size_t size() const { return stops.size(); }
    // The caption shown at stop k: the last caption step in it, else "".
    std::string caption(std::size_t k) const;
    // Sets stop k's caption: rewrites its last caption step, or puts one first when it has
    // none; an empty text removes its caption steps.
    void set_caption(std::size_t k, const std::string& text);
    // Moves stop k one place earlier (up) or later; false at the ends. A stop keeps its steps
    // and pause, and the last stop stays the one without a pause.
    bool move(std::size_t k, bool up);
    // Removes stop k with its steps.
    void remove(std::size_t k);
    // How many steps of stop k are not captions (the work it does).
    std::size_t actions(std::size_t k) const;
    // The first step index in the script of stop k's steps (where its path begins), and the
    // index of the pause ending it (or one past its last step when it has none).
    std::size_t first_step(std::size_t k) const;
    std::size_t pause_step(std::size_t k) const;

    // The script: format, version, title, summary, scene and steps.
    nlohmann::json to_json() const;
};

// From a script's JSON (its format and version checked; the steps themselves are checked
// when the script is read with script_from_json).
geom::Expected<LessonDraft> lesson_draft_from_json(const nlohmann::json& script);

// A stop added at the end of a journal of steps ("Add stop here" while recording): the
// caption, then the pause. The steps since the last pause become that stop.
void add_stop(nlohmann::json& steps, const std::string& caption);

} // namespace isoparm::scene
