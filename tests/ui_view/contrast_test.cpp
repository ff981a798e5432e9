// Overlay colours keep contrast with the scene's background.
#include <gtest/gtest.h>

#include "ui/view/contrast.hpp"

using namespace isoparm::ui;

TEST(Contrast, KnownRatios) {
    EXPECT_NEAR(contrast_ratio(glm::vec3(0), glm::vec3(1)), 21.0f, 1e-3f);
    EXPECT_NEAR(contrast_ratio(glm::vec3(0.5f), glm::vec3(0.5f)), 1.0f, 1e-6f);
}

TEST(Contrast, AReadableColourIsKept) {
    const glm::vec4 dark_net(0.1f, 0.1f, 0.1f, 1);
    EXPECT_EQ(readable_on(dark_net, glm::vec3(1), line_contrast), dark_net);
}

TEST(Contrast, APaleNetOnWhiteIsDarkenedJustEnough) {
    const glm::vec4 pale(0.85f, 0.85f, 0.8f, 0.7f);
    const glm::vec3 white(1);
    const glm::vec4 fixed = readable_on(pale, white, line_contrast);
    EXPECT_GE(contrast_ratio(glm::vec3(fixed), white), line_contrast);
    EXPECT_LT(contrast_ratio(glm::vec3(fixed), white), line_contrast + 0.1f); // the least change
    EXPECT_EQ(fixed.a, pale.a);
    EXPECT_LT(fixed.r, pale.r);
}

TEST(Contrast, DarkTextOnADarkBackgroundIsLightened) {
    const glm::vec3 bg(0.13f, 0.14f, 0.17f);
    const glm::vec4 fixed = readable_on(glm::vec4(0.2f, 0.2f, 0.25f, 1), bg, text_contrast);
    EXPECT_GE(contrast_ratio(glm::vec3(fixed), bg), text_contrast);
    EXPECT_GT(fixed.r, 0.2f);
}
