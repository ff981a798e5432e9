// Themes and font sizes.
#include "ui/theme.hpp"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

namespace isoparm::ui {

void apply_theme(bool presentation, float scale) {
    ImGuiStyle style;
    if (presentation) {
        // High contrast for projectors: black on white, strong borders, saturated accents.
        ImGui::StyleColorsLight(&style);
        ImVec4* c = style.Colors;
        c[ImGuiCol_Text] = ImVec4(0, 0, 0, 1);
        c[ImGuiCol_WindowBg] = ImVec4(1, 1, 1, 1);
        c[ImGuiCol_ChildBg] = ImVec4(1, 1, 1, 1);
        c[ImGuiCol_PopupBg] = ImVec4(1, 1, 1, 1);
        c[ImGuiCol_Border] = ImVec4(0, 0, 0, 1);
        c[ImGuiCol_FrameBg] = ImVec4(0.9f, 0.9f, 0.9f, 1);
        c[ImGuiCol_TitleBg] =
            ImVec4(0.82f, 0.82f, 0.82f, 1); // title text is Text: keep it dark on light
        c[ImGuiCol_TitleBgActive] = ImVec4(0.70f, 0.80f, 1.0f, 1);
        c[ImGuiCol_MenuBarBg] = ImVec4(0.92f, 0.92f, 0.92f, 1);
        c[ImGuiCol_SliderGrab] = ImVec4(0, 0.3f, 0.8f, 1);
        c[ImGuiCol_CheckMark] = ImVec4(0, 0.3f, 0.8f, 1);
        style.WindowBorderSize = 2;
        style.FrameBorderSize = 1.5f;
        style.PopupBorderSize = 2;
    } else {
        ImGui::StyleColorsDark(&style);
        ImVec4* c = style.Colors;
        c[ImGuiCol_WindowBg] = ImVec4(0.10f, 0.105f, 0.12f, 1);
        c[ImGuiCol_TitleBg] = ImVec4(0.14f, 0.16f, 0.21f, 1);
        c[ImGuiCol_TitleBgActive] = ImVec4(0.18f, 0.24f, 0.36f, 1);
        style.FrameRounding = 3;
        style.GrabRounding = 3;
        style.WindowBorderSize = 1;
    }
    style.WindowRounding = 0;
    style.WindowPadding = ImVec2(8, 6);
    style.ItemSpacing = ImVec2(8, 5);
    style.ScaleAllSizes(scale);
    ImGui::GetStyle() = style;
}

void rebuild_fonts(float scale) {
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    ImFontConfig cfg;
    cfg.SizePixels = 13.0f * scale;
    // The built-in ProggyClean font: always present and identical everywhere, which keeps
    // headless renders deterministic.
    io.Fonts->AddFontDefault(&cfg);
    io.Fonts->Build();
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
}

} // namespace isoparm::ui
