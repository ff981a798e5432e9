// Where the program's own files are (the example scenes, its modules): beside the installed
// executable (PREFIX/bin/isoparm -> PREFIX/share/isoparm, PREFIX/lib/isoparm), so an installed
// or unpacked package finds its files wherever its prefix is; a program run from its build
// tree uses the source tree's scenes and the build tree's modules.
#pragma once

#include <string>
#include <vector>

namespace isoparm::ui {

// The folder of example scenes; "" when neither place exists.
std::string examples_dir();
// The example scenes (*.json) in that folder, sorted by name, as full paths.
std::vector<std::string> example_scenes();

// The full path of the module `file` (a shared object the program loads when it needs it,
// e.g. libisoparm_video.so), or "" when it is in neither place.
std::string module_file(const std::string& file);
// Where module_file looks, for a message that it found nothing.
std::string module_dir_hint();

} // namespace isoparm::ui
