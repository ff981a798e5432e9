// The Basis tab's drawings as data (see basis_picture.hpp).
#include "ui/view/basis_picture.hpp"

#include <algorithm>
#include <cmath>

#include "core/geom/basis.hpp"
#include "core/geom/tessellate.hpp"
#include "ui/view/canvas_map.hpp"

namespace isoparm::ui {

namespace {

constexpr int curve_samples = 161;

unsigned byte(float x) {
    return static_cast<unsigned>(std::clamp(x, 0.f, 1.f) * 255 + 0.5f);
}

} // namespace

Rgba8 heat_rgba(float t) {
    static const float stops[5][3] = {{0.05f, 0.03f, 0.20f},
                                      {0.35f, 0.08f, 0.50f},
                                      {0.75f, 0.20f, 0.35f},
                                      {0.97f, 0.55f, 0.10f},
                                      {0.99f, 0.95f, 0.45f}};
    if (t < 0) {
        const float a = std::clamp(-t, 0.f, 1.f);
        return rgba8(byte(0.05f), byte(0.1f + 0.6f * a), byte(0.2f + 0.7f * a));
    }
    const float x = std::clamp(t, 0.f, 1.f) * 4;
    const int k = std::min(static_cast<int>(x), 3);
    const float f = x - static_cast<float>(k);
    float c[3];
    for (int n = 0; n < 3; ++n) c[n] = stops[k][n] + (stops[k + 1][n] - stops[k][n]) * f;
    return rgba8(byte(c[0]), byte(c[1]), byte(c[2]));
}

Picture basis_curves_picture(const geom::Knots& U, int p, int n, int index, double t,
                             const std::string& title, const std::string& name, const Rect& box,
                             const CanvasView& view, float scale, float line_height,
                             const PlotColors& colors) {
    const float k = scale;
    Picture pic;
    pic.view = name;
    pic.frame = box;
    pic.background = colors.background;
    pic.border = colors.border;
    pic.border_width = k;
    const geom::Interval d{U[static_cast<std::size_t>(p)], U[static_cast<std::size_t>(n)]};
    const std::vector<double> ts = geom::uniform_params(d.lo, d.hi, curve_samples);
    std::vector<std::vector<double>> values; // values[sample][k]
    values.reserve(ts.size());
    for (double x : ts) values.push_back(geom::all_basis(U, p, n, x)[0]);
    // The title's line above the plot, so no curve runs under it.
    const float top = box.y + 6 * k + line_height, h = box.h - 10 * k - line_height;
    auto pt = [&](std::size_t sample, double y) {
        const glm::dvec2 fitted(box.x + box.w * static_cast<double>(sample) /
                                            static_cast<double>(ts.size() - 1),
                                top + h * (1.0 - y));
        return glm::vec2(view_pixel(view, box, fitted));
    };
    auto curve = [&](int f, Rgba8 color, float width) {
        std::vector<glm::vec2> line(ts.size());
        for (std::size_t s = 0; s < ts.size(); ++s)
            line[s] = pt(s, values[s][static_cast<std::size_t>(f)]);
        pic.polyline(std::move(line), color, width);
    };
    for (int f = 0; f < n; ++f)
        if (f != index) curve(f, colors.faint, 1 * k);
    if (index >= 0) curve(index, colors.strong, 2.5f * k);
    const float x =
        static_cast<float>(view_pixel(view, box, {box.x + box.w * normalize_param(d, t), 0}).x);
    pic.line({x, box.y}, {x, box.y + box.h}, colors.parameter, 1.5f * k);
    pic.fixed_label({box.x + 4 * k, box.y + 2 * k}, title, colors.title, LabelAlign::top_left);
    return pic;
}

Picture heat_picture(const HeatInput& in) {
    const float k = in.scale;
    const Rect& sq = in.square;
    Picture pic;
    pic.view = "basis_heat";
    pic.frame = in.canvas;
    pic.border = in.border;
    pic.border_width = k;
    const int r = in.resolution;
    if (in.values && r > 0) {
        const float cw = sq.w / static_cast<float>(r), ch = sq.h / static_cast<float>(r);
        for (int row = 0; row < r; ++row)
            for (int c = 0; c < r; ++c) {
                const float v = (*in.values)[static_cast<std::size_t>(row * r + c)];
                const glm::vec2 a(sq.x + static_cast<float>(c) * cw,
                                  sq.y + static_cast<float>(row) * ch);
                const Rgba8 col = std::isnan(v)
                                      ? rgba8(90, 90, 90)
                                      : heat_rgba(in.max_value > 0 ? v / in.max_value : 0.f);
                pic.box(a, {a.x + cw + 0.5f, a.y + ch + 0.5f}, col);
            }
    }
    // The support, clipped to the domain.
    pic.box(domain_to_pixel(sq, {in.u0, in.v1}), domain_to_pixel(sq, {in.u1, in.v0}), 0,
            rgba8(255, 255, 255, 230), 1.5f * k);
    const glm::vec2 p = domain_to_pixel(sq, in.at);
    pic.disk(p, 5 * k, in.indicator, rgba8(0, 0, 0), 1.2f * k);
    pic.fixed_label({in.canvas.x + 3 * k, in.canvas.y + 2 * k}, in.name, rgba8(255, 255, 255),
                    LabelAlign::top_left)
        .plate = rgba8(0, 0, 0, 140);
    return pic;
}

} // namespace isoparm::ui
