// The de Boor tab: step control (level by level, back and forth, animated play) and every
// intermediate value of the construction at the indicator, u-stage then v-stage. A selected
// triangular patch gets de Casteljau's construction instead (triangle_casteljau.cpp).
#include <cstdio>
#include <imgui.h>
#include <string>

#include "core/geom/deboor.hpp"
#include "core/geom/status.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/stage_controls.hpp"
#include "ui/panels/triangle_panels.hpp"
#include "ui/surface_actions.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/deboor_overlay.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

namespace {

std::string point_text(const geom::HPoint& h, bool rational) {
    auto f = [](double x) { return geom::format_short(x); };
    if (const auto p = geom::DeBoorTriangle::cartesian(h)) {
        const std::string xyz = "(" + f(p->x) + ", " + f(p->y) + ", " + f(p->z) + ")";
        return rational ? xyz + " w " + f(h.w) : xyz;
    }
    return "at infinity: (" + f(h.x) + ", " + f(h.y) + ", " + f(h.z) + ") w 0";
}

ImVec4 level_color(bool u_stage, int level) {
    const glm::vec4 c = deboor_level_color(u_stage, level);
    return {c.r, c.g, c.b, 1};
}

// One triangle, a line per point: "P1,2" for the control points (level 0), then "d^k_i,j"
// level by level in the level's colour (the names the 3D view labels them with,
// deboor_point_name); levels after `upto` greyed out (not reached yet). While stepping
// (`stepping`), the lines of level `current` (the one the 3D view shows large and labelled;
// -1: none in this triangle) are marked with ">".
void triangle_lines(const geom::DeBoorTriangle& t, bool u_stage, int row, int upto, bool rational,
                    bool stepping, int current) {
    for (std::size_t k = 0; k < t.levels.size(); ++k) {
        const int level = static_cast<int>(k);
        const ImVec4 c = level > upto ? ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled)
                         : k == 0     ? ImGui::GetStyleColorVec4(ImGuiCol_Text)
                                      : level_color(u_stage, u_stage ? level : level + 1);
        const char* mark = !stepping ? "" : level == current ? "> " : "  ";
        for (std::size_t i = 0; i < t.levels[k].size(); ++i) {
            const int index = t.first_index + static_cast<int>(i) + level;
            const std::string name = deboor_point_name(u_stage, level, index, row);
            // Wrapped at spaces in a narrow column (never cut, a number never split).
            ImGui::PushStyleColor(ImGuiCol_Text, c);
            text_wrapped("%s%-9s %s", mark, name.c_str(),
                         point_text(t.levels[k][i], rational).c_str());
            ImGui::PopStyleColor();
        }
    }
}

} // namespace

void draw_deboor_panel(AppContext& ctx) {
    const doc::Object* obj = nullptr;
    const geom::Surface* s =
        teaching_panel_surface(ctx, StageView::deboor, draw_triangle_casteljau, &obj);
    if (!s) return;
    const glm::dvec2 uv = indicator_params(ctx.doc, *obj);
    const geom::DeBoorSurfaceTrace trace = geom::deboor_surface(*s, uv.x, uv.y);
    const int p_u = s->degree_u, p_v = s->degree_v;
    const int last = deboor_step_count(ctx);
    DeBoorPlayer& player = ctx.ui.deboor;
    const bool rational = geom::is_rational(s->type);

    // The surface may have changed under the counter (degree, net, another patch): never
    // "step 7 of 4".
    clamp_deboor_step(ctx);
    ImGui::Checkbox("Show in 3D (D)", &ctx.doc.view.display.deboor);
    // Beside the checkbox when it fits (presentation mode's narrow column: below it).
    const ImGuiStyle& style = ImGui::GetStyle();
    const float zoom_w = ImGui::CalcTextSize("Zoom to patch").x + style.FramePadding.x * 2;
    if (ImGui::GetItemRectMax().x + style.ItemSpacing.x + zoom_w <=
        ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x)
        ImGui::SameLine();
    if (ImGui::Button("Zoom to patch")) zoom_to_acting_patch(ctx);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Frame the %dx%d control points that act at (u, v); F fits everything",
                          p_u + 1, p_v + 1);
    // The step buttons on a row of their own: they must fit the narrow column in
    // presentation mode too.
    deboor_step_buttons(ctx, last);
    const DeBoorStepInfo info = deboor_step_info(player.step, p_u, p_v);
    if (player.step >= 0)
        text_wrapped("Step %d of %d: %s", player.step, last, info.text.c_str());
    else
        ImGui::Text("All %d steps shown", last);

    if (const auto p = trace.point()) {
        text_wrapped("S(%s, %s) = (%s, %s, %s)", geom::format_short(uv.x).c_str(),
                     geom::format_short(uv.y).c_str(), geom::format_short(p->x).c_str(),
                     geom::format_short(p->y).c_str(), geom::format_short(p->z).c_str());
    } else {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.6f, 0.2f, 1));
        text_wrapped("S(%s, %s) does not exist: the weights sum to zero here",
                     geom::format_short(uv.x).c_str(), geom::format_short(uv.y).c_str());
        ImGui::PopStyleColor();
    }
    if (rational) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        text_wrapped("Rational: computed on (wx, wy, wz, w), shown as points and weights");
        ImGui::PopStyleColor();
    }

    const int upto = player.step < 0 ? last : player.step;
    const bool stepping = player.step >= 0;
    ImGui::Separator();
    ImGui::BeginChild("##deboor_values");
    char title[128];
    std::snprintf(title, sizeof title, "u-stage: the rows at u = %s (span %d)",
                  geom::format_short(uv.x).c_str(),
                  trace.u_stage.empty() ? 0 : trace.u_stage.front().span);
    if (ImGui::CollapsingHeader(title, ImGuiTreeNodeFlags_DefaultOpen)) {
        for (std::size_t j = 0; j < trace.u_stage.size(); ++j) {
            const int row = static_cast<int>(j);
            const bool used =
                row >= trace.v_stage.first_index && row <= trace.v_stage.first_index + p_v;
            char label[64];
            std::snprintf(label, sizeof label, "row j = %d%s", row,
                          used ? "" : "  (not used at v)");
            if (ImGui::TreeNodeEx(label, used ? ImGuiTreeNodeFlags_DefaultOpen : 0)) {
                triangle_lines(trace.u_stage[j], true, row, std::min(upto, p_u), rational, stepping,
                               player.step <= p_u ? player.step : -1);
                ImGui::TreePop();
            }
        }
    }
    std::snprintf(title, sizeof title, "v-stage: the column at v = %s (span %d)",
                  geom::format_short(uv.y).c_str(), trace.v_stage.span);
    if (ImGui::CollapsingHeader(title, ImGuiTreeNodeFlags_DefaultOpen))
        triangle_lines(trace.v_stage, false, -1, upto - p_u - 1, rational, stepping,
                       player.step > p_u ? player.step - p_u - 1 : -1);
    ImGui::EndChild();
}

void deboor_step_buttons(AppContext& ctx, int last) {
    DeBoorPlayer& player = ctx.ui.deboor;
    if (ImGui::Button("|<")) deboor_step(ctx, -last - 1);
    ImGui::SameLine();
    if (ImGui::Button("<")) deboor_step(ctx, -1);
    report_item("deboor/back");
    ImGui::SameLine();
    if (ImGui::Button(player.playing ? "Pause" : "Play")) deboor_toggle_play(ctx, ImGui::GetTime());
    ImGui::SameLine();
    if (ImGui::Button(">")) deboor_step(ctx, +1);
    report_item("deboor/forward");
    ImGui::SameLine();
    if (ImGui::Button("All")) {
        player.step = -1;
        player.playing = false;
        ctx.doc.view.display.deboor = true;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Keys: [ and ] step, Space plays");
}

} // namespace isoparm::ui
