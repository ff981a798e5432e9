// The input queue (ui/input_queue): a burst of events that arrives during one slow frame (a
// typed number and Enter, a whole drag) reaches ImGui 1.86 widgets frame by frame and nothing
// is lost. Each burst is also given to ImGui the way the window did before the queue (every
// event applied at once, as the callbacks did), to show the loss the queue prevents.
#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <string>

#include <imgui.h>

#include "tests/ui/hand_driven_imgui.hpp"
#include "ui/input_queue.hpp"

using namespace isoparm::ui;
using Kind = InputEvent::Kind;

namespace {

// GLFW's key codes (ImGui 1.86 indexes io.KeysDown by them in this program).
constexpr int key_a = 65, key_period = 46, key_0 = 48, key_5 = 53, key_7 = 55;
constexpr int key_enter = 257, key_backspace = 259, key_left_control = 341;
constexpr int mod_control = 2;

InputEvent key(int code, bool down, int mods = 0) {
    InputEvent e{Kind::key};
    e.code = code;
    e.down = down;
    e.mods = mods;
    return e;
}
InputEvent character(unsigned c) {
    InputEvent e{Kind::character};
    e.ch = c;
    return e;
}
InputEvent mouse_at(double x, double y) {
    InputEvent e{Kind::mouse_pos};
    e.x = x;
    e.y = y;
    return e;
}
InputEvent button(bool down) {
    InputEvent e{Kind::mouse_button};
    e.code = 0;
    e.down = down;
    return e;
}

// xdotool's `key ctrl+a`, `type 0.75`, `key Return`: presses and releases microseconds apart.
std::vector<InputEvent> typed_entry() {
    std::vector<InputEvent> v = {key(key_left_control, true, mod_control),
                                 key(key_a, true, mod_control), key(key_a, false, mod_control),
                                 key(key_left_control, false)};
    const std::pair<int, char> typed[] = {
        {key_0, '0'}, {key_period, '.'}, {key_7, '7'}, {key_5, '5'}};
    for (const auto& [code, c] : typed) {
        v.push_back(key(code, true));
        v.push_back(character(static_cast<unsigned char>(c)));
        v.push_back(key(code, false));
    }
    v.push_back(key(key_enter, true));
    v.push_back(key(key_enter, false));
    return v;
}

// A real ImGui context with one window holding what a test draws; frames are driven by hand.
class ImGuiFrames : public ::testing::Test {
protected:
    void SetUp() override {
        isoparm::test::create_hand_driven_imgui();
        ImGuiIO& io = ImGui::GetIO();
        io.KeyMap[ImGuiKey_A] = key_a;
        io.KeyMap[ImGuiKey_Enter] = key_enter;
        io.KeyMap[ImGuiKey_Backspace] = key_backspace;
    }
    void TearDown() override { ImGui::DestroyContext(); }

    // One frame: `feed` gives ImGui its input, then the window with `draw` in it.
    void frame(const std::function<void()>& feed, const std::function<void()>& draw) {
        feed();
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(400, 300));
        ImGui::Begin("test", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove);
        draw();
        ImGui::End();
        ImGui::Render();
    }
    // Frames until the queue is empty (and two more, as the loop draws after input), at most 50.
    int drain(InputQueue& q, const std::function<void()>& draw) {
        int frames = 0;
        for (int idle = 0; idle < 2 && frames < 50; ++frames) {
            frame([&] { q.feed_frame(ImGui::GetIO(), presses); }, draw);
            if (q.empty()) ++idle;
        }
        return frames;
    }
    // The window before the queue: every event of the burst applied at once before one frame
    // (keys to io.KeysDown, characters queued, the pointer where it ended, a press seen once).
    void all_at_once(const std::vector<InputEvent>& burst) {
        ImGuiIO& io = ImGui::GetIO();
        bool pressed = false;
        for (const InputEvent& e : burst) {
            if (e.kind == Kind::key) io.KeysDown[e.code] = e.down;
            if (e.kind == Kind::character) io.AddInputCharacter(e.ch);
            if (e.kind == Kind::mouse_pos) io.MousePos = ImVec2(float(e.x), float(e.y));
            if (e.kind == Kind::mouse_button && e.down) pressed = true;
            if (e.kind == Kind::mouse_button) io.MouseDown[0] = e.down;
        }
        io.KeyCtrl = io.KeysDown[key_left_control];
        if (pressed) io.MouseDown[0] = true; // the GLFW backend's MouseJustPressed
    }

    std::vector<KeyPress> presses;
};

// A number field: click into it, then the burst; returns the text when Enter was taken.
struct NumberField {
    char text[32] = "1.25";
    int entered = 0;
    void draw() {
        ImGui::SetCursorPos(ImVec2(10, 10));
        ImGui::SetNextItemWidth(200);
        if (ImGui::InputText("##u", text, sizeof text, ImGuiInputTextFlags_EnterReturnsTrue))
            ++entered;
    }
    bool active() const { return ImGui::GetIO().WantTextInput; }
};

} // namespace

TEST_F(ImGuiFrames, TypedEntryInOneSlowFrameArrivesWhole) {
    NumberField field;
    InputQueue q;
    drain(q, [&] { field.draw(); }); // the window exists before anything is clicked in it
    // The click that focuses the field (its own frames, as the scenarios wait for "typing").
    q.push(mouse_at(60, 20));
    q.push(button(true));
    q.push(button(false));
    drain(q, [&] { field.draw(); });
    ASSERT_TRUE(field.active());

    for (const InputEvent& e : typed_entry()) q.push(e); // all during one frame
    const int frames = drain(q, [&] { field.draw(); });
    EXPECT_STREQ(field.text, "0.75");
    EXPECT_EQ(field.entered, 1);
    EXPECT_FALSE(field.active()); // Enter let go of the keyboard
    EXPECT_LE(frames, 20);
    // The shortcuts saw each press once, Ctrl with the A.
    ASSERT_GE(presses.size(), 2u);
    EXPECT_EQ(presses[1].key, key_a);
    EXPECT_TRUE(presses[1].ctrl);
}

TEST_F(ImGuiFrames, TypedEntryAllAtOnceLosesTheSelectAllAndTheOrder) {
    NumberField field;
    InputQueue q;
    drain(q, [&] { field.draw(); });
    q.push(mouse_at(60, 20));
    q.push(button(true));
    q.push(button(false));
    drain(q, [&] { field.draw(); });
    ASSERT_TRUE(field.active());
    frame([&] { all_at_once(typed_entry()); }, [&] { field.draw(); });
    for (int k = 0; k < 3; ++k) frame([] {}, [&] { field.draw(); });
    EXPECT_STRNE(field.text, "0.75") << "all at once gave " << field.text; // the queue prevents it
}

TEST_F(ImGuiFrames, DragInOneSlowFrameMovesWhileHeld) {
    // A canvas that moves a point by the mouse's drag while held (as the plane canvases do).
    float moved_x = 0, moved_y = 0;
    auto canvas = [&] {
        ImGui::SetCursorPos(ImVec2(0, 0));
        ImGui::InvisibleButton("canvas", ImVec2(300, 200));
        if (ImGui::IsItemActive()) {
            moved_x += ImGui::GetIO().MouseDelta.x;
            moved_y += ImGui::GetIO().MouseDelta.y;
        }
    };
    InputQueue q;
    q.push(mouse_at(100, 100));
    drain(q, canvas);
    q.push(button(true)); // press, eight moves and the release during one frame
    for (int k = 1; k <= 8; ++k) q.push(mouse_at(100 + 10 * k, 100 + 5 * k));
    q.push(button(false));
    drain(q, canvas);
    EXPECT_FLOAT_EQ(moved_x, 80);
    EXPECT_FLOAT_EQ(moved_y, 40);
    EXPECT_FALSE(ImGui::GetIO().MouseDown[0]);

    // The same burst all at once: pressed where it ended, nothing dragged.
    moved_x = moved_y = 0;
    std::vector<InputEvent> burst = {mouse_at(100, 100), button(true)};
    for (int k = 1; k <= 8; ++k) burst.push_back(mouse_at(100 + 10 * k, 100 + 5 * k));
    burst.push_back(button(false));
    frame([&] { all_at_once(burst); }, canvas);
    frame([] { ImGui::GetIO().MouseDown[0] = false; }, canvas);
    EXPECT_FLOAT_EQ(moved_x, 0);
}

TEST_F(ImGuiFrames, KeyTappedInOneFrameIsDownForOneFrameThenUp) {
    InputQueue q;
    q.push(key(key_enter, true));
    q.push(key(key_enter, false));
    bool seen_pressed = false;
    int frames = 0;
    while (!q.empty() && frames < 10) {
        frame([&] { q.feed_frame(ImGui::GetIO(), presses); },
              [&] { seen_pressed |= ImGui::IsKeyPressed(key_enter, false); });
        ++frames;
    }
    EXPECT_TRUE(seen_pressed);
    EXPECT_EQ(frames, 2);
    EXPECT_FALSE(ImGui::GetIO().KeysDown[key_enter]);
    ASSERT_EQ(presses.size(), 1u);
    EXPECT_EQ(presses[0].key, key_enter);
}

TEST_F(ImGuiFrames, ClickIsOneFrameDownAtItsPlace) {
    InputQueue q;
    int clicks = 0;
    auto draw = [&] {
        ImGui::SetCursorPos(ImVec2(20, 20));
        if (ImGui::Button("b", ImVec2(50, 30))) ++clicks;
    };
    drain(q, draw);
    q.push(mouse_at(40, 30)); // moved there, pressed and released within one frame
    q.push(button(true));
    q.push(button(false));
    drain(q, draw);
    EXPECT_EQ(clicks, 1);
}

TEST_F(ImGuiFrames, WheelNotchesAddUpInOneFrame) {
    InputQueue q;
    InputEvent notch{Kind::scroll};
    notch.y = 1;
    q.push(notch);
    q.push(notch);
    q.push(notch);
    float wheel = 0;
    frame([&] { q.feed_frame(ImGui::GetIO(), presses); },
          [&] { wheel = ImGui::GetIO().MouseWheel; });
    EXPECT_TRUE(q.empty());
    EXPECT_FLOAT_EQ(wheel, 3);
}
