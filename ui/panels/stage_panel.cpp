// The stage: one teaching view at full size in the main area (between the menu bar and the
// status bar), with a header that names it, says how to zoom and pan, and leads back; and the
// four-view layout (xy, 3D, xz, yz at equal size, as modelers have it).
#include <algorithm>
#include <imgui.h>
#include <string>

#include "ui/panels/panels.hpp"
#include "ui/panels/stage_controls.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"

namespace isoparm::ui {

namespace {

// No background, as the workstation's panels: the frame is cleared to the window colour first,
// and the 3D picture (de Boor's stage, the four views) is copied under ImGui's drawing.
constexpr ImGuiWindowFlags stage_flags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
    ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoBackground;

// The 3D view in a child region of `size` at the cursor, without its sliders.
void view3d_child(AppContext& ctx, const char* id, ImVec2 size) {
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    if (ImGui::BeginChild(id, size, false,
                          ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse |
                              ImGuiWindowFlags_NoBackground))
        draw_view3d_panel(ctx);
    ImGui::EndChild();
    ImGui::PopStyleVar();
}

// The header: the view's name, its neighbours (the three planes switch among themselves), how
// to zoom and pan, and the way back.
void stage_header(AppContext& ctx, StageView v) {
    const StageViewInfo* info = stage_info(v);
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(info->title);
    if (stage_plane(v) >= 0) {
        for (StageView p : {StageView::plane_xy, StageView::plane_xz, StageView::plane_yz}) {
            ImGui::SameLine();
            if (ImGui::RadioButton(stage_info(p)->name, v == p)) set_stage(ctx, p);
        }
    }
    const char* hint = "wheel: zoom   right-drag: pan   F: fit   Esc: back";
    const float room = ImGui::GetContentRegionAvail().x - ImGui::GetFrameHeight() * 2 -
                       ImGui::CalcTextSize(info->title).x;
    if (ImGui::CalcTextSize(hint).x < room) {
        ImGui::SameLine(0, 24 * ctx.ui.scale());
        ImGui::AlignTextToFramePadding();
        ImGui::TextDisabled("%s", hint);
    }
    stage_button(ctx, v);
    ImGui::Separator();
}

} // namespace

void draw_stage(AppContext& ctx, const Rect& area) {
    const StageView v = ctx.ui.stage.view;
    const StageViewInfo* info = stage_info(v);
    if (!info) return;
    ImGui::SetNextWindowPos(ImVec2(area.x, area.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(std::max(area.w, 1.f), std::max(area.h, 1.f)),
                             ImGuiCond_Always);
    report_rect("panel/Stage", area.x, area.y, area.w, area.h);
    if (ImGui::Begin("Stage", nullptr, stage_flags)) {
        stage_header(ctx, v);
        const ImVec2 at = ImGui::GetCursorScreenPos();
        const ImVec2 avail = ImGui::GetContentRegionAvail();
        report_rect(std::string("stage/") + info->name, at.x, at.y, avail.x, avail.y);
        const float gap = ImGui::GetStyle().ItemSpacing.x;
        switch (v) {
        case StageView::tracing:
            draw_tracing_panel(ctx);
            break;
        case StageView::basis:
            draw_basis_plot_panel(ctx);
            break;
        case StageView::deboor: {
            // The construction where it happens, large, beside its step list.
            const float side = std::clamp(avail.x * 0.4f, 220 * ctx.ui.scale(), avail.x * 0.5f);
            view3d_child(ctx, "##stage_3d", ImVec2(avail.x - side - gap, avail.y));
            ImGui::SameLine();
            if (ImGui::BeginChild("##stage_deboor", ImVec2(side, avail.y))) draw_deboor_panel(ctx);
            ImGui::EndChild();
            break;
        }
        case StageView::plane_xy:
        case StageView::plane_xz:
        case StageView::plane_yz:
            draw_plane_view(ctx, stage_plane(v), {at.x, at.y, avail.x, avail.y});
            break;
        case StageView::curve:
            draw_curve_designer_panel(ctx);
            break;
        case StageView::homogeneous:
            draw_homogeneous_panel(ctx);
            break;
        case StageView::blossom:
            draw_blossom_panel(ctx);
            break;
        case StageView::multires:
            draw_multires_panel(ctx);
            break;
        case StageView::continuity:
            draw_continuity_panel(ctx);
            break;
        case StageView::none:
            break;
        }
    }
    ImGui::End();
}

void draw_four_views(AppContext& ctx, const Rect& area) {
    ImGui::SetNextWindowPos(ImVec2(area.x, area.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(std::max(area.w, 1.f), std::max(area.h, 1.f)),
                             ImGuiCond_Always);
    report_rect("panel/Four views", area.x, area.y, area.w, area.h);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0);
    if (ImGui::Begin("Four views", nullptr,
                     stage_flags | ImGuiWindowFlags_NoScrollbar |
                         ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoBackground)) {
        const FourViews f = four_view_cells(area, 4 * ctx.ui.scale());
        for (int p = 0; p < 3; ++p) draw_plane_view(ctx, p, f.plane(p));
        ImGui::SetCursorScreenPos(ImVec2(f.view3d.x, f.view3d.y));
        view3d_child(ctx, "##four_3d", ImVec2(f.view3d.w, f.view3d.h));
        report_rect("four/3d", f.view3d.x, f.view3d.y, f.view3d.w, f.view3d.h);
    }
    ImGui::End();
    ImGui::PopStyleVar(2);
}

} // namespace isoparm::ui
