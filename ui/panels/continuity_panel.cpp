// The Continuity tab: every border of the current patch group with its continuity measured on
// the surfaces (core/doc/border_measure): the largest gap, angle between normals, first
// derivative mismatch across it and jump of mean curvature, each green when it holds.
#include <algorithm>
#include <cstdio>
#include <imgui.h>

#include "core/doc/border_measure.hpp"
#include "ui/panels/flow.hpp"
#include "ui/panels/panels.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

namespace {

// Relative to the group's size: a gap of 1e-12 on a unit patch is a join.
constexpr double holds = 1e-9;

void figure(const char* format, double value, double scale, bool light) {
    const bool ok = value <= holds * scale;
    const ImVec4 good = light ? ImVec4(0.0f, 0.45f, 0.1f, 1) : ImVec4(0.45f, 0.85f, 0.5f, 1);
    ImGui::TextColored(ok ? good : error_text_color(), format, value);
}

} // namespace

void draw_continuity_panel(AppContext& ctx) {
    const doc::Object* obj = nullptr;
    if (!current_surface(ctx.doc, &obj) || obj->patch_group == 0) {
        ImGui::TextWrapped("The current surface is not split into patches: Surface > Split at u or "
                           "v (S, Shift+S) makes a patch group, and this tab then measures every "
                           "border between its patches.");
        return;
    }
    const std::uint64_t group = obj->patch_group;
    const std::vector<doc::SharedBorder> borders = doc::shared_borders(ctx.doc, group);
    ImGui::TextWrapped("Kept across borders: %s. Measured on the surfaces at 33 points along "
                       "each border (green: holds).",
                       doc::continuity_name(ctx.doc.continuity));
    // The size the figures are relative to: the group's control points' extent.
    double size = 0;
    for (const doc::Object* p : doc::patch_members(ctx.doc, group))
        for (const glm::dvec3& q : p->surface()->points)
            size = std::max({size, std::abs(q.x), std::abs(q.y), std::abs(q.z)});
    size = std::max(size, 1e-300);
    const bool light = ctx.ui.presentation;
    // One block per border: its name, then the four figures, wrapping in a narrow panel.
    int kept = 0;
    for (const doc::SharedBorder& b : borders) {
        const doc::Object* lo = ctx.doc.find(b.low);
        const doc::Object* hi = ctx.doc.find(b.high);
        const doc::BorderMeasure m = doc::measure_border(ctx.doc, b);
        ImGui::Separator();
        ImGui::Text("%s | %s, across %s", lo ? lo->name.c_str() : "?", hi ? hi->name.c_str() : "?",
                    b.across == geom::Dir::u ? "u" : "v");
        if (ImGui::IsItemHovered())
            wrapped_tooltip(b.conforming ? "The border's control points pair up one to one: "
                                           "dragging a point keeps the continuity chosen."
                                         : "The borders do not pair up: " + b.why_not);
        figure("gap %.2g", m.gap, size, light);
        same_line_if_fits(ImGui::CalcTextSize("angle 0.00e-00 deg").x);
        figure("angle %.2g deg", m.angle_degrees, 1e3, light);
        same_line_if_fits(ImGui::CalcTextSize("dS 0.00e-00").x);
        figure("dS %.2g", m.derivative, size, light);
        same_line_if_fits(ImGui::CalcTextSize("dH 0.00e-00").x);
        figure("dH %.2g", m.curvature, 1e3, light);
        if (m.gap <= holds * size && m.derivative <= holds * size) ++kept;
    }
    ImGui::Separator();
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("gap: C0; angle between the normals: G1; dS, the first derivative across: "
                       "C1; dH, the jump of mean curvature: G2.");
    ImGui::PopStyleColor();
    report_fact("continuity/borders", static_cast<double>(borders.size()));
    report_fact("continuity/c1_measured", kept);
}

} // namespace isoparm::ui
