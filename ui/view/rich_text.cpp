// Captions' markup (rich_text.hpp).
#include "ui/view/rich_text.hpp"

namespace isoparm::ui {

std::vector<CaptionLine> parse_caption(std::string_view text) {
    std::vector<CaptionLine> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        CaptionLine l;
        if (line.starts_with("- ") || line.starts_with("* ")) {
            l.bullet = true;
            line.remove_prefix(2);
        }
        bool bold = false;
        std::string current;
        for (std::size_t k = 0; k < line.size(); ++k) {
            if (line.compare(k, 2, "**") == 0) {
                if (!current.empty()) l.runs.push_back({current, bold});
                current.clear();
                bold = !bold;
                ++k;
                continue;
            }
            current += line[k];
        }
        if (!current.empty()) l.runs.push_back({current, bold});
        out.push_back(std::move(l));
        if (end == text.size()) break;
        start = end + 1;
    }
    return out;
}

} // namespace isoparm::ui
