// The workstation's own settings (layout, recent files, window size per monitor size),
// remembered between runs in $XDG_CONFIG_HOME/isoparm/settings.json when XDG_CONFIG_HOME is an
// absolute path (the XDG specification ignores relative ones), else
// ~/.config/isoparm/settings.json.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ui/view/layout.hpp"
#include "ui/view/window_placement.hpp"

namespace isoparm::ui {

constexpr std::size_t max_recent_files = 10;

struct Settings {
    LayoutPrefs layout;
    std::vector<std::string> recent; // most recent first
    WindowSizes window_sizes;        // per monitor work-area size
    bool operator==(const Settings&) const = default;
};

// The directory from the environment values (either may be null or empty; a relative
// XDG_CONFIG_HOME is ignored); "" when neither gives one, in which case nothing is remembered.
std::string config_dir_from(const char* xdg_config_home, const char* home);
std::string config_dir();    // from the real environment
std::string settings_path(); // config_dir() + "/settings.json", or ""

nlohmann::json settings_to_json(const Settings& s);
// Tolerant: a missing or wrong value keeps its default (settings must never stop start-up).
Settings settings_from_json(const nlohmann::json& j);
Settings load_settings(const std::string& path);
// Creates the directory and writes through scene::write_file_atomically (temporary file, fsync,
// rename); false when it could not.
bool save_settings(const Settings& s, const std::string& path);

// Moves `path` to the front, removing duplicates, keeping at most `max` entries.
void add_recent(std::vector<std::string>& recent, const std::string& path,
                std::size_t max = max_recent_files);

} // namespace isoparm::ui
