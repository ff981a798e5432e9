// The tracing square's drawing as data (see tracing_picture.hpp).
#include "ui/view/tracing_picture.hpp"

#include <string>

#include "core/doc/patches.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/status.hpp"
#include "core/geom/trim/trim_classify.hpp"
#include "core/geom/trim/trim_flatten.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

namespace {

glm::vec2 param_pixel(const Rect& sq, const geom::ParamRect& dom, double u, double v) {
    return glm::vec2(domain_to_pixel(sq, {normalize_param(dom.u, u), normalize_param(dom.v, v)}));
}

// The rational picture over the current surface's part of the square: where w(u, v) < 0 a
// tint, and its zero set (where the surface goes to infinity) as a strong line.
void denominator(Picture& pic, const geom::Surface& s, const DenominatorView& view,
                 const geom::ParamRect& dom, const TracingInput& in) {
    const float k = in.scale;
    auto px = [&](double u, double v) { return param_pixel(in.square, dom, u, v); };
    const geom::ParamRect own = geom::domain(s);
    const int n = DenominatorView::sign_cells;
    const double du = (own.u.hi - own.u.lo) / n, dv = (own.v.hi - own.v.lo) / n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            if (view.signs()[static_cast<std::size_t>(i) * n + j] < 0)
                pic.box(px(own.u.lo + i * du, own.v.lo + (j + 1) * dv),
                        px(own.u.lo + (i + 1) * du, own.v.lo + j * dv), in.colors.negative);
    for (const geom::ParamSegment& seg : view.zero_set())
        pic.line(px(seg.a.x, seg.a.y), px(seg.b.x, seg.b.y), in.colors.zero, 2.5f * k);
}

// Each weight at its control point's Greville point (u_i*, v_j*), where that point pulls the
// surface most; weights other than 1 first (what the lesson is about), the rest where the
// placer finds room (the others are counted in its "+n").
void weight_labels(Picture& pic, const geom::Surface& s, const geom::ParamRect& dom,
                   const TracingInput& in) {
    for (int i = 0; i < s.n_u; ++i) {
        const double u = geom::greville_abscissa(s.knots_u, s.degree_u, i);
        for (int j = 0; j < s.n_v; ++j) {
            const double w = s.weight(i, j);
            const double v = geom::greville_abscissa(s.knots_v, s.degree_v, j);
            LabelRequest& r =
                pic.label(param_pixel(in.square, dom, u, v), geom::format_short(w),
                          w <= 0 ? in.colors.weight_warning : in.colors.weight, w != 1 ? 20 : 5);
            r.plate = in.colors.weight_plate;
            r.tooltip = point_name('w', i, j, s.n_u, s.n_v) + " = " + geom::format_number(w);
        }
    }
}

// The knot ticks beside the square (a held knot's highlighted) with their values and, where
// they say something, their multiplicities.
void knot_tick_labels(Picture& pic, const TracingPicture& out, const geom::Surface& s,
                      const TracingInput& in) {
    const float k = in.scale;
    const TracingColors& c = in.colors;
    const Rect& canvas = in.canvas;
    const glm::vec2 a(canvas.x, canvas.y), b(canvas.x + canvas.w, canvas.y + canvas.h);
    const float tick = 7 * k;
    const std::vector<KnotTick>& tu = out.ticks_u;
    const std::vector<KnotTick>& tv = out.ticks_v;
    auto held = [&](geom::Dir dir, const KnotTick& t) {
        return in.held && in.held->first == dir && in.held->second == t.first_index;
    };
    // The domain's ends and a held knot matter most: the placer drops an interior value that
    // would merge with them ("0.75" and "1" read as "0.751").
    auto tick_priority = [](const std::vector<KnotTick>& ts, std::size_t n, bool h) {
        return h ? 200 : (n == 0 || n + 1 == ts.size()) ? 150 : 100;
    };
    const float lh = in.line_height;
    for (std::size_t n = 0; n < tu.size(); ++n) {
        const float x = static_cast<float>(out.px_u[n]);
        if (x < canvas.x - 0.5f || x > canvas.x + canvas.w + 0.5f) continue;
        const bool h = held(geom::Dir::u, tu[n]);
        pic.line({x, b.y}, {x, b.y + tick}, h ? c.indicator : c.tick, (h ? 4 : 2) * k);
        const int pr = tick_priority(tu, n, h);
        pic.fixed_label({x, b.y + tick + 1}, geom::format_short(tu[n].value), c.text,
                        LabelAlign::top_center, pr)
            .tooltip = "u knot " + geom::format_number(tu[n].value);
        // Interior multiplicities (a clamped end's p + 1 says nothing new; the knot vector
        // under the square lists it).
        if (tu[n].multiplicity > 1 && (tu[n].interior || tu[n].multiplicity != s.degree_u + 1))
            pic.fixed_label({x, b.y + tick + 5 + lh}, "x" + std::to_string(tu[n].multiplicity),
                            c.multiplicity, LabelAlign::top_center, pr - 1);
    }
    for (std::size_t n = 0; n < tv.size(); ++n) {
        const float y = static_cast<float>(out.px_v[n]);
        if (y < canvas.y - 0.5f || y > canvas.y + canvas.h + 0.5f) continue;
        const bool h = held(geom::Dir::v, tv[n]);
        pic.line({a.x - tick, y}, {a.x, y}, h ? c.indicator : c.tick, (h ? 4 : 2) * k);
        const bool mult =
            tv[n].multiplicity > 1 && (tv[n].interior || tv[n].multiplicity != s.degree_v + 1);
        const int pr = tick_priority(tv, n, h);
        pic.fixed_label({a.x - tick - 3 * k, y}, geom::format_short(tv[n].value), c.text,
                        mult ? LabelAlign::bottom_right : LabelAlign::center_right, pr)
            .tooltip = "v knot " + geom::format_number(tv[n].value);
        if (mult)
            pic.fixed_label({a.x - tick - 3 * k, y}, "x" + std::to_string(tv[n].multiplicity),
                            c.multiplicity, LabelAlign::top_right, pr - 1);
    }
}

// Cells per side of the shading of what a trim cuts away.
constexpr int trim_shade_cells = 64;

// A trimmed surface's loops over its own part of the square, and the cells whose centres the
// trim cuts away shaded.
void trim_loops(Picture& pic, const geom::Trim& trim, const geom::ParamRect& own,
                const geom::ParamRect& dom, const TracingInput& in) {
    auto px = [&](double u, double v) { return param_pixel(in.square, dom, u, v); };
    const geom::TrimClassifier classify(trim, own);
    const int n = trim_shade_cells;
    const double du = (own.u.hi - own.u.lo) / n, dv = (own.v.hi - own.v.lo) / n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const glm::dvec2 centre{own.u.lo + (i + 0.5) * du, own.v.lo + (j + 0.5) * dv};
            if (classify.classify(centre) == geom::TrimSide::cut)
                pic.box(px(own.u.lo + i * du, own.v.lo + (j + 1) * dv),
                        px(own.u.lo + (i + 1) * du, own.v.lo + j * dv), in.colors.cut);
        }
    // Chords within a thousandth of the domain: smooth at any zoom the square allows.
    geom::FlattenRule rule;
    rule.tolerance = 1e-3 * geom::domain_scale(own);
    for (int k = 0; k < trim.loop_count(); ++k) {
        std::vector<glm::vec2> points;
        for (const glm::dvec2& p : geom::flatten_loop(trim.loop(k), rule).points)
            points.push_back(px(p.x, p.y));
        pic.polyline(std::move(points), in.colors.trim, 2.0f * in.scale, /*closed=*/true);
    }
}

// The ends of the shared domain where the current patch does not reach them.
void shared_domain_ends(Picture& pic, const geom::ParamRect& own, const geom::ParamRect& dom,
                        const TracingInput& in) {
    const float k = in.scale;
    const TracingColors& c = in.colors;
    const Rect& sq = in.square;
    const glm::vec2 a(in.canvas.x, in.canvas.y),
        b(in.canvas.x + in.canvas.w, in.canvas.y + in.canvas.h);
    const float tick = 7 * k;
    if (own.u.lo > dom.u.lo)
        pic.fixed_label({sq.x, b.y + tick + 1}, geom::format_short(dom.u.lo), c.faint,
                        LabelAlign::top_center, 90);
    if (own.u.hi < dom.u.hi)
        pic.fixed_label({sq.x + sq.w, b.y + tick + 1}, geom::format_short(dom.u.hi), c.faint,
                        LabelAlign::top_center, 90);
    if (own.v.lo > dom.v.lo)
        pic.fixed_label({a.x - tick - 3 * k, sq.y + sq.h}, geom::format_short(dom.v.lo), c.faint,
                        LabelAlign::center_right, 90);
    if (own.v.hi < dom.v.hi)
        pic.fixed_label({a.x - tick - 3 * k, sq.y}, geom::format_short(dom.v.hi), c.faint,
                        LabelAlign::center_right, 90);
}

} // namespace

TracingPicture tracing_picture(const doc::Document& d, const doc::Object& obj,
                               const TracingInput& in) {
    TracingPicture out;
    const geom::Surface& s = *obj.surface();
    const float k = in.scale;
    const TracingColors& c = in.colors;
    const Rect& canvas = in.canvas;
    const Rect& sq = in.square;
    // Subpatches share the original domain: the square shows all of it.
    const geom::ParamRect dom = doc::tracing_domain(d, obj);
    const std::vector<const doc::Object*> patches = doc::patch_members(d, obj.patch_group);
    auto to_square = [&](double u, double v) {
        return glm::dvec2{normalize_param(dom.u, u), normalize_param(dom.v, v)};
    };

    Picture& pic = out.picture;
    pic.view = "tracing";
    pic.frame = {canvas.x - in.label_w, canvas.y - 6 * k, in.label_w + canvas.w + 6 * k,
                 canvas.h + 6 * k + in.label_h};
    pic.style.offset = 4 * k;
    const glm::vec2 a(canvas.x, canvas.y), b(canvas.x + canvas.w, canvas.y + canvas.h);
    pic.box(a, b, c.background);
    pic.begin_clip(canvas);

    // The other subpatches, and the current one's part of the square.
    for (const doc::Object* p : patches) {
        const geom::ParamRect r = geom::domain(*p->surface());
        const glm::vec2 lo = domain_to_pixel(sq, to_square(r.u.lo, r.v.hi));
        const glm::vec2 hi = domain_to_pixel(sq, to_square(r.u.hi, r.v.lo));
        if (p == &obj) pic.box(lo, hi, c.current);
        pic.box(lo, hi, 0, c.border, 2.5f * k);
        pic.fixed_label({lo.x + 3 * k, lo.y + 2 * k}, p->name, c.text, LabelAlign::top_left, 40)
            .tooltip = p->name;
    }

    // Knot lines across the current patch (where the knot curves run) and ticks with labels.
    const geom::ParamRect own = geom::domain(s);
    out.ticks_u = knot_ticks(s.knots_u, s.degree_u, s.n_u);
    out.ticks_v = knot_ticks(s.knots_v, s.degree_v, s.n_v);
    const std::vector<KnotTick>& tu = out.ticks_u;
    const std::vector<KnotTick>& tv = out.ticks_v;
    for (const KnotTick& t : tu) out.px_u.push_back(sq.x + normalize_param(dom.u, t.value) * sq.w);
    for (const KnotTick& t : tv)
        out.px_v.push_back(sq.y + (1.0 - normalize_param(dom.v, t.value)) * sq.h);
    const glm::dvec2 own_lo = domain_to_pixel(sq, to_square(own.u.lo, own.v.lo));
    const glm::dvec2 own_hi = domain_to_pixel(sq, to_square(own.u.hi, own.v.hi));
    for (std::size_t n = 0; n < tu.size(); ++n) {
        const float x = static_cast<float>(out.px_u[n]);
        const float w = (1.0f + static_cast<float>(tu[n].multiplicity - 1) * 1.2f) * k;
        if (tu[n].interior)
            pic.line({x, static_cast<float>(own_hi.y)}, {x, static_cast<float>(own_lo.y)}, c.grid,
                     w);
    }
    for (std::size_t n = 0; n < tv.size(); ++n) {
        const float y = static_cast<float>(out.px_v[n]);
        const float w = (1.0f + static_cast<float>(tv[n].multiplicity - 1) * 1.2f) * k;
        if (tv[n].interior)
            pic.line({static_cast<float>(own_lo.x), y}, {static_cast<float>(own_hi.x), y}, c.grid,
                     w);
    }
    pic.end_clip();
    knot_tick_labels(pic, out, s, in);
    pic.box(a, b, 0, c.border, 1.5f * k);
    shared_domain_ends(pic, own, dom, in);
    pic.fixed_label({b.x - 4 * k, b.y - 2 * k}, "u", c.text, LabelAlign::bottom_right, 120);
    pic.fixed_label({a.x + 4 * k, a.y + 2 * k}, "v", c.text, LabelAlign::top_left, 120);

    pic.begin_clip(canvas);
    if (in.denominator && geom::is_rational(s.type)) denominator(pic, s, *in.denominator, dom, in);
    const geom::Trim* trim = doc::trim_of(obj.shape);
    if (trim && !trim->empty()) {
        trim_loops(pic, *trim, own, dom, in);
        const glm::dvec2 at{dom.u.lo + d.view.indicator.x * (dom.u.hi - dom.u.lo),
                            dom.v.lo + d.view.indicator.y * (dom.v.hi - dom.v.lo)};
        out.indicator_cut = !own.contains(at) ||
                            geom::TrimClassifier(*trim, own).classify(at) == geom::TrimSide::cut;
    }
    // The indicator with its two isoparametric lines; hollow where the trim cuts it away.
    const glm::vec2 ip = domain_to_pixel(sq, d.view.indicator);
    out.indicator = ip;
    pic.line({ip.x, a.y}, {ip.x, b.y}, c.cross, 1.5f * k);
    pic.line({a.x, ip.y}, {b.x, ip.y}, c.cross, 1.5f * k);
    if (out.indicator_cut)
        pic.disk(ip, 7 * k, 0, c.indicator, 2.5f * k);
    else
        pic.disk(ip, 7 * k, c.indicator, rgba8(0, 0, 0), 1.5f * k);
    pic.end_clip();
    if (out.indicator_cut)
        pic.label(ip, "cut away", c.indicator, 130).tooltip =
            "the indicator is outside the trimmed surface's kept region: no point of the surface "
            "there";
    if (canvas.contains(ip.x, ip.y))
        pic.keep_clear.push_back({ip.x - 7 * k, ip.y - 7 * k, 14 * k, 14 * k});
    if (in.weights && geom::is_rational(s.type)) weight_labels(pic, s, dom, in);
    return out;
}

} // namespace isoparm::ui
