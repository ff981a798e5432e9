// The workstation in a browser: emscripten's GLFW on a canvas that fills the page, WebGL 2,
// and a per-frame function the browser calls (requestAnimationFrame) instead of a loop.
//
// The page's address chooses what opens: ?scene=NAME (an example scene, assets/scenes/NAME.json)
// and ?lesson=NAME (assets/lessons/NAME.json); ?report=1 records the UI report
// (ui/ui_report.hpp) for tests, which read it through Module.uiReport().
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include "ui/actions.hpp"
#include "ui/workstation.hpp"

namespace isoparm::web {

namespace {

struct WebApp {
    GLFWwindow* window = nullptr;
    std::unique_ptr<ui::Workstation> workstation;
    int pending_frames = 3;
    bool drew_once = false;
    std::string title;
};

WebApp& app() {
    static WebApp a;
    return a;
}

void wake(GLFWwindow*) {
    app().pending_frames = 3;
}
void on_cursor(GLFWwindow* w, double, double) {
    wake(w);
}
void on_button(GLFWwindow* w, int, int, int) {
    wake(w);
}
void on_scroll(GLFWwindow* w, double, double) {
    wake(w);
}
void on_char(GLFWwindow* w, unsigned) {
    wake(w);
}
void on_key(GLFWwindow* w, int key, int, int action, int mods) {
    wake(w);
    if (action == GLFW_RELEASE || !app().workstation) return;
    app().workstation->context().ui.key_presses.push_back({key, (mods & GLFW_MOD_CONTROL) != 0,
                                                           (mods & GLFW_MOD_SHIFT) != 0,
                                                           (mods & GLFW_MOD_ALT) != 0});
}

EM_JS(int, page_width, (), { return window.innerWidth; });
EM_JS(int, page_height, (), { return window.innerHeight; });
EM_JS(char*, page_parameter, (const char* name), {
    const value = new URLSearchParams(window.location.search).get(UTF8ToString(name)) || "";
    const size = lengthBytesUTF8(value) + 1;
    const out = _malloc(size);
    stringToUTF8(value, out, size);
    return out;
});
// The frame's work in milliseconds, for the page (the test reads Module.isoparmFrames).
EM_JS(void, frame_done, (double ms), {
    if (!Module.isoparmFrames) Module.isoparmFrames = [];
    Module.isoparmFrames.push(ms);
    if (Module.isoparmFirstFrame == = undefined) Module.isoparmFirstFrame = performance.now();
});

std::string parameter(const char* name) {
    char* v = page_parameter(name);
    std::string s = v;
    free(v);
    return s;
}

EM_BOOL on_resize(int, const EmscriptenUiEvent*, void*) {
    glfwSetWindowSize(app().window, page_width(), page_height());
    app().pending_frames = 3;
    return EM_FALSE;
}

void frame(void*) {
    WebApp& a = app();
    ui::AppContext& ctx = a.workstation->context();
    if (a.pending_frames == 0) return; // nothing happened: the last picture stands
    --a.pending_frames;
    if (ImGui::IsAnyItemActive() && ImGui::IsAnyMouseDown())
        a.pending_frames = std::max(a.pending_frames, 1);
    const auto t0 = std::chrono::steady_clock::now();
    ImGui_ImplGlfw_NewFrame();
    a.workstation->frame(0);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    double& shown = ctx.ui.frame_ms;
    shown = shown <= 0 ? ms : shown * 0.8 + ms * 0.2;
    frame_done(ms);
    if (const std::string t = ctx.title(); t != a.title) {
        glfwSetWindowTitle(a.window, t.c_str());
        a.title = t;
    }
}

} // namespace

} // namespace isoparm::web

int main() {
    using namespace isoparm;
    web::WebApp& a = web::app();
    if (!glfwInit()) return 1;
    a.window = glfwCreateWindow(web::page_width(), web::page_height(), "isoparm", nullptr, nullptr);
    if (!a.window) return 1;
    glfwMakeContextCurrent(a.window);
    a.workstation = std::make_unique<ui::Workstation>(
        ui::WorkstationOptions{/*headless=*/false, 1.0f, ui::ViewMode::workstation, 4,
                               [] { web::app().pending_frames = 3; }});
    glfwSetCursorPosCallback(a.window, web::on_cursor);
    glfwSetMouseButtonCallback(a.window, web::on_button);
    glfwSetScrollCallback(a.window, web::on_scroll);
    glfwSetCharCallback(a.window, web::on_char);
    glfwSetKeyCallback(a.window, web::on_key);
    ImGui_ImplGlfw_InitForOpenGL(a.window, true);
    emscripten_set_resize_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, nullptr, EM_FALSE,
                                   web::on_resize);
    ui::AppContext& ctx = a.workstation->context();
    if (const std::string s = web::parameter("scene"); !s.empty())
        ui::open_file(ctx, "/isoparm/assets/scenes/" + s + ".json");
    if (const std::string l = web::parameter("lesson"); !l.empty())
        ui::open_lesson(ctx, "/isoparm/assets/lessons/" + l + ".json");
    emscripten_set_main_loop_arg(web::frame, nullptr, 0, false);
    return 0;
}
