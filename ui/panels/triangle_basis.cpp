// The Basis tab for a triangular patch: the selected b_ijk's Bernstein polynomial B^n_ijk
// (rational patch: R_ijk = w_ijk B^n_ijk / sum w B) as a heat map over the domain triangle, its
// peak, its value at the indicator, and the partition of unity sum B^n_ijk = 1 (Farin 17.1).
// Every value comes from core (geom::bernstein_triangle, geom::rational_bernstein_triangle).
#include <cmath>
#include <cstdio>
#include <string>

#include "core/geom/binomial.hpp"
#include "core/geom/status.hpp"
#include "ui/panels/canvas_hint.hpp"
#include "ui/panels/heat_color.hpp"
#include "ui/panels/picture_draw.hpp"
#include "ui/panels/triangle_panels.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

namespace {

// The grid the map is coloured on: (N + 1)(N + 2) / 2 values, N^2 small triangles whose
// colours ImGui blends between their corners.
constexpr int heat_subdivisions = 32;

bool has_negative(const TriangleHeat& h) {
    for (double v : h.values)
        if (v < 0) return true;
    return false;
}

// The map and its extremes (the lowest only where a negative weight makes R negative),
// recomputed when the degree, the weights or the point change: not while a point is dragged.
const TriangleHeat& cached_heat(AppContext& ctx, const geom::TrianglePatch& t, int i, int j) {
    TriangleHeat& h = ctx.ui.triangle_heat;
    if (same_heat(h, t, i, j, heat_subdivisions)) return h;
    h = triangle_heat(t, i, j, heat_subdivisions);
    h.peak = triangle_basis_peak(t, i, j, h);
    if (has_negative(h)) h.low = triangle_basis_peak(t, i, j, h, true);
    return h;
}

// "B^3_111" or, rational, "R111": how the panel names the function of b_ijk.
std::string function_name(const geom::TrianglePatch& t, int i, int j) {
    const std::string point = triangle_point_name(t.degree, 0, i, j); // "b111"
    return t.rational ? "R" + point.substr(1)
                      : "B^" + std::to_string(t.degree) + "_" + point.substr(1);
}

// n! / (i! j! k!) r^i s^j t^k with this point's numbers: "6 r s t", "3 r^2 t".
std::string closed_form(int n, int i, int j) {
    char coefficient[32];
    std::snprintf(coefficient, sizeof coefficient, "%.6g",
                  geom::binomial(n, i) * geom::binomial(n - i, j));
    std::string s = coefficient;
    const int power[3] = {i, j, n - i - j};
    static const char* names[3] = {"r", "s", "t"};
    for (int v = 0; v < 3; ++v) {
        if (power[v] == 0) continue;
        s += std::string(" ") + names[v];
        if (power[v] > 1) s += "^" + std::to_string(power[v]);
    }
    return s;
}

// sum over every b_abc of its basis function at p; nullopt where the patch point does not exist.
std::optional<double> basis_sum(const geom::TrianglePatch& t, const geom::Barycentric& p) {
    double sum = 0;
    for (int a = t.degree; a >= 0; --a)
        for (int b = t.degree - a; b >= 0; --b) {
            const auto R = geom::rational_bernstein_triangle(t, a, b, p);
            if (!R) return std::nullopt;
            sum += *R;
        }
    return sum;
}

// The heat map itself: one vertex per grid point, coloured by value / the largest |value|
// (grey where R does not exist), two triangles per grid cell as tessellate_triangle makes them.
void draw_heat(ImDrawList* dl, const TriangleCanvas& c, const TriangleHeat& h) {
    const int N = h.key.subdivisions;
    const int vertices = geom::TrianglePatch::count_for(N);
    const ImVec2 uv = ImGui::GetFontTexUvWhitePixel();
    dl->PrimReserve(3 * N * N, vertices);
    const unsigned base = dl->_VtxCurrentIdx;
    for (int a = N; a >= 0; --a)
        for (int b = N - a; b >= 0; --b) { // TrianglePatch::index(N, a, b) order
            const double v =
                h.values[static_cast<std::size_t>(geom::TrianglePatch::index(N, a, b))];
            const double d = N;
            const ImVec2 at = to_imvec(barycentric_to_pixel(c, {a / d, b / d, (N - a - b) / d}));
            const ImU32 col = std::isnan(v)
                                  ? IM_COL32(90, 90, 90, 255)
                                  : heat_color(h.largest_magnitude > 0
                                                   ? static_cast<float>(v / h.largest_magnitude)
                                                   : 0.f);
            dl->PrimWriteVtx(at, uv, col);
        }
    auto at = [&](int a, int b) {
        return static_cast<ImDrawIdx>(base +
                                      static_cast<unsigned>(geom::TrianglePatch::index(N, a, b)));
    };
    for (int a = 0; a < N; ++a)
        for (int b = 0; a + b < N; ++b) {
            // The cell's upward triangle, and its downward one where the cell has it.
            dl->PrimWriteIdx(at(a, b));
            dl->PrimWriteIdx(at(a + 1, b));
            dl->PrimWriteIdx(at(a, b + 1));
            if (a + b + 2 > N) continue;
            dl->PrimWriteIdx(at(a + 1, b));
            dl->PrimWriteIdx(at(a + 1, b + 1));
            dl->PrimWriteIdx(at(a, b + 1));
        }
}

// A vertical bar of the ramp beside the map, from 0 (or -max where negative weights make R
// negative) at the bottom to the largest |value| at the top, with those values written.
void colour_bar(ImDrawList* dl, Picture& pic, const Rect& bar, const TriangleHeat& h, float k) {
    const bool negative = has_negative(h);
    const float lo = negative ? -1.f : 0.f;
    constexpr int segments = 24;
    for (int s = 0; s < segments; ++s) {
        const float f0 = static_cast<float>(s) / segments,
                    f1 = static_cast<float>(s + 1) / segments;
        const ImU32 c0 = heat_color(lo + (1 - lo) * f0), c1 = heat_color(lo + (1 - lo) * f1);
        const float y0 = bar.y + bar.h * (1 - f0), y1 = bar.y + bar.h * (1 - f1);
        dl->AddRectFilledMultiColor(ImVec2(bar.x, y1), ImVec2(bar.x + bar.w, y0), c1, c1, c0, c0);
    }
    dl->AddRect(ImVec2(bar.x, bar.y), ImVec2(bar.x + bar.w, bar.y + bar.h),
                ImGui::GetColorU32(ImGuiCol_Border), 0, 0, k);
    const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
    const float x = bar.x + bar.w + 3 * k;
    pic.fixed_label({x, bar.y}, geom::format_short(h.largest_magnitude, 3), text,
                    LabelAlign::top_left, 110);
    pic.fixed_label({x, bar.y + bar.h},
                    geom::format_short(negative ? -h.largest_magnitude : 0.0, 3), text,
                    LabelAlign::bottom_left, 110);
}

// The marks over the map: the selected point's (i, j, k) / n, the max and min, the indicator.
void map_marks(AppContext& ctx, ImDrawList* dl, const TriangleCanvas& c,
               const geom::TrianglePatch& t, int i, int j, const BasisPeak& peak,
               const BasisPeak& low) {
    const float k = ctx.ui.scale();
    const int n = t.degree;
    const doc::Rgba& sc = ctx.doc.colors.selected_point;
    const glm::dvec2 home =
        barycentric_to_pixel(c, {static_cast<double>(i) / n, static_cast<double>(j) / n,
                                 static_cast<double>(n - i - j) / n});
    dl->AddCircle(to_imvec(home), 6 * k, ImGui::ColorConvertFloat4ToU32({sc.r, sc.g, sc.b, 1}), 16,
                  2 * k);
    // White + at the max, white x at the min (where a negative weight makes one).
    auto mark = [&](const BasisPeak& e, bool plus, const char* name) {
        if (!e.found) return;
        const ImVec2 m = to_imvec(barycentric_to_pixel(c, e.at));
        const float r = 5 * k;
        const ImU32 white = IM_COL32(255, 255, 255, 235);
        if (plus) {
            dl->AddLine(ImVec2(m.x - r, m.y), ImVec2(m.x + r, m.y), white, 1.5f * k);
            dl->AddLine(ImVec2(m.x, m.y - r), ImVec2(m.x, m.y + r), white, 1.5f * k);
        } else {
            dl->AddLine(ImVec2(m.x - r, m.y - r), ImVec2(m.x + r, m.y + r), white, 1.5f * k);
            dl->AddLine(ImVec2(m.x - r, m.y + r), ImVec2(m.x + r, m.y - r), white, 1.5f * k);
        }
        report_point(name, m.x, m.y);
    };
    mark(peak, true, "basis/triangle/peak");
    mark(low, false, "basis/triangle/low");
    draw_indicator_handle(dl, barycentric_to_pixel(c, ctx.doc.view.barycentric), ctx, 5 * k);
}

void value_line(const geom::TrianglePatch& t, int i, int j, const geom::Barycentric& p) {
    const std::string name = function_name(t, i, j);
    if (const auto R = geom::rational_bernstein_triangle(t, i, j, p)) {
        text_wrapped("%s(%.3f, %.3f, %.3f) = %.5f", name.c_str(), p[0], p[1], p[2], *R);
        report_fact("basis/triangle_value", *R);
    } else {
        text_wrapped("%s(%.3f, %.3f, %.3f) undefined (zero denominator)", name.c_str(), p[0], p[1],
                     p[2]);
    }
}

// B^n_ijk written out with this point's numbers, and for a rational patch how R_ijk is made
// from it.
void formula_lines(const geom::TrianglePatch& t, int i, int j, const geom::Barycentric& p) {
    const int n = t.degree;
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    const std::string b =
        "B^" + std::to_string(n) + "_" + triangle_point_name(n, 0, i, j).substr(1);
    text_wrapped("%s = %d!/(%d! %d! %d!) r^%d s^%d t^%d = %s", b.c_str(), n, i, j, n - i - j, i, j,
                 n - i - j, closed_form(n, i, j).c_str());
    if (t.rational)
        text_wrapped("%s = w %s / sum w B, with w = %.4g and %s = %.5f here",
                     function_name(t, i, j).c_str(), b.c_str(),
                     t.weights[geom::TrianglePatch::index(n, i, j)], b.c_str(),
                     geom::bernstein_triangle(n, i, j, p));
    ImGui::PopStyleColor();
}

void sum_line(const geom::TrianglePatch& t, const geom::Barycentric& p) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    const char* f = t.rational ? "R_ijk" : "B^n_ijk";
    if (const auto sum = basis_sum(t, p)) {
        text_wrapped("Partition of unity: the sum of all %d %s at (r, s, t) = %.6f",
                     geom::TrianglePatch::count_for(t.degree), f, *sum);
        report_fact("basis/triangle_sum", *sum);
    } else {
        text_wrapped("S(r, s, t) does not exist here (zero denominator)");
    }
    ImGui::PopStyleColor();
}

// "max 0.44444 at (2, 0, 1) / 3 = (i, j, k) / n" or, searched, where it is; `what` is "max"
// or "min".
void extreme_line(const char* what, const char* mark, int n, int i, int j, const BasisPeak& e) {
    const double value = e.value + 0.0; // no "-0"
    if (e.exact) {
        text_wrapped("%s %.5f at (%d, %d, %d) / %d = (i, j, k) / n (%s)", what, value, i, j,
                     n - i - j, n, mark);
        return;
    }
    const double d = std::abs(e.at[0] - static_cast<double>(i) / n) +
                     std::abs(e.at[1] - static_cast<double>(j) / n);
    text_wrapped("%s %.5f at (%.3f, %.3f, %.3f) (%s), found by search: %s", what, value, e.at[0],
                 e.at[1], e.at[2], mark,
                 d > 1e-6 ? "not at (i, j, k) / n (ring)" : "at (i, j, k) / n (ring)");
}

void peak_lines(const geom::TrianglePatch& t, int i, int j, const BasisPeak& peak,
                const BasisPeak& low) {
    report_fact("basis/triangle_unbounded", peak.unbounded ? 1 : 0);
    if (peak.unbounded) {
        text_wrapped("No max or min: sum w_abc B_abc is zero inside the triangle (weights "
                     "of both signs), and R_ijk grows without bound towards it.");
        return;
    }
    if (!peak.found) {
        text_wrapped("The function exists nowhere on the grid (zero denominator).");
        return;
    }
    report_fact("basis/triangle_max", peak.value + 0.0);
    extreme_line("max", "white +", t.degree, i, j, peak);
    // A negative weight turns R_ijk negative: its lowest value is the one to see.
    if (!low.found) return;
    report_fact("basis/triangle_min", low.value + 0.0);
    extreme_line("min", "white x", t.degree, i, j, low);
}

} // namespace

void draw_triangle_basis(AppContext& ctx, const doc::Object& obj, const geom::TrianglePatch& t) {
    const float k = ctx.ui.scale();
    const geom::Barycentric p = ctx.doc.view.barycentric;
    const doc::Selection& sel = ctx.doc.view.selection;
    const bool point =
        sel.object == obj.id && sel.has_point() && doc::has_control_point(obj.shape, sel.i, sel.j);
    if (point)
        value_line(t, sel.i, sel.j, p);
    else
        text_wrapped("Select a control point b_ijk to see its basis function.");
    sum_line(t, p);

    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float bar_w = 12 * k, bar_room = bar_w + ImGui::CalcTextSize("-0.000").x + 8 * k;
    const float lines = ImGui::GetTextLineHeightWithSpacing() * 2;
    const float width = std::max(avail.x - bar_room, 60 * k);
    // Never so small that the map is unreadable: the tab scrolls instead.
    const float height = std::max(
        std::min(width * std::sqrt(3.f) / 2 + triangle_label_room(k), avail.y - lines), 190 * k);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const Rect box{origin.x, origin.y, width, height};
    const TriangleCanvas c = fit_triangle(triangle_area(box, k), 4 * k);

    barycentric_canvas(ctx, "##triangle_heat", box, c);
    report_item("basis/triangle");
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 A = to_imvec(c.vertex[0]), B = to_imvec(c.vertex[1]), C = to_imvec(c.vertex[2]);
    Picture pic; // the map's texts (vertex names, the bar's values), placed together
    pic.view = "basis_heat";
    pic.frame = {box.x, box.y, box.w + bar_room, box.h};
    BasisPeak peak, low;
    if (point) {
        const TriangleHeat& h = cached_heat(ctx, t, sel.i, sel.j);
        draw_heat(dl, c, h);
        peak = h.peak;
        low = h.low;
        colour_bar(dl, pic, {box.x + box.w + 4 * k, B.y, bar_w, A.y - B.y}, h, k);
        if (!ImGui::IsItemActive() && canvas_hint_due(ctx.ui))
            ImGui::SetTooltip("%s over the domain triangle; press or drag to move the indicator",
                              function_name(t, sel.i, sel.j).c_str());
    }
    dl->AddTriangle(A, B, C, ImGui::GetColorU32(ImGuiCol_Border), k);
    vertex_labels(pic, c, t.degree, ImGui::GetColorU32(ImGuiCol_Text), k);
    if (point)
        map_marks(ctx, dl, c, t, sel.i, sel.j, peak, low);
    else
        draw_indicator_handle(dl, barycentric_to_pixel(c, p), ctx, 5 * k);
    draw_picture(pic, dl);

    ImGui::SetCursorScreenPos(ImVec2(origin.x, box.y + box.h));
    if (!point) return;
    peak_lines(t, sel.i, sel.j, peak, low);
    formula_lines(t, sel.i, sel.j, p);
}

} // namespace isoparm::ui
