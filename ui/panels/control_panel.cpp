// The control panel: colours of the scene (saved with it, undoable) and display settings.
#include <algorithm>
#include <imgui.h>

#include "core/doc/commands.hpp"
#include "ui/panels/enum_combo.hpp"
#include "ui/panels/flow.hpp"
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
    // Two columns while every whole label fits beside its swatch ("Backgrou" was cut on a
    // projector), else one.
    float widest = 0;
    for (const Row& r : rows) widest = std::max(widest, toggle_width(r.label));
    const int cols = columns_that_fit(widest + ImGui::GetStyle().CellPadding.x * 2, 2);
    if (ImGui::BeginTable("colors", cols)) {
        int n = 0;
        for (const Row& r : rows) {
            if (n % cols == 0) ImGui::TableNextRow();
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
    // The selected object's own toggles (C, N, I, K); with none selected, the defaults every
    // object without its own shows (and new objects start with).
    const doc::Object* sel = ctx.doc.selected();
    doc::ObjectDisplay od = doc::display_of(ctx.doc.view, ctx.doc.view.selection.object);
    const doc::ObjectDisplay was = od;
    ImGui::TextDisabled("%s", sel ? ("Of " + sel->name + ":").c_str() : "Of every object:");
    const float toggle = std::max(toggle_width("Control points"), toggle_width("Knot curves")) +
                         ImGui::GetStyle().CellPadding.x * 2;
    if (ImGui::BeginTable("toggles", columns_that_fit(toggle, 2))) {
        ImGui::TableNextColumn();
        ImGui::Checkbox("Control points", &od.control_points);
        ImGui::TableNextColumn();
        ImGui::Checkbox("Control net", &od.control_net);
        ImGui::TableNextColumn();
        ImGui::Checkbox("Point IDs", &od.point_ids);
        ImGui::TableNextColumn();
        ImGui::Checkbox("Knot curves", &od.knot_curves);
        ImGui::TableNextColumn();
        ImGui::Checkbox("S(u,v)", &d.indicator_point);
        ImGui::EndTable();
    }
    if (od != was) {
        if (sel) {
            ctx.doc.view.object_display[sel->id] = od;
        } else {
            d.control_points = od.control_points;
            d.control_net = od.control_net;
            d.point_ids = od.point_ids;
            d.knot_curves = od.knot_curves;
        }
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
    if (ctx.ui.knot_continuity &&
        !doc::display_of(ctx.doc.view, ctx.doc.view.selection.object).knot_curves) {
        if (sel)
            ctx.doc.view.object_display.try_emplace(sel->id, doc::defaults_of(d))
                .first->second.knot_curves = true;
        else
            d.knot_curves = true;
    }
    ImGui::Checkbox("Borders by continuity", &ctx.ui.border_continuity);
    report_item("display/border_continuity");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The current patch group's borders in the colour of the continuity "
                          "measured on them:\nbroken red, C0 orange, G1 yellow, C1 green, "
                          "C1 + G2 cyan");
}

} // namespace isoparm::ui
