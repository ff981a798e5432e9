// Where lessons and exercises are and what each is called: the shipped ones beside the
// program (PREFIX/share/isoparm/lessons and .../exercises, or the source tree's assets), the
// user's own in $XDG_DATA_HOME/isoparm/lessons (~/.local/share/isoparm/lessons), each with
// the title and one-line summary its file gives (the Lessons menu's entries).
#pragma once

#include <string>
#include <vector>

namespace isoparm::ui {

// The shipped lessons' and exercises' folders; "" when neither place exists.
std::string shipped_lessons_dir();
std::string shipped_exercises_dir();
// The user's lessons folder (it may not exist yet): XDG_DATA_HOME when it is an absolute path
// (the XDG Base Directory rule), else HOME/.local/share; "" when neither is set.
std::string user_lessons_dir();
std::string user_lessons_dir_from(const char* xdg_data_home, const char* home);

struct CourseEntry {
    std::string path;
    std::string title;   // the file's "title", else its name with dashes as spaces
    std::string summary; // the file's "summary", else ""
};

// The *.json files of `dir` with their titles and summaries, sorted by file name. A file that
// is not JSON, or not of the format asked for ("isoparm-script" or "isoparm-exercise"), is
// left out: the menu lists only what opens.
std::vector<CourseEntry> list_course_files(const std::string& dir, const std::string& format);
inline std::vector<CourseEntry> list_lessons(const std::string& dir) {
    return list_course_files(dir, "isoparm-script");
}
inline std::vector<CourseEntry> list_exercises(const std::string& dir) {
    return list_course_files(dir, "isoparm-exercise");
}

// Where File > Open lesson starts: the user's lessons when that folder holds any, else the
// shipped ones, else "".
std::string lesson_dialog_dir();

} // namespace isoparm::ui
