// The label placer: greedy by priority over candidate places around each anchor (the
// classic point-feature labelling order of Imhof and of Christensen, Marks and Shieber's
// greedy baseline), rings further out with leader lines, dropping what does not fit.
#include "ui/view/label_placer.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace isoparm::ui {

namespace {

Rect grown(const Rect& r, float by) {
    return {r.x - by, r.y - by, r.w + 2 * by, r.h + 2 * by};
}

bool inside(const Rect& r, const Rect& bounds) {
    return r.x >= bounds.x && r.y >= bounds.y && r.x + r.w <= bounds.x + bounds.w &&
           r.y + r.h <= bounds.y + bounds.h;
}

// A fixed label's rectangle from its anchor and alignment.
Rect aligned(const glm::vec2& a, const glm::vec2& size, LabelAlign align) {
    const int col = static_cast<int>(align) % 3, row = static_cast<int>(align) / 3;
    return {a.x - size.x * 0.5f * static_cast<float>(col),
            a.y - size.y * 0.5f * static_cast<float>(row), size.x, size.y};
}

float distance_to(const Rect& r, const glm::vec2& p) {
    const float dx = std::max({r.x - p.x, 0.f, p.x - (r.x + r.w)});
    const float dy = std::max({r.y - p.y, 0.f, p.y - (r.y + r.h)});
    return std::sqrt(dx * dx + dy * dy);
}

glm::vec2 nearest_on(const Rect& r, const glm::vec2& p) {
    return {std::clamp(p.x, r.x, r.x + r.w), std::clamp(p.y, r.y, r.y + r.h)};
}

// Places around the anchor, nearest first: right of it, left, above, below (the classic
// order), then rows further up and down beside it and further out above and below, each a
// label's height apart, so that a pile of labels on one point stacks into readable columns.
std::vector<Rect> candidates(const glm::vec2& a, const glm::vec2& size, float offset, float gap,
                             int rows) {
    struct Scored {
        Rect r;
        float d;
        int order;
    };
    std::vector<Scored> c;
    const float w = size.x, h = size.y, step = h + gap;
    auto add = [&](float x, float y) {
        const Rect r{x, y, w, h};
        c.push_back({r, distance_to(r, a), static_cast<int>(c.size())});
    };
    for (int n = 0; n < rows; ++n) {
        const float dy = static_cast<float>(n) * step;
        for (const float sign : {-1.f, 1.f}) {
            if (n == 0 && sign > 0) continue;
            const float y = a.y - h * 0.5f + sign * dy;
            add(a.x + offset, y);     // right
            add(a.x - offset - w, y); // left
        }
        const float above = a.y - offset - h - dy, below = a.y + offset + dy;
        for (const float y : {above, below}) {
            add(a.x - w * 0.5f, y); // centred
            add(a.x + offset, y);   // to the right
            add(a.x - offset - w, y);
        }
        // Further right and left, a label's width out (a second column).
        if (n > 0)
            for (const float sign : {-1.f, 1.f}) {
                const float y = a.y - h * 0.5f + sign * (dy - step);
                add(a.x + offset + w + gap, y);
                add(a.x - offset - 2 * w - gap, y);
            }
    }
    std::stable_sort(c.begin(), c.end(), [](const Scored& p, const Scored& q) {
        return std::round(p.d * 2) < std::round(q.d * 2);
    });
    std::vector<Rect> out;
    out.reserve(c.size());
    for (const Scored& s : c) out.push_back(s.r);
    return out;
}

struct Board {
    Rect bounds;
    float margin = 1;
    std::vector<Rect> taken;     // placed labels
    std::vector<Rect> obstacles; // handles the labels keep clear of
    bool free(const Rect& r, const std::vector<Rect>& also = {}) const {
        if (!inside(r, bounds)) return false;
        const Rect g = grown(r, margin);
        for (const Rect& t : taken)
            if (rects_overlap(g, t)) return false;
        for (const Rect& o : obstacles)
            if (rects_overlap(r, o)) return false;
        for (const Rect& o : also)
            if (rects_overlap(r, o)) return false;
        return true;
    }
};

} // namespace

bool rects_overlap(const Rect& a, const Rect& b) {
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

LabelPlacement place_labels(const std::vector<LabelRequest>& requests, const Rect& bounds,
                            const MeasureText& measure, const PlacerStyle& style,
                            const std::vector<Rect>& obstacles) {
    LabelPlacement out;
    const std::size_t n = requests.size();
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const bool fa = requests[a].mode == LabelMode::fixed;
        const bool fb = requests[b].mode == LabelMode::fixed;
        if (fa != fb) return fa;
        return requests[a].priority > requests[b].priority;
    });
    Board board{bounds, style.margin, {}, obstacles};
    const float leader_min = style.leader_min > 0 ? style.leader_min : style.offset * 2;
    const float pad = style.padding;

    // The anchors of the labels placed around points: a label should not hide another's point.
    std::vector<Rect> anchors;
    const float dot = std::max(style.offset * 0.5f, 2.f);
    for (const LabelRequest& r : requests)
        if (r.mode == LabelMode::around)
            anchors.push_back({r.anchor.x - dot, r.anchor.y - dot, 2 * dot, 2 * dot});

    std::vector<glm::vec2> sizes(n);
    for (std::size_t k = 0; k < n; ++k) sizes[k] = measure(requests[k].text) + glm::vec2(2 * pad);

    const int rings = std::clamp(style.rings, 1, 8);
    for (std::size_t k : order) {
        const LabelRequest& r = requests[k];
        const glm::vec2 size = sizes[k];
        std::optional<Rect> chosen;
        if (r.mode == LabelMode::fixed) {
            Rect rect = aligned(r.anchor, size, r.align);
            // Kept inside the view: shifted in rather than cut at its edge.
            rect.x = std::clamp(rect.x, bounds.x, std::max(bounds.x, bounds.x + bounds.w - rect.w));
            rect.y = std::clamp(rect.y, bounds.y, std::max(bounds.y, bounds.y + bounds.h - rect.h));
            Board fixed_board = board;
            fixed_board.obstacles.clear(); // fixed labels name the view itself: handles may pass
            if (fixed_board.free(rect)) chosen = rect;
        } else {
            // The label's own anchor is no obstacle to it.
            std::vector<Rect> others;
            for (const Rect& a : anchors)
                if (!(std::abs(a.x + dot - r.anchor.x) < 1e-3f &&
                      std::abs(a.y + dot - r.anchor.y) < 1e-3f))
                    others.push_back(a);
            const std::vector<Rect> places =
                candidates(r.anchor, size, style.offset, style.margin + 1, 2 + 2 * rings);
            for (int pass = 0; pass < 2 && !chosen; ++pass)
                for (const Rect& c : places)
                    if (board.free(c, pass == 0 ? others : std::vector<Rect>{})) {
                        chosen = c;
                        break;
                    }
        }
        if (!chosen) {
            out.dropped.push_back(k);
            continue;
        }
        PlacedLabel p;
        p.request = k;
        p.rect = *chosen;
        p.text_at = {chosen->x + pad, chosen->y + pad};
        if (r.mode == LabelMode::around && distance_to(*chosen, r.anchor) > leader_min)
            p.leader = std::make_pair(r.anchor, nearest_on(*chosen, r.anchor));
        board.taken.push_back(*chosen);
        out.placed.push_back(p);
    }

    // The badge for what was dropped: a free corner, else the lower right corner with the
    // labels under it dropped too (they are listed in its hover).
    for (int attempt = 0; attempt < 4 && !out.dropped.empty(); ++attempt) {
        out.more_text = "+" + std::to_string(out.dropped.size());
        const glm::vec2 size = measure(out.more_text) + glm::vec2(2 * pad);
        const float inset = 2;
        const float left = bounds.x + inset, right = bounds.x + bounds.w - size.x - inset;
        const float top = bounds.y + inset, bottom = bounds.y + bounds.h - size.y - inset;
        // The corners first, then along the bottom and top edges, then down the sides.
        std::vector<Rect> corners{{right, bottom, size.x, size.y},
                                  {left, bottom, size.x, size.y},
                                  {right, top, size.x, size.y},
                                  {left, top, size.x, size.y}};
        for (float x = right - size.x; x > left; x -= size.x) {
            corners.push_back({x, bottom, size.x, size.y});
            corners.push_back({x, top, size.x, size.y});
        }
        for (float y = bottom - size.y; y > top; y -= size.y) {
            corners.push_back({right, y, size.x, size.y});
            corners.push_back({left, y, size.x, size.y});
        }
        std::optional<Rect> badge;
        for (const Rect& c : corners)
            if (board.free(c)) {
                badge = c;
                break;
            }
        if (badge) {
            out.more = badge;
            out.more_text_at = {badge->x + pad, badge->y + pad};
            break;
        }
        const Rect c = corners[0];
        if (c.w > bounds.w || c.h > bounds.h) break; // no room even for the badge
        std::vector<PlacedLabel> kept;
        board.taken.clear();
        const Rect g = grown(c, style.margin);
        for (const PlacedLabel& p : out.placed) {
            if (rects_overlap(g, p.rect)) {
                out.dropped.push_back(p.request);
            } else {
                kept.push_back(p);
                board.taken.push_back(p.rect);
            }
        }
        out.placed = std::move(kept);
    }
    return out;
}

} // namespace isoparm::ui
