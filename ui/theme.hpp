// ImGui look: the normal dark theme and the classroom (presentation) theme, scaled for
// HiDPI, with the built-in font rebuilt at the needed size.
#pragma once

namespace isoparm::ui {

// Sets colours and sizes for the scale (content scale times the presentation factor).
void apply_theme(bool presentation, float scale);
// Rebuilds ImGui's font atlas with the built-in font at 13 px times `scale`; call between
// frames, then let the OpenGL3 backend recreate its font texture.
void rebuild_fonts(float scale);

} // namespace isoparm::ui
