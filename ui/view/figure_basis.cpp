// The basis functions as a figure: every N_{i,p} over the domain, one path each, labelled at
// its peak, the selected control point's function stronger, their sum (the partition of
// unity) dashed at 1, the knots on the axis and the knot vector written out below.
#include <algorithm>
#include <cmath>

#include "core/geom/basis.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/tessellate.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/figure_common.hpp"

namespace isoparm::ui::figure_detail {

namespace {

// Colours that stay apart on paper and for most colour-blind readers (Okabe and Ito).
constexpr DrawColor function_colors[] = {
    {0.00f, 0.45f, 0.70f, 1}, {0.84f, 0.37f, 0.00f, 1}, {0.00f, 0.62f, 0.45f, 1},
    {0.80f, 0.47f, 0.65f, 1}, {0.34f, 0.71f, 0.91f, 1}, {0.90f, 0.62f, 0.00f, 1},
    {0.35f, 0.35f, 0.35f, 1},
};

std::string knot_vector_text(const geom::Knots& U) {
    std::string s;
    for (std::size_t k = 0; k < U.size(); ++k) s += (k ? ", " : "") + number(U[k]);
    return s;
}

} // namespace

geom::Expected<Drawing> basis_figure(const doc::Document& d, const FigureOptions& o) {
    // A selected curve shows its own basis; otherwise the current surface's, along o.direction.
    const doc::Object* sel = d.selected();
    const geom::Curve* curve = sel ? sel->curve() : nullptr;
    const doc::Object* obj = sel;
    const geom::Surface* s = curve ? nullptr : current_surface(d, &obj);
    if (!curve && !s)
        for (const doc::Object& other : d.objects)
            if ((curve = other.curve())) {
                obj = &other;
                break;
            }
    if (!curve && !s)
        return geom::make_error_nopath(geom::ErrorCode::schema,
                                       "the basis view needs a surface or a curve");
    const geom::Dir dir = curve ? geom::Dir::u : o.direction;
    const geom::Knots& U = curve ? curve->knots : s->knots(dir);
    const int p = curve ? curve->degree : s->degree(dir);
    const int n = curve ? curve->count() : s->count(dir);
    const char* var = curve ? "t" : dir == geom::Dir::u ? "u" : "v";
    double at =
        curve ? denormalize_param(geom::domain(*curve), o.t)
              : (dir == geom::Dir::u ? indicator_params(d, *obj).x : indicator_params(d, *obj).y);
    int selected = -1;
    if (obj && d.view.selection.object == obj->id)
        selected = dir == geom::Dir::u ? d.view.selection.i : d.view.selection.j;

    Drawing dr;
    const double fs = o.font_size;
    const PageBox area =
        start_page(dr, o,
                   "B-spline basis N_{i," + std::to_string(p) + "}(" + var + ") of " + obj->name +
                       " (" + std::to_string(n) + " functions)");
    const double left = 2.2 * fs, below = 4.6 * fs, above = 1.6 * fs;
    const PageBox plot{area.x + left, area.y + above, area.w - left - fs,
                       std::max(area.h - below - above, 4 * fs)};
    const geom::Interval dom{U[static_cast<std::size_t>(p)], U[static_cast<std::size_t>(n)]};
    const DataMap m{plot, dom.lo, dom.hi, 0, 1};

    // Axes: 0 and 1, the domain's ends.
    dr.line(m(dom.lo, 1), m(dom.hi, 1), stroke(Palette::grid, 0.6), "grid");
    dr.line(m(dom.lo, 0), m(dom.hi, 0), stroke(Palette::ink, 0.8), "axis");
    dr.line(m(dom.lo, 0), m(dom.lo, 1.05), stroke(Palette::ink, 0.8), "axis");
    dr.text(m(dom.lo, 0) + glm::dvec2(-0.4 * fs, 0), "0", fs, Palette::ink, HAlign::right,
            VAlign::middle, "axis-label");
    dr.text(m(dom.lo, 1) + glm::dvec2(-0.4 * fs, 0), "1", fs, Palette::ink, HAlign::right,
            VAlign::middle, "axis-label");

    const int samples = 241;
    const std::vector<double> ts = geom::uniform_params(dom.lo, dom.hi, samples);
    std::vector<std::vector<double>> values; // values[sample][i]
    values.reserve(ts.size());
    for (double x : ts) values.push_back(geom::all_basis(U, p, n, x)[0]);
    std::vector<glm::dvec2> peaks;
    std::vector<std::string> names;
    for (int i = 0; i < n; ++i) {
        std::vector<glm::dvec2> line;
        std::size_t best = 0;
        for (std::size_t k = 0; k < ts.size(); ++k) {
            const double y = values[k][static_cast<std::size_t>(i)];
            line.push_back(m(ts[k], y));
            if (y > values[best][static_cast<std::size_t>(i)]) best = k;
        }
        const DrawColor c =
            i == selected
                ? Palette::selected
                : function_colors[static_cast<std::size_t>(i) % std::size(function_colors)];
        dr.polyline(std::move(line), stroke(c, i == selected ? 2.4 : 1.3), "basis");
        peaks.push_back(m(ts[best], values[best][static_cast<std::size_t>(i)]));
        names.push_back("N_{" + std::to_string(i) + "," + std::to_string(p) + "}");
    }
    point_labels(dr, peaks, names, 0.9 * fs, Palette::ink, "basis-label");

    // The partition of unity: the sum of every function, 1 all over the domain.
    std::vector<glm::dvec2> sum;
    for (std::size_t k = 0; k < ts.size(); ++k) {
        double total = 0;
        for (double v : values[k]) total += v;
        sum.push_back(m(ts[k], total));
    }
    dr.polyline(std::move(sum), stroke(Palette::ink, 1.0, {4, 3}), "partition-of-unity");
    dr.text(m(dom.hi, 1) + glm::dvec2(0, -0.5 * fs), "sum of all = 1", 0.9 * fs, Palette::ink,
            HAlign::right, VAlign::bottom, "partition-label");

    // The knots on the axis, thinned so no two values touch.
    const std::vector<KnotTick> ticks = knot_ticks(U, p, n);
    std::vector<double> px;
    for (const KnotTick& t : ticks) px.push_back(m(t.value, 0).x);
    const std::vector<bool> keep = thin_labels(px, 3.2 * fs);
    for (std::size_t k = 0; k < ticks.size(); ++k) {
        const glm::dvec2 q = m(ticks[k].value, 0);
        dr.line(q, q + glm::dvec2(0, 0.5 * fs), stroke(Palette::ink, 0.8), "knot-tick");
        if (keep[k])
            dr.text(q + glm::dvec2(0, 0.8 * fs), number(ticks[k].value), fs, Palette::ink,
                    HAlign::center, VAlign::top, "knot-label");
    }
    // The parameter the panels trace.
    const DrawStroke hair = stroke(Palette::indicator, 0.8, {3, 2});
    dr.line(m(at, 0), m(at, 1.05), hair, "indicator-line");
    dr.text(m(at, 1.05) + glm::dvec2(0.3 * fs, 0), std::string(var) + " = " + number(at), 0.9 * fs,
            Palette::indicator, HAlign::left, VAlign::baseline, "indicator-label");
    dr.text({plot.x, plot.y + plot.h + 3.4 * fs}, "U = {" + knot_vector_text(U) + "}", 0.9 * fs,
            Palette::muted, HAlign::left, VAlign::baseline, "knot-vector");
    return dr;
}

} // namespace isoparm::ui::figure_detail
