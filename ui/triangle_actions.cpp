// Triangle actions through the command layer, their refusals shown as the commands give them.
#include "ui/triangle_actions.hpp"

#include "core/doc/commands.hpp"
#include "core/doc/commands_triangle.hpp"
#include "core/doc/placement.hpp"
#include "ui/actions.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

namespace {

const doc::Object* selected_triangle(const AppContext& ctx) {
    const doc::Object* o = ctx.doc.selected();
    return o && o->triangle() ? o : nullptr;
}

std::string barycentric_text(const geom::Barycentric& p) {
    return "(" + geom::format_short(p[0], 3) + ", " + geom::format_short(p[1], 3) + ", " +
           geom::format_short(p[2], 3) + ")";
}

ActionState checked(std::string label, const doc::Command& cmd, const doc::Document& d) {
    ActionState a;
    a.label = std::move(label);
    const geom::Status st = cmd.check(d);
    a.enabled = st.ok();
    if (!st) a.why = st.error().message;
    return a;
}

void run(AppContext& ctx, std::unique_ptr<doc::Command> cmd) {
    ctx.seal();
    const doc::Command* applied = cmd.get();
    if (ctx.execute(std::move(cmd)))
        note_action(ctx, applied->label(), false);
    else
        note_action(ctx, ctx.ui.status, true);
    ctx.seal();
}

} // namespace

void new_triangle(AppContext& ctx, int degree, bool rational) {
    auto patch = doc::make_flat_triangle(degree, rational);
    if (!patch) {
        note_action(ctx, patch.error().message, true);
        return;
    }
    doc::Object o;
    o.name = fresh_name(ctx.doc, "triangle");
    o.shape = doc::TriangleObject{std::move(patch).value()};
    doc::place_beside_scene(ctx.doc, o.shape);
    ctx.seal();
    if (ctx.execute(doc::add_object(std::move(o)))) {
        // The middle control point, so the first drag shapes the inside of the patch.
        const int i = degree / 3, j = degree / 3;
        ctx.doc.view.selection = {ctx.doc.objects.back().id, i, j};
        ctx.doc.view.barycentric = {1.0 / 3, 1.0 / 3, 1.0 / 3};
        fit_view(ctx); // beside the scene: the camera takes it in
        note_action(ctx, "Added a degree-" + std::to_string(degree) + " triangular patch", false);
    }
    ctx.seal();
}

ActionState elevate_triangle_state(const AppContext& ctx) {
    const doc::Object* o = selected_triangle(ctx);
    if (!o) return {"Elevate triangle degree", false, "select a triangular patch"};
    const int n = o->triangle()->degree;
    return checked("Elevate triangle degree (" + std::to_string(n) + " to " +
                       std::to_string(n + 1) + ")",
                   *doc::elevate_degree(o->id, geom::Dir::u), ctx.doc);
}

ActionState split_triangle_state(const AppContext& ctx) {
    const doc::Object* o = selected_triangle(ctx);
    if (!o) return {"Split triangle at the indicator", false, "select a triangular patch"};
    return checked("Split triangle at " + barycentric_text(ctx.doc.view.barycentric),
                   *doc::split_triangle(o->id, ctx.doc.view.barycentric), ctx.doc);
}

void elevate_selected_triangle(AppContext& ctx) {
    if (const doc::Object* o = selected_triangle(ctx))
        run(ctx, doc::elevate_degree(o->id, geom::Dir::u));
}

void split_triangle_at_indicator(AppContext& ctx) {
    if (const doc::Object* o = selected_triangle(ctx))
        run(ctx, doc::split_triangle(o->id, ctx.doc.view.barycentric));
}

} // namespace isoparm::ui
