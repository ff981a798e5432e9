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
#include "core/geom/trim/projected_loop.hpp"
#include "core/geom/trim/trim_flatten.hpp"
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

// The loop turned to run the way its role wants (holes clockwise, the outer loop
// counter-clockwise), judged by the area its flattened polyline encloses.
geom::TrimLoop oriented(geom::TrimLoop loop, bool hole) {
    const double area = geom::twice_signed_area(geom::flatten_loop(loop, {}).points);
    return (area > 0) == hole ? geom::reversed(loop) : loop;
}

// The direction a curve drawn in `plane` is projected along; nullopt for a 3D curve.
std::optional<glm::dvec3> plane_normal(doc::CurvePlane plane) {
    switch (plane) {
    case doc::CurvePlane::xy:
        return glm::dvec3(0, 0, 1);
    case doc::CurvePlane::xz:
        return glm::dvec3(0, 1, 0);
    case doc::CurvePlane::yz:
        return glm::dvec3(1, 0, 0);
    case doc::CurvePlane::free3d:
        return std::nullopt;
    }
    return std::nullopt;
}

const char* seen_along(doc::CurvePlane plane) {
    return plane == doc::CurvePlane::xy ? "z" : plane == doc::CurvePlane::xz ? "y" : "x";
}

// The trim with `loop`, turned to run the right way, as one more hole or as the outer loop.
geom::Trim with_loop(geom::Trim trim, geom::TrimLoop loop, bool hole) {
    loop = oriented(std::move(loop), hole);
    if (hole)
        trim.holes.push_back(std::move(loop));
    else
        trim.outer = std::move(loop);
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
                    "corner closes it, Backspace takes a corner back, C makes it smooth or a "
                    "polygon, Escape abandons it.";
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

geom::TrimLoop drawn_loop(const std::vector<glm::dvec2>& corners, bool smooth) {
    return smooth ? geom::smooth_loop(corners) : geom::polygon_loop(corners);
}

void toggle_smooth_loops(AppContext& ctx) {
    ctx.ui.smooth_loops = !ctx.ui.smooth_loops;
    if (ctx.ui.trim_drawing.active())
        ctx.ui.status = ctx.ui.smooth_loops
                            ? "Smooth loop: the corners are the control points of a closed cubic "
                              "B-spline (C: a polygon again)."
                            : "Polygon loop: straight edges through the corners (C: smooth).";
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
    if (ctx.execute(doc::set_trim(
            d.object, with_loop(s->trim, drawn_loop(d.corners, ctx.ui.smooth_loops), hole)))) {
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

ActionState trim_by_curve_state(const AppContext& ctx, const doc::Object& curve) {
    const doc::CurveObject* c = curve.curve_object();
    std::string label = curve.name;
    if (c && plane_normal(c->plane))
        label += std::string(" (seen along ") + seen_along(c->plane) + ")";
    if (!c) return {label, false, "not a curve"};
    if (!target(ctx).surface) return {label, false, "select the surface to trim"};
    if (!plane_normal(c->plane))
        return {label, false,
                "a curve drawn in 3D has no plane to project along: set its plane to xy, xz or "
                "yz in the curve designer"};
    return {label, true, {}};
}

void trim_by_curve(AppContext& ctx, std::uint64_t curve, bool hole) {
    const Target t = target(ctx);
    const doc::Object* o = ctx.doc.find(curve);
    if (!t.surface || !o || !o->curve_object()) return;
    const ActionState state = trim_by_curve_state(ctx, *o);
    const doc::CurveObject& c = *o->curve_object();
    const std::string refused = "Cannot trim " + t.object->name + " by " + o->name + ": ";
    if (!state.enabled) {
        note_action(ctx, refused + state.why, true);
        return;
    }
    auto loop = geom::projected_loop(t.surface->surface, c.curve, *plane_normal(c.plane));
    if (!loop) {
        note_action(ctx, refused + loop.error().message, true);
        return;
    }
    run_noted(ctx, state, refused,
              doc::set_trim(t.object->id, with_loop(t.surface->trim, std::move(*loop), hole)),
              std::string(hole ? "Hole cut along " : "Outer loop set along ") + o->name +
                  " seen along " + seen_along(c.plane) + ": " +
                  (hole ? "the surface inside it is cut away."
                        : "the surface keeps what lies inside it."));
}

void remove_trim_current(AppContext& ctx) {
    const Target t = target(ctx);
    if (!t.surface) return;
    run_noted(ctx, remove_trim_state(ctx),
              "Cannot remove the trim: ", doc::remove_trim(t.object->id),
              "Trim removed: the whole domain is kept (Ctrl+Z brings the loops back).");
}

} // namespace isoparm::ui
