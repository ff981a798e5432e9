#include "ui/view/drawing.hpp"

namespace isoparm::ui {

void Drawing::line(glm::dvec2 a, glm::dvec2 b, const DrawStroke& s, std::string role) {
    items.push_back(DrawPath{{a, b}, false, s, std::nullopt, std::move(role)});
}

void Drawing::polyline(std::vector<glm::dvec2> points, const DrawStroke& s, std::string role) {
    items.push_back(DrawPath{std::move(points), false, s, std::nullopt, std::move(role)});
}

void Drawing::polygon(std::vector<glm::dvec2> points, std::optional<DrawStroke> s,
                      std::optional<DrawColor> fill, std::string role) {
    items.push_back(DrawPath{std::move(points), true, std::move(s), fill, std::move(role)});
}

void Drawing::dot(glm::dvec2 center, double radius, DrawColor fill, std::optional<DrawStroke> s,
                  std::string role) {
    items.push_back(DrawCircle{center, radius, std::move(s), fill, std::move(role)});
}

void Drawing::text(glm::dvec2 anchor, std::string text, double size, DrawColor color, HAlign h,
                   VAlign v, std::string role) {
    DrawText t;
    t.anchor = anchor;
    t.text = std::move(text);
    t.size = size;
    t.color = color;
    t.h = h;
    t.v = v;
    t.role = std::move(role);
    items.push_back(std::move(t));
}

std::vector<TextRun> text_runs(const std::string& s) {
    std::vector<TextRun> runs;
    auto add = [&](TextRun::Kind kind, char c) {
        if (runs.empty() || runs.back().kind != kind) runs.push_back({kind, {}});
        runs.back().text += c;
    };
    for (std::size_t k = 0; k < s.size(); ++k) {
        const char c = s[k];
        if (c == '\\' && k + 1 < s.size()) {
            add(TextRun::plain, s[++k]);
        } else if ((c == '_' || c == '^') && k + 1 < s.size()) {
            const TextRun::Kind kind = c == '_' ? TextRun::sub : TextRun::sup;
            if (s[k + 1] == '{') {
                std::size_t end = s.find('}', k + 2);
                if (end == std::string::npos) end = s.size();
                // An empty run still separates two scripts ("d^{1}_{4}").
                runs.push_back({kind, s.substr(k + 2, end - (k + 2))});
                k = end;
            } else {
                runs.push_back({kind, std::string(1, s[k + 1])});
                ++k;
            }
        } else {
            add(TextRun::plain, c);
        }
    }
    return runs;
}

std::string plain_text(const std::string& marked_up) {
    std::string out;
    for (const TextRun& r : text_runs(marked_up)) out += r.text;
    return out;
}

double approximate_text_width(const std::string& marked_up, double size) {
    double w = 0;
    for (const TextRun& r : text_runs(marked_up)) {
        // UTF-8 continuation bytes add no width.
        std::size_t chars = 0;
        for (unsigned char c : r.text) chars += (c & 0xC0) != 0x80;
        w += static_cast<double>(chars) * 0.6 * size * (r.kind == TextRun::plain ? 1.0 : 0.7);
    }
    return w;
}

} // namespace isoparm::ui
