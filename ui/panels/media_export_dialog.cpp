// The Export picture / figure / animation dialog: what to export, its size and file; the
// export itself runs before the next frame (ui/media_export.cpp), an animation with a
// progress bar and Cancel.
#include <imgui.h>
#include <imgui_stdlib.h>
#include <string>

#include "ui/app_context.hpp"
#include "ui/headless/animation_job.hpp"
#include "ui/media_export.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"

namespace isoparm::ui {

namespace {

constexpr const char* dialog_title = "Export##media";

void picture_fields(MediaExportState& m) {
    static const char* targets[] = {"3D view",
                                    "Whole window",
                                    "Domain and knots (tracing square)",
                                    "Basis / de Boor tabs",
                                    "Control point / curve designer panel",
                                    "Objects and display panel"};
    for (int k = 0; k < IM_ARRAYSIZE(targets); ++k) {
        ImGui::RadioButton(targets[k], &m.target, k);
        report_item("export/target/" + std::to_string(k));
    }
    const bool sized = m.target <= 1;
    ImGui::BeginDisabled(!sized);
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    ImGui::InputInt("width", &m.width, 0);
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    ImGui::InputInt("height", &m.height, 0);
    ImGui::EndDisabled();
    ImGui::TextDisabled(sized ? "0: the size it has on screen" : "a panel keeps its size");
    // Up to four times the screen's pixels, for print.
    ImGui::TextUnformatted("Scale");
    for (int k = 1; k <= 4; ++k) {
        ImGui::SameLine();
        const std::string label = std::to_string(k) + "x";
        if (ImGui::RadioButton(label.c_str(), m.scale == static_cast<float>(k)))
            m.scale = static_cast<float>(k);
        report_item("export/scale/" + std::to_string(k));
    }
    ImGui::Checkbox("Transparent background", &m.transparent);
}

void figure_fields(MediaExportState& m) {
    static const char* views[] = {"Tracing square",
                                  "Basis functions",
                                  "Curve designer",
                                  "de Boor's construction",
                                  "Homogeneous picture",
                                  "Blossom",
                                  "3D view (lines over the shaded surface)"};
    for (int k = 0; k < IM_ARRAYSIZE(views); ++k) {
        ImGui::RadioButton(views[k], &m.figure_view, k);
        report_item("export/view/" + std::to_string(k));
    }
    ImGui::TextDisabled("By extension: .svg, .pdf, .tex (TikZ) or .png");
    ImGui::Checkbox("Transparent background", &m.transparent);
}

void animation_fields(MediaExportState& m) {
    static const char* sources[] = {"de Boor's steps at the indicator", "Orbit of the camera",
                                    "Weight sweep of the selected point",
                                    "The lesson being played"};
    for (int k = 0; k < IM_ARRAYSIZE(sources); ++k) {
        ImGui::RadioButton(sources[k], &m.animation_source, k);
        report_item("export/source/" + std::to_string(k));
    }
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    ImGui::SliderInt("frames per second", &m.fps, 1, 50);
    ImGui::BeginDisabled(m.animation_source == 0 || m.animation_source == 3);
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    ImGui::SliderInt("pictures", &m.frames, 2, 400);
    ImGui::EndDisabled();
    ImGui::TextDisabled("By extension: .gif or .mp4 (H.264); the 3D view's size");
}

} // namespace

void draw_media_export_dialog(AppContext& ctx) {
    MediaExportState& m = ctx.ui.media_export;
    if (!begin_centered_modal(dialog_title, m.just_opened, 460 * ctx.ui.scale(),
                              ImGuiWindowFlags_NoSavedSettings))
        return;
    if (!m.open) {
        ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
        return;
    }
    const char* heading = m.kind == MediaExportState::Kind::picture  ? "Picture (PNG)"
                          : m.kind == MediaExportState::Kind::figure ? "Figure (vector)"
                                                                     : "Animation";
    ImGui::TextUnformatted(heading);
    ImGui::Separator();
    if (m.job) {
        // Rendering: progress and Cancel only.
        const float done = m.job->total_frames() > 0 ? static_cast<float>(m.job->frames_done()) /
                                                           static_cast<float>(m.job->total_frames())
                                                     : 0.f;
        const std::string text = std::to_string(m.job->frames_done()) + " / " +
                                 std::to_string(m.job->total_frames()) + " frames";
        ImGui::ProgressBar(done, ImVec2(-1, 0), text.c_str());
        report_fact("export/progress", done);
        if (ImGui::Button("Cancel")) {
            m.job.reset(); // nothing was written: the file is written when complete
            m.open = false;
            ctx.ui.status = "Animation cancelled; nothing was written";
        }
        ImGui::EndPopup();
        return;
    }
    switch (m.kind) {
    case MediaExportState::Kind::picture:
        picture_fields(m);
        break;
    case MediaExportState::Kind::figure:
        figure_fields(m);
        break;
    case MediaExportState::Kind::animation:
        animation_fields(m);
        break;
    }
    ImGui::Separator();
    ImGui::SetNextItemWidth(-1);
    ImGui::InputText("##dir", &m.directory);
    report_item("export/directory");
    ImGui::SetNextItemWidth(-1);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    // Clicking the name selects it all: typing replaces the suggested name.
    const bool enter =
        ImGui::InputText("##name", &m.name,
                         ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
    report_item("file/name");
    if (!m.error.empty()) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(error_text_color(), "%s", m.error.c_str());
        ImGui::PopTextWrapPos();
    }
    if (ImGui::Button("Export") || enter) m.pending = true;
    report_item("export/export");
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false))
        m.open = false;
    if (!m.open) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

} // namespace isoparm::ui
