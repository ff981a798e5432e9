// The 3D view as a vector figure: the overlay's segments clipped against a depth buffer of
// the surfaces (hidden-line removal by sampling, the way a z-buffer renderer decides pixel
// by pixel, but kept as vector pieces), sorted back to front.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "core/geom/knots.hpp"
#include "core/geom/tessellate.hpp"
#include "ui/view/figure_common.hpp"
#include "ui/view/scene_builder.hpp"

namespace isoparm::ui {

namespace {

using figure_detail::stroke;

// Screen position (page points) and the eye's distance along the view direction.
struct ScreenPoint {
    glm::dvec2 p;
    double depth = 0;
    bool ok = false;
};

class Projector {
public:
    Projector(const Camera& c, double w, double h)
        : vp_(view_projection(c, w / h)), view_(view_matrix(c)), w_(w), h_(h) {}
    ScreenPoint operator()(const glm::dvec3& x) const {
        const glm::dvec4 clip = vp_ * glm::dvec4(x, 1);
        if (clip.w <= 1e-12) return {};
        const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
        const double depth = -(view_ * glm::dvec4(x, 1)).z;
        return {{(ndc.x + 1) / 2 * w_, (1 - ndc.y) / 2 * h_}, depth, true};
    }

private:
    glm::dmat4 vp_, view_;
    double w_, h_;
};

// The nearest surface depth per cell of a grid over the page (1 / depth interpolated, which
// is affine on the screen).
class DepthBuffer {
public:
    DepthBuffer(double page_w, double page_h, double cells_per_point)
        : k_(cells_per_point), w_(std::max(1, static_cast<int>(page_w * k_))),
          h_(std::max(1, static_cast<int>(page_h * k_))),
          inv_(static_cast<std::size_t>(w_) * h_, 0.0) {}

    void triangle(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c) {
        if (!a.ok || !b.ok || !c.ok) return;
        const glm::dvec2 pa = a.p * k_, pb = b.p * k_, pc = c.p * k_;
        const double area = (pb.x - pa.x) * (pc.y - pa.y) - (pc.x - pa.x) * (pb.y - pa.y);
        if (std::abs(area) < 1e-12) return;
        const int x0 = std::max(0, static_cast<int>(std::floor(std::min({pa.x, pb.x, pc.x}))));
        const int x1 = std::min(w_ - 1, static_cast<int>(std::ceil(std::max({pa.x, pb.x, pc.x}))));
        const int y0 = std::max(0, static_cast<int>(std::floor(std::min({pa.y, pb.y, pc.y}))));
        const int y1 = std::min(h_ - 1, static_cast<int>(std::ceil(std::max({pa.y, pb.y, pc.y}))));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const glm::dvec2 q(x + 0.5, y + 0.5);
                const double l1 =
                    ((pc.x - pb.x) * (q.y - pb.y) - (q.x - pb.x) * (pc.y - pb.y)) / area;
                const double l2 =
                    ((pa.x - pc.x) * (q.y - pc.y) - (q.x - pc.x) * (pa.y - pc.y)) / area;
                const double l3 = 1 - l1 - l2;
                constexpr double edge = -1e-6;
                if (l1 < edge || l2 < edge || l3 < edge) continue;
                const double inv = l1 / a.depth + l2 / b.depth + l3 / c.depth;
                double& cell = inv_[static_cast<std::size_t>(y) * w_ + x];
                cell = std::max(cell, inv);
            }
    }

    // Whether a point at `depth` is in front of every surface around `p` (the cell and its
    // neighbours: a line drawn on a surface must not flicker out at the mesh's edges).
    bool visible(const glm::dvec2& p, double depth, double tolerance) const {
        const int cx = static_cast<int>(p.x * k_), cy = static_cast<int>(p.y * k_);
        double nearest = std::numeric_limits<double>::infinity();
        for (int y = cy - 1; y <= cy + 1; ++y)
            for (int x = cx - 1; x <= cx + 1; ++x) {
                if (x < 0 || y < 0 || x >= w_ || y >= h_) continue;
                const double inv = inv_[static_cast<std::size_t>(y) * w_ + x];
                if (inv > 0) nearest = std::min(nearest, 1 / inv);
            }
        return depth <= nearest + tolerance;
    }

private:
    double k_;
    int w_, h_;
    std::vector<double> inv_;
};

DrawColor color_of(const glm::vec4& c) {
    return {c.r, c.g, c.b, c.a};
}

struct Piece {
    std::vector<glm::dvec2> points;
    double depth = 0; // mean, for the painter's order
    DrawStroke stroke;
    std::string role;
};

// The surfaces' depth, for hiding what lies behind them.
DepthBuffer surface_depth(const BuiltScene& scene, const Projector& project, int width,
                          int height) {
    // The tolerance lets lines drawn on a surface (isocurves, knot curves) through despite the
    // tessellation's chords.
    DepthBuffer depth(width, height, 2.0);
    for (const SurfaceDraw& sd : scene.surfaces) {
        if (!sd.surface) continue;
        const int n = std::clamp(sd.density * 2, 16, 128);
        const geom::Mesh mesh = geom::tessellate(*sd.surface, n, n);
        std::vector<ScreenPoint> px;
        px.reserve(mesh.positions.size());
        for (const glm::dvec3& p : mesh.positions) px.push_back(project(p));
        for (const auto& t : mesh.triangles)
            if (mesh.vertex_exists(t[0]) && mesh.vertex_exists(t[1]) && mesh.vertex_exists(t[2]))
                depth.triangle(px[t[0]], px[t[1]], px[t[2]]);
    }
    return depth;
}

// The figure's lines as pieces of one stroke, each visible or (dashed) hidden.
struct PieceCollector {
    const Projector& project;
    const DepthBuffer& depth;
    double tolerance;
    std::vector<Piece> pieces;

    // A segment a-b sampled every point or so; runs of visible samples become pieces, and for
    // `dash_hidden` the hidden runs become dashed pieces.
    void add_segment(const glm::dvec3& a, const glm::dvec3& b, const DrawStroke& s,
                     bool dash_hidden, const std::string& role) {
        const ScreenPoint pa = project(a), pb = project(b);
        if (!pa.ok || !pb.ok) return;
        const double len = glm::length(pb.p - pa.p);
        const int n = std::clamp(static_cast<int>(len / 1.0), 1, 2000);
        int run_visible = -1;
        Piece cur;
        auto flush = [&] {
            if (cur.points.size() >= 2) {
                cur.depth /= static_cast<double>(cur.points.size());
                pieces.push_back(std::move(cur));
            }
            cur = Piece{};
        };
        for (int k = 0; k <= n; ++k) {
            const double f = static_cast<double>(k) / n;
            const ScreenPoint q = project(a + (b - a) * f);
            if (!q.ok) continue;
            const bool vis = depth.visible(q.p, q.depth, tolerance);
            if (static_cast<int>(vis) != run_visible) {
                // The run ends where the next begins, so pieces join without gaps.
                const std::optional<glm::dvec2> joint =
                    cur.points.empty() ? std::nullopt : std::optional(q.p);
                if (joint) {
                    cur.points.push_back(*joint);
                    cur.depth += q.depth;
                }
                flush();
                run_visible = vis;
                if (vis) {
                    cur.stroke = s;
                    cur.role = role;
                } else if (dash_hidden) {
                    DrawStroke h = s;
                    h.color.a *= 0.55f;
                    h.width *= 0.7;
                    h.dash = {2.5, 2};
                    cur.stroke = h;
                    cur.role = role + "-hidden";
                } else {
                    cur.role.clear(); // hidden: dropped at flush
                }
            }
            if (vis || dash_hidden) {
                cur.points.push_back(q.p);
                cur.depth += q.depth;
            }
        }
        flush();
    }
};

// Drop hidden runs; join pieces that continue one another (same stroke, shared end) so a
// curve is one path, not a hundred segments.
std::vector<Piece> joined_pieces(std::vector<Piece> pieces) {
    pieces.erase(
        std::remove_if(pieces.begin(), pieces.end(), [](const Piece& p) { return p.role.empty(); }),
        pieces.end());
    std::vector<Piece> joined;
    for (Piece& p : pieces) {
        if (!joined.empty()) {
            Piece& last = joined.back();
            const auto same = [](const DrawStroke& x, const DrawStroke& y) {
                return x.width == y.width && x.dash == y.dash && x.color.r == y.color.r &&
                       x.color.g == y.color.g && x.color.b == y.color.b && x.color.a == y.color.a;
            };
            if (last.role == p.role && same(last.stroke, p.stroke) &&
                glm::length(last.points.back() - p.points.front()) < 1e-6) {
                const double nl = static_cast<double>(last.points.size());
                const double np = static_cast<double>(p.points.size());
                last.depth = (last.depth * nl + p.depth * np) / (nl + np);
                last.points.insert(last.points.end(), p.points.begin() + 1, p.points.end());
                continue;
            }
        }
        joined.push_back(std::move(p));
    }
    return joined;
}

// Points: visible ones as dots (those drawn on top always), nearest last.
void add_dots(Drawing& dr, const BuiltScene& scene, const Projector& project,
              const DepthBuffer& depth, double tolerance, double line_scale) {
    struct Dot {
        glm::dvec2 p;
        double depth, r;
        DrawColor c;
        bool sphere;
    };
    std::vector<Dot> dots;
    for (const PointBatch& batch : scene.overlay.points)
        for (const OverlayVertex& v : batch.points) {
            const ScreenPoint q = project(v.position);
            if (!q.ok) continue;
            if (!batch.on_top && !depth.visible(q.p, q.depth, tolerance)) continue;
            dots.push_back(
                {q.p, q.depth, 0.25 * batch.size_px * line_scale, color_of(v.color), batch.sphere});
        }
    std::stable_sort(dots.begin(), dots.end(),
                     [](const Dot& a, const Dot& b) { return a.depth > b.depth; });
    for (const Dot& dt : dots)
        dr.dot(dt.p, dt.r, dt.c, stroke({0, 0, 0, 0.6f}, 0.3),
               dt.sphere ? "result-point" : "point");
}

} // namespace

geom::Expected<Drawing> view3d_figure(const doc::Document& d, const View3dFigureInput& in,
                                      const FigureOptions& o) {
    SceneStyle style;
    style.deboor_step = in.deboor_step;
    const BuiltScene scene = build_scene(d, style);
    Drawing dr;
    dr.width = o.width;
    dr.height = o.height;
    dr.title = "3D view";
    if (!o.transparent)
        dr.background =
            DrawColor{d.colors.background.r, d.colors.background.g, d.colors.background.b, 1};
    if (in.raster) dr.items.push_back(*in.raster);
    const Projector project(in.camera, o.width, o.height);

    // The surfaces hide what lies behind them.
    const DepthBuffer depth = surface_depth(scene, project, o.width, o.height);
    const double tolerance = 0.012 * in.camera.distance;

    PieceCollector lines{project, depth, tolerance, {}};
    auto add_segment = [&lines](const glm::dvec3& a, const glm::dvec3& b, const DrawStroke& s,
                                bool dash_hidden, const std::string& role) {
        lines.add_segment(a, b, s, dash_hidden, role);
    };

    // The figure's wireframe: isocurves at the knots' span ends and between them.
    if (in.isocurves)
        for (const SurfaceDraw& sd : scene.surfaces) {
            if (!sd.surface) continue;
            const geom::Surface& s = *sd.surface;
            const DrawStroke st = stroke(color_of(sd.wire), 0.45 * in.line_scale);
            for (geom::Dir dir : {geom::Dir::u, geom::Dir::v}) {
                const geom::Interval dom = geom::domain(s, dir);
                for (double t : geom::uniform_params(dom.lo, dom.hi, 9))
                    for (const auto& line : iso_curve(s, dir, t, 65))
                        for (std::size_t k = 1; k < line.size(); ++k)
                            add_segment(line[k - 1], line[k], st, false, "isocurve");
            }
        }
    for (const LineBatch& batch : scene.overlay.lines)
        for (std::size_t k = 0; k + 1 < batch.vertices.size(); k += 2) {
            const OverlayVertex& a = batch.vertices[k];
            const DrawStroke st = stroke(color_of(a.color), 0.5 * batch.width_px * in.line_scale);
            add_segment(a.position, batch.vertices[k + 1].position, st, batch.faint_when_hidden,
                        batch.faint_when_hidden ? "net" : "line");
        }
    std::vector<Piece> joined = joined_pieces(std::move(lines.pieces));
    std::stable_sort(joined.begin(), joined.end(),
                     [](const Piece& a, const Piece& b) { return a.depth > b.depth; });
    for (Piece& p : joined) dr.polyline(std::move(p.points), p.stroke, p.role);

    add_dots(dr, scene, project, depth, tolerance, in.line_scale);
    return dr;
}

} // namespace isoparm::ui
