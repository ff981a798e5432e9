// The surface kind's view: its tessellation (the renderer's, from SurfaceDraw::surface), net,
// points and knot curves in the 3D view; its rows and columns as the control net.
#include "core/geom/knots.hpp"
#include "ui/view/kinds/kind_view.hpp"
#include "ui/view/scene_builder.hpp"

namespace isoparm::ui {

namespace {

void add_net(LineBatch& b, const geom::Surface& s, const glm::vec4& c) {
    for (int i = 0; i < s.n_u; ++i)
        for (int j = 0; j < s.n_v; ++j) {
            const glm::vec3 p(s.point(i, j));
            if (j + 1 < s.n_v)
                b.vertices.insert(b.vertices.end(), {{p, c}, {glm::vec3(s.point(i, j + 1)), c}});
            if (i + 1 < s.n_u)
                b.vertices.insert(b.vertices.end(), {{p, c}, {glm::vec3(s.point(i + 1, j)), c}});
        }
}

// Knot curves S(u_k, v) and S(u, v_k); a repeated knot draws thicker.
void add_knot_curves(const geom::Surface& s, const ObjectLook& look, SceneBatches& out) {
    for (geom::Dir dir : {geom::Dir::u, geom::Dir::v}) {
        const geom::Interval dom = geom::domain(s, dir);
        for (const geom::KnotRun& r : geom::knot_runs(s.knots(dir))) {
            if (r.value < dom.lo || r.value > dom.hi) continue;
            const bool interior = r.value > dom.lo && r.value < dom.hi;
            LineBatch& b = !interior || r.multiplicity == 1 ? out.knots
                           : r.multiplicity == 2            ? out.knots_double
                                                            : out.knots_full;
            const glm::vec4 base = to_vec4(look.colors->knot_curves);
            const glm::vec4 c = look.knot_continuity && interior
                                    ? knot_continuity_color(s.degree(dir), r.multiplicity, base)
                                    : base;
            for (const auto& piece : iso_curve(s, dir, r.value, 97))
                Overlay::add_polyline(b, piece, c);
        }
    }
}

} // namespace

void draw_kind(const doc::SurfaceObject& object, const ObjectLook& look, SceneBatches& out) {
    const geom::Surface& s = object.surface;
    SurfaceDraw sd = patch_draw(look);
    sd.surface = &s;
    if (!object.trim.empty()) sd.trim = &object.trim;
    sd.density = look.density;
    out.surfaces.push_back(sd);

    if (look.own.control_net) add_net(out.net, s, to_vec4(look.colors->control_net));
    if (look.own.control_points)
        for (int i = 0; i < s.n_u; ++i)
            for (int j = 0; j < s.n_v; ++j)
                add_control_point(look, i, j, s.point(i, j), out.points);
    if (look.own.knot_curves) add_knot_curves(s, look, out);
}

ControlNet kind_net(const doc::SurfaceObject& object) {
    const geom::Surface& s = object.surface;
    ControlNet net;
    for (int i = 0; i < s.n_u; ++i)
        for (int j = 0; j < s.n_v; ++j) {
            net.ids.emplace_back(i, j);
            net.points.push_back(s.point(i, j));
        }
    auto at = [&](int i, int j) { return i * s.n_v + j; };
    for (int i = 0; i < s.n_u; ++i) {
        std::vector<int>& row = net.lines.emplace_back();
        for (int j = 0; j < s.n_v; ++j) row.push_back(at(i, j));
    }
    for (int j = 0; j < s.n_v; ++j) {
        std::vector<int>& column = net.lines.emplace_back();
        for (int i = 0; i < s.n_u; ++i) column.push_back(at(i, j));
    }
    return net;
}

KindTraits kind_traits(const doc::SurfaceObject& s) {
    return {ObjectEditor::control_points, true, geom::name_of(s.surface.type),
            s.trim.empty() ? "" : "trimmed"};
}

} // namespace isoparm::ui
