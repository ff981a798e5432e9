// The toolbox's actions: which knot the indicator is on, the command for each tool, and the
// conversion question.
#include "ui/toolbox_actions.hpp"

#include <cmath>
#include <cstdio>
#include <imgui.h>

#include "core/doc/commands.hpp"
#include "core/geom/knots.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

namespace {

struct Target {
    const doc::Object* object = nullptr;
    const geom::Knots* knots = nullptr;
    int degree = 0, count = 0;
    double t = 0; // the indicator's parameter along the tool's direction
};

Target target(const AppContext& ctx, geom::Dir dir, bool curve) {
    Target out;
    if (curve) {
        const doc::Object* o = ctx.doc.selected();
        const doc::CurveObject* c = o ? o->curve_object() : nullptr;
        if (!c) return out;
        out = {o, &c->curve.knots, c->curve.degree, c->curve.count(),
               ctx.ui.curve.trace_param(c->curve)};
        return out;
    }
    const geom::Surface* s = current_surface(ctx.doc, &out.object);
    if (!s) return out;
    const glm::dvec2 uv = indicator_params(ctx.doc, *out.object);
    out.knots = &s->knots(dir);
    out.degree = s->degree(dir);
    out.count = s->count(dir);
    out.t = dir == geom::Dir::u ? uv.x : uv.y;
    return out;
}

std::string param_name(geom::Dir dir, bool curve) {
    return curve ? "t" : dir == geom::Dir::u ? "u" : "v";
}

// Four significant digits in a menu; the command gets the knot's exact value.
std::string where(geom::Dir dir, bool curve, double t) {
    return param_name(dir, curve) + " = " + geom::format_short(t);
}

const char* direction_suffix(geom::Dir dir, bool curve) {
    return curve ? "" : dir == geom::Dir::u ? " in u" : " in v";
}

std::unique_ptr<doc::Command> make(const AppContext& ctx, Tool tool, geom::Dir dir,
                                   const Target& at, double knot) {
    const std::uint64_t id = at.object->id;
    const double tol = ctx.ui.toolbox.tolerance;
    switch (tool) {
    case Tool::remove_knot:
        return doc::remove_knot(id, dir, knot, 1, tol);
    case Tool::reduce_degree:
        return doc::reduce_degree(id, dir, tol);
    case Tool::split_knot:
        return doc::split_knot(id, dir, knot, std::nullopt);
    case Tool::close:
        break;
    }
    return doc::close_object(id, dir);
}

std::string tool_label(Tool tool, geom::Dir dir, bool curve, const Target& at,
                       std::optional<double> knot) {
    switch (tool) {
    case Tool::remove_knot:
        return knot ? "Remove knot " + where(dir, curve, *knot)
                    : "Remove knot" + std::string(direction_suffix(dir, curve));
    case Tool::reduce_degree:
        return "Reduce degree" + std::string(direction_suffix(dir, curve)) +
               (at.object ? " (" + std::to_string(at.degree) + " to " +
                                std::to_string(at.degree - 1) + ")"
                          : std::string());
    case Tool::split_knot:
        if (!knot) return "Split knot" + std::string(direction_suffix(dir, curve));
        return "Split knot " + where(dir, curve, *knot) + " (x" +
               std::to_string(geom::multiplicity(*at.knots, *knot)) + ")";
    case Tool::close:
        break;
    }
    return curve ? "Close the curve" : std::string("Close") + direction_suffix(dir, curve);
}

bool needs_knot(Tool tool) {
    return tool == Tool::remove_knot || tool == Tool::split_knot;
}

} // namespace

std::optional<double> knot_under_indicator(const AppContext& ctx, geom::Dir dir, bool curve) {
    const Target at = target(ctx, dir, curve);
    if (!at.object) return std::nullopt;
    const geom::Knots& U = *at.knots;
    const double a = U[at.degree], b = U[at.count];
    std::optional<double> best;
    for (double k : U)
        if (k > a && k < b && (!best || std::abs(k - at.t) < std::abs(*best - at.t))) best = k;
    return best;
}

ActionState tool_state(const AppContext& ctx, Tool tool, geom::Dir dir, bool curve) {
    const Target at = target(ctx, dir, curve);
    const std::optional<double> knot =
        at.object ? knot_under_indicator(ctx, dir, curve) : std::nullopt;
    ActionState s;
    s.label = tool_label(tool, dir, curve, at, knot);
    if (!at.object) {
        s.why = curve ? "select a curve first" : "no surface";
        return s;
    }
    if (needs_knot(tool) && !knot) {
        s.why = "'" + at.object->name + "' has no interior knot" +
                (curve ? std::string() : std::string(" in ") + param_name(dir, false)) +
                ": insert one first";
        return s;
    }
    const geom::Status st = make(ctx, tool, dir, at, knot.value_or(0))->check(ctx.doc);
    s.enabled = st.ok();
    if (!st) s.why = st.error().message;
    return s;
}

void run_tool(AppContext& ctx, Tool tool, geom::Dir dir, bool curve) {
    const ActionState state = tool_state(ctx, tool, dir, curve);
    if (!state.enabled) {
        note_action(ctx, state.label + ": not done. " + state.why, true);
        return;
    }
    const Target at = target(ctx, dir, curve);
    const std::optional<double> knot = knot_under_indicator(ctx, dir, curve);
    ctx.seal();
    if (ctx.execute(make(ctx, tool, dir, at, knot.value_or(0))))
        note_action(ctx, ctx.history.undo_label() + ".", false);
    else
        note_action(ctx, ctx.ui.status, true);
    ctx.seal();
}

void request_convert(AppContext& ctx, geom::SplineType to, bool curve) {
    const doc::Object* o = nullptr;
    if (curve) {
        o = ctx.doc.selected();
        if (o && !o->curve_object()) o = nullptr;
    } else {
        current_surface(ctx.doc, &o);
    }
    if (!o) return;
    auto losses = doc::conversion_losses(*o, to);
    if (!losses) {
        note_action(ctx,
                    "Convert to " + std::string(geom::label_of(to)) + ": not done. " +
                        losses.error().message,
                    true);
        return;
    }
    ConvertQuestion& q = ctx.ui.toolbox.convert;
    q = {o->id, to, losses->weights_differ, losses->text, !losses->text.empty()};
    if (!q.open) {
        ctx.seal();
        if (ctx.execute(doc::convert_object(o->id, to)))
            note_action(ctx, ctx.history.undo_label() + ".", false);
        else
            note_action(ctx, ctx.ui.status, true);
        ctx.seal();
    }
}

void draw_convert_dialog(AppContext& ctx) {
    ConvertQuestion& q = ctx.ui.toolbox.convert;
    if (!begin_centered_modal("Convert?", q.open, 460 * ctx.ui.scale())) return;
    const doc::Object* o = ctx.doc.find(q.object);
    if (!o) {
        ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
        return;
    }
    ImGui::Text("Convert '%s' to %s?", o->name.c_str(), geom::label_of(q.to));
    ImGui::Separator();
    text_wrapped("%s", q.text.c_str());
    ImGui::TextDisabled("Edit > Undo takes it back.");
    ImGui::Spacing();
    const bool convert = ImGui::Button("Convert");
    report_item("convert/convert");
    ImGui::SameLine();
    const bool cancel =
        ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
    report_item("convert/cancel");
    if (convert) {
        ctx.seal();
        if (ctx.execute(doc::convert_object(q.object, q.to, q.reset_weights)))
            note_action(ctx, ctx.history.undo_label() + ".", false);
        else
            note_action(ctx, ctx.ui.status, true);
        ctx.seal();
    }
    if (convert || cancel) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

} // namespace isoparm::ui
