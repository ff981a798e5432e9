// Text broken into lines that fit a width (pure), only at spaces: never inside a number.
// ImGui 1.86's own wrapping also breaks after '.' and ',', which split "R22(0.5, 0.5) = 0.41026"
// into "0." and "41026" and "6.3e-16" into "6." and "3e-16" (read as 6).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ui/view/label_placer.hpp"

namespace isoparm::ui {

// The lines of `text` no wider than `width` where possible: broken at spaces only (a run of
// spaces at a break is dropped), a word wider than the width keeps a line of its own whole,
// and '\n' always starts a new line.
std::vector<std::string> wrap_at_spaces(std::string_view text, float width,
                                        const MeasureText& measure);

// The text cut to fit `width`, ending in ".." when cut (whole when it fits).
std::string shortened(std::string_view text, float width, const MeasureText& measure);
// The same with the cut in the middle, so the end still shows: names that differ only at
// their end ("Surface 1.1.1", "Surface 1.1.2") stay apart ("Surf..1.1.1", "Surf..1.1.2").
std::string shortened_middle(std::string_view text, float width, const MeasureText& measure);

} // namespace isoparm::ui
