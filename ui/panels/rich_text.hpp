// A lesson caption drawn with its light markup (ui/view/rich_text.hpp): lines, bullets and
// **bold** (DejaVu Sans Bold; in the accent colour where that font is missing), wrapped at
// the window's content width.
#pragma once

#include <string>

namespace isoparm::ui {

void draw_rich_text(const std::string& text);

} // namespace isoparm::ui
