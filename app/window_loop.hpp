// The window's turn, shared by the desktop and the browser: events in, a frame drawn when
// something happened, the autosave. The desktop loop (gui_command.cpp) waits for events
// between turns; the browser calls a turn once per animation frame (app/web/web_main.cpp),
// since a page cannot block.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "core/scene/autosave.hpp"
#include "core/scene/autosave_timer.hpp"

struct GLFWwindow;

namespace isoparm::ui {
class Workstation;
struct AppContext;
} // namespace isoparm::ui

namespace isoparm::app {

// Asks for a frame from any thread (a mesh ready in the background, an animation's next step):
// the next turn draws one, and the desktop's wait for events ends (glfwPostEmptyEvent).
void request_frame();
// A few frames after an event (ImGui settles hover and layout over two or three).
void wake_window(GLFWwindow*);

// The start-up's candidates for recovery files: the scene asked for, the untitled document and
// the recent files (recovery file names hash the path, so only known paths can be found).
std::vector<scene::RecoveryInfo> recovery_offers(const std::string& scene,
                                                 const std::vector<std::string>& recent);

class WindowLoop {
public:
    // `present` shows a drawn frame (glfwSwapBuffers on the desktop; nothing in a browser,
    // which shows the canvas after the animation frame); `autosave_seconds` 0: no autosave.
    // Installs the input queue's callbacks on `window` (app/window_input.hpp).
    WindowLoop(GLFWwindow* window, ui::Workstation& workstation, int autosave_seconds,
               std::function<void()> present);

    // Whether the next turn draws (the desktop polls instead of waiting then).
    bool frame_due() const;
    // One turn: a frame if one is due, else only the idle autosave. Returns whether it drew.
    bool turn();
    // The work of the last frame drawn (input, build, render, present), milliseconds.
    double last_frame_ms() const { return last_ms_; }
    // A clean exit: the recovery file of work that was saved or deliberately dropped goes.
    void finish();
    // Writes the recovery file now if the document has unsaved changes (the browser, when
    // its page is about to go).
    void autosave_now();

private:
    void autosave();
    GLFWwindow* window_;
    ui::Workstation& workstation_;
    bool autosaving_;
    scene::AutosaveTimer timer_;
    std::function<void()> present_;
    std::string title_;
    double last_ms_ = 0;
    int popups_ = 0; // ImGui's open popups after the last frame
};

} // namespace isoparm::app
