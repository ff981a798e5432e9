// Wrapping at spaces only: a number never breaks across lines.
#include <gtest/gtest.h>

#include "ui/view/text_wrap.hpp"

using namespace isoparm::ui;

namespace {
const MeasureText mono = [](std::string_view s) {
    return glm::vec2(7.f * static_cast<float>(s.size()), 12.f);
};
} // namespace

TEST(TextWrap, BreaksAtSpacesNeverInsideANumber) {
    // ImGui 1.86 broke this after "0." at a width of 26 characters.
    const auto lines = wrap_at_spaces("R22(0.500, 0.500) = 0.41026", 7 * 22, mono);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "R22(0.500, 0.500) =");
    EXPECT_EQ(lines[1], "0.41026");
    const auto d = wrap_at_spaces("largest distance 6.3e-16", 7 * 18, mono);
    ASSERT_EQ(d.size(), 2u);
    EXPECT_EQ(d[1], "6.3e-16");
}

TEST(TextWrap, AWordWiderThanTheWidthStaysWholeOnItsLine) {
    const auto lines = wrap_at_spaces("a 0.76262626262626 b", 7 * 5, mono);
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[1], "0.76262626262626");
}

TEST(TextWrap, KeepsNewlinesAndShortTextWhole) {
    EXPECT_EQ(wrap_at_spaces("one line", 1000, mono), std::vector<std::string>{"one line"});
    EXPECT_EQ(wrap_at_spaces("a\nb", 1000, mono), (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(wrap_at_spaces("", 1000, mono), std::vector<std::string>{""});
}

TEST(TextWrap, ShortenedEndsInDotsOnlyWhenCut) {
    EXPECT_EQ(shortened("Background", 7 * 20, mono), "Background");
    const std::string s = shortened("Background colour", 7 * 8, mono);
    EXPECT_EQ(s, "Backgr..");
    EXPECT_LE(mono(s).x, 7 * 8);
}

TEST(TextWrap, ShortenedInTheMiddleKeepsTheDistinguishingEnd) {
    const std::string a = shortened_middle("Surface 1.1.1", 7 * 11, mono);
    const std::string b = shortened_middle("Surface 1.1.2", 7 * 11, mono);
    EXPECT_NE(a, b);
    EXPECT_LE(mono(a).x, 7 * 11);
    EXPECT_EQ(a.back(), '1');
    EXPECT_EQ(b.back(), '2');
    EXPECT_EQ(shortened_middle("vase", 100, mono), "vase");
}
