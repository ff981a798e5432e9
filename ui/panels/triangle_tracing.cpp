// The tracing panel for a triangular patch: the barycentric domain triangle in place of the
// (u, v) square (Farin 17.1), with the control points' domain positions (i, j, k) / n and the
// draggable indicator (r, s, t); the three coordinates typed exactly, and S(r, s, t).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <string>

#include "core/geom/status.hpp"
#include "ui/panels/flow.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/picture_draw.hpp"
#include "ui/panels/triangle_panels.hpp"
#include "ui/surface_actions.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

namespace {

struct TrianglePalette {
    ImU32 bg, border, grid, text, dot, selected, cross;
};

TrianglePalette triangle_palette(const AppContext& ctx) {
    const bool light = ctx.ui.presentation;
    const doc::Rgba& kc = ctx.doc.colors.knot_curves;
    const doc::Rgba& pc = ctx.doc.colors.control_points;
    const doc::Rgba& sc = ctx.doc.colors.selected_point;
    const doc::Rgba& ic = ctx.doc.colors.indicator;
    TrianglePalette p;
    p.bg = light ? IM_COL32(250, 250, 250, 255) : IM_COL32(28, 30, 36, 255);
    p.border = light ? IM_COL32(0, 0, 0, 255) : IM_COL32(170, 175, 190, 255);
    p.grid = ImGui::ColorConvertFloat4ToU32(ImVec4(kc.r, kc.g, kc.b, 0.35f));
    p.text = ImGui::GetColorU32(ImGuiCol_Text);
    // Control-point yellow is unreadable on the light background: dark there.
    p.dot =
        light ? IM_COL32(60, 60, 60, 255) : ImGui::ColorConvertFloat4ToU32({pc.r, pc.g, pc.b, 1});
    p.selected = ImGui::ColorConvertFloat4ToU32({sc.r, sc.g, sc.b, 1});
    p.cross = ImGui::ColorConvertFloat4ToU32(ImVec4(ic.r, ic.g, ic.b, 0.45f));
    return p;
}

ImVec4 warning_color(const AppContext& ctx) {
    return ctx.ui.presentation ? ImVec4(0.7f, 0.25f, 0, 1) : ImVec4(1, 0.72f, 0.3f, 1);
}

// The domain grid (i, j, k) / n: the lines on which one coordinate is a multiple of 1/n, the
// parameter lines the control net follows.
void draw_grid(ImDrawList* dl, const TriangleCanvas& c, int n, ImU32 color, float k) {
    if (n > 40) return; // a solid fill, not a grid, past this
    for (int a = 1; a < n; ++a) {
        const double f = static_cast<double>(a) / n;
        for (int v = 0; v < 3; ++v) {
            // Coordinate v = f: from the edge where the next coordinate is 0 to the one where
            // the one after it is.
            geom::Barycentric p{}, q{};
            p[v] = q[v] = f;
            p[(v + 1) % 3] = 1 - f;
            q[(v + 2) % 3] = 1 - f;
            dl->AddLine(to_imvec(barycentric_to_pixel(c, p)), to_imvec(barycentric_to_pixel(c, q)),
                        color, k);
        }
    }
}

// The square's Denominator w picture on the triangle: where sum w_ijk B_ijk is negative,
// tinted red under the grid, and its zero set (where the patch goes to infinity) over it.
const TriangleDenominatorView& denominator_picture(AppContext& ctx, const geom::TrianglePatch& t) {
    constexpr int subdivisions = 48;
    TriangleDenominatorView& v = ctx.ui.triangle_denominator;
    if (!same_denominator(v, t, subdivisions)) v = triangle_denominator_view(t, subdivisions);
    return v;
}

void draw_negative_part(const AppContext& ctx, ImDrawList* dl, const TriangleCanvas& c,
                        const TriangleDenominatorView& v) {
    // Opaque: translucent small triangles would show their seams.
    const ImU32 tint =
        ctx.ui.presentation ? IM_COL32(246, 196, 196, 255) : IM_COL32(96, 34, 40, 255);
    for (const auto& small : v.negative)
        dl->AddTriangleFilled(to_imvec(barycentric_to_pixel(c, small[0])),
                              to_imvec(barycentric_to_pixel(c, small[1])),
                              to_imvec(barycentric_to_pixel(c, small[2])), tint);
}

void draw_zero_set(ImDrawList* dl, const TriangleCanvas& c, const TriangleDenominatorView& v,
                   float k) {
    for (const auto& segment : v.zero_set)
        dl->AddLine(to_imvec(barycentric_to_pixel(c, segment[0])),
                    to_imvec(barycentric_to_pixel(c, segment[1])), IM_COL32(230, 40, 40, 255),
                    2 * k);
    report_fact("tracing/zero_set_segments", static_cast<double>(v.zero_set.size()));
}

// Lines r = const, s = const and t = const through the indicator: the three isoparametric
// lines the 3D view draws on the patch.
void draw_cross(ImDrawList* dl, const TriangleCanvas& c, const geom::Barycentric& p, ImU32 color,
                float k) {
    for (int v = 0; v < 3; ++v) {
        geom::Barycentric a{}, b{};
        a[v] = b[v] = p[v];
        a[(v + 1) % 3] = 1 - p[v];
        b[(v + 2) % 3] = 1 - p[v];
        dl->AddLine(to_imvec(barycentric_to_pixel(c, a)), to_imvec(barycentric_to_pixel(c, b)),
                    color, 1.5f * k);
    }
}

float dot_radius(int n, float k) {
    return n <= 12 ? 3.5f * k : 2 * k;
}

// b_ijk at (i, j, k) / n, where B^n_ijk peaks (the selected one larger, in the selection's
// colour); for a rational patch with Weights on, each weight beside its dot.
void draw_domain_points(const AppContext& ctx, ImDrawList* dl, Picture& pic,
                        const TriangleCanvas& c, const geom::TrianglePatch& t,
                        const TrianglePalette& pal) {
    const float k = ctx.ui.scale();
    const int n = t.degree;
    const doc::Selection& sel = ctx.doc.view.selection;
    const float r = dot_radius(n, k);
    const bool weights = t.rational && ctx.ui.show_weights && n <= 12;
    const glm::dvec2 centre = barycentric_to_pixel(c, {1.0 / 3, 1.0 / 3, 1.0 / 3});
    for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j) {
            const glm::dvec2 at =
                barycentric_to_pixel(c, {static_cast<double>(i) / n, static_cast<double>(j) / n,
                                         static_cast<double>(n - i - j) / n});
            if (n <= 9)
                report_point("tracing/triangle/b" + std::to_string(i) + std::to_string(j) +
                                 std::to_string(n - i - j),
                             static_cast<float>(at.x), static_cast<float>(at.y));
            const bool chosen = sel.i == i && sel.j == j;
            dl->AddCircleFilled(to_imvec(at), r, chosen ? pal.selected : pal.dot, 12);
            // A ring, not a larger disc: the indicator is a red disc too.
            if (chosen) dl->AddCircle(to_imvec(at), 2.2f * r, pal.selected, 16, 2 * k);
            if (!weights) continue;
            // The placer keeps each weight beside its dot, clear of the others and of the
            // vertices' labels.
            const double w = t.weights[geom::TrianglePatch::index(n, i, j)];
            LabelRequest& l =
                pic.label(glm::vec2(at), geom::format_short(w, 3), pal.text, w != 1 ? 20 : 5);
            l.tooltip = triangle_point_name(n, 0, i, j) + ": w = " + geom::format_number(w);
        }
    (void)centre;
}

// The width of each of the r, s, t fields, and on how many rows they fall in this column.
struct FieldsLayout {
    float width, label;
    int rows;
};

FieldsLayout fields_layout(const AppContext& ctx, float avail) {
    const ImGuiStyle& st = ImGui::GetStyle();
    const float field = ImGui::CalcTextSize("0.00000").x + st.FramePadding.x * 2;
    const float label = ImGui::CalcTextSize("r").x + st.ItemInnerSpacing.x + st.ItemSpacing.x;
    const float width = std::max(std::min((avail - 3 * label) / 3, 110 * ctx.ui.scale()), field);
    const int per_row = std::max(1, std::min(3, static_cast<int>(avail / (width + label))));
    return {width, label, (3 + per_row - 1) / per_row};
}

// r, s and t typed: the other two keep their ratio (set_barycentric_coordinate); a value
// outside [0, 1] is refused with the reason under the fields.
void coordinate_fields(AppContext& ctx, float avail) {
    static const char* labels[3] = {"r", "s", "t"};
    static const char* items[3] = {"tracing/r", "tracing/s", "tracing/t"};
    const FieldsLayout f = fields_layout(ctx, avail);
    const float width = f.width, label = f.label;
    geom::Barycentric& p = ctx.doc.view.barycentric;
    for (int v = 0; v < 3; ++v) {
        if (v > 0) same_line_if_fits(width + label);
        double value = p[v];
        ImGui::SetNextItemWidth(width);
        // Applied on Enter: while typing, "1" on the way to "1.2" would move the indicator.
        if (ImGui::InputDouble(labels[v], &value, 0, 0, "%.4f",
                               ImGuiInputTextFlags_EnterReturnsTrue)) {
            const auto q = set_barycentric_coordinate(p, v, value);
            if (q) {
                p = *q;
                ctx.ui.barycentric_refusal.clear();
            } else {
                ctx.ui.barycentric_refusal = "Not moved: " + q.error().message + ".";
            }
        }
        report_item(items[v]);
        if (ImGui::IsItemHovered())
            wrapped_tooltip("Type a value and press Enter: the other two coordinates keep "
                            "their ratio and share the rest, so r + s + t stays 1.");
    }
    if (!ctx.ui.barycentric_refusal.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, warning_color(ctx));
        text_wrapped("%s", ctx.ui.barycentric_refusal.c_str());
        ImGui::PopStyleColor();
    }
    report_fact("tracing/barycentric_refused", ctx.ui.barycentric_refusal.empty() ? 0 : 1);
}

void patch_point_line(const geom::TrianglePatch& t, const geom::Barycentric& p) {
    if (const auto S = geom::triangle_point(t, p)) {
        text_wrapped("S(%.4g, %.4g, %.4g) = (%.6g, %.6g, %.6g)", p[0], p[1], p[2], S->x, S->y,
                     S->z);
    } else {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.6f, 0.2f, 1));
        text_wrapped("S(%.4g, %.4g, %.4g) does not exist: sum w_ijk B_ijk = 0 here", p[0], p[1],
                     p[2]);
        ImGui::PopStyleColor();
    }
}

} // namespace

void draw_triangle_tracing(AppContext& ctx, const doc::Object& obj, const geom::TrianglePatch& t) {
    const float k = ctx.ui.scale();
    const int n = t.degree;
    text_wrapped("%s  (%s triangular Bezier, degree %d)", obj.name.c_str(),
                 t.rational ? "rational" : "polynomial", n);
    const ActionNote* note = current_action_note(ctx);
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float note_h = note ? ImGui::CalcTextSize(note->text.c_str(), nullptr, false, avail.x).y +
                                    ImGui::GetStyle().ItemSpacing.y
                              : 0.f;
    // Below the canvas: the fields, a refusal, S(r, s, t) (two lines in a narrow column), the
    // selection and the weights toggle.
    const float line = ImGui::GetTextLineHeightWithSpacing();
    const int field_rows = fields_layout(ctx, avail.x).rows;
    const float fields_h =
        ImGui::GetFrameHeightWithSpacing() * (field_rows + (t.rational ? 1 : 0)) +
        line * (ctx.ui.barycentric_refusal.empty() ? 4 : 6) + note_h;
    const float height = std::max(
        std::min(avail.x * std::sqrt(3.f) / 2 + triangle_label_room(k), avail.y - fields_h),
        120.f * k);
    const ImVec2 cur = ImGui::GetCursorScreenPos();
    const Rect box{cur.x, cur.y, avail.x, height};
    const TriangleCanvas c = fit_triangle(triangle_area(box, k), 6 * k);

    ctx.ui.indicator_drag = barycentric_canvas(ctx, "##triangle", box, c);
    report_item("tracing/triangle");
    const char* vertex_names[3] = {"tracing/triangle/r1", "tracing/triangle/s1",
                                   "tracing/triangle/t1"};
    for (int v = 0; v < 3; ++v)
        report_point(vertex_names[v], static_cast<float>(c.vertex[v].x),
                     static_cast<float>(c.vertex[v].y));

    const TrianglePalette pal = triangle_palette(ctx);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 A = to_imvec(c.vertex[0]), B = to_imvec(c.vertex[1]), C = to_imvec(c.vertex[2]);
    dl->AddTriangleFilled(A, B, C, pal.bg);
    const TriangleDenominatorView* denominator =
        t.rational && ctx.ui.show_denominator ? &denominator_picture(ctx, t) : nullptr;
    if (denominator) draw_negative_part(ctx, dl, c, *denominator);
    draw_grid(dl, c, n, pal.grid, k);
    if (denominator) draw_zero_set(dl, c, *denominator, k);
    const geom::Barycentric& p = ctx.doc.view.barycentric;
    draw_cross(dl, c, p, pal.cross, k);
    dl->AddTriangle(A, B, C, pal.border, 1.5f * k);
    Picture pic; // every text on the canvas, placed together over the drawing
    pic.view = "tracing";
    pic.frame = box;
    pic.style.offset = 4 * k;
    vertex_labels(pic, c, n, pal.text, k);
    draw_domain_points(ctx, dl, pic, c, t, pal);
    const glm::dvec2 handle = barycentric_to_pixel(c, p);
    draw_indicator_handle(dl, handle, ctx, 7 * k);
    pic.keep_clear.push_back({static_cast<float>(handle.x) - 7 * k,
                              static_cast<float>(handle.y) - 7 * k, 14 * k, 14 * k});
    draw_picture(pic, dl);
    report_point("tracing/barycentric_handle", static_cast<float>(handle.x),
                 static_cast<float>(handle.y));
    report_fact("tracing/barycentric", {p[0], p[1], p[2]});
    // A right click on a dot selects its control point (the Basis tab then shows its basis
    // function); the left button stays the indicator's, also on a dot.
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const auto dot = ImGui::IsItemHovered()
                         ? domain_point_at(c, n, {mouse.x, mouse.y}, 2.2f * dot_radius(n, k))
                         : std::nullopt;
    if (dot && ImGui::IsMouseClicked(ImGuiMouseButton_Right))
        ctx.doc.view.selection = {obj.id, dot->first, dot->second};
    if (dot && !ImGui::IsItemActive()) {
        wrapped_tooltip(point_name('P', dot->first, dot->second, &obj) + " at (" +
                        std::to_string(dot->first) + ", " + std::to_string(dot->second) + ", " +
                        std::to_string(n - dot->first - dot->second) + ") / " + std::to_string(n) +
                        ". Right-click to select it.");
    } else if (ImGui::IsItemHovered() && !ImGui::IsItemActive()) {
        wrapped_tooltip("The domain triangle: each point is (r, s, t), r + s + t = 1. The dots "
                        "are (i, j, k) / n, where b_ijk pulls the patch most. Press or drag to "
                        "move the indicator; right-click a dot to select its control point.");
    }

    ImGui::SetCursorScreenPos(ImVec2(cur.x, box.y + box.h));
    coordinate_fields(ctx, avail.x);
    patch_point_line(t, p);
    const doc::Selection& sel = ctx.doc.view.selection;
    if (sel.object == obj.id && sel.has_point()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        text_wrapped("%s at (%d, %d, %d) / %d", point_name('P', sel.i, sel.j, &obj).c_str(), sel.i,
                     sel.j, n - sel.i - sel.j, n);
        ImGui::PopStyleColor();
    }
    if (t.rational) {
        ImGui::Checkbox("Denominator w", &ctx.ui.show_denominator);
        report_item("tracing/denominator");
        if (ImGui::IsItemHovered())
            wrapped_tooltip("Where w(r, s, t) = sum w_ijk B_ijk is negative the triangle is "
                            "tinted red; the red line is w = 0, where the patch goes to infinity.");
        same_line_if_fits(toggle_width("Weights"));
        ImGui::Checkbox("Weights", &ctx.ui.show_weights);
        report_item("tracing/weights");
        if (ImGui::IsItemHovered())
            wrapped_tooltip("Each control point's weight w_ijk beside its dot (i, j, k) / n.");
    }
    if (note) {
        ImGui::PushStyleColor(ImGuiCol_Text, note->refused
                                                 ? warning_color(ctx)
                                                 : ImGui::GetStyleColorVec4(ImGuiCol_Text));
        text_wrapped("%s", note->text.c_str());
        ImGui::PopStyleColor();
    }
}

} // namespace isoparm::ui
