// The de Boor tab for a triangular patch: de Casteljau's construction on the triangle (Farin
// 17.3) at the indicator (r, s, t), level by level with the same step control as de Boor's
// (|<, <, Play, >, All and the [ ] keys through deboor_step), every point b^l_ijk by name.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "ui/panels/flow.hpp"
#include "ui/panels/triangle_panels.hpp"
#include "ui/surface_actions.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/deboor_overlay.hpp"

namespace isoparm::ui {

namespace {

using Levels = std::vector<std::vector<std::optional<glm::dvec3>>>;

std::string point_text(const std::optional<glm::dvec3>& b, double w, bool rational) {
    char buf[128];
    if (!b)
        std::snprintf(buf, sizeof buf, "at infinity (w 0)");
    else if (rational)
        std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g) w %.4g", b->x, b->y, b->z, w);
    else
        std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", b->x, b->y, b->z);
    return buf;
}

// The colours the 3D view draws the levels in (ui/view/triangle_scene.cpp): level 0 plain,
// level l as de Boor's u-stage level l.
ImVec4 level_color(int level) {
    if (level == 0) return ImGui::GetStyleColorVec4(ImGuiCol_Text);
    const glm::vec4 c = deboor_level_color(true, level);
    return {c.r, c.g, c.b, 1};
}

// The rule every level applies; what it means, with this indicator's numbers, on hover (the
// tab is short: the points come first).
void formula_line(const geom::Barycentric& p, bool rational) {
    text_wrapped("b^l_ijk = r b^(l-1)_(i+1)jk + s b^(l-1)_i(j+1)k + t b^(l-1)_ij(k+1)");
    if (ImGui::IsItemHovered())
        wrapped_tooltip(
            "With (r, s, t) = (" + geom::format_number(p[0]) + ", " + geom::format_number(p[1]) +
            ", " + geom::format_number(p[2]) +
            ") and i + j + k = n - l: each point of level l is the point (r, s, t) of a small "
            "triangle of level l - 1, so each level has one point fewer along every side." +
            (rational ? " Rational: computed on (wx, wy, wz, w), shown as points and weights."
                      : ""));
}

// The three points of level - 1 a point of `level` is made from, with their weights r, s, t.
std::string parents_text(int n, int level, int i, int j, const geom::Barycentric& p) {
    char buf[160];
    const int l = level - 1;
    std::snprintf(buf, sizeof buf, "%s = %.4g %s + %.4g %s + %.4g %s",
                  triangle_point_name(n, level, i, j).c_str(), p[0],
                  triangle_point_name(n, l, i + 1, j).c_str(), p[1],
                  triangle_point_name(n, l, i, j + 1).c_str(), p[2],
                  triangle_point_name(n, l, i, j).c_str());
    return buf;
}

// One level's points, a line each in the level's colour; greyed when not reached yet,
// marked ">" when it is the current step's.
void level_lines(const geom::TrianglePatch& t, const Levels& levels,
                 const std::vector<std::vector<double>>& weights, const geom::Barycentric& p,
                 int level, int upto, bool current) {
    const int n = t.degree, m = n - level;
    const ImVec4 c =
        level > upto ? ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled) : level_color(level);
    const auto& points = levels[static_cast<std::size_t>(level)];
    const auto& w = weights[static_cast<std::size_t>(level)];
    for (int i = m; i >= 0; --i)
        for (int j = m - i; j >= 0; --j) {
            const std::size_t at = static_cast<std::size_t>(geom::TrianglePatch::index(m, i, j));
            const std::string name = triangle_point_name(n, level, i, j);
            ImGui::TextColored(c, "%s%-9s %s", current ? "> " : "  ", name.c_str(),
                               point_text(points[at], w[at], t.rational).c_str());
            if (level > 0 && ImGui::IsItemHovered())
                ImGui::SetTooltip("%s", parents_text(n, level, i, j, p).c_str());
        }
}

} // namespace

void draw_triangle_casteljau(AppContext& ctx, const doc::Object& obj,
                             const geom::TrianglePatch& t) {
    const int n = t.degree;
    const int last = deboor_step_count(ctx); // n: steps 0..n
    clamp_deboor_step(ctx);
    DeBoorPlayer& player = ctx.ui.deboor;
    const geom::Barycentric p = ctx.doc.view.barycentric;
    const Levels levels = geom::triangle_de_casteljau(t, p);
    const std::vector<std::vector<double>> weights = triangle_level_weights(t, p);

    text_wrapped("de Casteljau on the triangle %s (degree %d)", obj.name.c_str(), n);
    ImGui::Checkbox("Show in 3D (D)", &ctx.doc.view.display.deboor);
    same_line_if_fits(button_width("Zoom to patch"));
    if (ImGui::Button("Zoom to patch")) zoom_to_acting_patch(ctx);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Frame the %d control points (all act everywhere); F fits everything",
                          geom::TrianglePatch::count_for(n));
    deboor_step_buttons(ctx, last);
    if (player.step >= 0)
        text_wrapped("Step %d of %d: %s", player.step, last,
                     triangle_step_text(player.step, n).c_str());
    else
        ImGui::Text("All %d levels shown", last + 1);
    const int level = player.step;
    report_fact("deboor/level", level);
    int shown = 0;
    for (int l = 0; l <= n; ++l)
        if (level < 0 || l == level) shown += triangle_level_size(n, l);
    report_fact("deboor/level_points", shown);

    // (r, s, t) is in the tracing panel above: the point's name and value are what is new.
    if (const auto& S = levels.back()[0])
        text_wrapped("S = %s = (%.5g, %.5g, %.5g)", triangle_point_name(n, n, 0, 0).c_str(), S->x,
                     S->y, S->z);
    else {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.6f, 0.2f, 1));
        text_wrapped("S(%.4g, %.4g, %.4g) does not exist: the weights sum to zero here", p[0], p[1],
                     p[2]);
        ImGui::PopStyleColor();
    }
    formula_line(p, t.rational);

    const int upto = level < 0 ? n : level;
    ImGui::Separator();
    // The list scrolls under the controls; in a very short tab, the whole tab scrolls rather
    // than leave the list a line or two.
    const float list_h =
        std::max(ImGui::GetContentRegionAvail().y, ImGui::GetTextLineHeightWithSpacing() * 8);
    ImGui::BeginChild("##casteljau_values", ImVec2(0, list_h));
    // When the step moves, the level it reaches opens and the others close (all open for
    // "All"); in between, the teacher may open or close any of them.
    static int opened_for = -2;
    const bool moved = opened_for != level;
    opened_for = level;
    for (int l = 0; l <= n; ++l) {
        const int count = triangle_level_size(n, l);
        const std::string title =
            (l == 0 ? std::string("control points") : "level " + std::to_string(l)) + ": " +
            std::to_string(count) + (count == 1 ? " point" : " points");
        const bool current = level >= 0 && l == level;
        if (moved) ImGui::SetNextItemOpen(level < 0 || current, ImGuiCond_Always);
        ImGui::PushID(l);
        const bool open = ImGui::TreeNode(title.c_str());
        ImGui::PopID();
        if (!open) continue;
        level_lines(t, levels, weights, p, l, upto, current);
        ImGui::TreePop();
    }
    ImGui::EndChild();
}

} // namespace isoparm::ui
