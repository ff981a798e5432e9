// Colours that stay readable on the scene's background (a teacher may pick white): WCAG 2
// relative luminance and contrast ratio, and a colour pushed toward black or white until it
// reaches a ratio.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace isoparm::ui {

// Lines and points need 3:1 against their background, text 4.5:1 (WCAG 2.1, 1.4.11 / 1.4.3).
constexpr float line_contrast = 3.0f;
constexpr float text_contrast = 4.5f;

float relative_luminance(const glm::vec3& srgb);
float contrast_ratio(const glm::vec3& a, const glm::vec3& b);
// `color` itself when it already reaches `ratio` on `background`; otherwise the least mix
// toward black (on light backgrounds) or white (on dark ones) that does. Alpha is kept.
glm::vec4 readable_on(const glm::vec4& color, const glm::vec3& background, float ratio);

} // namespace isoparm::ui
