// `isoparm render [SCENE] -o OUT.png`: the workstation or its 3D view as a PNG, through EGL
// on Mesa's surfaceless platform (no display needed), with the same code as the window.
#include <iostream>
#include <memory>
#include <regex>

#include "app/commands.hpp"
#include "ui/headless/headless_render.hpp"

namespace isoparm::app {

namespace {

struct RenderOptions {
    std::string scene;
    std::string output;
    std::string size = "1280x800";
    std::string view = "workstation";
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
    return [o]() -> int {
        ui::HeadlessRequest req;
        req.scene_path = o->scene;
        req.output = o->output;
        static const std::regex size_re(R"(^(\d{1,5})x(\d{1,5})$)");
        std::smatch m;
        if (!std::regex_match(o->size, m, size_re)) {
            std::cerr << "isoparm render: --size '" << o->size << "' must be WxH, e.g. 1280x800\n";
            return 2;
        }
        req.width = std::stoi(m[1]);
        req.height = std::stoi(m[2]);
        req.view = o->view == "3d" ? ui::ViewMode::view3d_only : ui::ViewMode::workstation;
        const std::string error = ui::render_headless(req);
        if (!error.empty()) {
            std::cerr << "isoparm render: " << error << "\n";
            return 1;
        }
        return 0;
    };
}

} // namespace isoparm::app
