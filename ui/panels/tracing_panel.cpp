// The tracing panel: the domain square with the draggable position indicator (u, v) and
// the u and v knots as ticks labelled with their values and multiplicities. A selected
// triangular patch gets its domain triangle and (r, s, t) instead (triangle_tracing.cpp).
#include <algorithm>
#include <cstdio>
#include <imgui.h>
#include <string>
#include <vector>

#include "core/doc/commands.hpp"
#include "core/doc/patches.hpp"
#include "core/geom/knots.hpp"
#include "ui/panels/flow.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/triangle_panels.hpp"
#include "ui/surface_actions.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/knot_drag.hpp"

namespace isoparm::ui {

namespace {

ImVec2 iv(const glm::dvec2& p) {
    return {static_cast<float>(p.x), static_cast<float>(p.y)};
}

std::string short_number(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    return buf;
}

std::string knot_vector_text(const geom::Knots& U) {
    // Runs written as value^multiplicity, as the paper writes 0^4 0.5 1^4; long vectors keep
    // their first and last runs around an ellipsis (the ticks show every knot).
    std::vector<std::string> runs;
    std::size_t k = 0;
    while (k < U.size()) {
        std::size_t m = 1;
        while (k + m < U.size() && U[k + m] == U[k]) ++m;
        std::string r = short_number(U[k]);
        if (m > 1) r += "^" + std::to_string(m);
        runs.push_back(r);
        k += m;
    }
    constexpr std::size_t keep = 4;
    std::string s;
    for (std::size_t n = 0; n < runs.size(); ++n) {
        if (runs.size() > 2 * keep + 1 && n == keep) {
            s += " ... ";
            n = runs.size() - keep - 1;
            continue;
        }
        if (!s.empty() && s.back() != ' ') s += "  ";
        s += runs[n];
    }
    return s;
}

struct Palette {
    ImU32 bg, border, grid, tick, text, mult, indicator, cross, current;
};

Palette palette(const AppContext& ctx) {
    const doc::Rgba& ic = ctx.doc.colors.indicator;
    const doc::Rgba& kc = ctx.doc.colors.knot_curves;
    const bool light = ctx.ui.presentation;
    Palette p;
    p.bg = light ? IM_COL32(250, 250, 250, 255) : IM_COL32(28, 30, 36, 255);
    p.border = light ? IM_COL32(0, 0, 0, 255) : IM_COL32(170, 175, 190, 255);
    p.grid = ImGui::ColorConvertFloat4ToU32(ImVec4(kc.r, kc.g, kc.b, 0.55f));
    p.tick = ImGui::ColorConvertFloat4ToU32(ImVec4(kc.r, kc.g, kc.b, 1));
    p.text = ImGui::GetColorU32(ImGuiCol_Text);
    p.mult = light ? IM_COL32(170, 60, 0, 255) : IM_COL32(255, 190, 90, 255);
    p.indicator = ImGui::ColorConvertFloat4ToU32(ImVec4(ic.r, ic.g, ic.b, 1));
    p.cross = ImGui::ColorConvertFloat4ToU32(ImVec4(ic.r, ic.g, ic.b, 0.45f));
    p.current = light ? IM_COL32(255, 236, 200, 255) : IM_COL32(52, 56, 70, 255);
    return p;
}

ImVec4 warning_color(const AppContext& ctx) {
    return ctx.ui.presentation ? ImVec4(0.7f, 0.25f, 0, 1) : ImVec4(1, 0.72f, 0.3f, 1);
}

// The last action's note (a refusal or what an insertion / split did), wrapped to the
// panel's width: it stays under the square until the next action or edit.
void action_note_line(const AppContext& ctx, const ActionNote& note) {
    ImGui::PushStyleColor(ImGuiCol_Text, note.refused ? warning_color(ctx)
                                                      : ImGui::GetStyleColorVec4(ImGuiCol_Text));
    ImGui::TextWrapped("%s", note.text.c_str());
    ImGui::PopStyleColor();
}

// A knot tick strip (below the square for u, left of it for v): press a tick and drag to
// move that knot, all its copies together, between its neighbours; the surface follows live.
void knot_strip(AppContext& ctx, const doc::Object& obj, const geom::Surface& s, geom::Dir dir,
                const std::vector<KnotTick>& ticks, const std::vector<double>& px,
                const Rect& strip, const Rect& sq, const geom::ParamRect& dom) {
    const bool along_x = dir == geom::Dir::u;
    ImGui::SetCursorScreenPos(ImVec2(strip.x, strip.y));
    ImGui::InvisibleButton(along_x ? "##uknots" : "##vknots", ImVec2(strip.w, strip.h));
    const ImVec2 m = ImGui::GetIO().MousePos;
    const double along = along_x ? m.x : m.y;
    const float k = ctx.ui.scale();
    KnotDrag& kd = ctx.ui.knot_drag;
    std::vector<bool> interior;
    for (const KnotTick& t : ticks) interior.push_back(t.interior);
    const double radius = knot_handle_radius(k);
    const auto hit = hit_movable_tick(px, interior, along, radius);
    const bool movable = hit.has_value();
    if (ImGui::IsItemHovered() && movable && !ImGui::IsItemActive()) {
        ImGui::SetMouseCursor(along_x ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
        const KnotTick& t = ticks[*hit];
        // The handle under the pointer, so the room sees which knot is about to move.
        const float c = static_cast<float>(px[*hit]), r = static_cast<float>(radius);
        const ImVec2 lo = along_x ? ImVec2(c - r, strip.y) : ImVec2(strip.x, c - r);
        const ImVec2 hi =
            along_x ? ImVec2(c + r, strip.y + strip.h) : ImVec2(strip.x + strip.w, c + r);
        ImDrawList* dl = ImGui::GetWindowDrawList();
        dl->AddRectFilled(lo, hi, ImGui::GetColorU32(ImGuiCol_ButtonHovered, 0.45f), 3 * k);
        dl->AddRect(lo, hi, ImGui::GetColorU32(ImGuiCol_ButtonActive), 3 * k, 0, 1.5f * k);
        const char* name = along_x ? "u" : "v";
        const std::string copies =
            t.multiplicity > 1
                ? " (" + std::string(name) + std::to_string(t.first_index) + " .. " + name +
                      std::to_string(t.first_index + t.multiplicity - 1) + ", they move as one)"
                : "";
        // Why multiplicity matters: the continuity the surface has across this knot line.
        const int p = s.degree(dir);
        ImGui::SetTooltip("Knot %s%d = %s, multiplicity %d in degree %d: %s%s\nDrag to move it "
                          "between its neighbours %s and %s",
                          name, t.first_index, short_number(t.value).c_str(), t.multiplicity, p,
                          geom::continuity_text(p, t.multiplicity).c_str(), copies.c_str(),
                          short_number(ticks[*hit - 1].value).c_str(),
                          short_number(ticks[*hit + 1].value).c_str());
    }
    if (ImGui::IsItemActivated() && movable)
        kd = {true, dir, ticks[*hit].first_index, ticks[*hit].multiplicity, obj.id};
    if (!ImGui::IsItemActive()) {
        if (kd.active && kd.dir == dir) kd.active = false;
        return;
    }
    if (!kd.active || kd.dir != dir || kd.object != obj.id) return;
    // A key pressed during the drag (insert, elevate, undo) may have changed the knots: the
    // held run must still be one run between two distinct neighbours, else the drag ends.
    const geom::Knots& U = s.knots(dir);
    if (!is_inner_knot_run(U, kd.first, kd.count)) {
        kd.active = false;
        return;
    }
    const double f = along_x ? (m.x - sq.x) / sq.w : 1.0 - (m.y - sq.y) / sq.h;
    const double t = dragged_knot_value(U, kd.first, kd.count, dom.interval(dir), f);
    if (t != U[kd.first]) ctx.execute(doc::move_knot_run(obj.id, dir, kd.first, kd.count, t));
}

// The patch structure's setting (kept with the scene) and which borders it can hold.
void continuity_controls(AppContext& ctx, const doc::Object& obj) {
    ImGui::TextUnformatted("Keep across borders:");
    for (doc::Continuity c : {doc::Continuity::off, doc::Continuity::c0, doc::Continuity::c1}) {
        same_line_if_fits(toggle_width(geom::name_of(c)));
        if (ImGui::RadioButton(geom::name_of(c), ctx.doc.continuity == c)) set_continuity(ctx, c);
    }
    if (ctx.doc.continuity == doc::Continuity::off) return;
    const bool c1 = ctx.doc.continuity == doc::Continuity::c1;
    int held = 0;
    std::vector<std::string> why;
    const std::vector<doc::SharedBorder> borders = doc::shared_borders(ctx.doc, obj.patch_group);
    for (const doc::SharedBorder& b : borders) {
        const doc::Object* lo = ctx.doc.find(b.low);
        const doc::Object* hi = ctx.doc.find(b.high);
        const std::string pair = lo->name + " | " + hi->name + ": ";
        if (!b.conforming) {
            why.push_back(pair + b.why_not);
        } else if (c1 && !b.c1_possible) {
            // C1 across a border is a condition on the next row in, which needs both sides
            // clamped there (Piegl & Tiller eq. 5.26); otherwise only C0 is kept.
            why.push_back(pair + "only C0: a side is not clamped at the border");
        } else {
            ++held;
        }
    }
    report_fact("borders_kept", held);
    report_fact("borders", static_cast<double>(borders.size()));
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%d of %d borders kept %s when a point moves", held,
                       static_cast<int>(borders.size()), geom::name_of(ctx.doc.continuity));
    ImGui::PopStyleColor();
    // Why the others are not, in the panel itself (a tooltip would hide most of it).
    if (!why.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, warning_color(ctx));
        for (const std::string& w : why) ImGui::TextWrapped("Not kept: %s", w.c_str());
        ImGui::PopStyleColor();
        // Borders an insertion broke later (U / V on one side) can be paired up again.
        if (!doc::conforming_insertions(ctx.doc, obj.patch_group).empty() &&
            ImGui::Button("Insert the knots the borders lack"))
            conform_current_group(ctx);
    }
}

ImVec2 param_pixel(const Rect& sq, const geom::ParamRect& dom, double u, double v) {
    return iv(domain_to_pixel(sq, {normalize_param(dom.u, u), normalize_param(dom.v, v)}));
}

// The rational picture over the current surface's part of the square: where w(u, v) < 0 a red
// tint, and its zero set (where the surface goes to infinity) as a strong line.
void draw_denominator(AppContext& ctx, const geom::Surface& s, const Rect& sq,
                      const geom::ParamRect& dom, ImDrawList* dl) {
    const float k = ctx.ui.scale();
    const bool light = ctx.ui.presentation;
    auto px = [&](double u, double v) { return param_pixel(sq, dom, u, v); };
    const geom::ParamRect own = geom::domain(s);
    DenominatorView& view = ctx.ui.denominator;
    view.update(s);
    const int n = DenominatorView::sign_cells;
    const ImU32 negative = light ? IM_COL32(230, 60, 60, 70) : IM_COL32(230, 70, 70, 80);
    const ImU32 zero = light ? IM_COL32(200, 0, 0, 255) : IM_COL32(255, 90, 90, 255);
    const double du = (own.u.hi - own.u.lo) / n, dv = (own.v.hi - own.v.lo) / n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            if (view.signs()[static_cast<std::size_t>(i) * n + j] < 0)
                dl->AddRectFilled(px(own.u.lo + i * du, own.v.lo + (j + 1) * dv),
                                  px(own.u.lo + (i + 1) * du, own.v.lo + j * dv), negative);
    for (const geom::ParamSegment& seg : view.zero_set())
        dl->AddLine(px(seg.a.x, seg.a.y), px(seg.b.x, seg.b.y), zero, 2.5f * k);
    report_fact("tracing/zero_set_segments", static_cast<double>(view.zero_set().size()));
}

// Each weight as a label at its control point's Greville point (u_i*, v_j*), where that point
// pulls the surface most.
void draw_weight_labels(AppContext& ctx, const geom::Surface& s, const Rect& sq,
                        const geom::ParamRect& dom, ImDrawList* dl) {
    const float k = ctx.ui.scale();
    const bool light = ctx.ui.presentation;
    auto px = [&](double u, double v) { return param_pixel(sq, dom, u, v); };
    const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
    const ImU32 warn = light ? IM_COL32(190, 0, 0, 255) : IM_COL32(255, 110, 110, 255);
    const ImU32 back = light ? IM_COL32(255, 255, 255, 200) : IM_COL32(20, 22, 28, 190);
    // Weights other than 1 first (they are what the lesson is about), then the rest where
    // they do not cover a label already drawn: a dense net stays readable.
    std::vector<ImVec4> taken; // drawn labels as (x0, y0, x1, y1)
    int shown = 0;
    for (const bool unusual : {true, false}) {
        for (int i = 0; i < s.n_u; ++i) {
            const double u = geom::greville_abscissa(s.knots_u, s.degree_u, i);
            for (int j = 0; j < s.n_v; ++j) {
                const double w = s.weight(i, j);
                if ((w != 1) != unusual) continue;
                const double v = geom::greville_abscissa(s.knots_v, s.degree_v, j);
                const std::string label = short_number(w);
                const ImVec2 at = px(u, v), ts = ImGui::CalcTextSize(label.c_str());
                // Kept inside the square: corner labels would hang over its edge.
                const ImVec2 lo(std::clamp(at.x - ts.x / 2, sq.x, sq.x + sq.w - ts.x),
                                std::clamp(at.y - ts.y / 2, sq.y, sq.y + sq.h - ts.y));
                const ImVec4 box(lo.x - 1, lo.y, lo.x + ts.x + 1, lo.y + ts.y);
                const bool covers = std::any_of(taken.begin(), taken.end(), [&](const ImVec4& b) {
                    return box.x < b.z && b.x < box.z && box.y < b.w && b.y < box.w;
                });
                if (covers) continue;
                taken.push_back(box);
                dl->AddRectFilled(ImVec2(box.x, box.y), ImVec2(box.z, box.w), back, 2 * k);
                dl->AddText(lo, w <= 0 ? warn : text, label.c_str());
                ++shown;
            }
        }
    }
    report_fact("tracing/weight_labels", shown);
}

// Under the square for rational types: the denominator picture and the weight labels.
void rational_toggles(AppContext& ctx) {
    ImGui::Checkbox("Denominator w", &ctx.ui.show_denominator);
    report_item("tracing/denominator");
    if (ImGui::IsItemHovered())
        wrapped_tooltip("Where w(u, v) = sum N_i N_j w_ij is negative the square is tinted red; "
                        "the red line is w = 0, where the surface goes to infinity.");
    same_line_if_fits(toggle_width("Weights"));
    ImGui::Checkbox("Weights", &ctx.ui.show_weights);
    report_item("tracing/weights");
    if (ImGui::IsItemHovered())
        wrapped_tooltip("Each control point's weight, at its Greville point (the mean of its "
                        "knots), where it pulls the surface most.");
}

} // namespace

void draw_tracing_panel(AppContext& ctx) {
    // A selected triangular patch has its own version of the panel (Farin ch. 17).
    const doc::Object* triangle = nullptr;
    if (const geom::TrianglePatch* t = selected_triangle(ctx.doc, &triangle)) {
        draw_triangle_tracing(ctx, *triangle, *t);
        return;
    }
    const doc::Object* obj = nullptr;
    const geom::Surface* s = current_surface(ctx.doc, &obj);
    if (!s) {
        ImGui::TextWrapped("No surface. Use Surface > New Surface... to create one.");
        return;
    }
    const float k = ctx.ui.scale();
    // Subpatches share the original domain: the square shows all of it.
    const geom::ParamRect dom = doc::tracing_domain(ctx.doc, *obj);
    const std::vector<const doc::Object*> patches = doc::patch_members(ctx.doc, obj->patch_group);
    const glm::dvec2 uv = indicator_params(ctx.doc, *obj);
    ImGui::TextWrapped("%s  (%s, degree %d x %d)", obj->name.c_str(), geom::name_of(s->type),
                       s->degree_u, s->degree_v);
    if (!patches.empty()) {
        char part[48];
        std::snprintf(
            part, sizeof part, "- patch %d of %d",
            static_cast<int>(std::find(patches.begin(), patches.end(), obj) - patches.begin()) + 1,
            static_cast<int>(patches.size()));
        // Beside the name where it fits, else on its own line (never cut).
        ImGui::SameLine();
        if (ImGui::GetContentRegionAvail().x < ImGui::CalcTextSize(part).x) ImGui::NewLine();
        ImGui::TextDisabled("%s", part);
    }

    // Room for the v labels on the left and the u labels below the square.
    const float label_w = ImGui::CalcTextSize("0.000").x + 10 * k;
    const float label_h = ImGui::GetTextLineHeight() * 2 + 8 * k;
    const ActionNote* note = current_action_note(ctx);
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    // The note's wrapped height is kept free below the square so it is seen without scrolling.
    const float note_h = note ? ImGui::CalcTextSize(note->text.c_str(), nullptr, false, avail.x).y +
                                    ImGui::GetStyle().ItemSpacing.y
                              : 0.f;
    const bool rational = geom::is_rational(s->type);
    const float fields_h = ImGui::GetFrameHeightWithSpacing() * (rational ? 3 : 2) +
                           ImGui::GetTextLineHeightWithSpacing() * 3 + note_h;
    const float side =
        std::max(std::min(avail.x - label_w - 12 * k, avail.y - label_h - fields_h), 60.f * k);
    const ImVec2 cur = ImGui::GetCursorScreenPos();
    const Rect sq{cur.x + label_w, cur.y + 6 * k, side, side};
    auto to_square = [&](double u, double v) {
        return glm::dvec2{normalize_param(dom.u, u), normalize_param(dom.v, v)};
    };

    // The square is one canvas: press anywhere to move the indicator there, then drag.
    ImGui::SetCursorScreenPos(ImVec2(sq.x, sq.y));
    ImGui::InvisibleButton("##domain", ImVec2(sq.w, sq.h));
    report_item("tracing/square");
    if (ImGui::IsItemActive()) {
        const ImVec2 m = ImGui::GetIO().MousePos;
        ctx.doc.view.indicator = pixel_to_domain(sq, {m.x, m.y}); // view state, not undoable
    }
    ctx.ui.indicator_drag = ImGui::IsItemActive();

    const Palette pal = palette(ctx);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 a(sq.x, sq.y), b(sq.x + sq.w, sq.y + sq.h);
    dl->AddRectFilled(a, b, pal.bg);

    // The other subpatches, and the current one's part of the square.
    if (!patches.empty()) {
        for (const doc::Object* p : patches) {
            const geom::ParamRect r = geom::domain(*p->surface());
            const ImVec2 lo = iv(domain_to_pixel(sq, to_square(r.u.lo, r.v.hi)));
            const ImVec2 hi = iv(domain_to_pixel(sq, to_square(r.u.hi, r.v.lo)));
            if (p == obj) dl->AddRectFilled(lo, hi, pal.current);
            dl->AddRect(lo, hi, pal.border, 0, 0, 2.5f * k);
            const ImVec2 ts = ImGui::CalcTextSize(p->name.c_str());
            if (ts.x + 6 * k < hi.x - lo.x)
                dl->AddText(ImVec2(lo.x + 3 * k, lo.y + 2 * k), pal.text, p->name.c_str());
        }
    }

    // Knot lines across the current patch (where the knot curves run) and ticks with labels.
    const geom::ParamRect own = geom::domain(*s);
    const std::vector<KnotTick> tu = knot_ticks(s->knots_u, s->degree_u, s->n_u);
    const std::vector<KnotTick> tv = knot_ticks(s->knots_v, s->degree_v, s->n_v);
    const float tick = 7 * k;
    std::vector<double> px_u, px_v;
    for (const KnotTick& t : tu) px_u.push_back(sq.x + normalize_param(dom.u, t.value) * sq.w);
    for (const KnotTick& t : tv)
        px_v.push_back(sq.y + (1.0 - normalize_param(dom.v, t.value)) * sq.h);
    const float own_top = static_cast<float>(domain_to_pixel(sq, to_square(own.u.lo, own.v.hi)).y);
    const float own_bottom =
        static_cast<float>(domain_to_pixel(sq, to_square(own.u.lo, own.v.lo)).y);
    const float own_left = static_cast<float>(domain_to_pixel(sq, to_square(own.u.lo, own.v.lo)).x);
    const float own_right =
        static_cast<float>(domain_to_pixel(sq, to_square(own.u.hi, own.v.lo)).x);
    const std::vector<bool> keep_u = thin_labels(px_u, ImGui::CalcTextSize("0.00").x + 8 * k);
    // v runs upward on screen: thin from the bottom (ascending pixel order reversed).
    std::vector<double> rev_v;
    for (double p : px_v) rev_v.push_back(-p);
    const std::vector<bool> keep_v = thin_labels(rev_v, ImGui::GetTextLineHeight() * 2.1);
    const KnotDrag& kd = ctx.ui.knot_drag;
    auto held = [&](geom::Dir dir, const KnotTick& t) {
        return kd.active && kd.object == obj->id && kd.dir == dir && kd.first == t.first_index;
    };

    for (std::size_t n = 0; n < tu.size(); ++n) {
        const float x = static_cast<float>(px_u[n]);
        const float w = (1.0f + static_cast<float>(tu[n].multiplicity - 1) * 1.2f) * k;
        if (tu[n].interior) dl->AddLine(ImVec2(x, own_top), ImVec2(x, own_bottom), pal.grid, w);
        const bool h = held(geom::Dir::u, tu[n]);
        dl->AddLine(ImVec2(x, b.y), ImVec2(x, b.y + tick), h ? pal.indicator : pal.tick,
                    (h ? 4 : 2) * k);
        if (!keep_u[n] && !h) continue;
        const std::string v = short_number(tu[n].value);
        const float tw = ImGui::CalcTextSize(v.c_str()).x;
        dl->AddText(ImVec2(x - tw / 2, b.y + tick + 1), pal.text, v.c_str());
        if (tu[n].multiplicity > 1) {
            const std::string m = "x" + std::to_string(tu[n].multiplicity);
            const float mw = ImGui::CalcTextSize(m.c_str()).x;
            dl->AddText(ImVec2(x - mw / 2, b.y + tick + 1 + ImGui::GetTextLineHeight()), pal.mult,
                        m.c_str());
        }
    }
    for (std::size_t n = 0; n < tv.size(); ++n) {
        const float y = static_cast<float>(px_v[n]);
        const float w = (1.0f + static_cast<float>(tv[n].multiplicity - 1) * 1.2f) * k;
        if (tv[n].interior) dl->AddLine(ImVec2(own_left, y), ImVec2(own_right, y), pal.grid, w);
        const bool h = held(geom::Dir::v, tv[n]);
        dl->AddLine(ImVec2(a.x - tick, y), ImVec2(a.x, y), h ? pal.indicator : pal.tick,
                    (h ? 4 : 2) * k);
        if (!keep_v[n] && !h) continue;
        const std::string v = short_number(tv[n].value);
        const ImVec2 ts = ImGui::CalcTextSize(v.c_str());
        const float lh = ImGui::GetTextLineHeight();
        const bool mult = tv[n].multiplicity > 1;
        const float top = y - (mult ? lh : lh / 2);
        dl->AddText(ImVec2(a.x - tick - 3 * k - ts.x, top), pal.text, v.c_str());
        if (mult) {
            const std::string m = "x" + std::to_string(tv[n].multiplicity);
            const float mw = ImGui::CalcTextSize(m.c_str()).x;
            dl->AddText(ImVec2(a.x - tick - 3 * k - mw, top + lh), pal.mult, m.c_str());
        }
    }
    dl->AddRect(a, b, pal.border, 0, 0, 1.5f * k);
    // The ends of the shared domain where the current patch does not reach them.
    const ImU32 faint = ImGui::GetColorU32(ImGuiCol_TextDisabled);
    const float lh = ImGui::GetTextLineHeight();
    auto u_end = [&](double t, float x) {
        const std::string v = short_number(t);
        dl->AddText(ImVec2(x - ImGui::CalcTextSize(v.c_str()).x / 2, b.y + tick + 1), faint,
                    v.c_str());
    };
    auto v_end = [&](double t, float y) {
        const std::string v = short_number(t);
        dl->AddText(ImVec2(a.x - tick - 3 * k - ImGui::CalcTextSize(v.c_str()).x, y - lh / 2),
                    faint, v.c_str());
    };
    if (own.u.lo > dom.u.lo) u_end(dom.u.lo, a.x);
    if (own.u.hi < dom.u.hi) u_end(dom.u.hi, b.x);
    if (own.v.lo > dom.v.lo) v_end(dom.v.lo, b.y);
    if (own.v.hi < dom.v.hi) v_end(dom.v.hi, a.y);
    dl->AddText(
        ImVec2(b.x - ImGui::CalcTextSize("u").x - 4 * k, b.y - ImGui::GetTextLineHeight() - 2 * k),
        pal.text, "u");
    dl->AddText(ImVec2(a.x + 4 * k, a.y + 2 * k), pal.text, "v");

    if (rational && ctx.ui.show_denominator) draw_denominator(ctx, *s, sq, dom, dl);

    // The indicator with its two isoparametric lines.
    const ImVec2 ip = iv(domain_to_pixel(sq, ctx.doc.view.indicator));
    dl->AddLine(ImVec2(ip.x, a.y), ImVec2(ip.x, b.y), pal.cross, 1.5f * k);
    dl->AddLine(ImVec2(a.x, ip.y), ImVec2(b.x, ip.y), pal.cross, 1.5f * k);
    dl->AddCircleFilled(ip, 7 * k, pal.indicator, 24);
    dl->AddCircle(ip, 7 * k, IM_COL32(0, 0, 0, 255), 24, 1.5f * k);
    // Over the indicator, so a weight under it stays readable.
    if (rational && ctx.ui.show_weights) draw_weight_labels(ctx, *s, sq, dom, dl);

    // Knot ticks are handles (after the drawing: their buttons sit beside the square).
    knot_strip(ctx, *obj, *s, geom::Dir::u, tu, px_u, {a.x - 4 * k, b.y, sq.w + 8 * k, label_h}, sq,
               dom);
    knot_strip(ctx, *obj, *s, geom::Dir::v, tv, px_v, {cur.x, a.y - 4 * k, label_w, sq.h + 8 * k},
               sq, dom);

    // Exact values, in the surface's own parameters.
    ImGui::SetCursorScreenPos(ImVec2(cur.x, b.y + label_h));
    double u = uv.x, v = uv.y;
    // Each field shows its whole value beside its - and + buttons; a narrow column (a
    // projector in presentation mode) puts v under u rather than cutting both.
    const ImGuiStyle& st = ImGui::GetStyle();
    const float field = ImGui::CalcTextSize("0.00000").x + st.FramePadding.x * 2 +
                        2 * (ImGui::GetFrameHeight() + st.ItemInnerSpacing.x);
    const float label = ImGui::CalcTextSize("u").x + st.ItemInnerSpacing.x + st.ItemSpacing.x;
    const bool one_row = 2 * (field + label) <= avail.x;
    const float width = one_row ? std::max(std::min(avail.x * 0.4f, 140 * k), field)
                                : std::max(avail.x - label, field);
    ImGui::SetNextItemWidth(width);
    if (ImGui::InputDouble("u", &u, 0.01, 0.1, "%.4f"))
        ctx.doc.view.indicator.x = std::clamp(normalize_param(dom.u, u), 0.0, 1.0);
    report_item("tracing/u");
    if (one_row) ImGui::SameLine();
    ImGui::SetNextItemWidth(width);
    if (ImGui::InputDouble("v", &v, 0.01, 0.1, "%.4f"))
        ctx.doc.view.indicator.y = std::clamp(normalize_param(dom.v, v), 0.0, 1.0);
    report_item("tracing/v");
    if (rational) rational_toggles(ctx);
    if (note) action_note_line(ctx, *note);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("knots u: %s", knot_vector_text(s->knots_u).c_str());
    ImGui::TextWrapped("knots v: %s", knot_vector_text(s->knots_v).c_str());
    ImGui::PopStyleColor();

    if (!patches.empty()) continuity_controls(ctx, *obj);
}

} // namespace isoparm::ui
