// Lessons and exercises on disk (course_files.hpp).
#include "ui/view/course_files.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "core/json/input_file.hpp"
#include "core/json/reader.hpp"
#include "ui/view/data_dir.hpp"

namespace isoparm::ui {

namespace fs = std::filesystem;

namespace {

// A lesson is small; a file much larger is not one (and is not read to build a menu).
constexpr std::uintmax_t max_listed_bytes = 8u << 20;

std::string shipped_dir(const char* name) {
    const std::string scenes = examples_dir(); // PREFIX/share/isoparm/scenes or assets/scenes
    if (scenes.empty()) return {};
    std::error_code ec;
    const fs::path dir = fs::path(scenes).parent_path() / name;
    return fs::is_directory(dir, ec) ? dir.string() : std::string();
}

std::string title_from_name(const fs::path& p) {
    std::string t = p.stem().string();
    std::replace(t.begin(), t.end(), '-', ' ');
    std::replace(t.begin(), t.end(), '_', ' ');
    if (!t.empty()) t[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(t[0])));
    return t;
}

} // namespace

std::string shipped_lessons_dir() {
    return shipped_dir("lessons");
}

std::string shipped_exercises_dir() {
    return shipped_dir("exercises");
}

std::string user_lessons_dir_from(const char* xdg_data_home, const char* home) {
    if (xdg_data_home && xdg_data_home[0] == '/')
        return std::string(xdg_data_home) + "/isoparm/lessons";
    if (home && *home) return std::string(home) + "/.local/share/isoparm/lessons";
    return {};
}

std::string user_lessons_dir() {
    return user_lessons_dir_from(std::getenv("XDG_DATA_HOME"), std::getenv("HOME"));
}

std::vector<CourseEntry> list_course_files(const std::string& dir, const std::string& format) {
    std::vector<CourseEntry> out;
    if (dir.empty()) return out;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path p = it->path();
        std::error_code e2;
        if (p.extension() != ".json" || !it->is_regular_file(e2)) continue;
        auto text = json_io::read_input_file(p.string(), max_listed_bytes);
        if (!text) continue;
        auto read = json_io::read_json(*text);
        if (!read || !read->value.is_object()) continue;
        const nlohmann::json& j = read->value;
        if (j.value("format", nlohmann::json()) != format) continue;
        CourseEntry e;
        e.path = p.string();
        const auto text_of = [&](const char* key) {
            const auto m = j.find(key);
            return m != j.end() && m->is_string() ? m->get<std::string>() : std::string();
        };
        e.title = text_of("title");
        if (e.title.empty()) e.title = title_from_name(p);
        e.summary = text_of("summary");
        out.push_back(std::move(e));
    }
    std::sort(out.begin(), out.end(),
              [](const CourseEntry& a, const CourseEntry& b) { return a.path < b.path; });
    return out;
}

std::string lesson_dialog_dir() {
    const std::string mine = user_lessons_dir();
    if (!mine.empty() && !list_lessons(mine).empty()) return mine;
    return shipped_lessons_dir();
}

} // namespace isoparm::ui
