// The window's turn (see window_loop.hpp).
#include "app/window_loop.hpp"

#include <algorithm>
#include <atomic>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>
#include <imgui_internal.h> // the active item and the popup stack: see settling()

#include "app/window_input.hpp"
#include "ui/platform/files.hpp"
#include "ui/workstation.hpp"

namespace isoparm::app {

namespace {

// Frames are drawn while something happens; when idle the desktop sleeps in glfwWaitEvents
// and the browser's animation frames return at once (on a CPU rasteriser every frame costs
// tens of milliseconds).
int& pending_frames() {
    static int n = 3;
    return n;
}
// Set from any thread; the next turn turns it into frames.
std::atomic<bool>& frame_requested() {
    static std::atomic<bool> flag{false};
    return flag;
}

// ImGui 1.86 publishes some of a frame's changes only at the next frame: a field that took the
// keyboard (io.WantTextInput), an item just activated, a popup opened or closed (laid out and
// focused there). Such a frame asks for one more, so what the user sees (and the UI report
// says) is never a frame behind.
bool settling(int& popups_before) {
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    const bool text_input = g.WantTextInputNextFrame > 0;
    const bool changed = g.ActiveIdIsJustActivated || g.OpenPopupStack.Size != popups_before ||
                         text_input != g.IO.WantTextInput;
    popups_before = g.OpenPopupStack.Size;
    return changed;
}

} // namespace

void request_frame() {
    frame_requested() = true;
    glfwPostEmptyEvent();
}

void wake_window(GLFWwindow*) {
    pending_frames() = 3;
}

std::vector<scene::RecoveryInfo> recovery_offers(const std::string& scene,
                                                 const std::vector<std::string>& recent) {
    std::vector<std::string> candidates;
    if (!scene.empty()) candidates.push_back(scene);
    candidates.push_back("");
    candidates.insert(candidates.end(), recent.begin(), recent.end());
    return scene::find_recoveries(candidates);
}

WindowLoop::WindowLoop(GLFWwindow* window, ui::Workstation& workstation, int autosave_seconds,
                       std::function<void()> present)
    : window_(window), workstation_(workstation), autosaving_(autosave_seconds > 0),
      timer_(scene::AutosaveTimer::Clock::now(),
             std::chrono::seconds(std::max(autosave_seconds, 1))),
      present_(std::move(present)) {
    install_input_queue(window, wake_window);
}

bool WindowLoop::frame_due() const {
    return pending_frames() > 0 || frame_requested().load();
}

bool WindowLoop::turn() {
    ui::AppContext& ctx = workstation_.context();
    if (frame_requested().exchange(false)) pending_frames() = std::max(pending_frames(), 1);
    if (pending_frames() == 0) {
        autosave(); // nothing happened: no frame
        return false;
    }
    --pending_frames();
    // Keep drawing while a mouse gesture is in progress (a focused text field alone draws on
    // its keys, not continuously).
    if (ImGui::IsAnyItemActive() && ImGui::IsAnyMouseDown())
        pending_frames() = std::max(pending_frames(), 1);
    const auto t0 = std::chrono::steady_clock::now();
    ImGui_ImplGlfw_NewFrame();
    if (feed_input_frame(ctx.ui.key_presses)) // more events than one frame shows
        pending_frames() = std::max(pending_frames(), 1);
    workstation_.frame(0);
    if (settling(popups_)) pending_frames() = std::max(pending_frames(), 1);
    if (present_) present_();
    // The work of a frame, not the time between frames (idle waits excluded).
    last_ms_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    double& shown = ctx.ui.frame_ms;
    shown = shown <= 0 ? last_ms_ : shown * 0.8 + last_ms_ * 0.2;
    if (const std::string t = ctx.title(); t != title_) {
        glfwSetWindowTitle(window_, t.c_str());
        title_ = t;
    }
    autosave();
    return true;
}

// One step of autosaving, after every turn: the dialog's answers first, then the timer. A
// write is a few milliseconds for a scene (serialization, fsync, rename), so it runs on the
// UI thread; it happens at most once an interval.
void WindowLoop::autosave() {
    if (!autosaving_) return;
    ui::AppContext& ctx = workstation_.context();
    ui::RecoveryPrompt& r = ctx.ui.recovery;
    for (const std::string& p : r.held) timer_.hold(scene::normalized_scene_path(p));
    r.held.clear();
    for (const std::string& p : r.restored)
        timer_.wrote(scene::normalized_scene_path(p), scene::document_fingerprint(ctx.doc));
    r.restored.clear();
    // Undone back to the saved state with work still on the redo stack: the recovery file
    // keeps that work (it is not discarded) until a redo, a new edit or a save moves on.
    if (!ctx.dirty() && ctx.history.can_redo()) return;
    const std::string path = scene::normalized_scene_path(ctx.file_path);
    const scene::AutosaveTimer::Step step =
        timer_.poll(scene::AutosaveTimer::Clock::now(), ctx.dirty(), path,
                    [&ctx] { return scene::document_fingerprint(ctx.doc); });
    using Kind = scene::AutosaveTimer::Step::Kind;
    if (step.kind == Kind::write) {
        if (const geom::Status st = scene::write_recovery(ctx.doc, step.path); st.ok()) {
            timer_.wrote(step.path, step.fingerprint);
            ui::files::keep_recovery();
        } else {
            ctx.ui.status = "Autosave failed: " + st.error().message;
        }
    } else if (step.kind == Kind::discard) {
        if (const geom::Status st = scene::discard_recovery(step.path); !st.ok())
            ctx.ui.status = st.error().message;
        ui::files::keep_recovery();
    }
}

void WindowLoop::autosave_now() {
    ui::AppContext& ctx = workstation_.context();
    const std::string path = scene::normalized_scene_path(ctx.file_path);
    if (!autosaving_ || !ctx.dirty() || timer_.held(path)) return;
    const std::uint64_t fingerprint = scene::document_fingerprint(ctx.doc);
    if (scene::write_recovery(ctx.doc, path).ok()) {
        timer_.wrote(path, fingerprint);
        ui::files::keep_recovery();
    }
}

void WindowLoop::finish() {
    if (!autosaving_) return;
    if (const std::optional<std::string> p = timer_.on_exit()) {
        scene::discard_recovery(*p);
        ui::files::keep_recovery();
    }
}

} // namespace isoparm::app
