// Entry point of `isoparm`: dispatches to the workstation, `render`, `script`, `figure`,
// `animate`, `geom`, `export` or `import`.
#include <CLI/CLI.hpp>
#include <iostream>

#include "app/commands.hpp"
#include "core/scene/atomic_file.hpp"
#ifdef ISOPARM_HAVE_OCCT
#include "core/exchange_occt/occt_reader.hpp"
#endif

int main(int argc, char** argv) {
    // A file-size limit (ulimit -f) must be an error a write reports, not a signal that kills
    // the program halfway through a save and leaves its temporary file behind.
    isoparm::scene::make_file_size_limit_an_error();
#ifdef ISOPARM_HAVE_OCCT
    // IGES and STEP import (isoparm import, File > Import, the `import` op) read through OCCT.
    isoparm::exchange_occt::install();
#endif
    CLI::App app{"isoparm: an interactive workstation for learning and designing NURBS surfaces"};
    app.set_version_flag("--version", "isoparm " ISOPARM_VERSION);
    const isoparm::app::Action geom = isoparm::app::register_geom_command(app);
    const isoparm::app::Action export_scene = isoparm::app::register_export_command(app);
    const isoparm::app::Action import_file = isoparm::app::register_import_command(app);
    const isoparm::app::Action check = isoparm::app::register_check_command(app);
#ifdef ISOPARM_HAVE_GUI
    const isoparm::app::Action render = isoparm::app::register_render_command(app);
    const isoparm::app::Action gui = isoparm::app::register_gui_command(app);
    const isoparm::app::Action examples = isoparm::app::register_examples_command(app);
    const isoparm::app::Action script = isoparm::app::register_script_command(app);
    const isoparm::app::Action figure = isoparm::app::register_figure_command(app);
    const isoparm::app::Action animate = isoparm::app::register_animate_command(app);
#endif
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help and --version end here with 0; everything else is bad input: the message
        // (which names the option and the value) and exit 2, as every subcommand's refusals.
        const int status = app.exit(e);
        return status == 0 ? 0 : 2;
    }
    for (CLI::App* sub : app.get_subcommands()) {
        if (sub->get_name() == "geom") return geom();
        if (sub->get_name() == "export") return export_scene();
        if (sub->get_name() == "import") return import_file();
        if (sub->get_name() == "check") return check();
#ifdef ISOPARM_HAVE_GUI
        if (sub->get_name() == "render") return render();
        if (sub->get_name() == "examples") return examples();
        if (sub->get_name() == "script") return script();
        if (sub->get_name() == "figure") return figure();
        if (sub->get_name() == "animate") return animate();
#endif
    }
#ifdef ISOPARM_HAVE_GUI
    return gui();
#else
    std::cerr << "isoparm: built without the workstation (ISOPARM_GUI=OFF); try 'isoparm geom'\n";
    return 2;
#endif
}
