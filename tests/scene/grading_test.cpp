// Grading a class: every file graded (in parallel, in the order given), unreadable files are
// failures with their reason, and the CSV and JSON say the same as the lines.
#include <gtest/gtest.h>

#include <fstream>

#include "core/doc/commands.hpp"
#include "core/scene/grading.hpp"
#include "core/scene/scene_io.hpp"
#include "tests/support/temp_dir.hpp"

using namespace isoparm;
using nlohmann::json;

namespace {

scene::Exercise weight_exercise() {
    const json j = {{"format", "isoparm-exercise"},
                    {"version", 1},
                    {"title", "Heavier"},
                    {"task", "Raise w22 to at least 4."},
                    {"scene", scene::scene_to_json(doc::default_document())},
                    {"checks", json::parse(R"([
                        {"check": "weight", "point": [2, 2], "min": 4, "hint": "Use the slider."},
                        {"check": "no_negative_weight"}])")}};
    auto e = scene::exercise_from_json(j, ".");
    EXPECT_TRUE(e.ok());
    return *e;
}

void write(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
}

TEST(Grading, AClassFolderIsGradedFileByFileAndBadFilesFail) {
    test::TempDir tmp("isoparm-grading");
    std::filesystem::create_directories(tmp.dir() / "class");
    for (int k = 0; k < 40; ++k) {
        doc::Document d = doc::default_document();
        doc::History h;
        EXPECT_TRUE(h.execute(d, doc::edit_point({1, 2, 2, std::nullopt, 1.0 + k / 4.0})).ok());
        char name[32];
        std::snprintf(name, sizeof name, "s%02d.json", k);
        ASSERT_TRUE(scene::save_scene(d, tmp.path("class/" + std::string(name))).ok());
    }
    write(tmp.path("class/broken.json"), "{\"format\": \"isoparm-scene\", ");
    write(tmp.path("class/notes.txt"), "not a submission");
    const std::vector<std::string> files =
        scene::expand_submissions({tmp.path("class"), tmp.path("missing.json")});
    ASSERT_EQ(files.size(), 42u); // 40 scenes, the broken one, the missing one; no .txt
    EXPECT_EQ(files.front(), tmp.path("class/broken.json"));
    const scene::Exercise ex = weight_exercise();
    const auto grades = scene::grade_files(ex, files, 3);
    ASSERT_EQ(grades.size(), files.size());
    std::size_t passed = 0;
    for (std::size_t k = 0; k < grades.size(); ++k) {
        EXPECT_EQ(grades[k].file, files[k]);
        passed += grades[k].passed();
    }
    EXPECT_EQ(passed, 28u); // weights 4 .. 10.75: k = 12 .. 39
    EXPECT_FALSE(grades.front().error.empty());
    EXPECT_NE(
        scene::grade_line(grades.front()).find("FAIL  " + files.front() + "  (cannot be read)"),
        std::string::npos);
    EXPECT_FALSE(grades.back().error.empty());     // missing.json
    const scene::SubmissionGrade& low = grades[1]; // s00: w22 = 1
    EXPECT_EQ(scene::grade_line(low),
              "FAIL  " + low.file +
                  "  (1/2): the weight of P2,2 of 'hill' is 1; the task asks for at least 4. "
                  "Hint: Use the slider.");
    EXPECT_EQ(scene::grade_summary(grades),
              "42 submissions: 28 passed, 14 failed (2 could not be read)");
    const std::string csv = scene::grades_csv(ex, grades);
    EXPECT_EQ(csv.substr(0, csv.find('\n')),
              "file,result,checks_passed,checks,first_failure,message,\"the weight of P2,2 of a "
              "surface or curve is at least 4\",no weight of any object is negative");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 43);
    const json j = scene::grades_json(ex, grades);
    EXPECT_EQ(j["summary"]["passed"], 28);
    EXPECT_EQ(j["summary"]["unreadable"], 2);
    EXPECT_EQ(j["submissions"][1]["checks"][0]["passed"], false);
}

} // namespace
