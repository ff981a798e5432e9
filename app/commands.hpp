// Subcommand registration: each subcommand of `isoparm` lives in its own file.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace isoparm::app {

// Each returns the action to run when its subcommand was chosen (an exit status).
using Action = std::function<int()>;
Action register_geom_command(CLI::App& app);
Action register_export_command(CLI::App& app);
Action register_import_command(CLI::App& app);
Action register_check_command(CLI::App& app);    // grading exercises: core only
Action register_render_command(CLI::App& app);   // ISOPARM_GUI only
Action register_gui_command(CLI::App& app);      // ISOPARM_GUI only: the default with no subcommand
Action register_examples_command(CLI::App& app); // ISOPARM_GUI only
Action register_script_command(CLI::App& app);   // ISOPARM_GUI only
Action register_figure_command(CLI::App& app);   // ISOPARM_GUI only
Action register_animate_command(CLI::App& app);  // ISOPARM_GUI only

} // namespace isoparm::app
