// `isoparm [SCENE]`: the workstation window (GLFW, OpenGL 3.3 core, Dear ImGui).
#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ui/render/gl.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include "app/commands.hpp"
#include "app/keep_libraries_loaded.hpp"
#include "app/window_loop.hpp"
#include "core/scene/autosave.hpp"
#include "ui/actions.hpp"
#include "ui/render/renderer.hpp"
#include "ui/view/settings.hpp"
#include "ui/view/stage.hpp"
#include "ui/view/window_placement.hpp"
#include "ui/workstation.hpp"

namespace isoparm::app {

namespace {

constexpr const char* render_hint =
    "to make pictures without a display, use 'isoparm render [SCENE] -o OUT.png'";

std::string& glfw_error() {
    static std::string last;
    return last;
}

void on_size(GLFWwindow* w, int, int) {
    wake_window(w);
}

ui::ScreenRect work_area_of(GLFWmonitor* m) {
    ui::ScreenRect r;
    glfwGetMonitorWorkarea(m, &r.x, &r.y, &r.width, &r.height);
    if (r.width <= 0 || r.height <= 0) { // some servers report no work area: the whole mode
        const GLFWvidmode* mode = glfwGetVideoMode(m);
        glfwGetMonitorPos(m, &r.x, &r.y);
        r.width = mode ? mode->width : ui::default_window_width;
        r.height = mode ? mode->height : ui::default_window_height;
    }
    return r;
}

// The monitor that holds most of the window (the primary one when it is on none).
GLFWmonitor* monitor_of(GLFWwindow* window) {
    int wx = 0, wy = 0, ww = 0, wh = 0;
    glfwGetWindowPos(window, &wx, &wy);
    glfwGetWindowSize(window, &ww, &wh);
    int count = 0;
    GLFWmonitor** monitors = glfwGetMonitors(&count);
    GLFWmonitor* best = glfwGetPrimaryMonitor();
    long best_area = 0;
    for (int k = 0; k < count; ++k) {
        const GLFWvidmode* mode = glfwGetVideoMode(monitors[k]);
        if (!mode) continue;
        int mx = 0, my = 0;
        glfwGetMonitorPos(monitors[k], &mx, &my);
        const long w = std::max(0, std::min(wx + ww, mx + mode->width) - std::max(wx, mx));
        const long h = std::max(0, std::min(wy + wh, my + mode->height) - std::max(wy, my));
        if (w * h > best_area) {
            best_area = w * h;
            best = monitors[k];
        }
    }
    return best;
}

// F11: true full screen on the monitor the window is on, and back to the window it was.
void toggle_fullscreen(GLFWwindow* window, ui::ScreenRect& windowed) {
    if (glfwGetWindowMonitor(window)) {
        glfwSetWindowMonitor(window, nullptr, windowed.x, windowed.y, windowed.width,
                             windowed.height, GLFW_DONT_CARE);
        return;
    }
    glfwGetWindowPos(window, &windowed.x, &windowed.y);
    glfwGetWindowSize(window, &windowed.width, &windowed.height);
    GLFWmonitor* m = monitor_of(window);
    const GLFWvidmode* mode = m ? glfwGetVideoMode(m) : nullptr;
    if (!mode) return;
    glfwSetWindowMonitor(window, m, 0, 0, mode->width, mode->height, mode->refreshRate);
}

// What the window shows first: the workstation, a teaching view on the stage, or four views.
struct FirstView {
    ui::StageView stage = ui::StageView::none;
    bool four_views = false;
};

int run_window(const std::string& scene, const std::string& lesson, int autosave_seconds,
               const FirstView& first) {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!x11 || !*x11) && (!wayland || !*wayland)) {
        std::cerr << "isoparm: no display (DISPLAY and WAYLAND_DISPLAY are unset); " << render_hint
                  << "\n";
        return 1;
    }
    glfwSetErrorCallback([](int, const char* text) { glfw_error() = text ? text : ""; });
    if (!glfwInit()) {
        std::cerr << "isoparm: cannot open the display (" << glfw_error() << "); " << render_hint
                  << "\n";
        return 1;
    }
    ui::Settings settings = ui::load_settings(ui::settings_path());
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
    // Placed before it is shown: a projector's 1024x768 gets a window that fits its work area.
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    GLFWmonitor* primary = glfwGetPrimaryMonitor();
    const ui::ScreenRect place =
        primary ? ui::place_window(work_area_of(primary), settings.window_sizes)
                : ui::ScreenRect{0, 0, ui::default_window_width, ui::default_window_height};
    GLFWwindow* window = glfwCreateWindow(place.width, place.height, "isoparm", nullptr, nullptr);
    if (!window) {
        std::cerr << "isoparm: cannot create an OpenGL 3.3 core window (" << glfw_error() << "); "
                  << render_hint << "\n";
        glfwTerminate();
        return 1;
    }
    glfwSetWindowPos(window, place.x, place.y);
    glfwShowWindow(window);
    glfwMakeContextCurrent(window);
    keep_libraries_loaded_for_leak_reports(); // the driver is loaded once a context is current
    glfwSwapInterval(1);
    ui::ScreenRect windowed = place; // where F11 returns to
    float xs = 1, ys = 1;
    glfwGetWindowContentScale(window, &xs, &ys);

    int status = 0;
    {
        // Multisampling costs ~5x on a CPU rasteriser: the window stays responsive without it
        // (lines and points are antialiased in their shaders anyway).
        const bool software = ui::software_renderer();
        const int msaa = software ? 0 : 4;
        ui::WorkstationOptions options{/*headless=*/false, std::max(xs, ys),
                                       ui::ViewMode::workstation, msaa, request_frame};
        // There each unchanged panel would be set up and filled again every frame.
        options.retained = software;
        ui::Workstation ws(options);
        ui::AppContext& ctx = ws.context();
        if (!ws.renderer_error().empty()) {
            std::cerr << "isoparm: OpenGL shaders failed: " << ws.renderer_error() << "\n";
            status = 1;
        } else {
            ctx.settings = settings;
            glfwSetFramebufferSizeCallback(window, on_size);
            glfwSetWindowContentScaleCallback(window, [](GLFWwindow* w, float sx, float sy) {
                auto* c = static_cast<ui::AppContext*>(glfwGetWindowUserPointer(w));
                c->ui.content_scale = std::max(sx, sy);
                wake_window(w);
            });
            glfwSetWindowUserPointer(window, &ctx);
            // The backend without its callbacks: input goes through the queue (window_input).
            ImGui_ImplGlfw_InitForOpenGL(window, false);
            WindowLoop loop(window, ws, autosave_seconds, [window] { glfwSwapBuffers(window); });

            if (!scene.empty() && !ui::open_file(ctx, scene))
                std::cerr << "isoparm: " << ctx.ui.error_message << "\n";
            if (!lesson.empty() && !ui::open_lesson(ctx, lesson))
                std::cerr << "isoparm: " << ctx.ui.error_message << "\n";
            ctx.ui.stage.view = first.stage;
            ctx.ui.stage.four_views = first.four_views;
            if (autosave_seconds > 0)
                ctx.ui.recovery.offers = recovery_offers(scene, ctx.settings.recent);
            while (!ctx.ui.quit_now) {
                if (loop.frame_due())
                    glfwPollEvents();
                else
                    glfwWaitEventsTimeout(0.5); // wakes for the autosave timer too
                if (glfwWindowShouldClose(window)) {
                    glfwSetWindowShouldClose(window, GLFW_FALSE);
                    ui::request_quit(ctx); // asks first when there are unsaved changes
                    wake_window(window);
                }
                if (!loop.turn()) continue;
                if (ctx.ui.fullscreen_request) {
                    ctx.ui.fullscreen_request = false;
                    toggle_fullscreen(window, windowed);
                    ctx.ui.fullscreen = glfwGetWindowMonitor(window) != nullptr;
                    wake_window(window);
                }
            }
            // A normal exit: the unsaved-changes question was answered, the work is safe or
            // deliberately dropped.
            loop.finish();
            // The size is kept for monitors of this work-area size (not a full-screen size).
            if (glfwGetWindowMonitor(window)) toggle_fullscreen(window, windowed);
            int w = 0, h = 0;
            glfwGetWindowSize(window, &w, &h);
            if (GLFWmonitor* m = monitor_of(window))
                ctx.settings.window_sizes[ui::work_area_key(work_area_of(m))] = {w, h};
            ui::store_settings(ctx);
            ImGui_ImplGlfw_Shutdown();
        }
    }
    keep_libraries_loaded_for_leak_reports(); // and those loaded since (cursors, dialogs)
    glfwDestroyWindow(window);
    glfwTerminate();
    return status;
}

} // namespace

Action register_gui_command(CLI::App& app) {
    auto scene = std::make_shared<std::string>();
    app.add_option(
        "SCENE", *scene,
        "scene to open in the workstation (default: a shaped 5x5 bicubic NURBS surface)");
    auto lesson = std::make_shared<std::string>();
    app.add_option("--lesson", *lesson,
                   "a script (docs/script-format.md) to play in the window from pause to pause: "
                   "Right arrow or Page Down goes on");
    auto autosave_seconds = std::make_shared<int>(60);
    app.add_option("--autosave-seconds", *autosave_seconds,
                   "seconds between autosaves of unsaved changes to the recovery file, which the "
                   "next start offers to restore after a crash (0: no autosave, no offer)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    auto stage = std::make_shared<std::string>();
    app.add_option("--stage", *stage,
                   "open with this teaching view at full size (Esc returns to the workstation): " +
                       ui::stage_view_names())
        ->check([](const std::string& name) -> std::string {
            if (ui::stage_view_named(name)) return {};
            return "'" + name + "' is not a teaching view; one of " + ui::stage_view_names();
        });
    auto layout = std::make_shared<std::string>("workstation");
    app.add_option("--layout", *layout,
                   "open with this layout: workstation, or four (xy, 3D, xz, yz at equal size)")
        ->check(CLI::IsMember({"workstation", "four"}))
        ->capture_default_str();
    return [scene, lesson, autosave_seconds, stage, layout]() -> int {
        FirstView first;
        if (!stage->empty()) first.stage = *ui::stage_view_named(*stage);
        first.four_views = *layout == "four" && first.stage == ui::StageView::none;
        return run_window(*scene, *lesson, *autosave_seconds, first);
    };
}

} // namespace isoparm::app
