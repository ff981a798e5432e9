// The current subpatch follows the indicator (see current_patch.hpp).
#include "ui/view/current_patch.hpp"

#include <algorithm>

#include "core/doc/patches.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::ui {

std::uint64_t patch_for_indicator(const doc::Document& doc, std::uint64_t current) {
    const doc::Object* o = doc.find(current);
    if (!o || o->patch_group == 0 || !o->surface()) return current;
    const geom::ParamRect r = doc::tracing_domain(doc, *o);
    const glm::dvec2 uv{r.u.lo + doc.view.indicator.x * (r.u.hi - r.u.lo),
                        r.v.lo + doc.view.indicator.y * (r.v.hi - r.v.lo)};
    const std::uint64_t found = doc::patch_at(doc, o->patch_group, uv, current);
    return found != 0 ? found : current;
}

bool follow_indicator(doc::Document& doc, std::uint64_t current) {
    const std::uint64_t next = patch_for_indicator(doc, current);
    if (next == current) return false;
    doc.view.selection = {next, -1, -1};
    return true;
}

std::uint64_t sync_patch_and_indicator(doc::Document& doc, std::uint64_t current,
                                       glm::dvec2 last_indicator, std::uint64_t last_current) {
    const doc::Object* o = doc.find(current);
    if (!o || o->patch_group == 0 || !o->surface()) return current;
    if (!(doc.view.indicator == last_indicator)) {
        const std::uint64_t next = patch_for_indicator(doc, current);
        if (next != current) doc.view.selection = {next, -1, -1};
        return next;
    }
    if (current == last_current) return current;
    const geom::ParamRect all = doc::tracing_domain(doc, *o);
    const geom::ParamRect own = geom::domain(*o->surface());
    auto into = [](const geom::Interval& whole, const geom::Interval& part, double s) {
        const double t = std::clamp(whole.lo + s * (whole.hi - whole.lo), part.lo, part.hi);
        return whole.hi > whole.lo ? (t - whole.lo) / (whole.hi - whole.lo) : 0.0;
    };
    doc.view.indicator = {into(all.u, own.u, doc.view.indicator.x),
                          into(all.v, own.v, doc.view.indicator.y)};
    return current;
}

} // namespace isoparm::ui
