// `isoparm render [SCENE] -o OUT.png`: the workstation or its 3D view as a PNG, through EGL
// on Mesa's surfaceless platform (no display needed), with the same code as the window.
#include <iostream>
#include <memory>
#include <string>

#include "app/commands.hpp"
#include "app/view_options.hpp"
#include "core/json/out_of_memory.hpp"
#include "ui/app_context.hpp"
#include "ui/headless/headless_render.hpp"

namespace isoparm::app {

namespace {

struct RenderOptions {
    std::string scene;
    std::string output;
    std::string size = "1280x800";
    std::string view = "workstation";
    bool transparent = false;
    ViewOptions view_options;
};

} // namespace

Action register_render_command(CLI::App& app) {
    CLI::App* sub = app.add_subcommand(
        "render", "Render a scene to a PNG without a display (EGL, Mesa surfaceless)");
    auto o = std::make_shared<RenderOptions>();
    sub->add_option("SCENE", o->scene, "scene file (default: the welcoming default scene)");
    sub->add_option("-o,--output", o->output, "the PNG to write")->required();
    sub->add_option("--size", o->size, "picture size WxH (default 1280x800)");
    sub->add_option("--view", o->view, "workstation (all panels) or 3d (the 3D view alone)")
        ->check(CLI::IsMember({"workstation", "3d"}));
    add_view_options(sub, o->view_options);
    sub->add_flag("--transparent", o->transparent,
                  "leave the background transparent (alpha 0) instead of the scene's colour");
    return [o]() -> int {
        ui::HeadlessRequest req;
        req.scene_path = o->scene;
        req.output = o->output;
        const auto size = picture_size(o->size);
        if (!size) {
            std::cerr << "isoparm render: --size '" << o->size
                      << "' must be WxH between 16x16 and 8192x8192, e.g. 1280x800\n";
            return 2;
        }
        req.width = size->first;
        req.height = size->second;
        req.view = o->view == "3d" ? ui::ViewMode::view3d_only : ui::ViewMode::workstation;
        req.configure = [o](ui::AppContext& ctx) {
            return apply_view_options(o->view_options, ctx);
        };
        req.transparent = o->transparent;
        std::string error;
        json_io::arm_memory_reserve(); // see out_of_memory.hpp: unwinding must find memory
        try {
            error = ui::render_headless(req);
        } catch (const std::bad_alloc&) {
            error = std::string(json_io::out_of_memory_message) + " (rendering '" +
                    (o->scene.empty() ? std::string("the default scene") : o->scene) + "')";
        }
        if (!error.empty()) {
            std::cerr << "isoparm render: " << error << "\n";
            return 1;
        }
        return 0;
    };
}

} // namespace isoparm::app
