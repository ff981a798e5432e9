// `isoparm examples`: where the example scenes are (installed beside the program, or in the
// source tree of a build), one path a line, to open or render.
#include <iostream>

#include "app/commands.hpp"
#include "ui/view/data_dir.hpp"

namespace isoparm::app {

Action register_examples_command(CLI::App& app) {
    app.add_subcommand("examples",
                       "List the example scenes (the paper's figures), one path a line");
    return []() -> int {
        const std::vector<std::string> scenes = ui::example_scenes();
        if (scenes.empty()) {
            std::cerr << "isoparm examples: no example scenes found beside the program "
                         "(PREFIX/share/isoparm/scenes)\n";
            return 1;
        }
        for (const std::string& s : scenes) std::cout << s << "\n";
        return 0;
    };
}

} // namespace isoparm::app
