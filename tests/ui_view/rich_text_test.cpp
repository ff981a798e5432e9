// Captions' light markup: lines, bullets and bold runs.
#include <gtest/gtest.h>

#include "ui/view/rich_text.hpp"

namespace isoparm::ui {
namespace {

TEST(RichText, LinesBulletsAndBold) {
    const auto lines = parse_caption("Raise **w22** to 5:\n- the surface **moves toward P22\n"
                                     "S(u, v) = sum R_ij P_ij");
    ASSERT_EQ(lines.size(), 3u);
    ASSERT_EQ(lines[0].runs.size(), 3u);
    EXPECT_EQ(lines[0].runs[0].text, "Raise ");
    EXPECT_FALSE(lines[0].runs[0].bold);
    EXPECT_EQ(lines[0].runs[1].text, "w22");
    EXPECT_TRUE(lines[0].runs[1].bold);
    EXPECT_EQ(lines[0].runs[2].text, " to 5:");
    EXPECT_TRUE(lines[1].bullet);
    ASSERT_EQ(lines[1].runs.size(), 2u);
    EXPECT_TRUE(lines[1].runs[1].bold); // unclosed: bold to the end of its line
    EXPECT_FALSE(lines[2].bullet);
    ASSERT_EQ(lines[2].runs.size(), 1u);
    EXPECT_EQ(lines[2].runs[0].text, "S(u, v) = sum R_ij P_ij");
    EXPECT_FALSE(lines[2].runs[0].bold);
}

TEST(RichText, EmptyLinesStay) {
    const auto lines = parse_caption("a\n\nb");
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_TRUE(lines[1].runs.empty());
    EXPECT_EQ(parse_caption("").size(), 1u);
}

} // namespace
} // namespace isoparm::ui
