// The tracing square as a figure (the paper's Fig. 2): the parameter domain with its knot
// lines and knot values, the indicator at (u, v), the current subpatch's part of the domain
// in a group, and for a rational surface each weight at its control point's Greville point.
#include <algorithm>

#include "core/doc/patches.hpp"
#include "core/geom/knots.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/figure_common.hpp"

namespace isoparm::ui::figure_detail {

namespace {

// The knot values along one edge, thinned so that no two labels touch.
void knot_labels(Drawing& dr, const DataMap& m, const geom::Surface& s, geom::Dir dir, double fs) {
    const bool along_u = dir == geom::Dir::u;
    const std::vector<KnotTick> ticks = knot_ticks(s.knots(dir), s.degree(dir), s.count(dir));
    std::vector<double> px;
    for (const KnotTick& t : ticks) {
        const glm::dvec2 p = along_u ? m(t.value, m.y0) : m(m.x0, t.value);
        px.push_back(along_u ? p.x : -p.y); // ascending either way
    }
    const std::vector<bool> keep = thin_labels(px, along_u ? 3.2 * fs : 1.3 * fs);
    for (std::size_t k = 0; k < ticks.size(); ++k) {
        const KnotTick& t = ticks[k];
        const glm::dvec2 p = along_u ? m(t.value, m.y0) : m(m.x0, t.value);
        const glm::dvec2 out = along_u ? glm::dvec2(0, 0.5 * fs) : glm::dvec2(-0.5 * fs, 0);
        dr.line(p, p + out, stroke(Palette::ink, 0.8), "knot-tick");
        if (!keep[k]) continue;
        std::string text = number(t.value);
        if (t.multiplicity > 1) text += "^{(" + std::to_string(t.multiplicity) + ")}";
        if (along_u)
            dr.text(p + glm::dvec2(0, 0.7 * fs), text, fs, Palette::ink, HAlign::center,
                    VAlign::top, "knot-label");
        else
            dr.text(p + glm::dvec2(-0.8 * fs, 0), text, fs, Palette::ink, HAlign::right,
                    VAlign::middle, "knot-label");
    }
}

} // namespace

geom::Expected<Drawing> tracing_figure(const doc::Document& d, const FigureOptions& o) {
    const doc::Object* obj = nullptr;
    const geom::Surface* s = current_surface(d, &obj);
    if (!s)
        return geom::make_error_nopath(geom::ErrorCode::schema,
                                       "the tracing view needs a surface (tensor product)");
    Drawing dr;
    const double fs = o.font_size;
    const PageBox area =
        start_page(dr, o,
                   obj->name + ": " + std::string(geom::name_of(s->type)) + ", degree " +
                       std::to_string(s->degree_u) + " x " + std::to_string(s->degree_v));
    // The square with room for the v labels on its left and the u labels below.
    const double left = 5.5 * fs, below = 3.4 * fs;
    const double side = std::max(std::min(area.w - left - fs, area.h - below), 4 * fs);
    const PageBox sq{area.x + left, area.y, side, side};
    const geom::ParamRect dom = doc::tracing_domain(d, *obj);
    const DataMap m{sq, dom.u.lo, dom.u.hi, dom.v.lo, dom.v.hi};

    // The current patch's part of a group's domain, shaded.
    const geom::ParamRect own = geom::domain(*s);
    if (own.u.lo != dom.u.lo || own.u.hi != dom.u.hi || own.v.lo != dom.v.lo ||
        own.v.hi != dom.v.hi)
        dr.polygon({m(own.u.lo, own.v.lo), m(own.u.hi, own.v.lo), m(own.u.hi, own.v.hi),
                    m(own.u.lo, own.v.hi)},
                   stroke(Palette::muted, 1.2), DrawColor{0.93f, 0.95f, 1.0f, 1}, "current-patch");
    // Interior knot lines: where the surface's pieces meet.
    for (const KnotTick& t : knot_ticks(s->knots_u, s->degree_u, s->n_u))
        if (t.interior)
            dr.line(m(t.value, own.v.lo), m(t.value, own.v.hi), stroke(Palette::faint, 0.8),
                    "knot-line");
    for (const KnotTick& t : knot_ticks(s->knots_v, s->degree_v, s->n_v))
        if (t.interior)
            dr.line(m(own.u.lo, t.value), m(own.u.hi, t.value), stroke(Palette::faint, 0.8),
                    "knot-line");
    dr.polygon({m(dom.u.lo, dom.v.lo), m(dom.u.hi, dom.v.lo), m(dom.u.hi, dom.v.hi),
                m(dom.u.lo, dom.v.hi)},
               stroke(Palette::ink, 1.2), std::nullopt, "domain");
    knot_labels(dr, m, *s, geom::Dir::u, fs);
    knot_labels(dr, m, *s, geom::Dir::v, fs);
    dr.text(m(dom.u.hi, dom.v.lo) + glm::dvec2(0, 2.3 * fs), "u", fs * 1.1, Palette::ink,
            HAlign::right, VAlign::top, "axis-name");
    dr.text(m(dom.u.lo, dom.v.hi) + glm::dvec2(-4.6 * fs, 0), "v", fs * 1.1, Palette::ink,
            HAlign::left, VAlign::top, "axis-name");

    // The indicator and its cross-hairs.
    const glm::dvec2 uv = indicator_params(d, *obj);
    const glm::dvec2 p = m(uv);
    const DrawStroke hair = stroke(Palette::indicator, 0.7, {3, 2});
    dr.line(m(dom.u.lo, uv.y), m(dom.u.hi, uv.y), hair, "indicator-line");
    dr.line(m(uv.x, dom.v.lo), m(uv.x, dom.v.hi), hair, "indicator-line");
    // Labels placed together, the indicator's first, so none covers another.
    std::vector<glm::dvec2> at{p};
    std::vector<std::string> texts{"(u, v) = (" + number(uv.x) + ", " + number(uv.y) + ")"};
    // Weights at the Greville points: where each control point pulls the surface. Only the
    // weights other than 1 are written when most are 1 (a note says so).
    if (geom::is_rational(s->type)) {
        int ones = 0;
        for (double w : s->weights) ones += w == 1.0;
        const bool only_special = ones * 2 > static_cast<int>(s->weights.size());
        for (int i = 0; i < s->n_u; ++i)
            for (int j = 0; j < s->n_v; ++j) {
                const glm::dvec2 q = m(geom::greville_abscissa(s->knots_u, s->degree_u, i),
                                       geom::greville_abscissa(s->knots_v, s->degree_v, j));
                dr.dot(q, 1.6, Palette::muted, std::nullopt, "weight-point");
                if (only_special && s->weight(i, j) == 1.0) continue;
                at.push_back(q);
                texts.push_back("w_{" + std::to_string(i) + std::to_string(j) +
                                "} = " + number(s->weight(i, j)));
            }
        if (only_special)
            dr.text({sq.x, sq.y + sq.h + 3.0 * fs}, "other weights 1", 0.85 * fs, Palette::muted,
                    HAlign::left, VAlign::baseline, "weight-note");
    }
    const std::size_t first = dr.items.size();
    point_labels(dr, at, texts, 0.85 * fs, Palette::muted, "weight");
    auto& label = std::get<DrawText>(dr.items[first]);
    label.color = Palette::indicator;
    label.role = "indicator-label";
    dr.dot(p, 3.2, Palette::indicator, stroke(Palette::white, 0.8), "indicator");
    return dr;
}

} // namespace isoparm::ui::figure_detail
