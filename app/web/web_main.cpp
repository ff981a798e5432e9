// The workstation in a browser: emscripten's GLFW on a canvas that fills the page, WebGL 2,
// and the window's turn (app/window_loop.hpp) called once per animation frame, since a page
// cannot run a loop of its own.
//
// The page's address chooses what opens: ?scene=NAME (an example, assets/scenes/NAME.json),
// ?lesson=NAME (assets/lessons/NAME.json), ?stage=NAME (a teaching view on the stage, as
// `isoparm --stage NAME`) and ?layout=four (the four views). ?report=1 records the UI report for
// tests (app/web/web_pre.js); ?autosave=S autosaves every S seconds instead of 15. For
// measurements: Module.isoparmFrames collects each drawn frame's work in milliseconds,
// isoparmFrameEnds when each ended and isoparmFirstFrame when the first did (performance.now():
// from navigation).
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>
#include <unistd.h>

#include <cstdlib>
#include <memory>
#include <optional>
#include <string>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include "app/window_loop.hpp"
#include "ui/actions.hpp"
#include "ui/platform/files.hpp"
#include "ui/view/settings.hpp"
#include "ui/view/stage.hpp"
#include "ui/workstation.hpp"

namespace isoparm::web {

namespace {

// Autosaves are cheap in memory and a closed tab is likelier than a crash: every 15 s.
constexpr int autosave_seconds = 15;

struct WebApp {
    GLFWwindow* window = nullptr;
    std::unique_ptr<ui::Workstation> workstation;
    std::unique_ptr<app::WindowLoop> loop;
};

WebApp& web_app() {
    static WebApp a;
    return a;
}

// JavaScript (not C++: clang-format would respace its operators).
// clang-format off
EM_JS(int, page_width, (), { return window.innerWidth; });
EM_JS(int, page_height, (), { return window.innerHeight; });
// The value of ?name=... in the page's address (malloc'd; "" when absent).
EM_JS(char*, page_parameter, (const char* name), {
    const value = new URLSearchParams(window.location.search).get(UTF8ToString(name)) || "";
    const size = lengthBytesUTF8(value) + 1;
    const out = _malloc(size);
    stringToUTF8(value, out, size);
    return out;
});
// WebGL drawn by the CPU (SwiftShader, llvmpipe under the browser): multisampling costs
// there what it costs in the desktop's software_renderer().
EM_JS(int, software_webgl, (), {
    const gl = Module.canvas.getContext('webgl2');
    const info = gl && gl.getExtension('WEBGL_debug_renderer_info');
    const name = info ? String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL)) : "";
    return ['SwiftShader', 'llvmpipe', 'softpipe', 'Software'].some(function(s) { return name.indexOf(s) >= 0; }) ? 1 : 0;
});
EM_JS(void, frame_drawn, (double ms), {
    (Module.isoparmFrames = Module.isoparmFrames || []).push(ms);
    (Module.isoparmFrameEnds = Module.isoparmFrameEnds || []).push(performance.now());
    if (Module.isoparmFirstFrame == undefined) Module.isoparmFirstFrame = performance.now();
});
// emscripten 3.1.6's GLFW has no clipboard: ImGui's copy goes to the browser's clipboard, and
// its paste reads the text of the page's last paste event (a page may not read the clipboard
// whenever it likes).
EM_JS(void, install_paste_listener, (), {
    Module.isoparmPasted = "";
    document.addEventListener(
        'paste', function(e) {
            Module.isoparmPasted = (e.clipboardData && e.clipboardData.getData('text/plain')) || "";
        });
});
EM_JS(void, copy_text, (const char* text), {
    const s = UTF8ToString(text);
    Module.isoparmPasted = s; // pasting inside the page works even where writing is refused
    if (navigator.clipboard) navigator.clipboard.writeText(s).catch(function(){});
});
EM_JS(char*, pasted_text, (), {
    const s = Module.isoparmPasted || "";
    const size = lengthBytesUTF8(s) + 1;
    const out = _malloc(size);
    stringToUTF8(s, out, size);
    return out;
});
// clang-format on

std::string parameter(const char* name) {
    char* v = page_parameter(name);
    std::string s = v;
    free(v);
    return s;
}

void set_clipboard(void*, const char* text) {
    copy_text(text);
}
const char* get_clipboard(void*) {
    static std::string text;
    char* s = pasted_text();
    text = s;
    free(s);
    return text.c_str();
}

EM_BOOL on_resize(int, const EmscriptenUiEvent*, void*) {
    glfwSetWindowSize(web_app().window, page_width(), page_height());
    app::wake_window(web_app().window);
    return EM_FALSE;
}

// The page is about to go (reload, close, another address): unsaved work goes to the recovery
// file now, and the browser asks whether to leave.
const char* on_before_unload(int, const void*, void*) {
    WebApp& a = web_app();
    a.loop->autosave_now();
    return a.workstation->context().dirty() ? "The scene has unsaved changes." : nullptr;
}

void turn(void*) {
    WebApp& a = web_app();
    if (!a.loop->turn()) return;
    frame_drawn(a.loop->last_frame_ms());
    ui::AppContext& ctx = a.workstation->context();
    if (ctx.ui.fullscreen_request) { // F11 or the menu: the browser's full screen
        ctx.ui.fullscreen_request = false;
        EmscriptenFullscreenChangeEvent state{};
        emscripten_get_fullscreen_status(&state);
        if (state.isFullscreen)
            emscripten_exit_fullscreen();
        else
            emscripten_request_fullscreen("#canvas", EM_TRUE);
    }
    if (ctx.ui.quit_now) { // Ctrl+Q: a page cannot close its own tab, and says so
        ctx.ui.quit_now = false;
        ctx.ui.status = ui::files::unavailable(ui::files::Feature::quit);
    }
}

} // namespace

} // namespace isoparm::web

// For the page's scripts: something arrived (an upload), draw frames as after an event.
extern "C" EMSCRIPTEN_KEEPALIVE void isoparm_web_wake() {
    isoparm::app::wake_window(isoparm::web::web_app().window);
}

// For tests: 1 when no frame is due, i.e. the picture shows everything that happened.
extern "C" EMSCRIPTEN_KEEPALIVE int isoparm_web_idle() {
    const isoparm::web::WebApp& a = isoparm::web::web_app();
    return a.loop && !a.loop->frame_due() ? 1 : 0;
}

int main() {
    using namespace isoparm;
    web::WebApp& a = web::web_app();
    // The file dialog starts among the page's own files: scenes/ and lessons/.
    if (chdir("/isoparm/assets") != 0) return 1;
    if (!glfwInit()) return 1;
    a.window = glfwCreateWindow(web::page_width(), web::page_height(), "isoparm", nullptr, nullptr);
    if (!a.window) return 1;
    glfwMakeContextCurrent(a.window);
    // The settings the last visit kept in local storage (web_pre.js put them in place).
    ui::Settings settings = ui::load_settings(ui::settings_path());
    const bool software = web::software_webgl() != 0;
    ui::WorkstationOptions options{/*headless=*/false, 1.0f, ui::ViewMode::workstation,
                                   software ? 0 : 4, app::request_frame};
    // As the desktop window on a CPU rasteriser: drags drawn coarse, the frame kept between
    // frames and drawn again only where it changed. ?gestures=full draws every frame in full
    // (the browser test's paired figure).
    const std::string gestures = web::parameter("gestures");
    const bool lighter = software && gestures != "full";
    options.cpu_rasteriser = lighter;
    options.retained = lighter;
    a.workstation = std::make_unique<ui::Workstation>(options);
    ui::AppContext& ctx = a.workstation->context();
    ctx.settings = settings;
    ImGui_ImplGlfw_InitForOpenGL(a.window, false);
    ImGuiIO& io = ImGui::GetIO();
    web::install_paste_listener();
    io.SetClipboardTextFn = web::set_clipboard;
    io.GetClipboardTextFn = web::get_clipboard;
    const std::string every = web::parameter("autosave");
    a.loop = std::make_unique<app::WindowLoop>(
        a.window, *a.workstation, every.empty() ? web::autosave_seconds : std::atoi(every.c_str()),
        nullptr);
    emscripten_set_resize_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, nullptr, EM_FALSE,
                                   web::on_resize);
    emscripten_set_beforeunload_callback(nullptr, web::on_before_unload);
    if (const std::string s = web::parameter("scene"); !s.empty())
        ui::open_file(ctx, "/isoparm/assets/scenes/" + s + ".json");
    if (const std::string l = web::parameter("lesson"); !l.empty())
        ui::open_lesson(ctx, "/isoparm/assets/lessons/" + l + ".json");
    // What the page shows first, as `isoparm --stage NAME` and `--layout four` choose it.
    if (const std::string st = web::parameter("stage"); !st.empty()) {
        if (const std::optional<ui::StageView> v = ui::stage_view_named(st))
            ctx.ui.stage.view = *v;
        else
            ctx.ui.status = "?stage=" + st + " is not a teaching view: " + ui::stage_view_names();
    }
    if (!gestures.empty() && gestures != "full")
        ctx.ui.status = "?gestures=" + gestures + " is not known: full draws every frame in full";
    if (web::parameter("layout") == "four" && ctx.ui.stage.view == ui::StageView::none)
        ctx.ui.stage.four_views = true;
    // Work a closed tab or a crash left: the recovery folder came back from IndexedDB.
    ctx.ui.recovery.offers = app::recovery_offers("", ctx.settings.recent);
    emscripten_set_main_loop_arg(web::turn, nullptr, 0, false);
    return 0;
}
