// A lesson played in the window: a script (docs/script-format.md) stepped through from pause to
// pause, its captions shown over the 3D view. Its commands go through the window's history,
// so the class can undo them and try things in between.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/scene/script.hpp"

namespace isoparm::ui {

struct AppContext;

struct Lesson {
    std::string path;
    scene::Script script;
    std::size_t next = 0;           // the next step to run
    std::string caption;            // the last caption reached
    std::string refused;            // a step the document refused (the lesson stops there)
    std::vector<std::string> unmet; // expectations of the last stretch that did not hold
    bool finished() const { return next >= script.steps.size(); }
    std::size_t pauses() const;      // how many stops the lesson has
    std::size_t pauses_done() const; // how many of them are behind
};

// Runs the steps up to and including the next pause (or to the end). Screenshots are skipped.
void lesson_next(AppContext& ctx);

} // namespace isoparm::ui
