// A program run from its build tree finds the example scenes in the source tree.
#include <gtest/gtest.h>

#include <algorithm>

#include "ui/view/data_dir.hpp"

namespace isoparm::ui {
namespace {

TEST(DataDir, TheExampleScenesAreFoundSortedByName) {
    EXPECT_NE(examples_dir(), "");
    const std::vector<std::string> scenes = example_scenes();
    ASSERT_FALSE(scenes.empty());
    EXPECT_TRUE(std::is_sorted(scenes.begin(), scenes.end()));
    for (const std::string& s : scenes) EXPECT_TRUE(s.ends_with(".json")) << s;
}

} // namespace
} // namespace isoparm::ui
