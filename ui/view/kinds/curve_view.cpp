// The curve kind's view: its polyline, control polygon and points in the 3D view; the
// polygon as its control net; the curve designer as its editor.
#include <glm/common.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/tessellate.hpp"
#include "ui/view/contrast.hpp"
#include "ui/view/kinds/kind_view.hpp"
#include "ui/view/scene_builder.hpp"

namespace isoparm::ui {

namespace {

std::vector<glm::vec3> curve_polyline(const geom::Curve& c, int samples) {
    std::vector<glm::vec3> out;
    const geom::Interval d = geom::domain(c);
    for (double t : geom::uniform_params(d.lo, d.hi, samples))
        if (const auto p = geom::curve_point(c, t)) out.emplace_back(*p);
    return out;
}

} // namespace

void draw_kind(const doc::CurveObject& object, const ObjectLook& look, SceneBatches& out) {
    const geom::Curve& c = object.curve;
    const doc::Colors& col = *look.colors;
    // A curve in the surface colour disappears against a surface built from it (a ruled or
    // skinned surface runs through its curves): curves take a pale tint.
    const glm::vec4 cc = look.selected
                             ? to_vec4(col.selected_surface)
                             : readable_on(glm::mix(to_vec4(col.surface), glm::vec4(1), 0.6f),
                                           look.background, line_contrast);
    Overlay::add_polyline(out.curves, curve_polyline(c, 200), cc);
    if (look.own.control_net) {
        std::vector<glm::vec3> poly;
        for (const glm::dvec3& p : c.points) poly.emplace_back(p);
        Overlay::add_polyline(out.net, poly, to_vec4(col.control_net));
    }
    // The selected point is i alone, whatever the selection's j.
    if (look.own.control_points)
        for (int i = 0; i < c.count(); ++i)
            add_control_point(look, i, look.point_j, c.points[static_cast<std::size_t>(i)],
                              out.points);
}

ControlNet kind_net(const doc::CurveObject& object) {
    const geom::Curve& c = object.curve;
    ControlNet net;
    std::vector<int>& polygon = net.lines.emplace_back();
    for (int i = 0; i < c.count(); ++i) {
        net.ids.emplace_back(i, -1);
        net.points.push_back(c.points[static_cast<std::size_t>(i)]);
        polygon.push_back(i);
    }
    return net;
}

KindTraits kind_traits(const doc::CurveObject&) {
    return {ObjectEditor::curve_designer, false, geom::name_of(doc::ObjectKind::curve)};
}

} // namespace isoparm::ui
