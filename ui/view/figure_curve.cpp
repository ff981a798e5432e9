// The curve views as figures, in the curve's plane at one scale: the curve designer (control
// polygon, curve, knot points, curvature comb and Frenet frame at t), de Boor's construction
// at t (de Casteljau's on a Bezier curve), its blossom labels, and the homogeneous picture.
#include <algorithm>
#include <cmath>

#include "core/geom/blossom.hpp"
#include "core/geom/deboor.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/tessellate.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/curve_glyphs.hpp"
#include "ui/view/figure_common.hpp"
#include "ui/view/homogeneous_scene.hpp"

namespace isoparm::ui::figure_detail {

namespace {

constexpr int plane_axes[3][2] = {{0, 1}, {0, 2}, {1, 2}};
constexpr const char* plane_names[3] = {"xy", "xz", "yz"};

geom::Error no_curve(const char* view) {
    return geom::make_error_nopath(geom::ErrorCode::schema,
                                   std::string("the ") + view +
                                       " view needs a curve (Curve > New curve) or a surface");
}

// Level k of m levels: from cyan through green to yellow, then the red point (as the
// designer's canvas colours them).
DrawColor level_color(int level, int levels) {
    if (level >= levels) return Palette::indicator;
    const double f = levels > 1 ? static_cast<double>(level - 1) / (levels - 1) : 0;
    const double h = (0.5 - 0.36 * f) * 6, s = 0.85, v = 0.75;
    const int i = static_cast<int>(h);
    const double fr = h - i, p = v * (1 - s), q = v * (1 - s * fr), t = v * (1 - s * (1 - fr));
    double r = v, g = t, b = p;
    switch (i % 6) {
    case 0:
        r = v, g = t, b = p;
        break;
    case 1:
        r = q, g = v, b = p;
        break;
    case 2:
        r = p, g = v, b = t;
        break;
    case 3:
        r = p, g = q, b = v;
        break;
    case 4:
        r = t, g = p, b = v;
        break;
    default:
        r = v, g = p, b = q;
        break;
    }
    return {static_cast<float>(r), static_cast<float>(g), static_cast<float>(b), 1};
}

// The curve in its plane, fitted to the page: what every curve view starts from.
struct CurvePage {
    FigureCurve fc;
    int a = 0, b = 1;
    double t = 0;
    DataMap map;
    glm::dvec2 to2(const glm::dvec3& p) const { return {p[a], p[b]}; }
    glm::dvec2 operator()(const glm::dvec3& p) const { return map(to2(p)); }
};

// `only`: frame these points alone (de Boor's acting points), else the control points and
// `extra`.
CurvePage curve_page(Drawing& dr, const FigureOptions& o, FigureCurve fc, const std::string& title,
                     const std::vector<glm::dvec3>& extra, bool only_extra = false) {
    CurvePage cp;
    cp.fc = std::move(fc);
    const geom::Curve& c = cp.fc.curve;
    const std::array<int, 2> best = best_plane(c);
    const int plane = cp.fc.plane;
    cp.a = plane >= 0 ? plane_axes[plane][0] : best[0];
    cp.b = plane >= 0 ? plane_axes[plane][1] : best[1];
    cp.t = denormalize_param(geom::domain(c), std::clamp(o.t, 0.0, 1.0));
    glm::dvec2 lo(1e300), hi(-1e300);
    auto grow = [&](const glm::dvec3& p) {
        lo = glm::min(lo, cp.to2(p));
        hi = glm::max(hi, cp.to2(p));
    };
    if (!only_extra)
        for (const glm::dvec3& p : c.points) grow(p);
    for (const glm::dvec3& p : extra) grow(p);
    if (only_extra) {
        // Room around the acting points for the curve near them and the labels.
        const glm::dvec2 pad = glm::max(hi - lo, glm::dvec2(1e-6)) * 0.12;
        lo -= pad;
        hi += pad;
    }
    std::string plane_name;
    for (int k = 0; k < 3; ++k)
        if (plane_axes[k][0] == cp.a && plane_axes[k][1] == cp.b) plane_name = plane_names[k];
    const PageBox area = start_page(dr, o, title + " (" + plane_name + " plane)");
    const double margin = 2.2 * o.font_size;
    cp.map = fit_equal({area.x + margin, area.y + margin, area.w - 2 * margin, area.h - 2 * margin},
                       lo, hi);
    return cp;
}

std::vector<glm::dvec2> curve_line(const CurvePage& cp, int samples = 401) {
    std::vector<glm::dvec2> line;
    const geom::Interval d = geom::domain(cp.fc.curve);
    for (double s : geom::uniform_params(d.lo, d.hi, samples))
        if (auto p = geom::curve_point(cp.fc.curve, s)) line.push_back(cp(*p));
    return line;
}

// Control polygon (dashed), the curve, the knot points; the control points' labels are
// returned for one placement with the rest.
void curve_basics(Drawing& dr, const CurvePage& cp, std::vector<glm::dvec2>& anchors,
                  std::vector<std::string>& labels, bool faint_polygon = false) {
    const geom::Curve& c = cp.fc.curve;
    std::vector<glm::dvec2> poly;
    for (const glm::dvec3& p : c.points) poly.push_back(cp(p));
    dr.polyline(poly, stroke(faint_polygon ? Palette::faint : Palette::muted, 0.8, {3, 2}),
                "control-polygon");
    dr.polyline(curve_line(cp), stroke(Palette::curve, 1.8), "curve");
    const geom::Interval d = geom::domain(c);
    for (const geom::KnotRun& run : geom::knot_runs(c.knots))
        if (d.contains(run.value))
            if (auto p = geom::curve_point(c, run.value))
                dr.polygon({cp(*p) + glm::dvec2(-1.8, -1.8), cp(*p) + glm::dvec2(1.8, -1.8),
                            cp(*p) + glm::dvec2(1.8, 1.8), cp(*p) + glm::dvec2(-1.8, 1.8)},
                           stroke(Palette::curve, 0.8), Palette::white, "knot-point");
    for (std::size_t i = 0; i < poly.size(); ++i) {
        dr.dot(poly[i], 2.4, Palette::ink, std::nullopt, "control-point");
        anchors.push_back(poly[i]);
        labels.push_back("P_{" + std::to_string(i) + "}");
    }
}

bool is_bezier(const geom::Curve& c) {
    return static_cast<int>(c.knots.size()) == 2 * (c.degree + 1) &&
           c.knots.front() == c.knots[static_cast<std::size_t>(c.degree)] &&
           c.knots.back() == c.knots[static_cast<std::size_t>(c.degree + 1)];
}

std::string polar_text(const std::vector<double>& args, double t) {
    std::string s = "f(";
    for (std::size_t k = 0; k < args.size(); ++k)
        s += (k ? ", " : "") + (args[k] == t ? std::string("t") : number(args[k]));
    return s + ")";
}

void arrow(Drawing& dr, glm::dvec2 from, glm::dvec2 to, DrawColor c, const std::string& role) {
    dr.line(from, to, stroke(c, 1.4), role);
    const glm::dvec2 dir = to - from;
    const double len = std::hypot(dir.x, dir.y);
    if (len < 1e-9) return;
    const glm::dvec2 u = dir / len, n(-u.y, u.x);
    dr.polygon({to, to - 6.0 * u + 2.5 * n, to - 6.0 * u - 2.5 * n}, std::nullopt, c, role);
}

} // namespace

geom::Expected<Drawing> curve_figure(const doc::Document& d, const FigureOptions& o, bool deboor) {
    std::optional<FigureCurve> fc = figure_curve(d);
    if (!fc) return no_curve(deboor ? "de Boor" : "curve");
    const geom::Curve& c = fc->curve;
    const double t = denormalize_param(geom::domain(c), std::clamp(o.t, 0.0, 1.0));
    // The glyphs reach beyond the control points: the page frames them too.
    CurveGlyphs glyphs;
    std::vector<glm::dvec3> extra;
    if (!deboor) {
        glyphs = curve_glyphs(c, t, {o.comb, false, o.frenet});
        for (const auto& [base, tip] : glyphs.teeth) extra.push_back(tip);
        if (glyphs.point && glyphs.tangent && glyphs.normal) {
            extra.push_back(*glyphs.point + glyphs.frame_length * *glyphs.tangent);
            extra.push_back(*glyphs.point + glyphs.frame_length * *glyphs.normal);
        }
    }
    const bool bezier = is_bezier(c);
    const std::string title = deboor ? std::string(bezier ? "de Casteljau's" : "de Boor's") +
                                           " construction on " + fc->name + " at t = " + number(t)
                                     : fc->name + ": degree " + std::to_string(c.degree) + ", " +
                                           std::to_string(c.count()) + " control points";
    if (deboor) {
        const geom::DeBoorTriangle acting = geom::deboor_curve(c, t);
        for (const geom::HPoint& h : acting.levels[0])
            if (auto p = geom::DeBoorTriangle::cartesian(h)) extra.push_back(*p);
    }
    Drawing dr;
    const CurvePage cp = curve_page(dr, o, *fc, title, extra, deboor && extra.size() > 1);
    std::vector<glm::dvec2> anchors;
    std::vector<std::string> labels;
    curve_basics(dr, cp, anchors, labels, deboor);
    const double fs = o.font_size;

    if (!deboor) {
        if (!glyphs.teeth.empty()) {
            for (const auto& [base, tip] : glyphs.teeth)
                dr.line(cp(base), cp(tip), stroke(Palette::comb, 0.6), "comb");
            std::vector<glm::dvec2> rim;
            for (const glm::dvec3& p : glyphs.rim) rim.push_back(cp(p));
            dr.polyline(std::move(rim), stroke(Palette::comb, 1.0), "comb-rim");
        }
        if (glyphs.point && glyphs.tangent && glyphs.normal) {
            const glm::dvec2 at = cp(*glyphs.point);
            arrow(dr, at, cp(*glyphs.point + glyphs.frame_length * *glyphs.tangent),
                  Palette::indicator, "frenet");
            arrow(dr, at, cp(*glyphs.point + glyphs.frame_length * *glyphs.normal), Palette::comb,
                  "frenet");
            dr.dot(at, 2.6, Palette::indicator, std::nullopt, "curve-point");
            anchors.push_back(cp(*glyphs.point + glyphs.frame_length * *glyphs.tangent));
            labels.push_back("T");
            anchors.push_back(cp(*glyphs.point + glyphs.frame_length * *glyphs.normal));
            labels.push_back("N");
            anchors.push_back(at);
            labels.push_back("C(" + number(t) + ")");
        }
        point_labels(dr, anchors, labels, fs, Palette::ink, "label");
        return dr;
    }

    // de Boor's triangle: level k holds p + 1 - k points, each an affine combination of two
    // of the level before (Piegl & Tiller A5.1 in homogeneous space).
    const geom::DeBoorTriangle tri = geom::deboor_curve(c, t);
    const int levels = static_cast<int>(tri.levels.size()) - 1;
    const int shown = o.deboor_level < 0 ? levels : std::min(o.deboor_level, levels);
    // The acting control points (level 0) stand out.
    for (const geom::HPoint& h : tri.levels[0])
        if (auto p = geom::DeBoorTriangle::cartesian(h))
            dr.dot(cp(*p), 3.4, Palette::selected, std::nullopt, "acting-point");
    for (int lv = 1; lv <= shown; ++lv) {
        const DrawColor col = level_color(lv, levels);
        std::vector<glm::dvec2> pts;
        for (std::size_t i = 0; i < tri.levels[static_cast<std::size_t>(lv)].size(); ++i) {
            const auto p =
                geom::DeBoorTriangle::cartesian(tri.levels[static_cast<std::size_t>(lv)][i]);
            if (!p) continue;
            pts.push_back(cp(*p));
            const int index = tri.first_index + static_cast<int>(i) + lv;
            anchors.push_back(pts.back());
            labels.push_back(lv == levels ? "C(t)"
                                          : "d^{" + std::to_string(lv) + "}_{" +
                                                std::to_string(index) + "}");
        }
        if (pts.size() > 1) dr.polyline(pts, stroke(col, 1.3), "deboor-level");
        for (const glm::dvec2& q : pts)
            dr.dot(q, lv == levels ? 3.4 : 2.4, col, stroke(Palette::ink, 0.4), "deboor-point");
    }
    point_labels(dr, anchors, labels, fs, Palette::ink, "label");
    return dr;
}

geom::Expected<Drawing> blossom_figure(const doc::Document& d, const FigureOptions& o) {
    std::optional<FigureCurve> fc = figure_curve(d);
    if (!fc) return no_curve("blossom");
    const geom::Curve& c = fc->curve;
    const double t = denormalize_param(geom::domain(c), std::clamp(o.t, 0.0, 1.0));
    const geom::DeBoorTriangle tri = geom::deboor_curve(c, t);
    const std::size_t s = static_cast<std::size_t>(tri.span);
    Drawing dr;
    std::vector<glm::dvec3> acting;
    for (const geom::HPoint& h : tri.levels[0])
        if (auto p = geom::DeBoorTriangle::cartesian(h)) acting.push_back(*p);
    const CurvePage cp = curve_page(dr, o, *fc,
                                    "Blossom of " + fc->name + " on [" + number(c.knots[s]) + ", " +
                                        number(c.knots[s + 1]) + "), t = " + number(t),
                                    acting, acting.size() > 1);
    std::vector<glm::dvec2> anchors;
    std::vector<std::string> labels;
    std::vector<glm::dvec2> unused_anchors;
    std::vector<std::string> unused_labels;
    curve_basics(dr, cp, unused_anchors, unused_labels, true);
    const int levels = static_cast<int>(tri.levels.size()) - 1;
    for (int lv = 0; lv <= levels; ++lv) {
        const DrawColor col = lv == 0 ? Palette::selected : level_color(lv, levels);
        std::vector<glm::dvec2> pts;
        for (std::size_t i = 0; i < tri.levels[static_cast<std::size_t>(lv)].size(); ++i) {
            const auto p =
                geom::DeBoorTriangle::cartesian(tri.levels[static_cast<std::size_t>(lv)][i]);
            if (!p) continue;
            pts.push_back(cp(*p));
            const int index = tri.first_index + static_cast<int>(i) + lv;
            anchors.push_back(pts.back());
            labels.push_back(
                polar_text(geom::deboor_point_arguments(c.knots, c.degree, lv, index, t), t));
        }
        if (lv > 0 && pts.size() > 1) dr.polyline(pts, stroke(col, 1.2), "deboor-level");
        for (const glm::dvec2& q : pts)
            dr.dot(q, 2.6, col, stroke(Palette::ink, 0.4), "blossom-point");
    }
    point_labels(dr, anchors, labels, 0.85 * o.font_size, Palette::ink, "blossom-label");
    return dr;
}

geom::Expected<Drawing> homogeneous_figure(const doc::Document& d, const FigureOptions& o) {
    std::optional<FigureCurve> fc = figure_curve(d);
    if (!fc) return no_curve("homogeneous");
    const geom::Curve& c = fc->curve;
    const std::array<int, 2> axes =
        fc->plane >= 0 ? std::array<int, 2>{plane_axes[fc->plane][0], plane_axes[fc->plane][1]}
                       : best_plane(c);
    const double t = denormalize_param(geom::domain(c), std::clamp(o.t, 0.0, 1.0));
    const HomogeneousScene hs = homogeneous_scene(c, axes, t);
    auto proj = [&](const glm::dvec3& p) {
        const glm::dvec3 q = orbit_project(p, o.yaw, o.pitch);
        return glm::dvec2(q.x, q.y);
    };
    // The page frames everything drawn, the origin included.
    const glm::dvec3 plane[4] = {{hs.plane_lo.x, hs.plane_lo.y, 1},
                                 {hs.plane_hi.x, hs.plane_lo.y, 1},
                                 {hs.plane_hi.x, hs.plane_hi.y, 1},
                                 {hs.plane_lo.x, hs.plane_hi.y, 1}};
    const double w_top = std::max(hs.hi.z, 1.0) * 1.15;
    glm::dvec2 lo(1e300), hi(-1e300);
    auto grow = [&](const glm::dvec3& p) {
        lo = glm::min(lo, proj(p));
        hi = glm::max(hi, proj(p));
    };
    grow({0, 0, 0});
    grow({0, 0, w_top});
    for (const glm::dvec3& p : plane) grow(p);
    for (const glm::dvec3& p : hs.lifted_points) grow(p);
    for (const glm::dvec3& p : hs.lifted_curve) grow(p);

    Drawing dr;
    const PageBox area = start_page(
        dr, o, "Homogeneous picture of " + fc->name + ": (w x, w y, w) projected to w = 1");
    const double margin = 2 * o.font_size;
    const DataMap m = fit_equal(
        {area.x + margin, area.y + margin, area.w - 2 * margin, area.h - 2 * margin}, lo, hi);
    auto at = [&](const glm::dvec3& p) { return m(proj(p)); };
    const double fs = o.font_size;

    std::vector<glm::dvec2> quad;
    for (const glm::dvec3& p : plane) quad.push_back(at(p));
    dr.polygon(quad, stroke(Palette::faint, 0.6), DrawColor{0.90f, 0.93f, 0.98f, 1}, "plane-w1");
    dr.text(quad[1] + glm::dvec2(0.3 * fs, 0), "w = 1", fs, Palette::muted, HAlign::left,
            VAlign::middle, "plane-label");
    arrow(dr, at({0, 0, 0}), at({0, 0, w_top}), Palette::ink, "axis");
    dr.text(at({0, 0, w_top}) + glm::dvec2(0.4 * fs, 0), "w", fs, Palette::ink, HAlign::left,
            VAlign::middle, "axis-name");
    dr.dot(at({0, 0, 0}), 2, Palette::ink, std::nullopt, "origin");
    // Rays from the origin through each lifted point meet w = 1 at the control point.
    for (std::size_t i = 0; i < hs.lifted_points.size(); ++i) {
        const glm::dvec3& lp = hs.lifted_points[i];
        const glm::dvec3 far = lp.z >= 1 || hs.weights[i] <= 0 ? lp : hs.projected_points[i];
        dr.line(at({0, 0, 0}), at(far), stroke(Palette::faint, 0.6, {2, 2}), "ray");
    }
    std::vector<glm::dvec2> anchors;
    std::vector<std::string> labels;
    std::vector<glm::dvec2> poly;
    for (std::size_t i = 0; i < hs.projected_points.size(); ++i)
        if (hs.weights[i] != 0) poly.push_back(at(hs.projected_points[i]));
    dr.polyline(poly, stroke(Palette::muted, 0.8, {3, 2}), "control-polygon");
    for (const auto& piece : hs.projected_curve) {
        std::vector<glm::dvec2> line;
        for (const glm::dvec3& p : piece) line.push_back(at(p));
        dr.polyline(std::move(line), stroke(Palette::curve, 1.6), "projected-curve");
    }
    poly.clear();
    for (const glm::dvec3& p : hs.lifted_points) poly.push_back(at(p));
    dr.polyline(poly, stroke(Palette::selected, 0.8, {3, 2}), "lifted-polygon");
    std::vector<glm::dvec2> lifted;
    for (const glm::dvec3& p : hs.lifted_curve) lifted.push_back(at(p));
    dr.polyline(std::move(lifted), stroke(Palette::selected, 1.6), "lifted-curve");
    for (std::size_t i = 0; i < hs.lifted_points.size(); ++i) {
        dr.dot(poly[i], 2.2, Palette::selected, std::nullopt, "lifted-point");
        anchors.push_back(poly[i]);
        labels.push_back("P^{w}_{" + std::to_string(i) + "}");
        if (hs.weights[i] != 0) {
            const glm::dvec2 q = at(hs.projected_points[i]);
            dr.dot(q, 2.2, Palette::curve, std::nullopt, "control-point");
            anchors.push_back(q);
            labels.push_back("P_{" + std::to_string(i) + "}");
        }
    }
    if (hs.lifted_at_t && hs.projected_at_t) {
        dr.line(at({0, 0, 0}), at(*hs.lifted_at_t), stroke(Palette::indicator, 0.8, {3, 2}),
                "ray-at-t");
        dr.dot(at(*hs.lifted_at_t), 3, Palette::indicator, std::nullopt, "point-at-t");
        dr.dot(at(*hs.projected_at_t), 3, Palette::indicator, std::nullopt, "point-at-t");
        anchors.push_back(at(*hs.lifted_at_t));
        labels.push_back("C^{w}(t)");
        anchors.push_back(at(*hs.projected_at_t));
        labels.push_back("C(t)");
    }
    point_labels(dr, anchors, labels, 0.9 * fs, Palette::ink, "label");
    return dr;
}

} // namespace isoparm::ui::figure_detail
