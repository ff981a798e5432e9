// Themes and font sizes.
#include "ui/theme.hpp"

#include <algorithm>
#include <backends/imgui_impl_opengl3.h>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <imgui.h>

#include "ui/view/text_wrap.hpp"

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

namespace {

ImFont* g_number_font = nullptr;
ImFont* g_bold_font = nullptr;

// Debian's fonts-dejavu-core; ISOPARM_FONT_DIR overrides the folder (tests, other systems).
std::string font_dir() {
    if (const char* d = std::getenv("ISOPARM_FONT_DIR"); d && *d) return d;
    return "/usr/share/fonts/truetype/dejavu";
}

bool readable(const std::string& path) {
    return std::ifstream(path, std::ios::binary).good();
}

} // namespace

std::string rebuild_fonts(float scale) {
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    g_number_font = nullptr;
    g_bold_font = nullptr;
    const float pixels = std::round(base_font_pixels * scale);
    const std::string sans = font_dir() + "/DejaVuSans.ttf";
    const std::string mono = font_dir() + "/DejaVuSansMono.ttf";
    std::string note;
    ImFontConfig cfg;
    cfg.OversampleH = 2; // crisper small text on a CPU rasteriser's 1:1 pixels
    cfg.OversampleV = 1;
    // Latin-1 and the Greek and maths glyphs the panels print (sums, arrows, mu, omega).
    static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x22FF, 0};
    ImFont* main = nullptr;
    if (readable(sans)) main = io.Fonts->AddFontFromFileTTF(sans.c_str(), pixels, &cfg, ranges);
    if (!main) {
        ImFontConfig fallback;
        fallback.SizePixels = std::round(13.0f * scale);
        io.Fonts->AddFontDefault(&fallback);
        note = "DejaVu Sans not found in " + font_dir() +
               " (install fonts-dejavu-core): using the built-in bitmap font";
    } else {
        if (readable(mono))
            g_number_font = io.Fonts->AddFontFromFileTTF(mono.c_str(), pixels, &cfg, ranges);
        // Lesson captions' **bold** (ui/panels/rich_text.cpp).
        if (const std::string bold = font_dir() + "/DejaVuSans-Bold.ttf"; readable(bold))
            g_bold_font = io.Fonts->AddFontFromFileTTF(bold.c_str(), pixels, &cfg, ranges);
    }
    io.Fonts->Build();
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
    return note;
}

namespace {

void wrapped_lines(const char* text, float width) {
    const MeasureText measure = [](std::string_view s) {
        const ImVec2 v = ImGui::CalcTextSize(s.data(), s.data() + s.size());
        return glm::vec2(v.x, v.y);
    };
    // One text item of several lines, as ImGui::TextWrapped lays it out (no item spacing
    // between the lines).
    std::string joined;
    for (const std::string& line : wrap_at_spaces(text, std::max(width, 1.f), measure)) {
        if (!joined.empty()) joined += '\n';
        joined += line;
    }
    ImGui::TextUnformatted(joined.c_str());
}

} // namespace

void center_next_window(float width) {
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + vp->Size.x * 0.5f, vp->Pos.y + vp->Size.y * 0.5f),
                            ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    if (width > 0) ImGui::SetNextWindowSize(ImVec2(width, 0));
}

bool begin_centered_modal(const char* id, bool& requested, float width, ImGuiWindowFlags flags) {
    if (requested) {
        ImGui::OpenPopup(id);
        requested = false;
    }
    center_next_window(width);
    return ImGui::BeginPopupModal(id, nullptr, flags);
}

void wrapped_tooltip(const std::string& text) {
    ImGui::BeginTooltip();
    wrapped_lines(text.c_str(), ImGui::GetFontSize() * 28.0f);
    ImGui::EndTooltip();
}

void text_wrapped(const char* fmt, ...) {
    va_list args, again;
    va_start(args, fmt);
    va_copy(again, args);
    const int n = std::vsnprintf(nullptr, 0, fmt, args);
    va_end(args);
    std::string text(static_cast<std::size_t>(std::max(n, 0)) + 1, '\0');
    std::vsnprintf(text.data(), text.size(), fmt, again);
    va_end(again);
    text.pop_back();
    wrapped_lines(text.c_str(), ImGui::GetContentRegionAvail().x);
}

ImVec4 error_text_color() {
    const ImVec4 bg = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
    const bool light = 0.2126f * bg.x + 0.7152f * bg.y + 0.0722f * bg.z > 0.5f;
    return light ? ImVec4(0.70f, 0.05f, 0.0f, 1) : ImVec4(1.0f, 0.62f, 0.35f, 1);
}

ImFont* bold_font() {
    return g_bold_font;
}

ImFont* number_font() {
    return g_number_font ? g_number_font : ImGui::GetIO().Fonts->Fonts[0];
}

} // namespace isoparm::ui
