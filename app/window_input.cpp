#include "app/window_input.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "ui/input_queue.hpp"

namespace isoparm::app {

namespace {

using Kind = ui::InputEvent::Kind;

ui::InputQueue& queue() {
    static ui::InputQueue q;
    return q;
}
void (*notify)(GLFWwindow*) = nullptr;

void push(GLFWwindow* w, const ui::InputEvent& e) {
    queue().push(e);
    if (notify) notify(w);
}

void on_cursor(GLFWwindow* w, double x, double y) {
    ui::InputEvent e{Kind::mouse_pos};
    e.x = x;
    e.y = y;
    push(w, e);
}
void on_enter(GLFWwindow* w, int entered) {
    if (!entered) push(w, ui::InputEvent{Kind::mouse_left});
}
void on_button(GLFWwindow* w, int button, int action, int) {
    ui::InputEvent e{Kind::mouse_button};
    e.code = button;
    e.down = action == GLFW_PRESS;
    push(w, e);
}
void on_scroll(GLFWwindow* w, double dx, double dy) {
    ui::InputEvent e{Kind::scroll};
    e.x = dx;
    e.y = dy;
    push(w, e);
}
void on_key(GLFWwindow* w, int key, int, int action, int mods) {
    ui::InputEvent e{Kind::key};
    e.code = key;
    e.down = action != GLFW_RELEASE; // a repeat: still down, and a press for the shortcuts
    e.mods = mods;
    push(w, e);
}
void on_char(GLFWwindow* w, unsigned c) {
    ui::InputEvent e{Kind::character};
    e.ch = c;
    push(w, e);
}
void on_focus(GLFWwindow* w, int focused) {
    ui::InputEvent e{Kind::focus};
    e.focused = focused != 0;
    push(w, e);
}

} // namespace

void install_input_queue(GLFWwindow* window, void (*on_event)(GLFWwindow*)) {
    notify = on_event;
    glfwSetCursorPosCallback(window, on_cursor);
    glfwSetCursorEnterCallback(window, on_enter);
    glfwSetMouseButtonCallback(window, on_button);
    glfwSetScrollCallback(window, on_scroll);
    glfwSetKeyCallback(window, on_key);
    glfwSetCharCallback(window, on_char);
    glfwSetWindowFocusCallback(window, on_focus);
}

bool feed_input_frame(std::vector<ui::KeyPress>& presses) {
    queue().feed_frame(ImGui::GetIO(), presses);
    return !queue().empty();
}

} // namespace isoparm::app
