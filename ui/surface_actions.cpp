// Knot insertion, degree elevation and splitting at the indicator; de Boor's step control.
#include "ui/surface_actions.hpp"

#include <algorithm>

#include "core/doc/commands.hpp"
#include "core/doc/patches.hpp"
#include "core/geom/deboor.hpp"
#include "core/geom/knots.hpp"
#include "ui/view/camera.hpp"
#include "ui/view/deboor_overlay.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/triangle_domain.hpp"

namespace isoparm::ui {

namespace {

const char* dir_name(geom::Dir d) {
    return d == geom::Dir::u ? "u" : "v";
}

geom::Dir other_dir(geom::Dir d) {
    return d == geom::Dir::u ? geom::Dir::v : geom::Dir::u;
}

struct Current {
    const doc::Object* object = nullptr;
    const geom::Surface* surface = nullptr;
    double t = 0; // the indicator's parameter in the chosen direction
};

Current current(const AppContext& ctx, geom::Dir dir) {
    Current c;
    c.surface = current_surface(ctx.doc, &c.object);
    if (c.surface) {
        const glm::dvec2 uv = indicator_params(ctx.doc, *c.object);
        c.t = dir == geom::Dir::u ? uv.x : uv.y;
    }
    return c;
}

} // namespace

namespace {

// Enabled exactly when the command would apply; otherwise the command's own refusal is the
// reason (menus never repeat the command's rules), with what a student should make of a refusal
// of the code `teach_about` added in words of the workstation.
ActionState state_of(std::string label, const doc::Command& cmd, const doc::Document& d,
                     geom::ErrorCode teach_about = geom::ErrorCode::internal,
                     const std::string& lesson = {}) {
    ActionState a;
    a.label = std::move(label);
    const geom::Status st = cmd.check(d);
    a.enabled = st.ok();
    if (!st) {
        a.why = st.error().message;
        if (st.error().code == teach_about && !lesson.empty()) a.why += " (" + lesson + ")";
    }
    return a;
}

} // namespace

ActionState insert_knot_state(const AppContext& ctx, geom::Dir dir) {
    const Current c = current(ctx, dir);
    if (!c.surface) return {std::string("Insert knot in ") + dir_name(dir), false, "no surface"};
    std::string label =
        std::string("Insert knot ") + dir_name(dir) + " = " + geom::format_short(c.t);
    const int m = geom::multiplicity(c.surface->knots(dir), c.t);
    if (m > 0) label += " (now x" + std::to_string(m) + ")";
    // A knot of multiplicity p already leaves only C0 there (Piegl & Tiller sec. 2.3): another
    // copy would add nothing, which is why insertion stops at the degree.
    return state_of(label, *doc::insert_knot(c.object->id, dir, c.t), ctx.doc,
                    geom::ErrorCode::multiplicity,
                    "the knot already has multiplicity " + std::to_string(m) +
                        " = the degree: the surface is only C0 there");
}

ActionState elevate_state(const AppContext& ctx, geom::Dir dir) {
    const Current c = current(ctx, dir);
    std::string label = std::string("Elevate degree in ") + dir_name(dir);
    if (!c.surface) return {label, false, "no surface"};
    label += " (" + std::to_string(c.surface->degree(dir)) + " to " +
             std::to_string(c.surface->degree(dir) + 1) + ")";
    return state_of(label, *doc::elevate_degree(c.object->id, dir), ctx.doc);
}

ActionState split_state(const AppContext& ctx, geom::Dir dir) {
    const Current c = current(ctx, dir);
    if (!c.surface) return {std::string("Split along ") + dir_name(dir), false, "no surface"};
    return state_of(std::string("Split at ") + dir_name(dir) + " = " + geom::format_short(c.t),
                    *doc::split_object(c.object->id, dir, c.t), ctx.doc, geom::ErrorCode::domain,
                    "move the indicator inside the patch, not on its edge, to split there");
}

void note_action(AppContext& ctx, std::string text, bool refused) {
    ctx.ui.status = text;
    ctx.ui.action_note = {std::move(text), refused, ctx.history.size(), ctx.history.undo_label()};
}

const ActionNote* current_action_note(const AppContext& ctx) {
    const ActionNote& n = ctx.ui.action_note;
    if (n.text.empty() || n.history_size != ctx.history.size() ||
        n.undo_label != ctx.history.undo_label())
        return nullptr;
    return &n;
}

void insert_knot_at_indicator(AppContext& ctx, geom::Dir dir) {
    const Current c = current(ctx, dir);
    if (!c.surface) return;
    const std::string what = std::string("knot ") + dir_name(dir) + " = " + geom::format_short(c.t);
    // Refused before the command runs, with the reason the menu gives.
    const int before = geom::multiplicity(c.surface->knots(dir), c.t);
    if (const ActionState state = insert_knot_state(ctx, dir); !state.enabled) {
        note_action(ctx, "Cannot insert " + what + ": " + state.why, true);
        return;
    }
    const int n = c.surface->count(dir), other = c.surface->count(other_dir(dir));
    ctx.seal();
    auto cmd = doc::insert_knot(c.object->id, dir, c.t);
    const doc::Command* applied = cmd.get();
    if (!ctx.execute(std::move(cmd))) {
        note_action(ctx, ctx.ui.status, true);
        ctx.seal();
        return;
    }
    auto net = [&](int along) {
        return dir == geom::Dir::u ? std::to_string(along) + " x " + std::to_string(other)
                                   : std::to_string(other) + " x " + std::to_string(along);
    };
    std::string text = "Inserted " + what + " (multiplicity " + std::to_string(before + 1) +
                       "): same shape, the net grows from " + net(n) + " to " + net(n + 1) +
                       " points.";
    // The command is in the history now: its record still answers.
    if (const std::string change = doc::refinement_type_change(*applied); !change.empty())
        text += " The " + change + ": a Bezier surface has no interior knots.";
    note_action(ctx, text, false);
    ctx.seal();
}

void elevate_current(AppContext& ctx, geom::Dir dir) {
    const Current c = current(ctx, dir);
    if (!c.surface) return;
    const int p = c.surface->degree(dir);
    ctx.seal();
    if (ctx.execute(doc::elevate_degree(c.object->id, dir)))
        note_action(ctx,
                    std::string("Degree in ") + dir_name(dir) + " raised from " +
                        std::to_string(p) + " to " + std::to_string(p + 1) +
                        ": same shape, more control points.",
                    false);
    else
        note_action(ctx, ctx.ui.status, true);
    ctx.seal();
}

void split_at_indicator(AppContext& ctx, geom::Dir dir) {
    const Current c = current(ctx, dir);
    if (!c.surface) return;
    if (const ActionState state = split_state(ctx, dir); !state.enabled) {
        note_action(ctx, "Cannot split: " + state.why, true);
        return;
    }
    ctx.seal();
    // The split replaces the object (and may reallocate the list): keep its name first.
    const std::string name = c.object->name;
    auto cmd = doc::split_object(c.object->id, dir, c.t);
    const doc::Command* applied = cmd.get();
    if (ctx.execute(std::move(cmd))) {
        // The label says which neighbours were refined so the borders pair up.
        const std::string label = applied->label();
        // "Split at v = 0.5 (...)" -> "Split wave.1 at v = 0.5 (...)".
        std::string text =
            label.rfind("Split ", 0) == 0 ? "Split " + name + label.substr(5) : label;
        text += ". Move the indicator to pick a subpatch";
        text += ctx.doc.continuity == doc::Continuity::off
                    ? " (Keep across borders: C0 or C1 keeps them closed or smooth)."
                    : ".";
        note_action(ctx, text, false);
    } else {
        note_action(ctx, ctx.ui.status, true);
    }
    ctx.seal();
}

void set_continuity(AppContext& ctx, doc::Continuity c) {
    const bool changed = ctx.doc.continuity != c;
    ctx.doc.continuity = c;
    if (changed && c != doc::Continuity::off) conform_current_group(ctx);
}

void conform_current_group(AppContext& ctx) {
    const doc::Object* obj = nullptr;
    if (!current_surface(ctx.doc, &obj) || obj->patch_group == 0) return;
    const std::uint64_t group = obj->patch_group;
    if (doc::conforming_insertions(ctx.doc, group).empty()) return;
    ctx.seal();
    auto cmd = doc::conform_borders(group);
    const doc::Command* applied = cmd.get();
    if (ctx.execute(std::move(cmd))) {
        const std::vector<doc::SharedBorder> borders = doc::shared_borders(ctx.doc, group);
        const auto paired = std::count_if(borders.begin(), borders.end(),
                                          [](const doc::SharedBorder& b) { return b.conforming; });
        note_action(ctx,
                    applied->label() + ": same shape; " + std::to_string(paired) + " of " +
                        std::to_string(borders.size()) + " borders pair up, so moving a point " +
                        "keeps them " + doc::continuity_name(ctx.doc.continuity) + ".",
                    false);
    } else
        note_action(ctx, ctx.ui.status, true);
    ctx.seal();
}

int deboor_step_count(const AppContext& ctx) {
    // A selected triangle: de Casteljau's levels 0 (the control points) .. n (the point S),
    // Farin 17.3.
    if (const geom::TrianglePatch* t = selected_triangle(ctx.doc)) return t->degree;
    const geom::Surface* s = current_surface(ctx.doc);
    return s ? s->degree_u + s->degree_v + 1 : 0;
}

void deboor_step(AppContext& ctx, int delta) {
    DeBoorPlayer& p = ctx.ui.deboor;
    const int last = deboor_step_count(ctx);
    ctx.doc.view.display.deboor = true;
    p.playing = false;
    if (p.step < 0) p.step = delta > 0 ? -1 : last;
    p.step = std::clamp(p.step + delta, 0, last);
}

void deboor_toggle_play(AppContext& ctx, double now_seconds) {
    DeBoorPlayer& p = ctx.ui.deboor;
    ctx.doc.view.display.deboor = true;
    p.playing = !p.playing;
    if (p.playing) {
        if (p.step < 0 || p.step >= deboor_step_count(ctx)) p.step = 0;
        p.next_time = now_seconds + p.seconds_per_step;
    }
}

void clamp_deboor_step(AppContext& ctx) {
    DeBoorPlayer& p = ctx.ui.deboor;
    const int last = deboor_step_count(ctx);
    if (p.step > last) p.step = last;
    if (p.playing && p.step >= last) p.playing = false;
}

void zoom_to_acting_patch(AppContext& ctx) {
    const doc::Object* obj = nullptr;
    std::vector<glm::dvec3> pts;
    if (const geom::TrianglePatch* t = selected_triangle(ctx.doc)) {
        // A Bezier triangle has no knots: every b_ijk acts everywhere.
        for (std::size_t k = 0; k < t->points.size(); ++k)
            if (t->weights[k] != 0) pts.push_back(t->points[k]);
    } else if (const geom::Surface* s = current_surface(ctx.doc, &obj)) {
        const glm::dvec2 uv = indicator_params(ctx.doc, *obj);
        pts = deboor_acting_points(geom::deboor_surface(*s, uv.x, uv.y), s->degree_v);
    }
    if (pts.empty()) return;
    const Rect& r = ctx.ui.view_rect;
    // fit_distance stays the whole scene's: the Zoom slider then reads above 100%.
    fit_to_points(ctx.ui.camera, pts, r.h > 0 ? static_cast<double>(r.w) / r.h : 1.6);
    ctx.doc.view.display.deboor = true;
}

bool deboor_tick(AppContext& ctx, double now_seconds) {
    clamp_deboor_step(ctx);
    DeBoorPlayer& p = ctx.ui.deboor;
    if (!p.playing) return false;
    if (now_seconds >= p.next_time) {
        p.step = std::min(p.step + 1, deboor_step_count(ctx));
        p.next_time = now_seconds + p.seconds_per_step;
        if (p.step >= deboor_step_count(ctx)) p.playing = false;
    }
    return p.playing;
}

} // namespace isoparm::ui
