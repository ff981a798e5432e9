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
#include "core/geom/tessellate.hpp"
#include "ui/panels/curve_designer.hpp"

namespace isoparm::ui::curve_designer {

namespace {

std::string short_number(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    return buf;
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
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const bool light = ctx.ui.presentation;
    const ImVec2 a(strip.x, strip.y), b(strip.x + strip.w, strip.y + strip.h);
    dl->AddRectFilled(a, b, light ? IM_COL32(250, 250, 250, 255) : IM_COL32(26, 28, 34, 255));
    const float base = strip.y + strip.h * 0.42f;
    dl->AddLine(ImVec2(x_at(strip, pad, 0), base), ImVec2(x_at(strip, pad, 1), base),
                ImGui::GetColorU32(ImGuiCol_TextDisabled), 1.5f * k);
    std::vector<double> label_px;
    for (const KnotTick& t : now_ticks) label_px.push_back(x_at(strip, pad, t.position));
    const std::vector<bool> keep = thin_labels(label_px, 34 * k);
    const ImU32 knot_col = rgba(ctx.doc.colors.knot_curves);
    const ImU32 text_col = ImGui::GetColorU32(ImGuiCol_Text);
    for (std::size_t q = 0; q < now_ticks.size(); ++q) {
        const KnotTick& t = now_ticks[q];
        const float x = static_cast<float>(label_px[q]);
        const bool dragged =
            cd.drag_knot >= t.first_index && cd.drag_knot < t.first_index + t.multiplicity;
        const float len = (5 + 3 * static_cast<float>(t.multiplicity - 1)) * k;
        dl->AddLine(ImVec2(x, base - len), ImVec2(x, base + len),
                    dragged ? IM_COL32(255, 255, 255, 255) : knot_col,
                    (t.interior && custom ? 2.5f : 1.5f) * k);
        if (t.multiplicity > 1) {
            const std::string mult = "x" + std::to_string(t.multiplicity);
            dl->AddText(ImVec2(x + 2 * k, base - len - ImGui::GetTextLineHeight()), knot_col,
                        mult.c_str());
        }
        if (keep[q]) {
            const std::string v = short_number(t.value);
            dl->AddText(ImVec2(x - ImGui::CalcTextSize(v.c_str()).x / 2, base + len + 1 * k),
                        text_col, v.c_str());
        }
    }
    // The parameter t of the trace and the basis plot.
    const float tx = x_at(strip, pad, std::clamp(cd.trace_t, 0.0, 1.0));
    dl->AddTriangleFilled(ImVec2(tx, base - 2 * k), ImVec2(tx - 5 * k, base - 10 * k),
                          ImVec2(tx + 5 * k, base - 10 * k), IM_COL32(235, 60, 60, 255));
    dl->AddRect(a, b, ImGui::GetColorU32(ImGuiCol_Border), 0, 0, k);
    if (hovered)
        ImGui::SetTooltip("%s", custom ? "Drag a knot (custom mode); press elsewhere to move t"
                                       : "Press or drag to move the parameter t");
}

void basis_plot(AppContext& ctx, const doc::CurveObject& c, int selected, const Rect& box) {
    const float k = ctx.ui.scale();
    const geom::Curve& g = c.curve;
    const int p = g.degree, n = g.count();
    const bool rational = geom::is_rational(g.type);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const bool light = ctx.ui.presentation;
    dl->AddRectFilled(ImVec2(box.x, box.y), ImVec2(box.x + box.w, box.y + box.h),
                      light ? IM_COL32(250, 250, 250, 255) : IM_COL32(26, 28, 34, 255));
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
    const float top = box.y + 4 * k, h = box.h - 8 * k;
    auto pt = [&](std::size_t sample, double y) {
        return ImVec2(
            x_at(box, pad, static_cast<double>(sample) / static_cast<double>(ts.size() - 1)),
            top + h * static_cast<float>((hi - y) / (hi - lo)));
    };
    if (lo < 0) // the zero line, when negative weights push a function below it
        dl->AddLine(pt(0, 0), pt(ts.size() - 1, 0), ImGui::GetColorU32(ImGuiCol_TextDisabled));
    const ImU32 faint = light ? IM_COL32(160, 160, 160, 255) : IM_COL32(110, 115, 135, 255);
    std::vector<ImVec2> line;
    auto curve = [&](int f, ImU32 color, float width) {
        line.clear();
        for (std::size_t s = 0; s < ts.size(); ++s) {
            if (values[s].empty()) {
                if (line.size() > 1)
                    dl->AddPolyline(line.data(), static_cast<int>(line.size()), color, 0, width);
                line.clear();
                continue;
            }
            line.push_back(pt(s, values[s][static_cast<std::size_t>(f)]));
        }
        if (line.size() > 1)
            dl->AddPolyline(line.data(), static_cast<int>(line.size()), color, 0, width);
    };
    for (int f = 0; f < n; ++f)
        if (f != selected) curve(f, faint, 1 * k);
    if (selected >= 0 && selected < n)
        curve(selected, rgba(ctx.doc.colors.selected_point), 2.5f * k);
    const float x = x_at(box, pad, std::clamp(ctx.ui.curve.trace_t, 0.0, 1.0));
    dl->AddLine(ImVec2(x, box.y), ImVec2(x, box.y + box.h), IM_COL32(235, 60, 60, 230), 1.5f * k);
    std::string name = selected >= 0
                           ? std::string(rational ? "R" : "N") + std::to_string(selected) + "(t)"
                           : std::string(rational ? "R_i(t)" : "N_i(t)");
    name += ", degree " + std::to_string(p);
    dl->AddText(ImVec2(box.x + 4 * k, box.y + 2 * k), ImGui::GetColorU32(ImGuiCol_TextDisabled),
                name.c_str());
    dl->AddRect(ImVec2(box.x, box.y), ImVec2(box.x + box.w, box.y + box.h),
                ImGui::GetColorU32(ImGuiCol_Border), 0, 0, k);
    ImGui::SetCursorScreenPos(ImVec2(box.x, box.y));
    ImGui::Dummy(ImVec2(box.w, box.h));
}

} // namespace isoparm::ui::curve_designer
