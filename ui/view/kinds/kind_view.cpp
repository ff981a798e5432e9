// The dispatchers over the kinds' views, and what the views share.
#include "ui/view/kinds/kind_view.hpp"

#include <variant>

#include "core/doc/commands.hpp"
#include "core/doc/commands_curve.hpp"
#include "ui/view/scene_builder.hpp"

namespace isoparm::ui {

void draw_in_scene(const doc::Object& o, const ObjectLook& look, SceneBatches& out) {
    std::visit([&](const auto& k) { draw_kind(k, look, out); }, o.shape);
}

ControlNet control_net_of(const doc::Object& o) {
    return std::visit([](const auto& k) { return kind_net(k); }, o.shape);
}

KindTraits traits_of(const doc::Shape& shape) {
    return std::visit([](const auto& k) { return kind_traits(k); }, shape);
}

ObjectEditor editor_of(const doc::Object& o) {
    return traits_of(o.shape).editor;
}

bool two_index_points(const doc::Shape& shape) {
    return traits_of(shape).two_index;
}

const char* kind_label(const doc::Object& o) {
    return traits_of(o.shape).label;
}

std::unique_ptr<doc::Command> move_point_command(const doc::Object& o, int i, int j,
                                                 const glm::dvec3& p) {
    // A curve's knots may follow its polygon (chord / centripetal): its own command. An
    // implicit surface's refusal comes from the command layer.
    auto by_index = [&] { return doc::move_control_point(o.id, i, j, p); };
    return std::visit(
        doc::overloaded{
            [&](const doc::SurfaceObject&) { return by_index(); },
            [&](const doc::CurveObject&) { return doc::move_curve_point(o.id, i, p); },
            [&](const doc::ImplicitObject&) { return by_index(); },
            [&](const doc::TriangleObject&) { return by_index(); },
        },
        o.shape);
}

SurfaceDraw patch_draw(const ObjectLook& look) {
    const doc::Colors& col = *look.colors;
    SurfaceDraw sd;
    sd.id = look.id;
    sd.shaded = look.shaded;
    sd.wireframe = look.wire;
    sd.fill = to_vec4(col.surface);
    glm::vec4 w = look.selected ? to_vec4(col.selected_surface) : to_vec4(col.surface);
    if (look.shaded) w = glm::vec4(glm::vec3(w) * 0.45f, 0.9f);
    sd.wire = w;
    sd.wire_width = (look.shaded ? 1.0f : 1.3f) * look.scale;
    return sd;
}

void add_control_point(const ObjectLook& look, int i, int j, const glm::dvec3& p, PointBatch& out) {
    if (look.selected && look.point_i == i && look.point_j == j) return;
    out.points.push_back({glm::vec3(p), to_vec4(look.colors->control_points)});
}

} // namespace isoparm::ui
