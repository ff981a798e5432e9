// A canvas's help hint (ui/panels/canvas_hint.hpp) waits until the pointer has rested on the
// canvas for canvas_hint_delay seconds, asking for frames meanwhile; a move, a held button or
// another canvas starts the wait again. ImGui alone, no window: frames are stepped by hand.
#include <gtest/gtest.h>

#include <imgui.h>

#include "tests/ui/hand_driven_imgui.hpp"
#include "ui/panels/canvas_hint.hpp"

using namespace isoparm::ui;

namespace {

class CanvasHint : public ::testing::Test {
protected:
    void SetUp() override { isoparm::test::create_hand_driven_imgui(); }
    void TearDown() override { ImGui::DestroyContext(); }

    // One frame of `dt` seconds with the pointer at (x, y) over two canvases side by side
    // (x 10..210 and 300..500): whether a hint is due, and for which canvas.
    int frame(float x, float y, double dt = 0.1, bool held = false) {
        ImGuiIO& io = ImGui::GetIO();
        io.DeltaTime = static_cast<float>(dt);
        io.MousePos = ImVec2(x, y);
        io.MouseDown[0] = held;
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(800, 600));
        ImGui::Begin("canvases", nullptr, ImGuiWindowFlags_NoDecoration);
        int due = 0;
        ui.hint_waiting = false;
        ImGui::SetCursorScreenPos(ImVec2(10, 10));
        ImGui::InvisibleButton("left", ImVec2(200, 200));
        if (canvas_hint_due(ui)) due = 1;
        ImGui::SetCursorScreenPos(ImVec2(300, 10));
        ImGui::InvisibleButton("right", ImVec2(200, 200));
        if (canvas_hint_due(ui)) due = 2;
        ImGui::End();
        ImGui::Render();
        return due;
    }

    UiState ui;
};

} // namespace

TEST_F(CanvasHint, ShownOnceThePointerHasRested) {
    EXPECT_EQ(frame(100, 100), 0); // arrives
    EXPECT_EQ(frame(100, 100), 0);
    EXPECT_TRUE(ui.hint_waiting); // frames are asked for meanwhile
    int frames = 0;
    while (frame(100, 100) == 0) ASSERT_LT(++frames, 20) << "the hint never came";
    // 0.1 s frames: due at the first frame canvas_hint_delay after the pointer stopped.
    EXPECT_GE(0.1 * (frames + 2), canvas_hint_delay - 1e-9);
    EXPECT_LE(0.1 * (frames + 2), canvas_hint_delay + 0.1 + 1e-9);
    EXPECT_TRUE(ui.hint_waiting); // one more frame: a tooltip shows in its second
    EXPECT_EQ(frame(100, 100), 1);
    EXPECT_TRUE(ui.hint_waiting);
    EXPECT_EQ(frame(100, 100), 1); // and stays, without asking for frames
    EXPECT_FALSE(ui.hint_waiting);
}

TEST_F(CanvasHint, AMoveAButtonOrAnotherCanvasWaitsAgain) {
    for (int k = 0; k < 10; ++k) frame(100, 100);
    ASSERT_EQ(frame(100, 100), 1);
    EXPECT_EQ(frame(101, 100), 0); // moved: not at once
    for (int k = 0; k < 10; ++k) frame(101, 100);
    ASSERT_EQ(frame(101, 100), 1);
    EXPECT_EQ(frame(101, 100, 0.1, true), 0); // a drag starts here
    EXPECT_EQ(frame(101, 100, 1.0, true), 0); // however long it is held
    EXPECT_EQ(frame(101, 100, 0.1), 0);       // released: waits again
    for (int k = 0; k < 10; ++k) frame(101, 100);
    ASSERT_EQ(frame(101, 100), 1);
    EXPECT_EQ(frame(400, 100), 0);      // the other canvas
    EXPECT_EQ(frame(400, 100, 1.0), 2); // a long frame there: due
    EXPECT_EQ(frame(600, 300, 1.0), 0); // over neither: nothing, nothing waits
    EXPECT_FALSE(ui.hint_waiting);
}
