// Stepping a lesson through the window's document: the script runner's steps on the window's
// history, with the camera and de Boor's step handed to the 3D view.
#include "ui/lesson.hpp"

#include <algorithm>
#include <cmath>

#include "ui/animation_actions.hpp"
#include "ui/app_context.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

namespace {

bool is_action(const scene::Step& s) {
    return std::holds_alternative<doc::CommandSpec>(s.action) ||
           std::holds_alternative<scene::UndoStep>(s.action) ||
           std::holds_alternative<scene::RedoStep>(s.action);
}

// The actions among the first `end` steps (all of them by default).
std::size_t action_count(const scene::Script& script, std::size_t end = SIZE_MAX) {
    const auto last = script.steps.begin() + static_cast<long>(std::min(end, script.steps.size()));
    return static_cast<std::size_t>(std::count_if(script.steps.begin(), last, is_action));
}

} // namespace

void prepare_lesson(Lesson& lesson) {
    const auto& steps = lesson.script.steps;
    lesson.halts.clear();
    lesson.captioned = std::any_of(steps.begin(), steps.end(), [](const scene::Step& s) {
        return std::holds_alternative<scene::CaptionStep>(s.action);
    });
    const bool paused = std::any_of(steps.begin(), steps.end(), [](const scene::Step& s) {
        return std::holds_alternative<scene::PauseStep>(s.action);
    });
    for (std::size_t k = 0; k < steps.size(); ++k) {
        if (paused && std::holds_alternative<scene::PauseStep>(steps[k].action))
            lesson.halts.push_back(k + 1); // the pause is part of its stop
        else if (!paused && is_action(steps[k]))
            lesson.halts.push_back(k); // a recording halts before each of its actions
    }
    if (lesson.halts.empty() || lesson.halts.back() != steps.size())
        lesson.halts.push_back(steps.size());
}

void lesson_next(AppContext& ctx) {
    if (!ctx.ui.lesson) return;
    Lesson& lesson = *ctx.ui.lesson;
    if (lesson.halts.empty()) prepare_lesson(lesson);
    if (lesson.stop >= lesson.halts.size()) return;
    lesson.unmet.clear();
    lesson.refused.clear();
    suspend_animation(ctx); // the steps act on the document, not an animation's frame
    scene::ScriptState state(ctx.doc, ctx.history);
    state.caption = lesson.caption;
    scene::ScriptResult result;
    const std::size_t halt = lesson.halts[lesson.stop];
    std::string did;
    ctx.seal();
    while (lesson.next < halt) {
        const scene::Step& step = lesson.script.steps[lesson.next];
        // A dry run: no screenshots; everything else acts on the window's document.
        if (geom::Status st = scene::run_step(step, state, {}, /*dry_run=*/true, result); !st) {
            lesson.refused = st.error().message + " (at " + st.error().path + ")";
            break;
        }
        ++lesson.next;
        if (const auto* cam = std::get_if<scene::CameraStep>(&step.action)) {
            ctx.ui.camera.yaw = cam->yaw_degrees * M_PI / 180.0;
            ctx.ui.camera.pitch = cam->pitch_degrees * M_PI / 180.0;
        }
        if (std::holds_alternative<scene::DeBoorStep>(step.action))
            ctx.ui.deboor.step = state.deboor_step;
        // An animate step puts its target on the Animate slider and plays it (never an edit).
        if (const auto* anim = std::get_if<scene::AnimateStep>(&step.action)) {
            if (anim->stop) {
                stop_animation(ctx);
            } else if (start_animation(ctx, anim->target, anim->seconds, anim->repeat,
                                       anim->play)) {
                ctx.ui.modeler.animation.player.speed = anim->speed;
                ctx.ui.modeler.animation.player.seek(anim->at);
            }
        }
        if (std::holds_alternative<doc::CommandSpec>(step.action) && ctx.history.can_undo())
            did = ctx.history.undo_label();
        else if (std::holds_alternative<scene::UndoStep>(step.action))
            did = "Undo";
        else if (std::holds_alternative<scene::RedoStep>(step.action))
            did = "Redo";
    }
    if (lesson.refused.empty()) ++lesson.stop;
    ctx.seal();
    normalize_selection(ctx.doc);
    lesson.unmet = result.failed_expects;
    if (lesson.captioned) {
        lesson.caption = state.caption;
    } else if (did.empty()) {
        // A recorded session: its starting scene, and what Next will do.
        lesson.caption = "The recording's starting scene. Next replays it one step at a time (" +
                         std::to_string(action_count(lesson.script)) + " steps).";
    } else {
        lesson.caption = "Step " + std::to_string(action_count(lesson.script, lesson.next)) +
                         " of " + std::to_string(action_count(lesson.script)) + ": " + did + ".";
    }
}

} // namespace isoparm::ui
