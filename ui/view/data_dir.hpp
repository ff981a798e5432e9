// Where the program's own files are (the example scenes): beside the installed executable
// (PREFIX/bin/isoparm -> PREFIX/share/isoparm), so an installed or unpacked package finds its
// files wherever its prefix is; a program run from its build tree uses the source tree's.
#pragma once

#include <string>
#include <vector>

namespace isoparm::ui {

// The folder of example scenes; "" when neither place exists.
std::string examples_dir();
// The example scenes (*.json) in that folder, sorted by name, as full paths.
std::vector<std::string> example_scenes();

} // namespace isoparm::ui
