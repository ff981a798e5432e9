// Wrapping and shortening text to a width, breaking at spaces only.
#include "ui/view/text_wrap.hpp"

namespace isoparm::ui {

namespace {

void wrap_paragraph(std::string_view text, float width, const MeasureText& measure,
                    std::vector<std::string>& out) {
    std::string line;
    std::size_t k = 0;
    bool any = false;
    while (k < text.size()) {
        const std::size_t start = text.find_first_not_of(' ', k);
        if (start == std::string_view::npos) break;
        std::size_t end = text.find(' ', start);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view word = text.substr(start, end - start);
        // Keep the spaces the text had between words on one line (aligned columns).
        const std::string_view gap = text.substr(k, start - k);
        std::string candidate = line;
        if (!line.empty()) candidate.append(gap.empty() ? " " : gap);
        candidate.append(word);
        if (!line.empty() && measure(candidate).x > width) {
            out.push_back(line);
            line.assign(word);
        } else {
            // The paragraph's leading spaces (an indent) stay.
            if (line.empty() && !any)
                candidate = std::string(text.substr(0, start)) + std::string(word);
            line = std::move(candidate);
        }
        any = true;
        k = end;
    }
    out.push_back(line);
}

} // namespace

std::vector<std::string> wrap_at_spaces(std::string_view text, float width,
                                        const MeasureText& measure) {
    std::vector<std::string> out;
    std::size_t k = 0;
    while (true) {
        const std::size_t nl = text.find('\n', k);
        wrap_paragraph(
            text.substr(k, nl == std::string_view::npos ? std::string_view::npos : nl - k), width,
            measure, out);
        if (nl == std::string_view::npos) break;
        k = nl + 1;
    }
    return out;
}

std::string shortened(std::string_view text, float width, const MeasureText& measure) {
    if (measure(text).x <= width) return std::string(text);
    std::string s(text);
    while (!s.empty()) {
        s.pop_back();
        while (!s.empty() && s.back() == ' ') s.pop_back();
        if (measure(s + "..").x <= width) return s + "..";
    }
    return "..";
}

std::string shortened_middle(std::string_view text, float width, const MeasureText& measure) {
    if (measure(text).x <= width) return std::string(text);
    // Keep about a third from the end, the rest from the start, as much as fits.
    for (std::size_t keep = text.size(); keep-- > 0;) {
        const std::size_t tail = std::min(keep, std::max<std::size_t>(keep / 3, 1));
        const std::size_t head = keep - tail;
        const std::string s =
            std::string(text.substr(0, head)) + ".." + std::string(text.substr(text.size() - tail));
        if (measure(s).x <= width) return s;
    }
    return "..";
}

} // namespace isoparm::ui
