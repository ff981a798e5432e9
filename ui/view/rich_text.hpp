// Lesson captions' light markup: lines as written, "- " or "* " starting a bullet line, and
// **bold** runs; everything else (maths too: "S(u, v) = sum R_ij P_ij") is plain text.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace isoparm::ui {

// Not "TextRun": drawing.hpp has a ui::TextRun of its own (sub/superscripts), and two classes
// of one name break the one-definition rule (their vectors' code is shared by the linker).
struct CaptionRun {
    std::string text;
    bool bold = false;
};
struct CaptionLine {
    std::vector<CaptionRun> runs;
    bool bullet = false;
};

// An unclosed ** is bold to the end of its line; "**" alone on a line is nothing.
std::vector<CaptionLine> parse_caption(std::string_view text);

} // namespace isoparm::ui
