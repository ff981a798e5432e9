// The curve designer's knot strip (knot values, draggable custom knots, the parameter t) and
// its basis-function plot (N_i or R_i of the selected control point over the domain).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/doc/commands.hpp"
#include "core/doc/commands_curve.hpp"
#include "core/geom/basis.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/status.hpp"
#include "core/geom/tessellate.hpp"
#include "ui/panels/curve_designer.hpp"
#include "ui/panels/picture_draw.hpp"

namespace isoparm::ui::curve_designer {

namespace {

std::string short_number(double x) {
    return geom::format_short(x, 3);
}

// Horizontal pixel of a normalised position inside a box with side padding.
float x_at(const Rect& box, float pad, double s) {
    return box.x + pad + (box.w - 2 * pad) * static_cast<float>(s);
}

} // namespace

void knot_strip(AppContext& ctx, const doc::Object& obj, const doc::CurveObject& c,
                const Rect& strip) {
    CurveDesignerState& cd = ctx.ui.curve;
    const float k = ctx.ui.scale();
    const float pad = 12 * k;
    const geom::Curve& g = c.curve;
    const int p = g.degree, n = g.count();
    const geom::Interval d = geom::domain(g);
    const bool custom = c.knot_mode == doc::CurveKnotMode::custom;
    const std::uint64_t id = obj.id;

    ImGui::SetCursorScreenPos(ImVec2(strip.x, strip.y));
    ImGui::InvisibleButton("##knot_strip", ImVec2(strip.w, strip.h));
    const float mx = ImGui::GetIO().MousePos.x;
    const double s_mouse =
        std::clamp(static_cast<double>((mx - strip.x - pad) / (strip.w - 2 * pad)), 0.0, 1.0);
    const std::vector<KnotTick> ticks = knot_ticks(g.knots, p, n);
    std::vector<double> tick_px;
    for (const KnotTick& t : ticks) tick_px.push_back(x_at(strip, pad, t.position));
    if (ImGui::IsItemActivated()) {
        ctx.seal();
        cd.drag_knot = -1;
        const auto hit = hit_tick(tick_px, mx, 6 * k);
        if (hit && ticks[*hit].interior && custom) {
            cd.drag_knot = ticks[*hit].first_index;
        } else if (hit && ticks[*hit].interior) {
            cd.message = std::string("Knots follow the ") + geom::label_of(c.knot_mode) +
                         " mode; choose the custom mode to drag them.";
        } else {
            cd.trace_t = s_mouse; // elsewhere: a press moves the parameter t
        }
    }
    if (ImGui::IsItemActive()) {
        if (cd.drag_knot >= 0 && cd.drag_knot < static_cast<int>(g.knots.size())) {
            const double target = denormalize_param(d, s_mouse);
            int idx = cd.drag_knot;
            const double now = g.knots[static_cast<std::size_t>(idx)];
            // A multiple knot splits: its last copy moves right, its first copy left.
            if (target > now)
                while (idx + 1 < static_cast<int>(g.knots.size()) &&
                       g.knots[static_cast<std::size_t>(idx + 1)] == now)
                    ++idx;
            cd.drag_knot = idx;
            if (idx < 1 || idx + 1 >= static_cast<int>(g.knots.size())) {
                cd.drag_knot = -1; // the knots changed under the drag (undo): stop it
                return;
            }
            // The knot stays between its neighbours while dragged (the strip pins it there).
            const double lo = g.knots[static_cast<std::size_t>(idx - 1)];
            const double hi = g.knots[static_cast<std::size_t>(idx + 1)];
            const double value = std::clamp(target, lo, hi);
            if (value != now && !ctx.execute(doc::set_knot(id, geom::Dir::u, idx, value)))
                cd.message = ctx.ui.status;
        } else if (cd.drag_knot < 0) {
            cd.trace_t = s_mouse;
        }
    }
    if (ImGui::IsItemDeactivated()) {
        cd.drag_knot = -1;
        ctx.seal();
    }
    const bool hovered = ImGui::IsItemHovered();

    // Draw the knots the document holds now.
    const doc::Object* o = ctx.doc.find(id);
    const geom::Curve* cur = o ? o->curve() : nullptr;
    if (!cur) return;
    const geom::Curve& h = *cur;
    const std::vector<KnotTick> now_ticks = knot_ticks(h.knots, h.degree, h.count());
    const bool light = ctx.ui.presentation;
    Picture pic;
    pic.view = "curve_knots";
    pic.frame = strip;
    pic.background = light ? rgba8(250, 250, 250) : rgba8(26, 28, 34);
    pic.border = ImGui::GetColorU32(ImGuiCol_Border);
    pic.border_width = k;
    const float base = strip.y + strip.h * 0.42f;
    pic.line({x_at(strip, pad, 0), base}, {x_at(strip, pad, 1), base},
             ImGui::GetColorU32(ImGuiCol_TextDisabled), 1.5f * k);
    const Rgba8 knot_col = rgba(ctx.doc.colors.knot_curves);
    const Rgba8 text_col = ImGui::GetColorU32(ImGuiCol_Text);
    for (std::size_t q = 0; q < now_ticks.size(); ++q) {
        const KnotTick& t = now_ticks[q];
        const float x = x_at(strip, pad, t.position);
        const bool dragged =
            cd.drag_knot >= t.first_index && cd.drag_knot < t.first_index + t.multiplicity;
        const float len = (5 + 3 * static_cast<float>(t.multiplicity - 1)) * k;
        pic.line({x, base - len}, {x, base + len}, dragged ? rgba8(255, 255, 255) : knot_col,
                 (t.interior && custom ? 2.5f : 1.5f) * k);
        // The ends and a dragged knot first; the placer drops values that would touch.
        const int priority = dragged ? 200 : (q == 0 || q + 1 == now_ticks.size()) ? 150 : 100;
        if (t.multiplicity > 1)
            pic.fixed_label({x + 2 * k, base - len}, "x" + std::to_string(t.multiplicity), knot_col,
                            LabelAlign::bottom_left, priority - 1);
        pic.fixed_label({x, base + len + 1 * k}, short_number(t.value), text_col,
                        LabelAlign::top_center, priority)
            .tooltip = "knot " + geom::format_number(t.value);
    }
    // The parameter t of the trace and the basis plot.
    const float tx = x_at(strip, pad, std::clamp(cd.trace_t, 0.0, 1.0));
    pic.polygon({{tx, base - 2 * k}, {tx + 5 * k, base - 10 * k}, {tx - 5 * k, base - 10 * k}},
                rgba8(235, 60, 60));
    draw_picture(pic);
    if (hovered)
        ImGui::SetTooltip("%s", custom ? "Drag a knot (custom mode); press elsewhere to move t"
                                       : "Press or drag to move the parameter t");
}

void basis_plot(AppContext& ctx, const doc::CurveObject& c, int selected, const Rect& box) {
    const float k = ctx.ui.scale();
    const geom::Curve& g = c.curve;
    const int p = g.degree, n = g.count();
    const bool rational = geom::is_rational(g.type);
    const bool light = ctx.ui.presentation;
    Picture pic;
    pic.view = "curve_basis";
    pic.frame = box;
    pic.background = light ? rgba8(250, 250, 250) : rgba8(26, 28, 34);
    pic.border = ImGui::GetColorU32(ImGuiCol_Border);
    pic.border_width = k;
    const geom::Interval d = geom::domain(g);
    const std::vector<double> ts = geom::uniform_params(d.lo, d.hi, 201);
    std::vector<std::vector<double>> values; // values[sample][i]; empty where undefined
    double lo = 0, hi = 1;
    for (double t : ts) {
        if (rational) {
            auto r = geom::rational_basis(g.knots, p, g.weights, t);
            values.push_back(r ? (*r)[0] : std::vector<double>{});
        } else {
            values.push_back(geom::all_basis(g.knots, p, n, t)[0]);
        }
        for (double v : values.back()) lo = std::min(lo, v), hi = std::max(hi, v);
    }
    const float pad = 12 * k; // the knot strip's padding, so the parameter lines up
    const float line_h = ImGui::GetTextLineHeight();
    const float top = box.y + 6 * k + line_h, h = box.h - 10 * k - line_h;
    auto pt = [&](std::size_t sample, double y) {
        return glm::vec2(
            x_at(box, pad, static_cast<double>(sample) / static_cast<double>(ts.size() - 1)),
            top + h * static_cast<float>((hi - y) / (hi - lo)));
    };
    if (lo < 0) // the zero line, when negative weights push a function below it
        pic.line(pt(0, 0), pt(ts.size() - 1, 0), ImGui::GetColorU32(ImGuiCol_TextDisabled));
    const Rgba8 faint = light ? rgba8(160, 160, 160) : rgba8(110, 115, 135);
    auto curve = [&](int f, Rgba8 color, float width) {
        std::vector<glm::vec2> line;
        for (std::size_t s = 0; s < ts.size(); ++s) {
            if (values[s].empty()) {
                pic.polyline(std::move(line), color, width);
                line.clear();
                continue;
            }
            line.push_back(pt(s, values[s][static_cast<std::size_t>(f)]));
        }
        pic.polyline(std::move(line), color, width);
    };
    for (int f = 0; f < n; ++f)
        if (f != selected) curve(f, faint, 1 * k);
    if (selected >= 0 && selected < n)
        curve(selected, rgba(ctx.doc.colors.selected_point), 2.5f * k);
    const float x = x_at(box, pad, std::clamp(ctx.ui.curve.trace_t, 0.0, 1.0));
    pic.line({x, box.y}, {x, box.y + box.h}, rgba8(235, 60, 60, 230), 1.5f * k);
    std::string name = selected >= 0
                           ? std::string(rational ? "R" : "N") + std::to_string(selected) + "(t)"
                           : std::string(rational ? "R_i(t)" : "N_i(t)");
    name += ", degree " + std::to_string(p);
    pic.fixed_label({box.x + 4 * k, box.y + 2 * k}, name, ImGui::GetColorU32(ImGuiCol_TextDisabled),
                    LabelAlign::top_left);
    draw_picture(pic);
    ImGui::SetCursorScreenPos(ImVec2(box.x, box.y));
    ImGui::Dummy(ImVec2(box.w, box.h));
}

} // namespace isoparm::ui::curve_designer
