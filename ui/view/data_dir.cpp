// The program's own files (see data_dir.hpp).
#include "ui/view/data_dir.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace isoparm::ui {

namespace fs = std::filesystem;

namespace {

// PREFIX of the running PREFIX/bin/isoparm, or "" where Linux does not say.
fs::path installed_prefix() {
    std::error_code ec;
    // Linux names the running executable here, whatever the working directory or PATH.
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path() : exe.parent_path().parent_path();
}

} // namespace

std::string examples_dir() {
    std::error_code ec;
    if (const fs::path prefix = installed_prefix(); !prefix.empty()) {
        const fs::path installed = prefix / "share/isoparm/scenes";
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

std::string module_file(const std::string& file) {
    std::error_code ec;
    if (const fs::path prefix = installed_prefix(); !prefix.empty()) {
        const fs::path installed = prefix / "lib/isoparm" / file;
        if (fs::is_regular_file(installed, ec)) return installed.string();
    }
#ifdef ISOPARM_MODULE_DIR
    const fs::path built = fs::path(ISOPARM_MODULE_DIR) / file;
    if (fs::is_regular_file(built, ec)) return built.string();
#endif
    return {};
}

std::string module_dir_hint() {
    const fs::path prefix = installed_prefix();
    const std::string installed =
        (prefix.empty() ? std::string("PREFIX") : prefix.string()) + "/lib/isoparm";
    std::string hint = "looked in " + installed;
#ifdef ISOPARM_MODULE_DIR
    if (installed != ISOPARM_MODULE_DIR) hint += " and " + std::string(ISOPARM_MODULE_DIR);
#endif
    return hint;
}

} // namespace isoparm::ui
