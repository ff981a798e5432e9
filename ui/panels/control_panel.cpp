// The control panel: colours of the scene (saved with it, undoable) and display settings.
#include <imgui.h>

#include "core/doc/commands.hpp"
#include "ui/panels/enum_combo.hpp"
#include "ui/panels/panels.hpp"
#include "ui/ui_report.hpp"

namespace isoparm::ui {

namespace {

bool color_row(const char* label, doc::Rgba& c) {
    float rgb[3] = {c.r, c.g, c.b};
    const bool changed = ImGui::ColorEdit3(label, rgb, ImGuiColorEditFlags_NoInputs);
    if (changed) {
        c.r = rgb[0];
        c.g = rgb[1];
        c.b = rgb[2];
    }
    return changed;
}

} // namespace

void draw_control_panel(AppContext& ctx) {
    doc::Colors colors = ctx.doc.colors;
    bool changed = false;
    ImGui::TextDisabled("Colours (saved with the scene)");
    if (ImGui::BeginTable("colors", 2)) {
        struct Row {
            const char* label;
            doc::Rgba* color;
        };
        const Row rows[] = {{"Background", &colors.background},
                            {"Surface", &colors.surface},
                            {"Selected surface", &colors.selected_surface},
                            {"Control net", &colors.control_net},
                            {"Control points", &colors.control_points},
                            {"Selected point", &colors.selected_point},
                            {"Knot curves", &colors.knot_curves},
                            {"Indicator", &colors.indicator}};
        int n = 0;
        for (const Row& r : rows) {
            if (n % 2 == 0) ImGui::TableNextRow();
            ImGui::TableNextColumn();
            changed |= color_row(r.label, *r.color);
            ++n;
        }
        ImGui::EndTable();
    }
    // One command per change; a drag in the colour picker merges into one undo step.
    if (changed) ctx.execute(doc::set_colors(colors));
    if (ImGui::Button("Default colours") && !(ctx.doc.colors == doc::Colors{})) {
        ctx.seal();
        ctx.execute(doc::set_colors(doc::Colors{}));
        ctx.seal();
    }

    ImGui::Separator();
    ImGui::TextDisabled("Display");
    doc::DisplaySettings& d = ctx.doc.view.display; // view state: not undoable
    int style = static_cast<int>(d.style);
    ImGui::RadioButton("Shaded", &style, static_cast<int>(doc::DisplayStyle::shaded));
    ImGui::SameLine();
    ImGui::RadioButton("Wireframe", &style, static_cast<int>(doc::DisplayStyle::wireframe));
    ImGui::SameLine();
    ImGui::RadioButton("Both", &style, static_cast<int>(doc::DisplayStyle::both));
    d.style = static_cast<doc::DisplayStyle>(style);
    if (ImGui::BeginTable("toggles", 2)) {
        ImGui::TableNextColumn();
        ImGui::Checkbox("Control points", &d.control_points);
        ImGui::TableNextColumn();
        ImGui::Checkbox("Control net", &d.control_net);
        ImGui::TableNextColumn();
        ImGui::Checkbox("Point IDs", &d.point_ids);
        ImGui::TableNextColumn();
        ImGui::Checkbox("S(u,v)", &d.indicator_point);
        ImGui::TableNextColumn();
        ImGui::Checkbox("Knot curves", &d.knot_curves);
        ImGui::EndTable();
    }
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    ImGui::SliderInt("Density", &d.density, 4, 64, "%d per span");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Tessellation samples per knot span in each direction");

    // Shape quality at a glance (also Display > Analysis, with the range and zebra settings).
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    enum_combo("Analysis", d.analysis, ItemCase::capitalized);
    report_item("display/analysis");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("False colour of curvature from exact derivatives, or reflection lines");
    if (d.analysis == doc::AnalysisMode::zebra || d.analysis == doc::AnalysisMode::isophote) {
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
        ImGui::SliderInt("Stripes", &d.stripes, 2, 64);
    }
    ImGui::Checkbox("Knot curves by continuity", &ctx.ui.knot_continuity);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Each interior knot curve in the colour of the continuity C(p - m) "
                          "it carries:\nC1 yellow, C0 orange, C-1 red");
    if (ctx.ui.knot_continuity) d.knot_curves = true;
    ImGui::Checkbox("Borders by continuity", &ctx.ui.border_continuity);
    report_item("display/border_continuity");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The current patch group's borders in the colour of the continuity "
                          "measured on them:\nbroken red, C0 orange, G1 yellow, C1 green, "
                          "C1 + G2 cyan");
}

} // namespace isoparm::ui
