// The window's input events, queued as they come and given to ImGui frame by frame.
//
// ImGui 1.86 samples input once a frame (io.KeysDown, io.MouseDown, io.MousePos), so a key
// pressed and released inside one slow frame, or a drag whose press, moves and release all
// arrive while a CPU rasteriser draws one frame, would never be seen. Later ImGui versions
// queue events and "trickle" them (io.AddKeyEvent, ImGui 1.87+): each frame takes events in
// order until one would change something this frame already changed. This is that queue for
// 1.86: the window's callbacks push, the loop calls feed_frame() after the platform backend's
// NewFrame and before ImGui::NewFrame, and asks for another frame while events are left.
//
// No GLFW here: key codes and actions are GLFW's numbers (which ImGui 1.86 indexes
// io.KeysDown by), passed as ints by app/window_input.cpp.
#pragma once

#include <cfloat>
#include <cstddef>
#include <deque>
#include <vector>

#include "ui/ui_state.hpp"

struct ImGuiIO;

namespace isoparm::ui {

struct InputEvent {
    enum class Kind { mouse_pos, mouse_left, mouse_button, scroll, key, character, focus };
    Kind kind = Kind::mouse_pos;
    double x = 0, y = 0;  // mouse_pos: window coordinates; scroll: wheel offsets
    int code = 0;         // mouse_button: 0 left, 1 right, 2 middle; key: GLFW key code
    bool down = false;    // mouse_button, key: pressed (a key's repeat counts as pressed)
    int mods = 0;         // key: GLFW modifier bits (1 shift, 2 control, 4 alt)
    unsigned int ch = 0;  // character: a Unicode code point
    bool focused = false; // focus
};

class InputQueue {
public:
    static constexpr int key_count = 512; // io.KeysDown's size in ImGui 1.86

    void push(const InputEvent& e) { events_.push_back(e); }
    bool empty() const { return events_.empty(); }
    std::size_t size() const { return events_.size(); }

    // Gives io the events one frame can show without hiding one another, in order: the mouse
    // position and buttons (written every frame, the backend polls its own), keys, characters,
    // wheel and focus. Stops before an event that would undo or blur a change this frame made
    // (a second change of one key or button, a release after the pointer moved, a key after
    // typed text, text after a non-character key); those wait for the next frame. Key presses
    // (and repeats) go to `presses` for the shortcuts in the frame ImGui sees them.
    void feed_frame(ImGuiIO& io, std::vector<KeyPress>& presses);

private:
    std::deque<InputEvent> events_;
    float mouse_x_ = -FLT_MAX, mouse_y_ = -FLT_MAX; // ImGui's "no mouse here"
    bool mouse_down_[5] = {};
};

} // namespace isoparm::ui
