// A lesson played in the window: a script (docs/script-format.md) stepped through from stop
// to stop, its captions shown over the 3D view. Its commands go through the window's history,
// so the class can undo them and try things in between. A stop ends at each pause; a script
// without pauses (a recorded session) stops before each of its commands, undos and redos,
// and says what each step did where it has no captions of its own.
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
    std::size_t stop = 0;           // stops reached (1 at the first)
    std::string caption;            // the last caption reached
    std::string refused;            // a step the document refused (the lesson stops there)
    std::vector<std::string> unmet; // expectations of the last stretch that did not hold
    // Where each stop ends: the step index the run halts before (after a pause, or before a
    // recording's next command), the last one the number of steps.
    std::vector<std::size_t> halts;
    bool captioned = false; // the script has captions (else each stop says what it did)

    bool finished() const { return next >= script.steps.size() && stop >= halts.size(); }
    std::size_t stops() const { return halts.size(); }
};

// Sets halts and captioned from the script (after loading it, or after the editor changed it).
void prepare_lesson(Lesson& lesson);

// Runs the steps up to the next stop. Screenshots are skipped.
void lesson_next(AppContext& ctx);

} // namespace isoparm::ui
