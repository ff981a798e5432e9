#include "ui/input_queue.hpp"

#include <bitset>

#include <imgui.h>

namespace isoparm::ui {

namespace {

// GLFW's codes (include/GLFW/glfw3.h): keys below 256 type a character, the rest (Enter,
// Backspace, arrows, function keys, the keypad, modifiers) do not.
constexpr int first_non_character_key = 256;
constexpr int left_shift = 340, left_control = 341, left_alt = 342, left_super = 343;
constexpr int right_shift = 344, right_control = 345, right_alt = 346, right_super = 347;
constexpr int mod_shift = 1, mod_control = 2, mod_alt = 4;

// What this frame has changed so far (the trickling rules of ImGui 1.87's UpdateInputEvents,
// with one more: a button's release waits for a frame that has not moved the pointer, so the
// widget being dragged sees the last position while the button is still down).
struct FrameChanges {
    bool moved = false, wheeled = false, typed = false, non_character_key = false;
    unsigned buttons = 0;
    std::bitset<InputQueue::key_count> keys;

    bool blocks(const InputEvent& e) const {
        using Kind = InputEvent::Kind;
        switch (e.kind) {
        case Kind::mouse_pos:
        case Kind::mouse_left:
            return buttons != 0 || wheeled || keys.any() || typed;
        case Kind::mouse_button:
            return (buttons & (1u << e.code)) != 0 || wheeled || (moved && !e.down);
        case Kind::scroll:
            return moved || buttons != 0;
        case Kind::key:
            return keys.test(e.code) || typed || buttons != 0;
        case Kind::character:
            return non_character_key || buttons != 0 || moved || wheeled;
        case Kind::focus:
            return false;
        }
        return false;
    }
};

bool valid_key(int code) {
    return code >= 0 && code < InputQueue::key_count;
}

} // namespace

void InputQueue::feed_frame(ImGuiIO& io, std::vector<KeyPress>& presses) {
    using Kind = InputEvent::Kind;
    FrameChanges changed;
    bool keys_touched = false;
    while (!events_.empty()) {
        const InputEvent& e = events_.front();
        if (changed.blocks(e)) break;
        switch (e.kind) {
        case Kind::mouse_pos:
            if (mouse_x_ != float(e.x) || mouse_y_ != float(e.y)) changed.moved = true;
            mouse_x_ = float(e.x);
            mouse_y_ = float(e.y);
            break;
        case Kind::mouse_left:
            if (mouse_x_ != -FLT_MAX) changed.moved = true;
            mouse_x_ = mouse_y_ = -FLT_MAX;
            break;
        case Kind::mouse_button:
            if (e.code >= 0 && e.code < 5 && mouse_down_[e.code] != e.down) {
                mouse_down_[e.code] = e.down;
                changed.buttons |= 1u << e.code;
            }
            break;
        case Kind::scroll:
            io.MouseWheelH += float(e.x);
            io.MouseWheel += float(e.y);
            changed.wheeled = true;
            break;
        case Kind::key:
            if (!valid_key(e.code)) break;
            if (io.KeysDown[e.code] != e.down) {
                io.KeysDown[e.code] = e.down;
                changed.keys.set(e.code);
                if (e.code >= first_non_character_key) changed.non_character_key = true;
                keys_touched = true;
            }
            if (e.down)
                presses.push_back({e.code, (e.mods & mod_control) != 0, (e.mods & mod_shift) != 0,
                                   (e.mods & mod_alt) != 0});
            break;
        case Kind::character:
            io.AddInputCharacter(e.ch);
            changed.typed = true;
            break;
        case Kind::focus:
            io.AddFocusEvent(e.focused);
            break;
        }
        events_.pop_front();
    }
    if (keys_touched) {
        // As the GLFW backend does: modifier events are not reliable across systems, the keys are.
        io.KeyCtrl = io.KeysDown[left_control] || io.KeysDown[right_control];
        io.KeyShift = io.KeysDown[left_shift] || io.KeysDown[right_shift];
        io.KeyAlt = io.KeysDown[left_alt] || io.KeysDown[right_alt];
        io.KeySuper = io.KeysDown[left_super] || io.KeysDown[right_super];
    }
    io.MousePos = ImVec2(mouse_x_, mouse_y_);
    for (int b = 0; b < 5; ++b) io.MouseDown[b] = mouse_down_[b];
}

} // namespace isoparm::ui
