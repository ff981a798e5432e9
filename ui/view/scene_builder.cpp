// Builds the renderer's input from the document each frame.
#include "ui/view/scene_builder.hpp"

#include <algorithm>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <variant>

#include "core/doc/placement.hpp"
#include "core/doc/point_set.hpp"
#include "core/geom/deboor.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/tessellate.hpp"
#include "core/geom/triangle.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/contrast.hpp"
#include "ui/view/deboor_overlay.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/implicit_meshes.hpp"
#include "ui/view/kinds/kind_view.hpp"
#include "ui/view/triangle_meshes.hpp"
#include "ui/view/triangle_scene.hpp"

namespace isoparm::ui {

namespace {

glm::vec4 with_alpha(glm::vec4 c, float a) {
    c.a *= a;
    return c;
}

glm::vec4 axis_color(int axis) {
    static const glm::vec4 colors[3] = {
        {0.95f, 0.3f, 0.3f, 1}, {0.35f, 0.85f, 0.35f, 1}, {0.35f, 0.55f, 1.0f, 1}};
    return colors[std::clamp(axis, 0, 2)];
}

} // namespace

glm::vec4 to_vec4(const doc::Rgba& c) {
    return {c.r, c.g, c.b, c.a};
}

std::vector<std::vector<glm::vec3>> iso_curve(const geom::Surface& s, geom::Dir fixed, double t,
                                              int samples) {
    std::vector<std::vector<glm::vec3>> pieces(1);
    const geom::Interval other = geom::domain(s, geom::opposite(fixed));
    for (double x : geom::uniform_params(other.lo, other.hi, samples)) {
        const auto p =
            fixed == geom::Dir::u ? geom::surface_point(s, t, x) : geom::surface_point(s, x, t);
        if (p) {
            pieces.back().emplace_back(*p);
        } else if (!pieces.back().empty()) {
            pieces.emplace_back();
        }
    }
    if (pieces.back().empty()) pieces.pop_back();
    return pieces;
}

// The scene's colours with every line and point colour kept readable on its background (a
// white background must not swallow a pale net).
doc::Colors readable_overlay_colors(const doc::Colors& c) {
    const glm::vec3 bg(c.background.r, c.background.g, c.background.b);
    auto fix = [&](doc::Rgba& x) {
        const glm::vec4 v = readable_on(to_vec4(x), bg, line_contrast);
        x = {v.r, v.g, v.b, v.a};
    };
    doc::Colors out = c;
    for (doc::Rgba* x : {&out.control_net, &out.control_points, &out.selected_point,
                         &out.knot_curves, &out.indicator})
        fix(*x);
    return out;
}

glm::vec4 knot_continuity_color(int degree, int multiplicity, const glm::vec4& smooth) {
    switch (geom::continuity_at_knot(degree, multiplicity)) {
    case 1:
        return {1.0f, 0.85f, 0.2f, 1};
    case 0:
        return {1.0f, 0.5f, 0.1f, 1};
    default:
        break;
    }
    return geom::continuity_at_knot(degree, multiplicity) < 0 ? glm::vec4(0.95f, 0.2f, 0.2f, 1)
                                                              : smooth;
}

glm::vec4 border_level_color(doc::BorderLevel level) {
    switch (level) {
    case doc::BorderLevel::broken:
        return {0.95f, 0.2f, 0.2f, 1};
    case doc::BorderLevel::c0:
        return {1.0f, 0.5f, 0.1f, 1};
    case doc::BorderLevel::g1:
        return {1.0f, 0.85f, 0.2f, 1};
    case doc::BorderLevel::c1:
        return {0.3f, 0.85f, 0.35f, 1};
    case doc::BorderLevel::g2:
        return {0.3f, 0.85f, 0.95f, 1};
    }
    return {1, 1, 1, 1};
}

namespace {

// Each border of the current patch group, traced on its low side, in the colour of the
// continuity measured across it (the Continuity tab's figures, drawn where they hold).
void add_borders(LineBatch& out, const doc::Document& d) {
    const doc::Object* current = nullptr;
    if (!current_surface(d, &current) || current->patch_group == 0) return;
    const double size = doc::group_size(d, current->patch_group);
    for (const doc::SharedBorder& b : doc::shared_borders(d, current->patch_group)) {
        const doc::Object* low = d.find(b.low);
        if (!low || !low->surface()) continue;
        const glm::vec4 c = border_level_color(doc::border_level(doc::measure_border(d, b), size));
        const geom::Surface& s = *low->surface();
        const double at = geom::domain(s, b.across).hi;
        std::vector<glm::vec3> piece;
        for (double t : geom::uniform_params(b.along.lo, b.along.hi, 65)) {
            const auto p = b.across == geom::Dir::u ? geom::surface_point(s, at, t)
                                                    : geom::surface_point(s, t, at);
            if (p) {
                piece.emplace_back(*p);
                continue;
            }
            Overlay::add_polyline(out, piece, c); // no point there: the line breaks
            piece.clear();
        }
        Overlay::add_polyline(out, piece, c);
    }
}

// The selected curve's comb, osculating circle and Frenet frame (curve_glyphs) in 3D.
void add_curve_glyphs(Overlay& out, const doc::Document& d, const SceneStyle& style, float k) {
    const doc::Object* sel = d.selected();
    const geom::Curve* c = sel && sel->visible ? sel->curve() : nullptr;
    const CurveGlyphRequest& want = style.curve_glyphs;
    if (!c || !(want.comb || want.osculating || want.frenet)) return;
    const double t = denormalize_param(geom::domain(*c), std::clamp(style.curve_t, 0.0, 1.0));
    const CurveGlyphs g = curve_glyphs(*c, t, want);
    LineBatch teeth{{}, 1.0f * k, true}, rim{{}, 1.6f * k, true}, circle{{}, 1.6f * k, true};
    LineBatch frame{{}, 3.0f * k, false};
    const glm::vec4 blue{0.47f, 0.78f, 1.0f, 0.8f}, orange{0.98f, 0.67f, 0.24f, 0.95f};
    for (const auto& [base, tip] : g.teeth) {
        teeth.vertices.push_back({glm::vec3(base), blue});
        teeth.vertices.push_back({glm::vec3(tip), blue});
    }
    std::vector<glm::vec3> line(g.rim.begin(), g.rim.end());
    Overlay::add_polyline(rim, line, with_alpha(blue, 1));
    line.assign(g.circle.begin(), g.circle.end());
    Overlay::add_polyline(circle, line, orange);
    if (g.point) {
        auto axis = [&](const std::optional<glm::dvec3>& dir, glm::vec4 col) {
            if (!dir) return;
            frame.vertices.push_back({glm::vec3(*g.point), col});
            frame.vertices.push_back({glm::vec3(*g.point + *dir * g.frame_length), col});
        };
        axis(g.tangent, {0.92f, 0.31f, 0.31f, 1});
        axis(g.normal, {0.35f, 0.82f, 0.35f, 1});
        axis(g.binormal, {0.35f, 0.55f, 1.0f, 1});
    }
    for (LineBatch* b : {&teeth, &rim, &circle, &frame})
        if (!b->vertices.empty()) out.lines.push_back(std::move(*b));
}

// The scene's draw lists, filled object by object, then the overlays of the selection, the
// indicator, de Boor's construction and the working grid.
class SceneAssembler {
public:
    SceneAssembler(const doc::Document& doc, const SceneStyle& scene_style,
                   const ImplicitMeshes* implicit_meshes, const TriangleMeshes* triangle_meshes)
        : d(doc), style(scene_style), implicit(implicit_meshes), triangles(triangle_meshes),
          k(style.scale), col(readable_overlay_colors(d.colors)),
          background(col.background.r, col.background.g, col.background.b), disp(d.view.display),
          shaded(disp.style != doc::DisplayStyle::wireframe),
          wire(disp.style != doc::DisplayStyle::shaded), points{{},
                                                                point_size_for(d) * k,
                                                                false,
                                                                false} {
        const doc::Object* sel_obj = d.selected();
        sel_triangle = sel_obj && sel_obj->visible ? sel_obj->triangle() : nullptr;
        base_look.point_i = d.view.selection.i;
        base_look.point_j = d.view.selection.j;
        base_look.colors = &col;
        base_look.background = background;
        base_look.scale = k;
        base_look.shaded = shaded;
        base_look.wire = wire;
        base_look.density = disp.density;
        base_look.knot_continuity = style.knot_continuity;
        base_look.implicit_meshes = implicit;
        base_look.triangle_meshes = triangles;
    }

    void add_objects() {
        for (const doc::Object& o : d.objects) {
            if (!o.visible) continue;
            const bool is_selected = o.id == d.view.selection.object;
            // The object's own toggles (C, N, K with it selected), else the scene's defaults.
            const doc::ObjectDisplay own = doc::display_of(d.view, o.id);
            ObjectLook look = base_look;
            look.id = o.id;
            look.selected = is_selected;
            look.own = own;
            draw_in_scene(o, look, batches);
        }
    }

    void add_selected_points() {
        // The selected control point: larger, in its own colour, always visible (unless its object
        // is hidden, or shows no points).
        if (has_valid_point(d) && d.selected()->visible &&
            doc::display_of(d.view, d.view.selection.object).control_points) {
            const doc::Object* o = d.selected();
            const glm::dvec3 p =
                doc::position_of(o->shape, {d.view.selection.i, d.view.selection.j});
            selected.points.push_back({glm::vec3(p), to_vec4(col.selected_point)});
        }
        if (disp.control_points)
            for (const glm::dvec3& p : style.also_selected)
                selected.points.push_back({glm::vec3(p), to_vec4(col.selected_point)});
    }

    void add_indicator() {
        // The indicator: S(u,v) as a small sphere, with the two isoparametric curves through it.
        // A selected triangle has its own indicator (r, s, t), with the three lines of constant
        // r, s and t through it.
        if (disp.indicator_point && sel_triangle) {
            const glm::vec4 ic = to_vec4(col.indicator);
            for (const auto& piece : triangle_iso_lines(*sel_triangle, d.view.barycentric, 97))
                Overlay::add_polyline(iso, piece, with_alpha(ic, 0.55f));
            if (const auto p = geom::triangle_point(*sel_triangle, d.view.barycentric))
                indicator.points.push_back({glm::vec3(*p), ic});
        } else if (disp.indicator_point) {
            const doc::Object* current = nullptr;
            // A hidden surface draws nothing, its indicator included.
            if (const geom::Surface* s = current_surface(d, &current); s && current->visible) {
                const glm::dvec2 uv = indicator_params(d, *current);
                const glm::vec4 ic = to_vec4(col.indicator);
                for (const auto& piece : iso_curve(*s, geom::Dir::u, uv.x, 97))
                    Overlay::add_polyline(iso, piece, with_alpha(ic, 0.55f));
                for (const auto& piece : iso_curve(*s, geom::Dir::v, uv.y, 97))
                    Overlay::add_polyline(iso, piece, with_alpha(ic, 0.55f));
                if (const auto p = geom::surface_point(*s, uv.x, uv.y))
                    indicator.points.push_back({glm::vec3(*p), ic});
            }
        }
    }

    void add_guide_and_deboor() {
        if (style.guide_axis >= 0) {
            glm::dvec3 dir(0);
            dir[style.guide_axis] = 1;
            const auto box = doc::scene_bounds(d);
            const double len = box ? std::max(glm::length(box->hi - box->lo), 1.0) * 2 : 10.0;
            const glm::vec4 gc = axis_color(style.guide_axis);
            guide.vertices.push_back({glm::vec3(style.guide_point - dir * len), gc});
            guide.vertices.push_back({glm::vec3(style.guide_point + dir * len), gc});
        }

        // De Boor's construction at the indicator, up to the step the lecture has reached.
        if (disp.deboor && sel_triangle) {
            add_triangle_de_casteljau(*sel_triangle, d.view.barycentric, style.deboor_step, k,
                                      deboor);
        } else if (disp.deboor) {
            const doc::Object* current = nullptr;
            if (const geom::Surface* s = current_surface(d, &current); s && current->visible) {
                const glm::dvec2 uv = indicator_params(d, *current);
                add_deboor_overlay(geom::deboor_surface(*s, uv.x, uv.y), s->degree_u, s->degree_v,
                                   style.deboor_step, k, deboor);
            }
        }

        if (style.border_continuity) add_borders(borders, d);
    }

    void add_working_grid() {
        // The working plane's grid, under everything (depth-tested, faint where hidden).
        LineBatch grid{{}, 1.0f * k, true};
        if (style.working_grid && style.grid_step > 0 && style.grid_lines > 0) {
            const double step = style.grid_step;
            const int n = style.grid_lines;
            const glm::dvec2 c = glm::round(style.grid_centre / step) * step;
            const glm::vec4 minor(0.55f, 0.58f, 0.65f, 0.28f), major(0.62f, 0.66f, 0.74f, 0.55f);
            for (int q = -n; q <= n; ++q) {
                const glm::dvec2 at = c + static_cast<double>(q) * step;
                const glm::vec4 cx = std::llround(at.x / step) % 5 == 0 ? major : minor;
                const glm::vec4 cy = std::llround(at.y / step) % 5 == 0 ? major : minor;
                grid.vertices.push_back({glm::vec3(at.x, c.y - n * step, 0), cx});
                grid.vertices.push_back({glm::vec3(at.x, c.y + n * step, 0), cx});
                grid.vertices.push_back({glm::vec3(c.x - n * step, at.y, 0), cy});
                grid.vertices.push_back({glm::vec3(c.x + n * step, at.y, 0), cy});
            }
            out.overlay.lines.push_back(std::move(grid));
        }
    }

    BuiltScene finish() {
        for (LineBatch* b :
             {&knots, &knots_double, &knots_full, &curves, &net, &box, &iso, &guide, &borders})
            if (!b->vertices.empty()) out.overlay.lines.push_back(std::move(*b));
        add_curve_glyphs(out.overlay, d, style, k);
        for (PointBatch* b : {&points, &indicator, &selected})
            if (!b->points.empty()) out.overlay.points.push_back(std::move(*b));
        // Last, so the construction draws over the net and the indicator.
        for (LineBatch& b : deboor.lines) out.overlay.lines.push_back(std::move(b));
        for (PointBatch& b : deboor.points) out.overlay.points.push_back(std::move(b));
        return std::move(out);
    }

private:
    // Many points (a 32x32 net) would bury the surface: they shrink with their number.
    static float point_size_for(const doc::Document& d) {
        std::size_t total_points = 0;
        // A curve's few points, on its own line, do not count.
        for (const doc::Object& o : d.objects)
            if (o.visible)
                total_points += std::visit(
                    doc::overloaded{
                        [](const doc::SurfaceObject& s) { return s.surface.points.size(); },
                        [](const doc::CurveObject&) { return std::size_t{0}; },
                        [](const doc::ImplicitObject&) { return std::size_t{0}; },
                        [](const doc::TriangleObject& t) { return t.patch.points.size(); },
                    },
                    o.shape);
        return total_points > 400 ? 6.f : total_points > 100 ? 7.5f : 9.f;
    }

    const doc::Document& d;
    const SceneStyle& style;
    const ImplicitMeshes* implicit;
    const TriangleMeshes* triangles;
    const float k;
    const doc::Colors col;
    const glm::vec3 background;
    const doc::DisplaySettings& disp;
    const bool shaded, wire;
    const geom::TrianglePatch* sel_triangle = nullptr;
    BuiltScene out;

    LineBatch net{{}, 1.4f * k, true};
    LineBatch knots{{}, 1.6f * k, true};
    // Multiplicity shows in the line: single knots thin, double thicker, triple and more
    // thickest (a C0 or broken join of the surface).
    LineBatch knots_double{{}, 3.0f * k, true};
    LineBatch knots_full{{}, 4.6f * k, true};
    LineBatch curves{{}, 2.2f * k, true};
    LineBatch box{{}, 1.2f * k, true};
    PointBatch points;
    PointBatch selected{{}, 13.f * k, false, true};
    // The indicator: S(u,v) as a small sphere, with the two isoparametric curves through it.
    LineBatch iso{{}, 1.6f * k, true};
    PointBatch indicator{{}, 14.f * k, true, true};
    LineBatch guide{{}, 1.5f * k, false};
    Overlay deboor;
    LineBatch borders{{}, 5.0f * k, true};
    // What each object's kind draws into (kinds/kind_view.hpp), and how.
    SceneBatches batches{out.surfaces, net, knots, knots_double, knots_full, curves, box, points};
    ObjectLook base_look;
};

} // namespace

BuiltScene build_scene(const doc::Document& d, const SceneStyle& style,
                       const ImplicitMeshes* implicit, const TriangleMeshes* triangles) {
    SceneAssembler scene(d, style, implicit, triangles);
    scene.add_objects();
    scene.add_selected_points();
    scene.add_indicator();
    scene.add_guide_and_deboor();
    scene.add_working_grid();
    return scene.finish();
}

std::vector<glm::dvec3> scene_points(const doc::Document& d) {
    std::vector<glm::dvec3> out;
    for (const doc::Object& o : d.objects) {
        if (!o.visible) continue;
        // Its control points, or an implicit surface's box (doc::bounds answers by kind).
        const std::span<const glm::dvec3> points = doc::control_points_of(o.shape);
        out.insert(out.end(), points.begin(), points.end());
        if (points.empty())
            if (const std::optional<doc::Box> box = doc::bounds_of(o.shape))
                for (int k = 0; k < 8; ++k)
                    out.push_back({k & 1 ? box->hi.x : box->lo.x, k & 2 ? box->hi.y : box->lo.y,
                                   k & 4 ? box->hi.z : box->lo.z});
    }
    return out;
}

} // namespace isoparm::ui
