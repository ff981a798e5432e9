// Contrast against the background (see contrast.hpp).
#include "ui/view/contrast.hpp"

#include <cmath>

#include <glm/common.hpp>

namespace isoparm::ui {

namespace {
float linear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
} // namespace

float relative_luminance(const glm::vec3& c) {
    const glm::vec3 s = glm::clamp(c, glm::vec3(0), glm::vec3(1));
    return 0.2126f * linear(s.r) + 0.7152f * linear(s.g) + 0.0722f * linear(s.b);
}

float contrast_ratio(const glm::vec3& a, const glm::vec3& b) {
    const float la = relative_luminance(a), lb = relative_luminance(b);
    return (std::max(la, lb) + 0.05f) / (std::min(la, lb) + 0.05f);
}

glm::vec4 readable_on(const glm::vec4& color, const glm::vec3& background, float ratio) {
    const glm::vec3 rgb(color);
    if (contrast_ratio(rgb, background) >= ratio) return color;
    // Toward whichever extreme lies farther from the background in luminance; the ratio
    // grows monotonically along that mix, so a bisection finds the least change.
    const glm::vec3 target = relative_luminance(background) > 0.18f ? glm::vec3(0) : glm::vec3(1);
    float lo = 0, hi = 1;
    for (int k = 0; k < 20; ++k) {
        const float mid = 0.5f * (lo + hi);
        if (contrast_ratio(glm::mix(rgb, target, mid), background) >= ratio)
            hi = mid;
        else
            lo = mid;
    }
    return glm::vec4(glm::mix(rgb, target, hi), color.a);
}

} // namespace isoparm::ui
