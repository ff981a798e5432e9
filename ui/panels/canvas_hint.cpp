#include "ui/panels/canvas_hint.hpp"

#include <imgui.h>

namespace isoparm::ui {

bool canvas_hint_due(UiState& ui) {
    // One pointer, one hovered canvas at a time: where it rests, since when, and the frames its
    // hint has been due (a tooltip's window is laid out in its first frame and shown in the
    // next: frames are asked for until then).
    static ImVec2 item_min{0, 0};
    static double resting_since = 0;
    static int last_frame = -2, due_frames = 0;
    if (!ImGui::IsItemHovered()) return false;
    const ImGuiIO& io = ImGui::GetIO();
    const ImVec2 min = ImGui::GetItemRectMin();
    const int frame = ImGui::GetFrameCount();
    const bool moved = io.MouseDelta.x != 0 || io.MouseDelta.y != 0;
    if (frame > last_frame + 1 || min.x != item_min.x || min.y != item_min.y || moved ||
        ImGui::IsAnyMouseDown()) {
        resting_since = ImGui::GetTime();
        due_frames = 0;
    }
    item_min = min;
    last_frame = frame;
    const bool due = ImGui::GetTime() - resting_since >= canvas_hint_delay;
    if (!due || ++due_frames <= 2) ui.hint_waiting = true;
    return due;
}

} // namespace isoparm::ui
