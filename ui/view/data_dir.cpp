// The program's own files (see data_dir.hpp).
#include "ui/view/data_dir.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace isoparm::ui {

namespace fs = std::filesystem;

std::string examples_dir() {
    std::error_code ec;
    // Linux names the running executable here, whatever the working directory or PATH.
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path installed = exe.parent_path().parent_path() / "share/isoparm/scenes";
        if (fs::is_directory(installed, ec)) return installed.string();
    }
#ifdef ISOPARM_SOURCE_DIR
    const fs::path source = fs::path(ISOPARM_SOURCE_DIR) / "assets/scenes";
    if (fs::is_directory(source, ec)) return source.string();
#endif
    return {};
}

std::vector<std::string> example_scenes() {
    std::vector<std::string> out;
    const std::string dir = examples_dir();
    if (dir.empty()) return out;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
        if (it->path().extension() == ".json") out.push_back(it->path().string());
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace isoparm::ui
