#include "ui/view/figure_common.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/doc/document.hpp"
#include "core/geom/rational_picture.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/label_placer.hpp"

namespace isoparm::ui {

namespace figure_detail {

DrawStroke stroke(DrawColor c, double width, std::vector<double> dash) {
    return DrawStroke{c, width, std::move(dash)};
}

std::string number(double x) {
    if (std::abs(x) < 1e-12) return "0";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", x);
    return buf;
}

glm::dvec2 DataMap::operator()(double x, double y) const {
    const double sx = x1 != x0 ? (x - x0) / (x1 - x0) : 0.5;
    const double sy = y1 != y0 ? (y - y0) / (y1 - y0) : 0.5;
    return {box.x + sx * box.w, box.y + (1 - sy) * box.h};
}

DataMap fit_equal(const PageBox& box, glm::dvec2 lo, glm::dvec2 hi) {
    glm::dvec2 span = hi - lo;
    const double size = std::max({span.x, span.y, 1e-9});
    span = glm::max(span, glm::dvec2(size * 1e-3));
    const double scale = std::min(box.w / span.x, box.h / span.y);
    const glm::dvec2 c = (lo + hi) * 0.5;
    const double hw = box.w / scale / 2, hh = box.h / scale / 2;
    return DataMap{box, c.x - hw, c.x + hw, c.y - hh, c.y + hh};
}

PageBox start_page(Drawing& d, const FigureOptions& o, const std::string& title) {
    d.width = o.width;
    d.height = o.height;
    d.title = title;
    if (!o.transparent) d.background = Palette::white;
    const double fs = o.font_size;
    d.text({fs, fs * 1.6}, title, fs * 1.1, Palette::ink, HAlign::left, VAlign::baseline, "title");
    const PageBox area{fs, fs * 2.6, o.width - 2 * fs, o.height - fs * 3.6};
    // The picture stays below the title (a curve framed on a few points runs beyond them).
    d.items.push_back(DrawClip{{0, area.y - 0.5 * fs}, {o.width, o.height - area.y + 0.5 * fs}});
    return area;
}

void point_labels(Drawing& d, const std::vector<glm::dvec2>& anchors,
                  const std::vector<std::string>& texts, double size, DrawColor color,
                  const std::string& role) {
    // The visible part of the page: the last clip in force, else the page.
    glm::dvec2 lo(0), hi(d.width, d.height);
    for (const DrawItem& item : d.items)
        if (const auto* c = std::get_if<DrawClip>(&item)) {
            lo = c->active() ? c->origin : glm::dvec2(0);
            hi = c->active() ? c->origin + c->size : glm::dvec2(d.width, d.height);
        }
    // The one label placer (label_placer.hpp), measuring with the figure's font; the page's
    // points are its pixels.
    std::vector<LabelRequest> requests;
    std::vector<std::size_t> which;
    for (std::size_t k = 0; k < anchors.size() && k < texts.size(); ++k) {
        // A point off the visible page has no label.
        if (anchors[k].x < lo.x || anchors[k].y < lo.y || anchors[k].x > hi.x ||
            anchors[k].y > hi.y)
            continue;
        LabelRequest r;
        r.anchor = glm::vec2(anchors[k]);
        r.text = texts[k];
        r.priority = -static_cast<int>(requests.size()); // earlier labels matter more
        requests.push_back(std::move(r));
        which.push_back(k);
    }
    const MeasureText measure = [size](std::string_view text) {
        return glm::vec2(static_cast<float>(approximate_text_width(std::string(text), size)),
                         static_cast<float>(size * 1.15));
    };
    PlacerStyle style;
    style.offset = static_cast<float>(0.45 * size);
    style.padding = static_cast<float>(0.1 * size);
    const Rect bounds{static_cast<float>(lo.x), static_cast<float>(lo.y),
                      static_cast<float>(hi.x - lo.x), static_cast<float>(hi.y - lo.y)};
    const LabelPlacement placement = place_labels(requests, bounds, measure, style);
    for (const PlacedLabel& p : placement.placed) {
        if (p.leader)
            d.line(glm::dvec2(p.leader->first), glm::dvec2(p.leader->second),
                   stroke(Palette::faint, 0.5), role + "-leader");
        // text_at is the text's top-left; the baseline lies an ascent below it.
        d.text({p.text_at.x, p.text_at.y + 0.9 * size}, requests[p.request].text, size, color,
               HAlign::left, VAlign::baseline, role);
    }
    if (placement.more)
        d.text({placement.more_text_at.x, placement.more_text_at.y + 0.9 * size},
               placement.more_text, 0.8 * size, Palette::muted, HAlign::left, VAlign::baseline,
               role + "-dropped");
}

} // namespace figure_detail

std::optional<FigureCurve> figure_curve(const doc::Document& d) {
    auto from = [](const doc::Object& o) -> std::optional<FigureCurve> {
        const doc::CurveObject* c = o.curve_object();
        if (!c) return std::nullopt;
        int plane = -1;
        switch (c->plane) {
        case doc::CurvePlane::xy:
            plane = 0;
            break;
        case doc::CurvePlane::xz:
            plane = 1;
            break;
        case doc::CurvePlane::yz:
            plane = 2;
            break;
        case doc::CurvePlane::free3d:
            break;
        }
        return FigureCurve{c->curve, o.name, plane};
    };
    if (const doc::Object* sel = d.selected())
        if (auto c = from(*sel)) return c;
    for (const doc::Object& o : d.objects)
        if (o.visible)
            if (auto c = from(o)) return c;
    const doc::Object* obj = nullptr;
    if (const geom::Surface* s = current_surface(d, &obj)) {
        const glm::dvec2 uv = indicator_params(d, *obj);
        if (auto iso = geom::isocurve(*s, geom::Dir::v, uv.y))
            return FigureCurve{*iso, obj->name + " at v = " + figure_detail::number(uv.y), -1};
    }
    return std::nullopt;
}

geom::Expected<Drawing> make_figure(const doc::Document& d, FigureView view,
                                    const FigureOptions& o) {
    using namespace figure_detail;
    switch (view) {
    case FigureView::tracing:
        return tracing_figure(d, o);
    case FigureView::basis:
        return basis_figure(d, o);
    case FigureView::curve:
        return curve_figure(d, o, false);
    case FigureView::deboor:
        return curve_figure(d, o, true);
    case FigureView::homogeneous:
        return homogeneous_figure(d, o);
    case FigureView::blossom:
        return blossom_figure(d, o);
    }
    return geom::make_error_nopath(geom::ErrorCode::internal, "unknown figure view");
}

} // namespace isoparm::ui
