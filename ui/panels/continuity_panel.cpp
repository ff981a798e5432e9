// The Continuity tab: every border of the current patch group with its continuity measured on
// the surfaces (core/doc/border_measure): the largest gap, angle between normals, first
// derivative mismatch across it and jump of mean curvature, each green when it holds.
#include <algorithm>
#include <cstdio>
#include <imgui.h>

#include "core/doc/border_measure.hpp"
#include "ui/panels/flow.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/stage_controls.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/scene_builder.hpp"

namespace isoparm::ui {

namespace {

void figure(const char* format, double value, bool ok, bool light) {
    const ImVec4 good = light ? ImVec4(0.0f, 0.45f, 0.1f, 1) : ImVec4(0.45f, 0.85f, 0.5f, 1);
    ImGui::TextColored(ok ? good : error_text_color(), format, value);
}

} // namespace

void draw_continuity_panel(AppContext& ctx) {
    note_hovered_view(ctx, StageView::continuity);
    const doc::Object* obj = nullptr;
    if (!current_surface(ctx.doc, &obj) || obj->patch_group == 0) {
        text_wrapped("The current surface is not split into patches: Surface > Split at u or "
                     "v (S, Shift+S) makes a patch group, and this tab then measures every "
                     "border between its patches.");
        return;
    }
    const std::uint64_t group = obj->patch_group;
    const std::vector<doc::SharedBorder> borders = doc::shared_borders(ctx.doc, group);
    text_wrapped("Kept across borders: %s. Measured on the surfaces at 33 points along "
                 "each border (green: holds).",
                 doc::continuity_name(ctx.doc.continuity));
    const double size = doc::group_size(ctx.doc, group);
    ImGui::Checkbox("Draw the borders in 3D in their colour", &ctx.ui.border_continuity);
    report_item("continuity/draw_borders");
    const bool light = ctx.ui.presentation;
    // One block per border: its name, then the four figures, wrapping in a narrow panel.
    int kept = 0;
    for (const doc::SharedBorder& b : borders) {
        const doc::Object* lo = ctx.doc.find(b.low);
        const doc::Object* hi = ctx.doc.find(b.high);
        const doc::BorderMeasure m = doc::measure_border(ctx.doc, b);
        ImGui::Separator();
        const doc::BorderLevel level = doc::border_level(m, size);
        // The swatch is the colour the 3D view draws this border in.
        const glm::vec4 c = border_level_color(level);
        ImGui::ColorButton("##level", ImVec4(c.r, c.g, c.b, 1), ImGuiColorEditFlags_NoTooltip,
                           ImVec2(ImGui::GetTextLineHeight(), ImGui::GetTextLineHeight()));
        ImGui::SameLine();
        ImGui::Text("%s | %s, across %s: %s", lo ? lo->name.c_str() : "?",
                    hi ? hi->name.c_str() : "?", b.across == geom::Dir::u ? "u" : "v",
                    doc::border_level_name(level));
        if (ImGui::IsItemHovered())
            wrapped_tooltip(b.conforming ? "The border's control points pair up one to one: "
                                           "dragging a point keeps the continuity chosen."
                                         : "The borders do not pair up: " + b.why_not);
        const doc::BorderHolds h = doc::border_holds(m, size);
        figure("gap %.2g", m.gap, h.c0, light);
        same_line_if_fits(ImGui::CalcTextSize("angle 0.00e-00 deg").x);
        figure("angle %.2g deg", m.angle_degrees, h.g1, light);
        same_line_if_fits(ImGui::CalcTextSize("dS 0.00e-00").x);
        figure("dS %.2g", m.derivative, h.c1, light);
        same_line_if_fits(ImGui::CalcTextSize("dH 0.00e-00").x);
        figure("dH %.2g", m.curvature, h.g2, light);
        if (h.c0 && h.c1) ++kept;
    }
    ImGui::Separator();
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    text_wrapped("gap: C0; angle between the normals: G1; dS, the first derivative across: "
                 "C1; dH, the jump of mean curvature: G2.");
    ImGui::PopStyleColor();
    report_fact("continuity/borders", static_cast<double>(borders.size()));
    report_fact("continuity/c1_measured", kept);
}

} // namespace isoparm::ui
