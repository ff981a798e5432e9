// Stepping a lesson through the window's document: the script runner's steps on the window's
// history, with the camera and de Boor's step handed to the 3D view.
#include "ui/lesson.hpp"

#include <algorithm>
#include <cmath>

#include "ui/animation_actions.hpp"
#include "ui/app_context.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

std::size_t Lesson::pauses() const {
    return static_cast<std::size_t>(
        std::count_if(script.steps.begin(), script.steps.end(), [](const scene::Step& s) {
            return std::holds_alternative<scene::PauseStep>(s.action);
        }));
}

std::size_t Lesson::pauses_done() const {
    const auto end = script.steps.begin() + static_cast<long>(std::min(next, script.steps.size()));
    return static_cast<std::size_t>(
        std::count_if(script.steps.begin(), end, [](const scene::Step& s) {
            return std::holds_alternative<scene::PauseStep>(s.action);
        }));
}

void lesson_next(AppContext& ctx) {
    if (!ctx.ui.lesson) return;
    Lesson& lesson = *ctx.ui.lesson;
    lesson.unmet.clear();
    lesson.refused.clear();
    suspend_animation(ctx); // the steps act on the document, not an animation's frame
    scene::ScriptState state(ctx.doc, ctx.history);
    state.caption = lesson.caption;
    scene::ScriptResult result;
    ctx.seal();
    while (!lesson.finished()) {
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
        if (std::holds_alternative<scene::PauseStep>(step.action)) break;
    }
    ctx.seal();
    normalize_selection(ctx.doc);
    lesson.caption = state.caption;
    lesson.unmet = result.failed_expects;
}

} // namespace isoparm::ui
