// Animations in the window: a preview shown from the start of a frame to its end, never a
// command until Keep.
#include "ui/animation_actions.hpp"

#include "ui/actions.hpp"
#include "ui/view/kinds/kind_view.hpp"

namespace isoparm::ui {

namespace {

void take_back(AppContext& ctx) {
    AnimationState& a = ctx.ui.modeler.animation;
    if (a.preview) {
        doc::restore_preview(ctx.doc, *a.preview);
        a.preview.reset();
    }
}

} // namespace

bool start_animation(AppContext& ctx, const doc::AnimationTarget& target, double seconds,
                     doc::Repeat repeat, bool play) {
    AnimationState& a = ctx.ui.modeler.animation;
    take_back(ctx);
    if (!a.open) a.focus = true;
    a.open = true;
    if (geom::Status st = doc::check_target(ctx.doc, target); !st) {
        a.error = st.error().message;
        a.active = false;
        ctx.ui.status = "Animate: " + a.error;
        return false;
    }
    a.error.clear();
    a.active = true;
    a.player = AnimationPlayer{};
    a.player.target = target;
    a.player.seconds = seconds;
    a.player.repeat = repeat;
    a.last_time = -1;
    if (play) a.player.play();
    return true;
}

void stop_animation(AppContext& ctx) {
    take_back(ctx);
    AnimationState& a = ctx.ui.modeler.animation;
    a.active = false;
    a.player.pause();
    a.deboor_step = -1;
}

void keep_animation_value(AppContext& ctx) {
    AnimationState& a = ctx.ui.modeler.animation;
    if (!a.active) return;
    take_back(ctx);
    a.player.pause();
    const doc::AnimationTarget& t = a.player.target;
    const double value = doc::value_at(t, a.player.phase);
    if (t.kind == doc::AnimatedKind::indicator_line ||
        t.kind == doc::AnimatedKind::indicator_circle) {
        ctx.doc.view.indicator = doc::indicator_at(t, a.player.phase); // view state, kept as is
        return;
    }
    if (t.kind == doc::AnimatedKind::deboor_step) {
        ctx.ui.deboor.step = doc::step_at(t, a.player.phase);
        return;
    }
    std::unique_ptr<doc::Command> keep = doc::keep_value(ctx.doc, t, value);
    if (!keep) return;
    ctx.seal();
    ctx.execute(std::move(keep));
    ctx.seal();
}

bool animation_begin_frame(AppContext& ctx, double now) {
    AnimationState& a = ctx.ui.modeler.animation;
    if (!a.active) return false;
    if (a.last_time >= 0) a.player.advance(now - a.last_time);
    a.last_time = now;
    const doc::AnimationTarget& t = a.player.target;
    if (t.kind == doc::AnimatedKind::deboor_step) {
        a.deboor_step = doc::step_at(t, a.player.phase);
        ctx.ui.deboor.step = a.deboor_step;
        return a.player.playing;
    }
    if (doc::check_target(ctx.doc, t).ok() == false) { // the object went away (undo, delete)
        stop_animation(ctx);
        return false;
    }
    a.shown_value = doc::value_at(t, a.player.phase);
    auto preview =
        doc::show_preview(ctx.doc, t, a.shown_value, doc::indicator_at(t, a.player.phase));
    if (!preview) {
        a.error = preview.error().message;
        a.player.pause();
        return false;
    }
    a.preview = std::move(preview).value();
    return a.player.playing;
}

void animation_end_frame(AppContext& ctx) {
    take_back(ctx);
}

void suspend_animation(AppContext& ctx) {
    AnimationState& a = ctx.ui.modeler.animation;
    if (!a.preview) return;
    take_back(ctx);
    a.player.pause();
}

doc::AnimationTarget weight_target_of_selection(const doc::Document& doc) {
    doc::AnimationTarget t;
    t.kind = doc::AnimatedKind::weight;
    t.object = doc.view.selection.object;
    t.i = doc.view.selection.i;
    t.j = doc.view.selection.j;
    if (const doc::Object* o = doc.find(t.object); o && !two_index_points(o->shape)) t.j = -1;
    t.from = 0;
    t.to = 5;
    return t;
}

} // namespace isoparm::ui
