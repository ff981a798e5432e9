// Trimming in the window: a hole is one more clockwise loop in the surface's trim, a drawn
// outer loop replaces the outer one (set_trim validates the result against the other loops and
// the domain, so an overlap or a loop reaching out of the domain is refused with the loop
// named).
#include "ui/trim_actions.hpp"

#include <algorithm>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "core/doc/commands_trim.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/status.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

namespace {

struct Target {
    const doc::Object* object = nullptr;
    const doc::SurfaceObject* surface = nullptr;
};

Target target(const AppContext& ctx) {
    Target t;
    if (!current_surface(ctx.doc, &t.object) || !t.object) return {};
    t.surface = std::get_if<doc::SurfaceObject>(&t.object->shape);
    return t.surface ? t : Target{};
}

ActionState state_of(std::string label, const doc::Command& cmd, const doc::Document& d) {
    ActionState a{std::move(label), true, {}};
    if (const geom::Status st = cmd.check(d); !st) {
        a.enabled = false;
        a.why = st.error().message;
    }
    return a;
}

// The current trim with a circle about the indicator added as a hole (clockwise), or the
// reason none can be made.
geom::Expected<geom::Trim> with_hole(const AppContext& ctx, const Target& t) {
    const geom::ParamRect box = geom::domain(t.surface->surface);
    const double radius = punched_hole_radius * std::min(box.u.hi - box.u.lo, box.v.hi - box.v.lo);
    auto hole = geom::circle_loop(indicator_params(ctx.doc, *t.object), radius, true);
    if (!hole) return hole.error();
    geom::Trim trim = t.surface->trim;
    trim.holes.push_back(std::move(*hole));
    return trim;
}

// Runs `cmd` as one undo step when `state` allows it; what happened, or the refusal after
// `refused`, becomes the action's note (the status bar and the tracing panel).
void run_noted(AppContext& ctx, const ActionState& state, const std::string& refused,
               std::unique_ptr<doc::Command> cmd, const std::string& done) {
    if (!state.enabled || !cmd) {
        note_action(ctx, refused + state.why, true);
        return;
    }
    ctx.seal();
    if (ctx.execute(std::move(cmd)))
        note_action(ctx, done, false);
    else
        note_action(ctx, ctx.ui.status, true);
    ctx.seal();
}

// Twice the signed area of the polygon (positive: counter-clockwise).
double signed_area2(const std::vector<glm::dvec2>& p) {
    double a = 0;
    for (std::size_t k = 0; k < p.size(); ++k) {
        const glm::dvec2 q = p[k], r = p[(k + 1) % p.size()];
        a += q.x * r.y - r.x * q.y;
    }
    return a;
}

// The trim with the drawn polygon as one more hole or as the outer loop.
geom::Trim with_drawn_loop(const doc::SurfaceObject& s, const TrimDrawing& d) {
    std::vector<glm::dvec2> corners = d.corners;
    if ((signed_area2(corners) > 0) == d.hole) std::reverse(corners.begin(), corners.end());
    geom::Trim trim = s.trim;
    if (d.hole)
        trim.holes.push_back(geom::polygon_loop(corners));
    else
        trim.outer = geom::polygon_loop(corners);
    return trim;
}

ActionState draw_state(const AppContext& ctx, bool hole) {
    const std::string label =
        hole ? "Draw a hole in the tracing square" : "Draw the outer loop in the tracing square";
    if (!target(ctx).surface) return {label, false, "select a surface"};
    if (ctx.ui.trim_drawing.active())
        return {label, false, "a loop is being drawn: Enter closes it, Escape abandons it"};
    return {label, true, {}};
}

void start_drawing(AppContext& ctx, bool hole) {
    const Target t = target(ctx);
    if (!t.surface) return;
    ctx.ui.trim_drawing = {t.object->id, hole, {}};
    ctx.ui.status = std::string("Drawing ") + (hole ? "a hole" : "the outer loop") +
                    ": click its corners in the tracing square; Enter or a click on the first "
                    "corner closes it, Backspace takes a corner back, Escape abandons it.";
}

} // namespace

ActionState draw_hole_state(const AppContext& ctx) {
    return draw_state(ctx, true);
}

ActionState draw_outer_state(const AppContext& ctx) {
    return draw_state(ctx, false);
}

void start_drawing_hole(AppContext& ctx) {
    start_drawing(ctx, true);
}

void start_drawing_outer(AppContext& ctx) {
    start_drawing(ctx, false);
}

void add_loop_corner(AppContext& ctx, glm::dvec2 uv) {
    TrimDrawing& d = ctx.ui.trim_drawing;
    if (!d.active()) return;
    d.corners.push_back(uv);
    ctx.ui.status = "Corner " + std::to_string(d.corners.size()) + " at (u, v) = (" +
                    geom::format_short(uv.x) + ", " + geom::format_short(uv.y) + ")" +
                    (d.corners.size() >= 3 ? ": Enter closes the loop." : ".");
}

void take_back_loop_corner(AppContext& ctx) {
    TrimDrawing& d = ctx.ui.trim_drawing;
    if (d.active() && !d.corners.empty()) d.corners.pop_back();
}

void cancel_loop_drawing(AppContext& ctx) {
    if (!ctx.ui.trim_drawing.active()) return;
    ctx.ui.trim_drawing = {};
    ctx.ui.status = "Loop abandoned: the trim is as it was.";
}

void close_drawn_loop(AppContext& ctx) {
    TrimDrawing& d = ctx.ui.trim_drawing;
    if (!d.active()) return;
    const doc::Object* o = ctx.doc.find(d.object);
    const auto* s = o ? std::get_if<doc::SurfaceObject>(&o->shape) : nullptr;
    if (!s) { // the surface went (undo, delete) while the loop was drawn
        d = {};
        return;
    }
    if (d.corners.size() < 3) {
        note_action(ctx,
                    "A loop needs at least 3 corners (" + std::to_string(d.corners.size()) +
                        " so far): click more in the tracing square, or Escape abandons it.",
                    true);
        return;
    }
    const bool hole = d.hole;
    ctx.seal();
    if (ctx.execute(doc::set_trim(d.object, with_drawn_loop(*s, d)))) {
        d = {};
        note_action(ctx,
                    hole ? "Hole added: the region inside it is cut away."
                         : "Outer loop set: the surface keeps only the region inside it.",
                    false);
    } else {
        // The corners stay: Backspace and new clicks mend the loop.
        note_action(ctx, "The loop is refused: " + ctx.ui.status, true);
    }
    ctx.seal();
}

ActionState punch_hole_state(const AppContext& ctx) {
    const std::string label = "Cut a round hole at the indicator";
    const Target t = target(ctx);
    if (!t.surface) return {label, false, "select a surface"};
    auto trim = with_hole(ctx, t);
    if (!trim) return {label, false, trim.error().message};
    return state_of(label, *doc::set_trim(t.object->id, std::move(*trim)), ctx.doc);
}

ActionState remove_trim_state(const AppContext& ctx) {
    const Target t = target(ctx);
    if (!t.surface) return {"Remove trim", false, "select a surface"};
    const int loops = t.surface->trim.loop_count();
    std::string label = "Remove trim";
    if (loops > 0) label += " (" + std::to_string(loops) + (loops == 1 ? " loop)" : " loops)");
    return state_of(label, *doc::remove_trim(t.object->id), ctx.doc);
}

void punch_hole_at_indicator(AppContext& ctx) {
    const Target t = target(ctx);
    if (!t.surface) return;
    const ActionState state = punch_hole_state(ctx);
    auto trim = with_hole(ctx, t);
    if (state.enabled && !trim) return;
    const int holes = trim ? static_cast<int>(trim->holes.size()) : 0;
    run_noted(ctx, state,
              "Cannot cut a hole: ", trim ? doc::set_trim(t.object->id, std::move(*trim)) : nullptr,
              "Cut hole " + std::to_string(holes - 1) +
                  ": the surface keeps its points and knots; its trim has " +
                  std::to_string(holes) + (holes == 1 ? " hole" : " holes") +
                  " (the indicator inside is cut away).");
}

void remove_trim_current(AppContext& ctx) {
    const Target t = target(ctx);
    if (!t.surface) return;
    run_noted(ctx, remove_trim_state(ctx),
              "Cannot remove the trim: ", doc::remove_trim(t.object->id),
              "Trim removed: the whole domain is kept (Ctrl+Z brings the loops back).");
}

} // namespace isoparm::ui
