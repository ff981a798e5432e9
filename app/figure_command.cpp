// `isoparm figure SCENE --view VIEW -o FILE.svg|pdf|tex|png`: a teaching view as a figure for
// slides and notes (ui/view/figures.hpp), written as SVG, PDF, TikZ or PNG
// (ui/figure/drawing_files.hpp). The 3D view needs EGL for its camera fit and its shaded raster.
#include <iostream>
#include <memory>
#include <string>

#include "app/command_run.hpp"
#include "app/commands.hpp"
#include "app/view_options.hpp"
#include "core/json/out_of_memory.hpp"
#include "core/scene/atomic_file.hpp"
#include "core/scene/scene_io.hpp"
#include "ui/app_context.hpp"
#include "ui/figure/drawing_files.hpp"
#include "ui/headless/egl_context.hpp"
#include "ui/headless/view3d_figure_capture.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/figures.hpp"
#include "ui/view/scene_budget.hpp"

namespace isoparm::app {

namespace {

struct FigureCommandOptions {
    std::string scene, output, view, size, direction = "u";
    double font_size = 9, t = 0.4, scale = 2;
    int level = -1;
    bool no_comb = false, no_frenet = false, transparent = false, no_raster = false;
    bool from_panel = false;
    ViewOptions view_options;
};

const char* const name = "isoparm figure: ";

int run(const FigureCommandOptions& o) {
    if (!ui::drawing_format_of(o.output)) {
        std::cerr << name << "-o '" << o.output
                  << "' must end in .svg, .pdf, .tex (TikZ) or .png\n";
        return 2;
    }
    const bool three_d = o.view == "3d";
    const auto size = picture_size(o.size.empty() ? (three_d ? "480x360" : "360x300") : o.size);
    if (!size) {
        std::cerr << name << "--size '" << o.size
                  << "' must be WxH in points between 16x16 and 8192x8192, e.g. 360x300\n";
        return 2;
    }
    geom::Status usable = scene::check_output_path(o.output);
    if (usable) usable = scene::check_output_is_not_input(o.output, {o.scene});
    if (!usable) {
        std::cerr << name << usable.error().message << "\n";
        return 2;
    }
    ui::AppContext ctx;
    ctx.doc = doc::default_document();
    if (!o.scene.empty()) {
        geom::Expected<doc::Document> loaded = scene::load_scene(o.scene);
        if (!loaded) {
            std::cerr << name << "cannot load '" << o.scene << "': " << loaded.error().message
                      << "\n";
            return 2;
        }
        ctx.doc = std::move(loaded).value();
    }
    if (std::string too_large = ui::scene_over_budget(ctx.doc); !too_large.empty()) {
        std::cerr << name << too_large << "\n";
        return 2;
    }
    ui::normalize_selection(ctx.doc);
    if (std::string problem = apply_view_options(o.view_options, ctx); !problem.empty()) {
        std::cerr << name << problem << "\n";
        return 2;
    }
    ui::FigureOptions fo;
    fo.width = size->first;
    fo.height = size->second;
    fo.font_size = o.font_size;
    fo.t = o.t;
    fo.direction = o.direction == "v" ? geom::Dir::v : geom::Dir::u;
    fo.comb = !o.no_comb;
    fo.frenet = !o.no_frenet;
    fo.deboor_level = o.level;
    fo.transparent = o.transparent;
    if (!o.view_options.camera.empty())
        if (const auto c = numbers(o.view_options.camera, 2, 3)) {
            fo.yaw = (*c)[0];
            fo.pitch = (*c)[1];
        }
    geom::Expected<ui::Drawing> drawing = geom::make_error_nopath(geom::ErrorCode::internal, "");
    if (three_d) {
        // EGL for the camera fit and the shaded raster.
        std::string error;
        const std::unique_ptr<ui::EglContext> egl = ui::EglContext::create(error);
        if (!egl) {
            std::cerr << name << "no headless OpenGL: " << error << "\n";
            return 1;
        }
        drawing = ui::capture_view3d_figure(ctx, fo, o.scale, !o.no_raster);
    } else {
        const auto view = geom::parse_name<ui::FigureView>(o.view);
        if (o.from_panel) {
            // The panel's own Picture, from a headless frame of the workstation.
            std::string error;
            const std::unique_ptr<ui::EglContext> egl = ui::EglContext::create(error);
            if (!egl) {
                std::cerr << name << "no headless OpenGL: " << error << "\n";
                return 1;
            }
            auto panel = ui::capture_panel_figure(ctx, *view, 1280, 800, 1, error);
            if (!panel) {
                std::cerr << name << error << "\n";
                return 2;
            }
            drawing = std::move(*panel);
        } else {
            drawing = ui::make_figure(ctx.doc, *view, fo);
        }
    }
    if (!drawing) {
        std::cerr << name << drawing.error().message << "\n";
        return 2;
    }
    if (std::string problem = ui::write_drawing(*drawing, o.output, o.scale); !problem.empty()) {
        std::cerr << name << problem << "\n";
        return 1;
    }
    return 0;
}

} // namespace

Action register_figure_command(CLI::App& app) {
    CLI::App* sub = app.add_subcommand(
        "figure", "A teaching view as a figure for slides and notes: SVG, PDF, TikZ or PNG");
    auto o = std::make_shared<FigureCommandOptions>();
    sub->add_option("SCENE", o->scene, "scene file (default: the welcoming default scene)");
    sub->add_option("--view", o->view, "tracing, basis, curve, deboor, homogeneous, blossom or 3d")
        ->required()
        ->check(
            CLI::IsMember({"tracing", "basis", "curve", "deboor", "homogeneous", "blossom", "3d"}));
    sub->add_option("-o,--output", o->output,
                    "the figure: .svg, .pdf, .tex (a TikZ picture) or .png")
        ->required();
    sub->add_option("--size", o->size, "page size WxH in points (default 360x300; 3d: 480x360)");
    sub->add_option("--font-size", o->font_size, "label size in points (default 9)")
        ->check(CLI::Range(4.0, 72.0));
    sub->add_option("--t", o->t,
                    "the curve views' parameter, 0..1 over the curve's domain (default 0.4)")
        ->check(CLI::Range(0.0, 1.0));
    sub->add_option("--direction", o->direction, "the basis view's direction on a surface: u or v")
        ->check(CLI::IsMember({"u", "v"}));
    sub->add_option("--level", o->level,
                    "the deboor view: its construction up to this level (default: all)")
        ->check(CLI::Range(0, 64));
    sub->add_flag("--no-comb", o->no_comb, "the curve view without its curvature comb");
    sub->add_flag("--no-frenet", o->no_frenet, "the curve view without its Frenet frame");
    sub->add_option("--scale", o->scale,
                    "PNG pixels per point, and the 3D raster's resolution (1..4, default 2)")
        ->check(CLI::Range(1.0, 4.0));
    sub->add_flag("--transparent", o->transparent, "no background");
    sub->add_flag("--from-panel", o->from_panel,
                  "the 2D view as its panel draws it in the window (its Picture), not the figure "
                  "in print colours");
    sub->add_flag("--no-raster", o->no_raster,
                  "3d: the lines alone, without the shaded surfaces' raster under them");
    add_view_options(sub, o->view_options);
    return [o]() -> int { return run_memory_guarded([&o] { return run(*o); }, name); };
}

} // namespace isoparm::app
