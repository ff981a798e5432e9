// Knot insertion, degree elevation and splitting at the indicator; de Boor's step control.
#include "ui/surface_actions.hpp"

#include <algorithm>

#include "core/doc/commands.hpp"
#include "core/geom/knots.hpp"
#include "ui/doc_access.hpp"

namespace isoparm::ui {

namespace {

const char* dir_name(geom::Dir d) {
    return d == geom::Dir::u ? "u" : "v";
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

ActionState insert_knot_state(const AppContext& ctx, geom::Dir dir) {
    const Current c = current(ctx, dir);
    ActionState a;
    if (!c.surface) {
        a.label = std::string("Insert knot in ") + dir_name(dir);
        a.why = "no surface";
        return a;
    }
    a.label = std::string("Insert knot ") + dir_name(dir) + " = " + geom::format_number(c.t);
    const int m = geom::multiplicity(c.surface->knots(dir), c.t);
    const int p = c.surface->degree(dir);
    const geom::Interval d = geom::domain(c.surface->knots(dir), p, c.surface->count(dir));
    if (!d.contains(c.t)) {
        a.why = "the indicator is outside this patch's domain";
    } else if (m >= p) {
        a.why = "the knot already has multiplicity " + std::to_string(m) + " = the degree";
    } else {
        a.enabled = true;
        if (m > 0) a.label += " (now x" + std::to_string(m) + ")";
    }
    return a;
}

ActionState elevate_state(const AppContext& ctx, geom::Dir dir) {
    const Current c = current(ctx, dir);
    ActionState a;
    a.label = std::string("Elevate degree in ") + dir_name(dir);
    if (!c.surface) {
        a.why = "no surface";
        return a;
    }
    a.label += " (" + std::to_string(c.surface->degree(dir)) + " to " +
               std::to_string(c.surface->degree(dir) + 1) + ")";
    a.enabled = true;
    return a;
}

ActionState split_state(const AppContext& ctx, geom::Dir dir) {
    const Current c = current(ctx, dir);
    ActionState a;
    if (!c.surface) {
        a.label = std::string("Split along ") + dir_name(dir);
        a.why = "no surface";
        return a;
    }
    a.label = std::string("Split at ") + dir_name(dir) + " = " + geom::format_number(c.t);
    const geom::Interval d =
        geom::domain(c.surface->knots(dir), c.surface->degree(dir), c.surface->count(dir));
    if (!(d.lo < c.t && c.t < d.hi))
        a.why = "move the indicator inside the patch (not on its edge) to split there";
    else
        a.enabled = true;
    return a;
}

void insert_knot_at_indicator(AppContext& ctx, geom::Dir dir) {
    const Current c = current(ctx, dir);
    if (!c.surface) return;
    ctx.seal();
    ctx.execute(doc::insert_knot(c.object->id, dir, c.t));
    ctx.seal();
}

void elevate_current(AppContext& ctx, geom::Dir dir) {
    const Current c = current(ctx, dir);
    if (!c.surface) return;
    ctx.seal();
    ctx.execute(doc::elevate_degree(c.object->id, dir));
    ctx.seal();
}

void split_at_indicator(AppContext& ctx, geom::Dir dir) {
    const Current c = current(ctx, dir);
    if (!c.surface) return;
    ctx.seal();
    // The split replaces the object (and may reallocate the list): keep its name first.
    const std::string name = c.object->name;
    if (ctx.execute(doc::split_object(c.object->id, dir, c.t)))
        ctx.ui.status = "Split " + name + " at " + dir_name(dir) + " = " +
                        geom::format_number(c.t) +
                        ": move the indicator to pick a subpatch (Surface > Continuity keeps "
                        "borders closed)";
    ctx.seal();
}

int deboor_step_count(const AppContext& ctx) {
    const geom::Surface* s = current_surface(ctx.doc);
    return s ? s->degree_u + s->degree_v + 1 : 0;
}

void deboor_step(AppContext& ctx, int delta) {
    DeBoorPlayer& p = ctx.ui.deboor;
    const int last = deboor_step_count(ctx);
    ctx.doc.display.deboor = true;
    p.playing = false;
    if (p.step < 0) p.step = delta > 0 ? -1 : last;
    p.step = std::clamp(p.step + delta, 0, last);
}

void deboor_toggle_play(AppContext& ctx, double now_seconds) {
    DeBoorPlayer& p = ctx.ui.deboor;
    ctx.doc.display.deboor = true;
    p.playing = !p.playing;
    if (p.playing) {
        if (p.step < 0 || p.step >= deboor_step_count(ctx)) p.step = 0;
        p.next_time = now_seconds + p.seconds_per_step;
    }
}

bool deboor_tick(AppContext& ctx, double now_seconds) {
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
