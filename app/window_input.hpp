// The window's input for ImGui through ui::InputQueue: GLFW's callbacks queue every key,
// button, wheel, character, pointer and focus event; each frame takes what it can show.
#pragma once

#include <vector>

#include "ui/ui_state.hpp"

struct GLFWwindow;

namespace isoparm::app {

// Installs the callbacks (after ImGui_ImplGlfw_InitForOpenGL(window, false): the backend's
// own would write io at once). `on_event` runs for every event (the loop draws a frame).
void install_input_queue(GLFWwindow* window, void (*on_event)(GLFWwindow*));

// Between ImGui_ImplGlfw_NewFrame (which polls the pointer and buttons: overwritten here) and
// ImGui::NewFrame: this frame's events to ImGui and its key presses to `presses`. Returns
// true while events wait for later frames.
bool feed_input_frame(std::vector<ui::KeyPress>& presses);

} // namespace isoparm::app
