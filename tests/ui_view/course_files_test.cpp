// The Lessons menu's entries: the shipped lessons and exercises with their titles and
// summaries, the user's lessons folder by the XDG rule, and files that would not open left out.
#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/temp_dir.hpp"
#include "ui/view/course_files.hpp"

namespace isoparm::ui {
namespace {

TEST(CourseFiles, EveryShippedLessonAndExerciseHasATitleAndASummary) {
    const std::vector<CourseEntry> lessons = list_lessons(shipped_lessons_dir());
    EXPECT_GE(lessons.size(), 14u);
    for (const CourseEntry& e : lessons) {
        EXPECT_FALSE(e.title.empty()) << e.path;
        EXPECT_FALSE(e.summary.empty()) << e.path << ": the menu shows a one-line summary";
        EXPECT_LE(e.summary.size(), 60u) << e.path << ": a summary fits one menu line";
        EXPECT_EQ(e.summary.find('\n'), std::string::npos) << e.path;
    }
    const std::vector<CourseEntry> exercises = list_exercises(shipped_exercises_dir());
    EXPECT_GE(exercises.size(), 8u);
    for (const CourseEntry& e : exercises) EXPECT_FALSE(e.summary.empty()) << e.path;
}

TEST(CourseFiles, TheUsersFolderFollowsXdgDataHome) {
    EXPECT_EQ(user_lessons_dir_from("/data", "/home/a"), "/data/isoparm/lessons");
    // A relative XDG_DATA_HOME is invalid (XDG Base Directory) and ignored.
    EXPECT_EQ(user_lessons_dir_from("data", "/home/a"), "/home/a/.local/share/isoparm/lessons");
    EXPECT_EQ(user_lessons_dir_from(nullptr, "/home/a"), "/home/a/.local/share/isoparm/lessons");
    EXPECT_EQ(user_lessons_dir_from(nullptr, nullptr), "");
}

TEST(CourseFiles, FilesThatAreNotLessonsAreLeftOutAndTitlesDefaultToTheName) {
    test::TempDir tmp("isoparm-course-files");
    std::ofstream(tmp.path("my-first-lesson.json"))
        << R"({"format": "isoparm-script", "version": 1, "steps": []})";
    std::ofstream(tmp.path("b.json"))
        << R"({"format": "isoparm-script", "version": 1, "title": "Bees", "summary": "buzz",
              "steps": []})";
    std::ofstream(tmp.path("scene.json")) << R"({"format": "isoparm-scene", "version": 1})";
    std::ofstream(tmp.path("broken.json")) << "{";
    std::ofstream(tmp.path("notes.txt")) << "x";
    const std::vector<CourseEntry> lessons = list_lessons(tmp.dir().string());
    ASSERT_EQ(lessons.size(), 2u);
    EXPECT_EQ(lessons[0].title, "Bees");
    EXPECT_EQ(lessons[0].summary, "buzz");
    EXPECT_EQ(lessons[1].title, "My first lesson");
    EXPECT_EQ(lessons[1].summary, "");
    EXPECT_TRUE(list_exercises(tmp.dir().string()).empty());
    EXPECT_TRUE(list_lessons(tmp.path("missing")).empty());
}

} // namespace
} // namespace isoparm::ui
