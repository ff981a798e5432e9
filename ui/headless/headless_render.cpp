// Headless rendering: EGL context, Workstation frames into an FBO, read back, PNG.
#include "ui/headless/headless_render.hpp"

#include <vector>

#include "core/scene/atomic_file.hpp"
#include "core/scene/scene_io.hpp"
#include "ui/headless/egl_context.hpp"
#include "ui/headless/frame_capture.hpp"
#include "ui/image/png_writer.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/scene_budget.hpp"

namespace isoparm::ui {

namespace {

// The workstation drawn with `document` into a framebuffer of the request's size, read back
// and written as a PNG to `output`; needs a current GL context.
std::string draw_to_png(doc::Document document, const std::string& scene_path,
                        const HeadlessRequest& req, const std::string& output) {
    std::optional<Pixels> picture;
    {
        CaptureSettings settings;
        settings.width = req.width;
        settings.height = req.height;
        settings.view = req.view;
        settings.scale = req.scale;
        settings.transparent = req.transparent;
        FrameCapture capture(settings);
        if (!capture.error().empty()) return capture.error();
        AppContext& ctx = capture.context();
        ctx.doc = std::move(document);
        ctx.file_path = scene_path;
        normalize_selection(ctx.doc);
        ctx.history.mark_clean();
        if (req.configure) {
            // Options that do not fit the scene stop here: no PNG is written.
            if (std::string problem = req.configure(ctx); !problem.empty()) return problem;
        }
        std::string error;
        picture = capture.capture(error);
        if (!picture) return error;
        if (req.rendered) req.rendered(ctx);
    }
    return write_png(output, picture->width, picture->height, picture->rgba);
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
