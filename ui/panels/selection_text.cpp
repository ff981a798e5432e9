// What the left column and the status bar say about the selected object, whatever its kind:
// they never describe another object than the one selected.
#include <imgui.h>
#include <string>

#include "core/geom/knots.hpp"
#include "core/geom/status.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/stage_controls.hpp"
#include "ui/theme.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/triangle_domain.hpp"

namespace isoparm::ui {

const doc::Object* selected_non_surface(const doc::Document& d) {
    const doc::Object* sel = d.selected();
    if (!sel) return nullptr;
    // A triangular patch has its own versions of the surface panels.
    const bool described = std::visit(doc::overloaded{
                                          [](const doc::SurfaceObject&) { return false; },
                                          [](const doc::CurveObject&) { return true; },
                                          [](const doc::ImplicitObject&) { return true; },
                                          [](const doc::TriangleObject&) { return false; },
                                      },
                                      sel->shape);
    return described ? sel : nullptr;
}

std::string selection_summary(const AppContext& ctx) {
    const doc::Document& d = ctx.doc;
    const doc::Object* sel = d.selected();
    auto point = [&]() -> std::string {
        return has_valid_point(d)
                   ? "  " + point_name('P', d.view.selection.i, d.view.selection.j, d)
                   : std::string();
    };
    const std::string hidden = sel && !sel->visible ? " (hidden)" : "";
    // A selected surface, or none: the current surface (the subpatch the indicator is on).
    const std::string own =
        !sel ? std::string()
             : std::visit(doc::overloaded{
                              [](const doc::SurfaceObject&) { return std::string(); },
                              [&](const doc::CurveObject& co) {
                                  const geom::Curve& c = co.curve;
                                  return sel->name + hidden + ": " + geom::name_of(c.type) +
                                         " curve, " + std::to_string(c.count()) +
                                         " points, degree " + std::to_string(c.degree) + point();
                              },
                              [&](const doc::ImplicitObject&) {
                                  return sel->name + hidden + ": implicit surface f(x, y, z) = 0";
                              },
                              [&](const doc::TriangleObject& to) {
                                  const geom::TrianglePatch& t = to.patch;
                                  const geom::Barycentric& b = d.view.barycentric;
                                  return sel->name + hidden + ": " +
                                         (t.rational ? "rational " : "") + "triangle, degree " +
                                         std::to_string(t.degree) + "  (r, s, t) = (" +
                                         geom::format_short(b[0], 3) + ", " +
                                         geom::format_short(b[1], 3) + ", " +
                                         geom::format_short(b[2], 3) + ")" + point();
                              },
                          },
                          sel->shape);
    if (!own.empty()) return own;
    const doc::Object* obj = nullptr;
    if (const geom::Surface* s = current_surface(d, &obj)) {
        const std::string h = obj->visible ? "" : " (hidden)";
        return obj->name + h + ": " + geom::name_of(s->type) + " " + std::to_string(s->n_u) + "x" +
               std::to_string(s->n_v) + ", degree (" + std::to_string(s->degree_u) + "," +
               std::to_string(s->degree_v) + ")" + (obj == sel ? point() : std::string());
    }
    return d.objects.empty() ? "empty scene" : "nothing selected";
}

void no_surface_text(AppContext& ctx) {
    const doc::Object* sel = ctx.doc.selected();
    if (sel && sel->curve()) {
        const geom::Curve& c = *sel->curve();
        const geom::Interval t = geom::domain(c);
        text_wrapped("%s: %s curve of degree %d with %d control points, t in [%s, %s].",
                     sel->name.c_str(), geom::name_of(c.type), c.degree, c.count(),
                     geom::format_short(t.lo).c_str(), geom::format_short(t.hi).c_str());
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        text_wrapped("Its designer is in the right column (canvas, knots, basis functions); the "
                     "Blossom and Homogeneous tabs below show it too. Select a surface for the "
                     "tracing square.");
        ImGui::PopStyleColor();
        return;
    }
    if (sel && sel->implicit()) {
        text_wrapped("%s: the implicit surface f(x, y, z) = 0 with f = %s.", sel->name.c_str(),
                     sel->implicit()->expression.c_str());
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        text_wrapped("It has no parameters (u, v): its editor is in the right column. Select a "
                     "spline surface for the tracing square.");
        ImGui::PopStyleColor();
        return;
    }
    text_wrapped(ctx.doc.objects.empty() ? "No surface. Use Surface > New Surface... to create one."
                                         : "No surface selected. Select one in the Objects tab, "
                                           "or use Surface > New Surface... to create one.");
}

const geom::Surface* teaching_panel_surface(AppContext& ctx, StageView view,
                                            TrianglePanel triangle_panel, const doc::Object** obj) {
    note_hovered_view(ctx, view);
    // A selected triangular patch has its own version of the panel (Farin ch. 17).
    const doc::Object* triangle = nullptr;
    if (const geom::TrianglePatch* t = selected_triangle(ctx.doc, &triangle)) {
        triangle_panel(ctx, *triangle, *t);
        return nullptr;
    }
    const geom::Surface* s =
        selected_non_surface(ctx.doc) ? nullptr : current_surface(ctx.doc, obj);
    if (!s) no_surface_text(ctx);
    return s;
}

} // namespace isoparm::ui
