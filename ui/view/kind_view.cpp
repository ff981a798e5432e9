// The workstation's per-kind answers: every visit lists every kind (no `auto` catch-all).
#include "ui/view/kind_view.hpp"

#include <variant>

#include "core/doc/commands.hpp"
#include "core/doc/commands_curve.hpp"
#include "core/geom/enum_names.hpp"

namespace isoparm::ui {

ObjectEditor editor_of(const doc::Object& o) {
    return std::visit(doc::overloaded{
                          [](const doc::SurfaceObject&) { return ObjectEditor::control_points; },
                          [](const doc::CurveObject&) { return ObjectEditor::curve_designer; },
                          [](const doc::ImplicitObject&) { return ObjectEditor::implicit_surface; },
                          [](const doc::TriangleObject&) { return ObjectEditor::control_points; },
                      },
                      o.shape);
}

bool two_index_points(const doc::Shape& shape) {
    return std::visit(doc::overloaded{
                          [](const doc::SurfaceObject&) { return true; },
                          [](const doc::CurveObject&) { return false; },
                          [](const doc::ImplicitObject&) { return false; },
                          [](const doc::TriangleObject&) { return true; },
                      },
                      shape);
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

const char* kind_label(const doc::Object& o) {
    return std::visit(
        doc::overloaded{
            [](const doc::SurfaceObject& s) { return geom::name_of(s.surface.type); },
            [](const doc::CurveObject&) { return geom::name_of(doc::ObjectKind::curve); },
            [](const doc::ImplicitObject&) { return geom::name_of(doc::ObjectKind::implicit); },
            [](const doc::TriangleObject&) { return geom::name_of(doc::ObjectKind::triangle); },
        },
        o.shape);
}

} // namespace isoparm::ui
