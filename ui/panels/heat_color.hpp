// The heat maps' colour ramp, shared by the basis panel's square (R_ij over (u, v)) and its
// triangle (R_ijk over (r, s, t)).
#pragma once

#include <algorithm>
#include <imgui.h>

namespace isoparm::ui {

// A perceptually ordered ramp (dark blue, purple, orange, yellow) for t in [0, 1]; negative
// values (negative weights) use a separate cyan ramp so the sign is never ambiguous.
inline ImU32 heat_color(float t) {
    static const float stops[5][3] = {{0.05f, 0.03f, 0.20f},
                                      {0.35f, 0.08f, 0.50f},
                                      {0.75f, 0.20f, 0.35f},
                                      {0.97f, 0.55f, 0.10f},
                                      {0.99f, 0.95f, 0.45f}};
    if (t < 0) {
        const float a = std::clamp(-t, 0.f, 1.f);
        return ImGui::ColorConvertFloat4ToU32(ImVec4(0.05f, 0.1f + 0.6f * a, 0.2f + 0.7f * a, 1));
    }
    const float x = std::clamp(t, 0.f, 1.f) * 4;
    const int k = std::min(static_cast<int>(x), 3);
    const float f = x - static_cast<float>(k);
    float c[3];
    for (int n = 0; n < 3; ++n) c[n] = stops[k][n] + (stops[k + 1][n] - stops[k][n]) * f;
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], 1));
}

} // namespace isoparm::ui
