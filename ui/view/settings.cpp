// Settings file: JSON read tolerantly, written atomically.
#include "ui/view/settings.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "core/json/input_file.hpp"
#include "core/scene/atomic_file.hpp"

namespace isoparm::ui {

namespace fs = std::filesystem;

// Settings are a few hundred bytes; anything much larger is not ours.
constexpr std::uintmax_t settings_max_bytes = 1u << 20;

std::string config_dir_from(const char* xdg, const char* home) {
    // The XDG Base Directory specification says a relative value is invalid and ignored.
    if (xdg && xdg[0] == '/') return std::string(xdg) + "/isoparm";
    if (home && *home) return std::string(home) + "/.config/isoparm";
    return {};
}

std::string config_dir() {
    return config_dir_from(std::getenv("XDG_CONFIG_HOME"), std::getenv("HOME"));
}

std::string settings_path() {
    const std::string dir = config_dir();
    return dir.empty() ? std::string{} : dir + "/settings.json";
}

nlohmann::json settings_to_json(const Settings& s) {
    return {
        {"layout",
         {{"left_width", s.layout.left_width},
          {"right_width", s.layout.right_width},
          {"left_shares", s.layout.left_shares},
          {"right_shares", s.layout.right_shares},
          {"presentation_left", s.layout.presentation_left},
          {"presentation_right", s.layout.presentation_right}}},
        {"recent", s.recent},
        {"window_sizes", s.window_sizes},
    };
}

namespace {
template <class T> void read(const nlohmann::json& j, const char* key, T& out) {
    if (!j.is_object() || !j.contains(key)) return;
    try {
        out = j.at(key).get<T>();
    } catch (const nlohmann::json::exception&) {
        // Keep the default: a hand-edited settings file must not stop the program.
    }
}
} // namespace

Settings settings_from_json(const nlohmann::json& j) {
    Settings s;
    if (!j.is_object()) return s;
    if (j.contains("layout")) {
        const nlohmann::json& l = j["layout"];
        read(l, "left_width", s.layout.left_width);
        read(l, "right_width", s.layout.right_width);
        read(l, "left_shares", s.layout.left_shares);
        read(l, "right_shares", s.layout.right_shares);
        read(l, "presentation_left", s.layout.presentation_left);
        read(l, "presentation_right", s.layout.presentation_right);
        s.layout = sanitize(s.layout);
    }
    std::vector<std::string> recent;
    read(j, "recent", recent);
    for (const std::string& r : recent)
        if (!r.empty() && s.recent.size() < max_recent_files) s.recent.push_back(r);
    WindowSizes sizes;
    read(j, "window_sizes", sizes);
    for (const auto& [key, size] : sizes)
        if (size[0] >= min_window_width && size[0] <= 16384 && size[1] >= min_window_height &&
            size[1] <= 16384)
            s.window_sizes[key] = size;
    return s;
}

Settings load_settings(const std::string& path) {
    if (path.empty()) return {};
    // Read like every input: a FIFO or a directory in its place must not block start-up.
    auto text = json_io::read_input_file(path, settings_max_bytes);
    if (!text) return {};
    const nlohmann::json j = nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded()) return {};
    return settings_from_json(j);
}

bool save_settings(const Settings& s, const std::string& path) {
    if (path.empty()) return false;
    std::error_code ec;
    const fs::path target(path);
    if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
    return scene::write_file_atomically(path, settings_to_json(s).dump(2) + "\n").ok();
}

void add_recent(std::vector<std::string>& recent, const std::string& path, std::size_t max) {
    recent.erase(std::remove(recent.begin(), recent.end(), path), recent.end());
    recent.insert(recent.begin(), path);
    if (recent.size() > max) recent.resize(max);
}

} // namespace isoparm::ui
