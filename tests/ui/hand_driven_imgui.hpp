// A real ImGui context without a window or a renderer, for tests that drive frames by hand:
// an 800 x 600 display, no .ini file, the font atlas built (NewFrame needs it).
#pragma once

#include <imgui.h>

namespace isoparm::test {

inline void create_hand_driven_imgui() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(800, 600);
    io.DeltaTime = 1.0f / 60;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
}

} // namespace isoparm::test
