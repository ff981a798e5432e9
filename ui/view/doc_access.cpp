// Document read helpers for panels.
#include "ui/view/doc_access.hpp"

#include <algorithm>
#include <variant>

#include "core/doc/patches.hpp"
#include "core/geom/knots.hpp"
#include "ui/view/canvas_map.hpp"

namespace isoparm::ui {

std::string fresh_name(const doc::Document& d, const std::string& base) {
    for (int n = 1;; ++n) {
        const std::string name = base + " " + std::to_string(n);
        if (std::none_of(d.objects.begin(), d.objects.end(),
                         [&](const doc::Object& o) { return o.name == name; }))
            return name;
    }
}

const geom::Surface* current_surface(const doc::Document& d, const doc::Object** object) {
    const doc::Object* found = nullptr;
    if (const doc::Object* sel = d.selected(); sel && sel->surface()) found = sel;
    if (!found)
        for (const doc::Object& o : d.objects)
            if (o.visible && o.surface()) {
                found = &o;
                break;
            }
    if (object) *object = found;
    return found ? found->surface() : nullptr;
}

bool has_valid_point(const doc::Document& d) {
    const doc::Object* o = d.selected();
    if (!o || !d.view.selection.has_point()) return false;
    return doc::has_control_point(o->shape, d.view.selection.i, d.view.selection.j);
}

void normalize_selection(doc::Document& d) {
    if (d.view.selection.object != 0 && !d.find(d.view.selection.object)) d.view.selection = {};
    if (d.view.selection.has_point() && !has_valid_point(d)) {
        d.view.selection.i = -1;
        d.view.selection.j = -1;
    }
}

std::string point_name(char prefix, int i, int j, int n_u, int n_v) {
    std::string s(1, prefix);
    if (j < 0) return s + std::to_string(i);
    const bool compact = n_u <= 10 && n_v <= 10;
    return s + std::to_string(i) + (compact ? "" : ",") + std::to_string(j);
}

std::string point_name(char prefix, int i, int j, const doc::Object* o) {
    if (!o) return point_name(prefix, i, j, 0, 0);
    return std::visit(
        doc::overloaded{
            [&](const doc::SurfaceObject& s) {
                return point_name(prefix, i, j, s.surface.n_u, s.surface.n_v);
            },
            [&](const doc::CurveObject&) { return point_name(prefix, i, j, 0, 0); },
            [&](const doc::ImplicitObject&) { return point_name(prefix, i, j, 0, 0); },
            [&](const doc::TriangleObject& to) {
                // b_ijk (w_ijk), k = n - i - j: the triangle's own three indices.
                const int n = to.patch.degree;
                const char letter = prefix == 'P' ? 'b' : prefix;
                const std::string sep = n < 10 ? "" : ",";
                return std::string(1, letter) + std::to_string(i) + sep + std::to_string(j) + sep +
                       std::to_string(n - i - j);
            },
        },
        o->shape);
}

std::string point_name(char prefix, int i, int j, const doc::Document& d) {
    return point_name(prefix, i, j, d.selected());
}

glm::dvec2 indicator_params(const doc::Document& d, const doc::Object& surface_object) {
    const geom::ParamRect r = doc::tracing_domain(d, surface_object);
    // Clamped to the object's own domain: for a subpatch the indicator may lie in another
    // patch's part of the square (for a frame, or in a hole of the group), and evaluation
    // needs a parameter inside the domain.
    const geom::ParamRect own = geom::domain(*surface_object.surface());
    return {std::clamp(denormalize_param(r.u, d.view.indicator.x), own.u.lo, own.u.hi),
            std::clamp(denormalize_param(r.v, d.view.indicator.y), own.v.lo, own.v.hi)};
}

glm::dvec2 indicator_in_own_domain(const doc::Document& d, const doc::Object& surface_object) {
    const glm::dvec2 uv = indicator_params(d, surface_object);
    const geom::ParamRect own = geom::domain(*surface_object.surface());
    return {std::clamp(normalize_param(own.u, uv.x), 0.0, 1.0),
            std::clamp(normalize_param(own.v, uv.y), 0.0, 1.0)};
}

glm::dvec2 indicator_from_own_domain(const doc::Document& d, const doc::Object& surface_object,
                                     glm::dvec2 own) {
    const geom::ParamRect mine = geom::domain(*surface_object.surface());
    const geom::ParamRect all = doc::tracing_domain(d, surface_object);
    return {normalize_param(all.u, denormalize_param(mine.u, own.x)),
            normalize_param(all.v, denormalize_param(mine.v, own.y))};
}

} // namespace isoparm::ui
