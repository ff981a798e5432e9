// Document read helpers for panels.
#include "ui/doc_access.hpp"

#include "core/geom/knots.hpp"
#include "ui/canvas_map.hpp"

namespace isoparm::ui {

const geom::Surface* surface_of(const doc::Object& o) {
    const auto* s = std::get_if<doc::SurfaceObject>(&o.shape);
    return s ? &s->surface : nullptr;
}

const geom::Surface* current_surface(const doc::Document& d, const doc::Object** object) {
    const doc::Object* found = nullptr;
    if (const doc::Object* sel = d.selected(); sel && surface_of(*sel)) found = sel;
    if (!found)
        for (const doc::Object& o : d.objects)
            if (o.visible && surface_of(o)) {
                found = &o;
                break;
            }
    if (object) *object = found;
    return found ? surface_of(*found) : nullptr;
}

bool has_valid_point(const doc::Document& d) {
    const doc::Object* o = d.selected();
    if (!o || !d.selection.has_point()) return false;
    if (const geom::Surface* s = surface_of(*o))
        return d.selection.i < s->n_u && d.selection.j >= 0 && d.selection.j < s->n_v;
    if (const auto* c = std::get_if<doc::CurveObject>(&o->shape))
        return d.selection.i < c->curve.count();
    return false;
}

void normalize_selection(doc::Document& d) {
    if (d.selection.object != 0 && !d.find(d.selection.object)) d.selection = {};
    if (d.selection.has_point() && !has_valid_point(d)) {
        d.selection.i = -1;
        d.selection.j = -1;
    }
}

std::string point_name(char prefix, int i, int j, int n_u, int n_v) {
    std::string s(1, prefix);
    if (j < 0) return s + std::to_string(i);
    const bool compact = n_u <= 10 && n_v <= 10;
    return s + std::to_string(i) + (compact ? "" : ",") + std::to_string(j);
}

std::string point_name(char prefix, int i, int j, const doc::Document& d) {
    const doc::Object* o = d.selected();
    const geom::Surface* s = o ? surface_of(*o) : nullptr;
    return point_name(prefix, i, j, s ? s->n_u : 0, s ? s->n_v : 0);
}

geom::Interval domain_u(const geom::Surface& s) {
    return geom::domain(s.knots_u, s.degree_u, s.n_u);
}
geom::Interval domain_v(const geom::Surface& s) {
    return geom::domain(s.knots_v, s.degree_v, s.n_v);
}

glm::dvec2 indicator_params(const doc::Document& d, const geom::Surface& s) {
    return {denormalize_param(domain_u(s), d.indicator.x),
            denormalize_param(domain_v(s), d.indicator.y)};
}

} // namespace isoparm::ui
