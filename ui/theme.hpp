// ImGui look: the normal dark theme and the classroom (presentation) theme, scaled for
// HiDPI, with DejaVu Sans (and DejaVu Sans Mono for numbers) rasterised at the size in use.
#pragma once

#include <imgui.h>
#include <string>

struct ImFont;
struct ImVec4;

namespace isoparm::ui {

// Text height in pixels at scale 1: DejaVu Sans reads at 15 px where ProggyClean needed 13.
constexpr float base_font_pixels = 15.0f;

// Sets colours and sizes for the scale (content scale times the presentation factor).
void apply_theme(bool presentation, float scale);
// Rebuilds ImGui's font atlas at base_font_pixels times `scale` from Debian's
// fonts-dejavu-core; where that is missing, the built-in font, and the returned note says so
// (empty when the vector fonts loaded). Call between frames: it recreates the font texture.
std::string rebuild_fonts(float scale);
// Refusals and errors inside panels and dialogs: orange on the dark theme, dark red on the
// light (presentation) theme, so they read on either.
ImVec4 error_text_color();
// A tooltip of text wrapped at about 40 characters, so a long refusal stays on screen.
void wrapped_tooltip(const std::string& text);
// ImGui::TextWrapped, but broken at spaces only (ui/view/text_wrap.hpp): ImGui 1.86 also breaks
// after '.', which cut "0.41026" into "0." and "41026". One item, for hover checks.
void text_wrapped(const char* fmt, ...) IM_FMTARGS(1);
// The next window centred in the main viewport, `width` pixels wide (0: as wide as its content).
void center_next_window(float width);
// A centred modal popup `id`, `width` pixels wide (0: as its content): opened once when
// `requested` (which is cleared), then begun; true while it is open (end it with EndPopup).
bool begin_centered_modal(const char* id, bool& requested, float width,
                          ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize);
// DejaVu Sans Mono at the same size, for columns of numbers (the default font when missing).
ImFont* number_font();
// DejaVu Sans Bold at the same size, or null where it is missing (bold then shows in colour).
ImFont* bold_font();

} // namespace isoparm::ui
