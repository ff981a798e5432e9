// The ImGui backend of ui/view/picture.hpp.
#include "ui/panels/picture_draw.hpp"

#include <string>
#include <type_traits>
#include <variant>

#include "ui/ui_report.hpp"

namespace isoparm::ui {

static_assert(rgba8(1, 2, 3, 4) == IM_COL32(1, 2, 3, 4), "Rgba8 is packed as IM_COL32");

MeasureText imgui_measure() {
    return [](std::string_view s) {
        const ImVec2 v = ImGui::CalcTextSize(s.data(), s.data() + s.size());
        return glm::vec2(v.x, v.y);
    };
}

namespace {

std::vector<ImVec2> to_imgui(const std::vector<glm::vec2>& pts) {
    std::vector<ImVec2> out;
    out.reserve(pts.size());
    for (const glm::vec2& p : pts) out.push_back(iv2(p));
    return out;
}

void draw_shape(ImDrawList* dl, const Shape& s) {
    std::visit(
        [dl](const auto& x) {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, shape::Segment>) {
                dl->AddLine(iv2(x.a), iv2(x.b), x.color, x.width);
            } else if constexpr (std::is_same_v<T, shape::Polyline>) {
                const std::vector<ImVec2> pts = to_imgui(x.points);
                dl->AddPolyline(pts.data(), static_cast<int>(pts.size()), x.color,
                                x.closed ? ImDrawFlags_Closed : 0, x.width);
            } else if constexpr (std::is_same_v<T, shape::Polygon>) {
                const std::vector<ImVec2> pts = to_imgui(x.points);
                dl->AddConvexPolyFilled(pts.data(), static_cast<int>(pts.size()), x.fill);
            } else if constexpr (std::is_same_v<T, shape::Box>) {
                if (x.fill) dl->AddRectFilled(iv2(x.lo), iv2(x.hi), x.fill, x.rounding);
                if (x.outline) dl->AddRect(iv2(x.lo), iv2(x.hi), x.outline, x.rounding, 0, x.width);
            } else if constexpr (std::is_same_v<T, shape::Disk>) {
                const int segments = x.radius > 12 ? 32 : 20;
                if (x.fill) dl->AddCircleFilled(iv2(x.center), x.radius, x.fill, segments);
                if (x.outline) dl->AddCircle(iv2(x.center), x.radius, x.outline, segments, x.width);
            }
        },
        s);
}

} // namespace

LabelPlacement draw_picture(const Picture& p, ImDrawList* dl) {
    if (!dl) dl = ImGui::GetWindowDrawList();
    const ImVec2 a(p.frame.x, p.frame.y), b(p.frame.x + p.frame.w, p.frame.y + p.frame.h);
    dl->PushClipRect(a, b, true);
    if (p.background) dl->AddRectFilled(a, b, p.background);
    int clip = -1;
    for (std::size_t k = 0; k < p.shapes.size(); ++k) {
        const int want = k < p.shape_clips.size() ? p.shape_clips[k] : -1;
        if (want != clip) {
            if (clip >= 0) dl->PopClipRect();
            if (want >= 0) {
                const Rect& r = p.clips[static_cast<std::size_t>(want)];
                dl->PushClipRect(ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h), true);
            }
            clip = want;
        }
        draw_shape(dl, p.shapes[k]);
    }
    if (clip >= 0) dl->PopClipRect();

    const LabelPlacement placed = place(p, imgui_measure());
    for (const PlacedLabel& l : placed.placed) {
        const LabelRequest& r = p.labels[l.request];
        if (l.leader)
            dl->AddLine(iv2(l.leader->first), iv2(l.leader->second),
                        (r.color & 0x00ffffffu) | 0xa0000000u, 1.f);
        const ImVec2 lo = iv2({l.rect.x, l.rect.y}),
                     hi = iv2({l.rect.x + l.rect.w, l.rect.y + l.rect.h});
        if (r.plate) dl->AddRectFilled(lo, hi, r.plate, 3);
        if (r.frame) dl->AddRect(lo, hi, r.frame, 3);
        dl->AddText(iv2(l.text_at), r.color, r.text.c_str());
    }
    const bool light = ImGui::GetStyle().Colors[ImGuiCol_WindowBg].x > 0.5f;
    if (placed.more) {
        const Rect& m = *placed.more;
        const ImVec2 lo(m.x, m.y), hi(m.x + m.w, m.y + m.h);
        dl->AddRectFilled(lo, hi, light ? IM_COL32(255, 255, 255, 230) : IM_COL32(20, 22, 28, 230),
                          3);
        dl->AddRect(lo, hi, light ? IM_COL32(0, 0, 0, 255) : IM_COL32(200, 200, 210, 255), 3);
        dl->AddText(iv2(placed.more_text_at),
                    light ? IM_COL32(0, 0, 0, 255) : IM_COL32(235, 235, 235, 255),
                    placed.more_text.c_str());
    }
    dl->PopClipRect();
    if (p.border) dl->AddRect(a, b, p.border, 0, 0, p.border_width);

    // Hover: the dropped labels behind "+n", or a shortened label's whole text.
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const bool over_window = ImGui::IsWindowHovered(ImGuiHoveredFlags_AllowWhenBlockedByActiveItem);
    if (over_window && placed.more && placed.more->contains(mouse.x, mouse.y)) {
        std::string list = "Not shown here (no room):";
        for (std::size_t k : placed.dropped) list += "\n" + p.labels[k].text;
        ImGui::SetTooltip("%s", list.c_str());
    } else if (over_window) {
        for (const PlacedLabel& l : placed.placed)
            if (!p.labels[l.request].tooltip.empty() && l.rect.contains(mouse.x, mouse.y))
                ImGui::SetTooltip("%s", p.labels[l.request].tooltip.c_str());
    }

    if (ui_report_enabled() && !p.view.empty()) {
        report_rect("frame/" + p.view, p.frame.x, p.frame.y, p.frame.w, p.frame.h);
        const std::string prefix = "label/" + p.view + "/";
        for (std::size_t k = 0; k < placed.placed.size(); ++k) {
            const Rect& r = placed.placed[k].rect;
            report_rect(prefix + std::to_string(k), r.x, r.y, r.w, r.h);
        }
        if (placed.more)
            report_rect(prefix + "more", placed.more->x, placed.more->y, placed.more->w,
                        placed.more->h);
        report_fact(prefix + "dropped", static_cast<double>(placed.dropped.size()));
    }
    return placed;
}

} // namespace isoparm::ui
