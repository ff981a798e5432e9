// Word-by-word layout of a caption's runs: ImGui 1.86 wraps one font per item, so each word
// is its own item, placed after the last on the line while it fits.
#include "ui/panels/rich_text.hpp"

#include <imgui.h>

#include "ui/theme.hpp"
#include "ui/view/rich_text.hpp"

namespace isoparm::ui {

namespace {

// The words of a run with the spaces after them, so a line break falls between words.
std::vector<std::string> words_of(const std::string& text) {
    std::vector<std::string> out;
    std::string w;
    for (char ch : text) {
        w += ch;
        if (ch == ' ') {
            out.push_back(std::move(w));
            w.clear();
        }
    }
    if (!w.empty()) out.push_back(std::move(w));
    return out;
}

} // namespace

void draw_rich_text(const std::string& text) {
    ImFont* bold = bold_font();
    const float left = ImGui::GetCursorPosX();
    const float right = left + ImGui::GetContentRegionAvail().x;
    for (const CaptionLine& line : parse_caption(text)) {
        float x = left;
        bool first = true;
        if (line.bullet) {
            ImGui::Bullet();
            ImGui::SameLine(0, 0);
            x = ImGui::GetCursorPosX();
            first = false;
        }
        const float indent = x;
        if (line.runs.empty() && !line.bullet) ImGui::NewLine();
        for (const CaptionRun& run : line.runs) {
            if (run.bold && bold) ImGui::PushFont(bold);
            if (run.bold && !bold)
                ImGui::PushStyleColor(ImGuiCol_Text,
                                      ImGui::GetStyleColorVec4(ImGuiCol_PlotHistogram));
            for (const std::string& word : words_of(run.text)) {
                const float w = ImGui::CalcTextSize(word.c_str()).x;
                if (!first && x + w > right && x > indent) {
                    x = indent; // wrap: the next line starts under the bullet's text
                    ImGui::SetCursorPosX(indent);
                } else if (!first) {
                    ImGui::SameLine(0, 0);
                }
                if (x == indent) ImGui::SetCursorPosX(indent);
                ImGui::TextUnformatted(word.c_str());
                x += w;
                first = false;
            }
            if (run.bold && !bold) ImGui::PopStyleColor();
            if (run.bold && bold) ImGui::PopFont();
        }
    }
}

} // namespace isoparm::ui
