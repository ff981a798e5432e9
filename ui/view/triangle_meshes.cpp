// Triangle meshes cached by the patch they came from (geom::tessellate_triangle).
#include "ui/view/triangle_meshes.hpp"

#include <algorithm>

#include "core/geom/triangle.hpp"

namespace isoparm::ui {

namespace {

bool same_patch(const geom::TrianglePatch& a, const geom::TrianglePatch& b) {
    return a.rational == b.rational && a.degree == b.degree && a.points == b.points &&
           a.weights == b.weights;
}

} // namespace

int TriangleMeshes::subdivisions(int degree, int density) {
    return std::clamp(std::max(density, 4 * degree), 4, 256);
}

void TriangleMeshes::update(const doc::Document& d, int density) {
    std::unordered_map<std::uint64_t, Entry> kept;
    for (const doc::Object& o : d.objects) {
        const geom::TrianglePatch* t = o.visible ? o.triangle() : nullptr;
        if (!t) continue;
        const int rows = subdivisions(t->degree, density);
        auto found = entries_.find(o.id);
        if (found != entries_.end() && found->second.rows == rows &&
            same_patch(found->second.patch, *t)) {
            kept.emplace(o.id, std::move(found->second));
            continue;
        }
        Entry e;
        e.patch = *t;
        e.rows = rows;
        e.mesh = geom::tessellate_triangle(*t, rows);
        e.revision = next_revision_++;
        kept.emplace(o.id, std::move(e));
    }
    entries_ = std::move(kept);
}

TriangleMeshes::View TriangleMeshes::view(std::uint64_t id) const {
    const auto found = entries_.find(id);
    if (found == entries_.end()) return {};
    return {&found->second.mesh, found->second.revision};
}

} // namespace isoparm::ui
