// Lesson captions' light markup: lines as written, "- " or "* " starting a bullet line, and
// **bold** runs; everything else (maths too: "S(u, v) = sum R_ij P_ij") is plain text.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace isoparm::ui {

struct TextRun {
    std::string text;
    bool bold = false;
};
struct TextLine {
    std::vector<TextRun> runs;
    bool bullet = false;
};

// An unclosed ** is bold to the end of its line; "**" alone on a line is nothing.
std::vector<TextLine> parse_caption(std::string_view text);

} // namespace isoparm::ui
