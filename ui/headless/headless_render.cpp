// Headless rendering: EGL context, Workstation frames into an FBO, read back, PNG.
#include "ui/headless/headless_render.hpp"

#include <cfloat>
#include <cstring>
#include <imgui.h>
#include <vector>

#include "core/scene/atomic_file.hpp"
#include "core/scene/scene_io.hpp"
#include "ui/headless/egl_context.hpp"
#include "ui/headless/offscreen_target.hpp"
#include "ui/image/png_writer.hpp"
#include "ui/render/gl.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/scene_budget.hpp"
#include "ui/workstation.hpp"

namespace isoparm::ui {

namespace {

// The workstation drawn with `document` into a framebuffer of the request's size, read back
// and written as a PNG to `output`; needs a current GL context.
std::string draw_to_png(doc::Document document, const std::string& scene_path,
                        const HeadlessRequest& req, const std::string& output) {
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(req.width) * req.height * 4);
    {
        OffscreenTarget target(req.width, req.height);
        if (!target.complete())
            return "cannot create a " + std::to_string(req.width) + "x" +
                   std::to_string(req.height) + " framebuffer";
        Workstation ws({/*headless=*/true, req.scale, req.view, /*msaa_samples=*/4, {}});
        if (!ws.renderer_error().empty()) return "shaders failed: " + ws.renderer_error();
        AppContext& ctx = ws.context();
        ctx.doc = std::move(document);
        ctx.file_path = scene_path;
        normalize_selection(ctx.doc);
        ctx.history.mark_clean();
        if (req.configure) {
            // Options that do not fit the scene stop here: no PNG is written.
            if (std::string problem = req.configure(ctx); !problem.empty()) return problem;
        }

        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(static_cast<float>(req.width), static_cast<float>(req.height));
        io.DisplayFramebufferScale = ImVec2(1, 1);
        io.DeltaTime = 1.0f / 60.0f;
        io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
        // Two frames: the first settles layout-dependent sizes (menu bar, tables, camera fit).
        for (int f = 0; f < 2; ++f) ws.frame(target.fbo());
        if (req.rendered) req.rendered(ctx);

        while (glGetError() != GL_NO_ERROR) {
        } // only the read-back's own errors count below
        glBindFramebuffer(GL_READ_FRAMEBUFFER, target.fbo());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, req.width, req.height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (glGetError() != GL_NO_ERROR) return "reading the picture back failed";
    }
    // OpenGL's first row is the bottom: flip, and make the picture opaque.
    const std::size_t row = static_cast<std::size_t>(req.width) * 4;
    std::vector<std::uint8_t> flipped(pixels.size());
    for (int y = 0; y < req.height; ++y)
        std::memcpy(&flipped[static_cast<std::size_t>(y) * row],
                    &pixels[static_cast<std::size_t>(req.height - 1 - y) * row], row);
    for (std::size_t k = 3; k < flipped.size(); k += 4) flipped[k] = 255;
    return write_png(output, req.width, req.height, flipped);
}

} // namespace

std::string render_headless(const HeadlessRequest& req) {
    if (req.width < 16 || req.height < 16 || req.width > 8192 || req.height > 8192)
        return "the size " + std::to_string(req.width) + "x" + std::to_string(req.height) +
               " is outside 16x16 .. 8192x8192";
    // The output before anything else: a directory, a device or the scene itself as output is
    // refused before any work (and the scene is never overwritten by its own picture).
    if (const geom::Status usable = scene::check_output_path(req.output); !usable)
        return usable.error().message;
    if (const geom::Status distinct =
            scene::check_output_is_not_input(req.output, {req.scene_path});
        !distinct)
        return distinct.error().message;
    // Load first: a bad scene should not cost a GL context.
    doc::Document document = doc::default_document();
    if (!req.scene_path.empty()) {
        geom::Expected<doc::Document> loaded = scene::load_scene(req.scene_path);
        if (!loaded.ok()) {
            const geom::Error& e = loaded.error();
            const std::string where = e.has_path && !e.path.empty() ? " (at " + e.path + ")" : "";
            // The file name once: the loader's message may already carry it.
            if (e.message.find(req.scene_path) != std::string::npos)
                return "cannot load the scene: " + e.message + where;
            return "cannot load '" + req.scene_path + "': " + e.message + where;
        }
        document = std::move(loaded).value();
    }
    // A scene that would take minutes or gigabytes to show is refused like a bad one.
    if (std::string too_large = scene_over_budget(document); !too_large.empty())
        return req.scene_path.empty() ? too_large : "'" + req.scene_path + "': " + too_large;
    // Under `ulimit -v`, a render that cannot fit is refused before the driver would crash.
    if (std::string short_of = memory_limit_problem(document, display_driver_bytes);
        !short_of.empty())
        return short_of;

    std::string error;
    const std::unique_ptr<EglContext> egl = EglContext::create(error);
    if (!egl) return "no headless OpenGL: " + error;
    return draw_to_png(std::move(document), req.scene_path, req, req.output);
}

std::unique_ptr<HeadlessSession> HeadlessSession::create(std::string& error) {
    std::unique_ptr<EglContext> egl = EglContext::create(error);
    if (!egl) {
        error = "no headless OpenGL: " + error;
        return nullptr;
    }
    return std::unique_ptr<HeadlessSession>(new HeadlessSession(std::move(egl)));
}

HeadlessSession::HeadlessSession(std::unique_ptr<EglContext> egl) : egl_(std::move(egl)) {}
HeadlessSession::~HeadlessSession() = default;

std::string HeadlessSession::render(doc::Document document, const HeadlessRequest& req) {
    if (req.width < 16 || req.height < 16 || req.width > 8192 || req.height > 8192)
        return "the size " + std::to_string(req.width) + "x" + std::to_string(req.height) +
               " is outside 16x16 .. 8192x8192";
    if (const geom::Status usable = scene::check_output_path(req.output); !usable)
        return usable.error().message;
    if (std::string too_large = scene_over_budget(document); !too_large.empty()) return too_large;
    // The driver is loaded: what is left to fit is the scene (see render_headless).
    if (std::string short_of = memory_limit_problem(document, 0); !short_of.empty())
        return short_of;
    return draw_to_png(std::move(document), req.scene_path, req, req.output);
}

} // namespace isoparm::ui
