#include "ui/view/drawing_picture.hpp"

#include <string>

namespace isoparm::ui {

namespace {

DrawColor color_of(Rgba8 c) {
    return {static_cast<float>(red_of(c)) / 255.f, static_cast<float>(green_of(c)) / 255.f,
            static_cast<float>(blue_of(c)) / 255.f, static_cast<float>(alpha_of(c)) / 255.f};
}

std::optional<DrawStroke> stroke_of(Rgba8 c, float width) {
    if (alpha_of(c) == 0) return std::nullopt;
    return DrawStroke{color_of(c), width, {}};
}

std::optional<DrawColor> fill_of(Rgba8 c) {
    if (alpha_of(c) == 0) return std::nullopt;
    return color_of(c);
}

} // namespace

Drawing drawing_of(const Picture& p, double font_size) {
    Drawing d;
    d.width = p.frame.w;
    d.height = p.frame.h;
    d.title = p.view;
    if (alpha_of(p.background)) d.background = color_of(p.background);
    const glm::dvec2 o(p.frame.x, p.frame.y);
    auto at = [&](glm::vec2 q) { return glm::dvec2(q) - o; };
    const std::string role = p.view;
    int clip = -2; // none emitted yet
    for (std::size_t k = 0; k < p.shapes.size(); ++k) {
        // Shapes are clipped to the frame (the page) or to a clip rectangle of their own.
        const int c = k < p.shape_clips.size() ? p.shape_clips[k] : -1;
        if (c != clip) {
            const bool own = c >= 0 && static_cast<std::size_t>(c) < p.clips.size();
            const Rect r = own ? p.clips[static_cast<std::size_t>(c)] : p.frame;
            d.items.push_back(DrawClip{glm::dvec2(r.x, r.y) - o, {r.w, r.h}});
            clip = c;
        }
        std::visit(
            [&](const auto& s) {
                using T = std::decay_t<decltype(s)>;
                if constexpr (std::is_same_v<T, shape::Segment>) {
                    d.items.push_back(DrawPath{{at(s.a), at(s.b)},
                                               false,
                                               stroke_of(s.color, s.width),
                                               std::nullopt,
                                               role});
                } else if constexpr (std::is_same_v<T, shape::Polyline>) {
                    std::vector<glm::dvec2> pts;
                    for (glm::vec2 q : s.points) pts.push_back(at(q));
                    d.items.push_back(DrawPath{std::move(pts), s.closed,
                                               stroke_of(s.color, s.width), std::nullopt, role});
                } else if constexpr (std::is_same_v<T, shape::Polygon>) {
                    std::vector<glm::dvec2> pts;
                    for (glm::vec2 q : s.points) pts.push_back(at(q));
                    d.items.push_back(
                        DrawPath{std::move(pts), true, std::nullopt, fill_of(s.fill), role});
                } else if constexpr (std::is_same_v<T, shape::Box>) {
                    const glm::dvec2 lo = at(s.lo), hi = at(s.hi);
                    d.items.push_back(DrawPath{{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}},
                                               true,
                                               stroke_of(s.outline, s.width),
                                               fill_of(s.fill),
                                               role});
                } else if constexpr (std::is_same_v<T, shape::Disk>) {
                    d.items.push_back(DrawCircle{at(s.center), s.radius,
                                                 stroke_of(s.outline, s.width), fill_of(s.fill),
                                                 role});
                }
            },
            p.shapes[k]);
    }
    d.items.push_back(DrawClip{}); // labels stay inside the frame by placement
    const MeasureText measure = [font_size](std::string_view text) {
        return glm::vec2(static_cast<float>(approximate_text_width(std::string(text), font_size)),
                         static_cast<float>(font_size * 1.15));
    };
    const LabelPlacement placed = place(p, measure);
    for (const PlacedLabel& l : placed.placed) {
        const LabelRequest& r = p.labels[l.request];
        if (l.leader)
            d.items.push_back(DrawPath{{at(l.leader->first), at(l.leader->second)},
                                       false,
                                       stroke_of(r.color, 0.6f),
                                       std::nullopt,
                                       "leader"});
        if (alpha_of(r.plate) || alpha_of(r.frame)) {
            const glm::dvec2 lo = at({l.rect.x, l.rect.y}),
                             hi = at({l.rect.x + l.rect.w, l.rect.y + l.rect.h});
            d.items.push_back(DrawPath{{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}},
                                       true,
                                       stroke_of(r.frame, 0.6f),
                                       fill_of(r.plate),
                                       "plate"});
        }
        DrawText t;
        t.anchor = at(l.text_at) + glm::dvec2(0, 0.9 * font_size);
        t.text = r.text;
        t.size = font_size;
        t.color = color_of(r.color);
        t.role = "label";
        d.items.push_back(std::move(t));
    }
    if (placed.more) {
        DrawText t;
        t.anchor = at(placed.more_text_at) + glm::dvec2(0, 0.9 * font_size);
        t.text = placed.more_text;
        t.size = 0.85 * font_size;
        t.color = {0.4f, 0.4f, 0.44f, 1};
        t.role = "label-dropped";
        d.items.push_back(std::move(t));
    }
    return d;
}

} // namespace isoparm::ui
