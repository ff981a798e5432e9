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
#include "ui/panels/picture_draw.hpp"
#include "ui/panels/stage_controls.hpp"
#include "ui/panels/tracing_trim_drawing.hpp"
#include "ui/panels/triangle_panels.hpp"
#include "ui/surface_actions.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/knot_drag.hpp"
#include "ui/view/picture.hpp"
#include "ui/view/text_wrap.hpp"
#include "ui/view/tracing_picture.hpp"

namespace isoparm::ui {

namespace {

// Knot values as ticks and runs show them: the one formatter (geom::format_short).
std::string short_number(double x) {
    return geom::format_short(x);
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

// The tracing square's colours in the window's theme (the dark one, or presentation's light).
TracingColors tracing_colors(const AppContext& ctx) {
    const doc::Rgba& ic = ctx.doc.colors.indicator;
    const doc::Rgba& kc = ctx.doc.colors.knot_curves;
    const bool light = ctx.ui.presentation;
    TracingColors p;
    p.background = light ? rgba8(250, 250, 250) : rgba8(28, 30, 36);
    p.border = light ? rgba8(0, 0, 0) : rgba8(170, 175, 190);
    p.grid = ImGui::ColorConvertFloat4ToU32(ImVec4(kc.r, kc.g, kc.b, 0.55f));
    p.tick = ImGui::ColorConvertFloat4ToU32(ImVec4(kc.r, kc.g, kc.b, 1));
    p.text = ImGui::GetColorU32(ImGuiCol_Text);
    p.faint = ImGui::GetColorU32(ImGuiCol_TextDisabled);
    p.multiplicity = light ? rgba8(170, 60, 0) : rgba8(255, 190, 90);
    p.indicator = ImGui::ColorConvertFloat4ToU32(ImVec4(ic.r, ic.g, ic.b, 1));
    p.cross = ImGui::ColorConvertFloat4ToU32(ImVec4(ic.r, ic.g, ic.b, 0.45f));
    p.current = light ? rgba8(255, 236, 200) : rgba8(52, 56, 70);
    p.negative = light ? rgba8(230, 60, 60, 70) : rgba8(230, 70, 70, 80);
    p.zero = light ? rgba8(200, 0, 0) : rgba8(255, 90, 90);
    p.weight = ImGui::GetColorU32(ImGuiCol_Text);
    p.weight_warning = light ? rgba8(190, 0, 0) : rgba8(255, 110, 110);
    p.weight_plate = light ? rgba8(255, 255, 255, 200) : rgba8(20, 22, 28, 190);
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
    text_wrapped("%s", note.text.c_str());
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
    text_wrapped("%d of %d borders kept %s when a point moves", held,
                 static_cast<int>(borders.size()), geom::name_of(ctx.doc.continuity));
    ImGui::PopStyleColor();
    // Why the others are not, in the panel itself (a tooltip would hide most of it).
    if (!why.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, warning_color(ctx));
        for (const std::string& w : why) text_wrapped("Not kept: %s", w.c_str());
        ImGui::PopStyleColor();
        // Borders an insertion broke later (U / V on one side) can be paired up again.
        if (!doc::conforming_insertions(ctx.doc, obj.patch_group).empty() &&
            ImGui::Button("Insert the knots the borders lack"))
            conform_current_group(ctx);
    }
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

// The exact values under the square (beside it on the stage): u and v in the surface's own
// parameters, the rational toggles, the last action's note, the knot vectors and the patch
// group's continuity.
void tracing_fields(AppContext& ctx, const doc::Object& obj, const geom::Surface& s,
                    const geom::ParamRect& dom, const glm::dvec2& uv, const ActionNote* note,
                    const std::vector<const doc::Object*>& patches) {
    const float k = ctx.ui.scale();
    const ImVec2 avail = ImGui::GetContentRegionAvail();
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
    if (geom::is_rational(s.type)) rational_toggles(ctx);
    if (note) action_note_line(ctx, *note);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    text_wrapped("knots u: %s", knot_vector_text(s.knots_u).c_str());
    text_wrapped("knots v: %s", knot_vector_text(s.knots_v).c_str());
    ImGui::PopStyleColor();
    if (!patches.empty()) continuity_controls(ctx, obj);
}

std::string tracing_title(const doc::Object& obj, const geom::Surface& s,
                          const std::vector<const doc::Object*>& patches) {
    std::string title = obj.name + "  (" + geom::name_of(s.type) + ", degree " +
                        std::to_string(s.degree_u) + " x " + std::to_string(s.degree_v) + ")";
    if (!patches.empty())
        title +=
            " - patch " +
            std::to_string(std::find(patches.begin(), patches.end(), &obj) - patches.begin() + 1) +
            " of " + std::to_string(patches.size());
    return title;
}

void title_line(AppContext& ctx, const std::string& title) {
    const float room = ImGui::GetContentRegionAvail().x - ImGui::GetFrameHeight() -
                       ImGui::GetStyle().ItemSpacing.x;
    const std::string shown = shortened(title, room, imgui_measure());
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(shown.c_str());
    if (shown != title && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", title.c_str());
    stage_button(ctx, StageView::tracing);
}

// The square's side in the room left: beside the fields on the stage, above them elsewhere.
float square_side(const AppContext& ctx, bool staged, const ImVec2& avail, float label_w,
                  float label_h, const ActionNote* note, bool rational) {
    const float k = ctx.ui.scale();
    // On the stage the fields stand beside the square, which takes the height.
    if (staged)
        return std::max(std::min(avail.y - label_h - 8 * k, (avail.x - label_w) * 0.68f), 60.f * k);
    // The note's wrapped height is kept free below the square so it is seen without
    // scrolling.
    const float note_h = note ? ImGui::CalcTextSize(note->text.c_str(), nullptr, false, avail.x).y +
                                    ImGui::GetStyle().ItemSpacing.y
                              : 0.f;
    const float fields_h = ImGui::GetFrameHeightWithSpacing() * (rational ? 3 : 2) +
                           ImGui::GetTextLineHeightWithSpacing() * 3 + note_h;
    return std::max(std::min(avail.x - label_w - 12 * k, avail.y - label_h - fields_h), 60.f * k);
}

// The square's picture (knot lines and ticks, the indicator, weights and the denominator),
// drawn; returns it for the knot handles.
TracingPicture draw_square(AppContext& ctx, const doc::Object& obj, const geom::Surface& s,
                           const Rect& canvas, const Rect& sq, float label_w, float label_h) {
    const float k = ctx.ui.scale();
    const bool rational = geom::is_rational(s.type);
    TracingInput in;
    in.canvas = canvas;
    in.square = sq;
    in.label_w = label_w;
    in.label_h = label_h;
    in.scale = k;
    in.line_height = ImGui::GetTextLineHeight();
    in.colors = tracing_colors(ctx);
    in.weights = rational && ctx.ui.show_weights;
    if (rational && ctx.ui.show_denominator) {
        ctx.ui.denominator.update(s);
        in.denominator = &ctx.ui.denominator;
        report_fact("tracing/zero_set_segments",
                    static_cast<double>(ctx.ui.denominator.zero_set().size()));
    }
    const KnotDrag& kd = ctx.ui.knot_drag;
    if (kd.active && kd.object == obj.id) in.held = std::pair{kd.dir, kd.first};
    const TracingPicture drawn = tracing_picture(ctx.doc, obj, in);
    if (in.weights) {
        int weights = 0;
        for (const LabelRequest& r : drawn.picture.labels)
            weights += r.priority == 20 || r.priority == 5;
        report_fact("tracing/weight_labels", weights);
    }
    // For the GUI tests: whether the indicator is drawn hollow (cut away by a trim).
    report_fact("tracing/indicator_cut", drawn.indicator_cut ? 1 : 0);
    draw_picture(drawn.picture);
    return drawn;
}

} // namespace

void draw_tracing_panel(AppContext& ctx) {
    const doc::Object* obj = nullptr;
    const geom::Surface* s =
        teaching_panel_surface(ctx, StageView::tracing, draw_triangle_tracing, &obj);
    if (!s) return;
    const float k = ctx.ui.scale();
    const bool staged = on_stage(ctx, StageView::tracing);
    // Subpatches share the original domain: the square shows all of it.
    const geom::ParamRect dom = doc::tracing_domain(ctx.doc, *obj);
    const std::vector<const doc::Object*> patches = doc::patch_members(ctx.doc, obj->patch_group);
    const glm::dvec2 uv = indicator_params(ctx.doc, *obj);
    // The name line, cut with its whole text in a tooltip where the column is narrow; on the
    // stage it heads the column beside the square, which then takes the whole height.
    const std::string title = tracing_title(*obj, *s, patches);
    if (!staged) title_line(ctx, title);

    // Room for the v labels on the left and the u labels below the square.
    // (Two lines of labels below: a knot's value and its multiplicity, each with the label
    // placer's padding.)
    const float label_w = ImGui::CalcTextSize("0.000").x + 10 * k;
    const float label_h = (ImGui::GetTextLineHeight() + 4) * 2 + 9 * k;
    const ActionNote* note = current_action_note(ctx);
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const bool rational = geom::is_rational(s->type);
    const float side = square_side(ctx, staged, avail, label_w, label_h, note, rational);
    const ImVec2 cur = ImGui::GetCursorScreenPos();
    const Rect canvas{cur.x + label_w, cur.y + 6 * k, side, side};
    // The square is one canvas: press anywhere to move the indicator there, then drag. On the
    // stage the wheel zooms into the domain and a right-drag pans (F fits).
    ImGui::SetCursorScreenPos(ImVec2(canvas.x, canvas.y));
    ImGui::InvisibleButton("##domain", ImVec2(canvas.w, canvas.h));
    report_item("tracing/square");
    const CanvasView cv = canvas_view(ctx, "tracing", canvas);
    const Rect sq = view_rect(cv, canvas, canvas); // the whole domain, seen through the view
    // While a trim loop is drawn (Surface > Trim), a click adds a corner instead.
    const bool drawing_loop = drawing_loop_on(ctx, *obj);
    if (drawing_loop) {
        loop_drawing_click(ctx, *obj, sq);
    } else if (ImGui::IsItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        const ImVec2 m = ImGui::GetIO().MousePos;
        ctx.doc.view.indicator = pixel_to_domain(sq, {m.x, m.y}); // view state, not undoable
    }
    ctx.ui.indicator_drag = !drawing_loop && ImGui::IsItemActive();

    // The drawing (ui/view/tracing_picture: the same Picture a figure of the view draws).
    const TracingPicture drawn = draw_square(ctx, *obj, *s, canvas, sq, label_w, label_h);
    if (drawing_loop) draw_loop_in_progress(ctx, *obj, sq, canvas);
    const std::vector<KnotTick>& tu = drawn.ticks_u;
    const std::vector<KnotTick>& tv = drawn.ticks_v;
    const std::vector<double>& px_u = drawn.px_u;
    const std::vector<double>& px_v = drawn.px_v;
    const ImVec2 a(canvas.x, canvas.y), b(canvas.x + canvas.w, canvas.y + canvas.h);

    // Knot ticks are handles (after the drawing: their buttons sit beside the square).
    knot_strip(ctx, *obj, *s, geom::Dir::u, tu, px_u, {a.x - 4 * k, b.y, canvas.w + 8 * k, label_h},
               sq, dom);
    knot_strip(ctx, *obj, *s, geom::Dir::v, tv, px_v,
               {cur.x, a.y - 4 * k, label_w, canvas.h + 8 * k}, sq, dom);

    // Exact values, in the surface's own parameters: under the square, or beside it on the
    // stage.
    bool side_column = false;
    if (staged) {
        const float x = cur.x + label_w + side + 16 * k;
        ImGui::SetCursorScreenPos(ImVec2(x, cur.y));
        side_column = ImGui::BeginChild("##tracing_fields",
                                        ImVec2(std::max(cur.x + avail.x - x, 1.f), avail.y));
        text_wrapped("%s", title.c_str());
    } else {
        ImGui::SetCursorScreenPos(ImVec2(cur.x, b.y + label_h));
    }
    tracing_fields(ctx, *obj, *s, dom, uv, note, patches);
    if (staged) {
        (void)side_column;
        ImGui::EndChild();
    }
}

} // namespace isoparm::ui
