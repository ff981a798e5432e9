// The implicit kind's view: its polygonized mesh (implicit_meshes.hpp owns the cache) and,
// selected, its box in the 3D view; no control net; the implicit surface editor.
#include "ui/view/implicit_meshes.hpp"
#include "ui/view/kinds/kind_view.hpp"
#include "ui/view/scene_builder.hpp"

namespace isoparm::ui {

namespace {

// The 12 edges of an axis-aligned box (an implicit object's bounds).
void add_box(LineBatch& b, const glm::dvec3& lo, const glm::dvec3& hi, const glm::vec4& c) {
    auto corner = [&](int k) {
        return glm::vec3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
    };
    for (int k = 0; k < 8; ++k)
        for (int bit : {1, 2, 4})
            if (!(k & bit))
                b.vertices.insert(b.vertices.end(), {{corner(k), c}, {corner(k | bit), c}});
}

} // namespace

void draw_kind(const doc::ImplicitObject& im, const ObjectLook& look, SceneBatches& out) {
    const doc::Colors& col = *look.colors;
    const ImplicitMeshes::View v =
        look.implicit_meshes ? look.implicit_meshes->drawn(look.id) : ImplicitMeshes::View{};
    if (v.mesh && !v.mesh->triangles.empty()) {
        SurfaceDraw sd;
        sd.id = look.id;
        sd.mesh = v.mesh;
        sd.mesh_revision = v.revision;
        sd.implicit = &im;
        sd.seen_side = v.seen_side;
        sd.box_lo = v.lo;
        sd.box_hi = v.hi;
        sd.shaded = look.shaded;
        // Every triangle edge over a shaded surface would hide it: wireframe only in the
        // wireframe style.
        sd.wireframe = !look.shaded;
        sd.fill = to_vec4(col.surface);
        sd.wire = to_vec4(look.selected ? col.selected_surface : col.surface);
        sd.wire_width = 1.0f * look.scale;
        out.surfaces.push_back(sd);
    }
    if (look.selected) add_box(out.box, im.lo, im.hi, to_vec4(col.selected_surface));
}

ControlNet kind_net(const doc::ImplicitObject&) {
    return {};
}

KindTraits kind_traits(const doc::ImplicitObject&) {
    return {ObjectEditor::implicit_surface, false, geom::name_of(doc::ObjectKind::implicit)};
}

} // namespace isoparm::ui
