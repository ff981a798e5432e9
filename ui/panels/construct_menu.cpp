// The Curve menu (new curves, exact primitives) and the Construct menu (make compatible,
// ruled, revolve, swing, sweep, oriented sweep, skin) with its dialog.
#include <algorithm>
#include <cstdio>
#include <imgui.h>
#include <string>
#include <vector>

#include "core/doc/commands.hpp"
#include "core/doc/commands_construction.hpp"
#include "core/doc/commands_curve.hpp"
#include "core/doc/curve_constructions.hpp"
#include "core/doc/placement.hpp"
#include "ui/actions.hpp"
#include "ui/fit_actions.hpp"
#include "ui/modeler_actions.hpp"
#include "ui/panels/panels.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

namespace {

// After the doc::Construction values (isocurve, the last, has menu items of its own).
constexpr int make_compatible_kind = 9;
constexpr int isocurve_kind = static_cast<int>(doc::Construction::isocurve);

// A new curve beside what the scene holds (never on top of it), with a name no other object
// has; selected, and the camera refits to show it.
void add_and_select(AppContext& ctx, geom::Expected<doc::Object> o, const char* what) {
    if (!o) {
        show_error(ctx, std::string("Cannot add the ") + what, o.error().message);
        return;
    }
    doc::place_beside_scene(ctx.doc, o->shape);
    o->name = doc::unique_name(ctx.doc, o->name);
    ctx.seal();
    if (ctx.execute(doc::add_object(std::move(o).value()))) {
        ctx.doc.view.selection = {ctx.doc.objects.back().id, -1, -1};
        fit_view(ctx);
    }
    ctx.seal();
}

// A starting curve in a plane: four points of a gentle S, cubic, clamped uniform knots.
void new_curve(AppContext& ctx, doc::CurvePlane plane) {
    const PlaneAxes ax = plane_axes[plane == doc::CurvePlane::free3d ? 0 : static_cast<int>(plane)];
    std::vector<glm::dvec3> pts;
    const double xy[4][2] = {{-1, 0}, {-0.35, 0.8}, {0.35, -0.8}, {1, 0}};
    for (const auto& q : xy) {
        glm::dvec3 p(0);
        p[ax.a] = q[0];
        p[ax.b] = q[1];
        pts.push_back(p);
    }
    add_and_select(ctx,
                   doc::new_curve_object(fresh_name(ctx.doc, "curve"), plane, pts, 3,
                                         doc::CurveKnotMode::clamped_uniform),
                   "curve");
}

void curve_menu(AppContext& ctx) {
    if (!begin_menu("Curve")) return;
    const char* planes[] = {"New curve in xy", "New curve in xz", "New curve in yz",
                            "New 3D curve"};
    for (int p = 0; p < 4; ++p)
        if (menu_item(planes[p])) new_curve(ctx, static_cast<doc::CurvePlane>(p));
    ImGui::Separator();
    ImGui::TextDisabled("Exact primitives (xy plane; the designer's Primitives edit more)");
    if (menu_item("Line"))
        add_and_select(ctx,
                       doc::line_object(fresh_name(ctx.doc, "line"), doc::CurvePlane::xy,
                                        {-1, 0, 0}, {1, 0, 0}),
                       "line");
    if (menu_item("Circular arc (90 degrees)"))
        add_and_select(
            ctx,
            doc::arc_object(fresh_name(ctx.doc, "arc"), doc::CurvePlane::xy, {0, 0, 0}, 1, 0, 90),
            "arc");
    if (menu_item("Full circle"))
        add_and_select(
            ctx,
            doc::circle_object(fresh_name(ctx.doc, "circle"), doc::CurvePlane::xy, {0, 0, 0}, 1),
            "circle");
    ImGui::Separator();
    if (menu_item("Fit curve to points...", nullptr, ctx.ui.fit.open)) open_fit_panel(ctx);
    ImGui::Separator();
    const doc::Object* sel = ctx.doc.selected();
    if (sel && sel->curve_object()) {
        ImGui::TextDisabled("Selected curve: %s", sel->name.c_str());
        toolbox_items(ctx, true);
        multires_menu_item(ctx, true);
    } else {
        ImGui::TextDisabled("Select a curve for knot removal, reduction, splitting, closing");
    }
    ImGui::EndMenu();
}

void open_dialog(AppContext& ctx, int kind) {
    CurveDesignerState& cd = ctx.ui.curve;
    cd.construct_kind = kind;
    cd.construct_open = true;
    cd.editing = 0;
    cd.note.clear();
    // Keep the chosen curves that still exist; start from the selected curve.
    std::erase_if(cd.chosen, [&](std::uint64_t id) {
        const doc::Object* o = ctx.doc.find(id);
        return !o || !std::holds_alternative<doc::CurveObject>(o->shape);
    });
    const doc::Object* sel = ctx.doc.selected();
    if (cd.chosen.empty() && sel && std::holds_alternative<doc::CurveObject>(sel->shape))
        cd.chosen.push_back(sel->id);
}

// Construct > Edit construction: the dialog on the selected object's recipe, changed in place.
void open_edit_dialog(AppContext& ctx, const doc::Object& o) {
    const doc::Recipe& r = *o.construction;
    CurveDesignerState& cd = ctx.ui.curve;
    cd.construct_kind = static_cast<int>(r.kind);
    cd.construct_open = true;
    cd.editing = o.id;
    cd.note.clear();
    cd.chosen = r.curves;
    cd.angle = r.angle;
    cd.swing_scale = r.scale;
    cd.skin_degree = r.skin_degree;
    cd.parametrization = static_cast<int>(r.parametrization);
    cd.sections = r.sections;
    cd.gordon_u_count = r.gordon_u_count;
    cd.iso_dir = r.iso_dir == geom::Dir::u ? 0 : 1;
    cd.iso_t = r.iso_t;
}

// Construct > Isocurve at the indicator: the selected surface's curve through (u, v), linked.
void build_isocurve(AppContext& ctx, geom::Dir dir) {
    const doc::Object* s = nullptr;
    if (!current_surface(ctx.doc, &s) || !s) return;
    doc::Recipe r;
    r.kind = doc::Construction::isocurve;
    r.curves = {s->id};
    r.iso_dir = dir;
    r.iso_t = dir == geom::Dir::u ? ctx.doc.view.indicator.x : ctx.doc.view.indicator.y;
    ctx.seal();
    if (ctx.execute(doc::construct(r))) {
        if (const std::uint64_t id = doc::constructed_id(*ctx.history.top()))
            ctx.doc.view.selection = {id, -1, -1};
    }
    ctx.seal();
}

void construct_menu(AppContext& ctx) {
    if (!begin_menu("Construct")) return;
    if (menu_item("Make compatible...")) open_dialog(ctx, make_compatible_kind);
    ImGui::Separator();
    const char* items[] = {"Ruled...",          "Revolve...", "Swing...", "Sweep...",
                           "Oriented sweep...", "Skin...",    "Coons...", "Gordon..."};
    static_assert(std::size(items) == isocurve_kind);
    for (int k = 0; k < isocurve_kind; ++k) {
        if (k == 6) ImGui::Separator(); // from a boundary or a network of curves
        if (menu_item(items[k])) open_dialog(ctx, k);
    }
    ImGui::Separator();
    const doc::Object* cur = nullptr;
    const bool surface = current_surface(ctx.doc, &cur) != nullptr;
    if (menu_item("Isocurve along v at the indicator's u", nullptr, false, surface))
        build_isocurve(ctx, geom::Dir::u);
    if (menu_item("Isocurve along u at the indicator's v", nullptr, false, surface))
        build_isocurve(ctx, geom::Dir::v);
    ImGui::Separator();
    // Constructions stay linked to their curves: edit the recipe, or cut the link.
    const doc::Object* sel = ctx.doc.selected();
    const bool linked = sel && sel->construction;
    if (menu_item("Edit construction...", nullptr, false, linked)) open_edit_dialog(ctx, *sel);
    if (!linked && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("Select a constructed object (one built here, still linked)");
    if (menu_item("Detach (free the selected object)", nullptr, false, linked))
        detach_selected(ctx);
    ImGui::EndMenu();
}

const char* what_it_does(int kind) {
    switch (kind) {
    case 0:
        return "The ruled surface between two curves: every v-line is the straight segment "
               "from C0(u) to C1(u) (P&T 10.2). Choose 2 curves.";
    case 1:
        return "The surface of revolution of a profile about the z-axis, exact with rational "
               "quadratic arcs (P&T A8.1). Choose 1 curve.";
    case 2:
        return "A profile in the xz-plane swung along a trajectory in the xy-plane, scaled "
               "(P&T 10.4). Choose the profile, then the trajectory.";
    case 3:
        return "The profile translated along the trajectory: S = P(u) + T(v) - T(start), "
               "exact. Choose the profile, then the trajectory.";
    case 4:
        return "The profile carried along the trajectory and turned with it (rotation-"
               "minimizing frames), skinned through placed copies; the deviation from the "
               "ideal sweep is reported. Choose the profile, then the trajectory.";
    case 5:
        return "A surface through two or more section curves, in order (P&T 10.3): they are "
               "made compatible, then interpolated across.";
    case 6:
        return "The bilinearly blended Coons patch (P&T 10.5, Farin ch. 22) from four "
               "boundaries whose ends meet: S(u, 0), S(u, 1), S(0, v), S(1, v), in this order. "
               "It reproduces all four boundaries exactly.";
    case 7:
        return "The Gordon surface through a network (Gordon 1969; P&T 10.5): first the curves "
               "along u (constant v), then the curves along v (constant u); every u-curve must "
               "meet every v-curve. It interpolates every curve of the network.";
    case isocurve_kind:
        return "The curve of a surface at a fixed parameter, exact (P&T 3.4): it follows the "
               "surface, so a collar ruled from a vase's rim follows the vase's profile.";
    default:
        return "Ruled and skinned surfaces pair the i-th control points of their curves, so "
               "the curves need one degree and one knot vector. This raises the degrees "
               "(A5.9) and merges the knots (A5.4); each curve's shape stays the same.";
    }
}

std::string knot_text(const geom::Knots& U) {
    std::string s = "[";
    for (std::size_t q = 0; q < U.size(); ++q) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%s%.3g", q ? " " : "", U[q]);
        s += buf;
        if (q >= 14 && q + 1 < U.size()) {
            s += " ... (" + std::to_string(U.size()) + " knots)";
            break;
        }
    }
    return s + "]";
}

// "name: degree p, n points, U = [...]" for each chosen curve.
std::string curves_text(const doc::Document& d, const std::vector<std::uint64_t>& ids) {
    std::string s;
    for (std::uint64_t id : ids) {
        const doc::Object* o = d.find(id);
        const auto* c = o ? std::get_if<doc::CurveObject>(&o->shape) : nullptr;
        if (!c) continue;
        s += o->name + ": degree " + std::to_string(c->curve.degree) + ", " +
             std::to_string(c->curve.count()) + " points, U = " + knot_text(c->curve.knots) + "\n";
    }
    return s;
}

// The document's curves with checkboxes; the chosen ones in order, with up / down buttons.
void curve_chooser(AppContext& ctx) {
    CurveDesignerState& cd = ctx.ui.curve;
    const float k = ctx.ui.scale();
    const bool surfaces = cd.construct_kind == isocurve_kind; // an isocurve reads a surface
    ImGui::TextUnformatted(surfaces ? "Surfaces of the scene:" : "Curves of the scene:");
    ImGui::BeginChild("##curves", ImVec2(0, 110 * k), true);
    for (const doc::Object& o : ctx.doc.objects) {
        if (surfaces && o.surface() && o.id != cd.editing) {
            const auto it = std::find(cd.chosen.begin(), cd.chosen.end(), o.id);
            bool on = it != cd.chosen.end();
            ImGui::PushID(static_cast<int>(o.id));
            if (ImGui::Checkbox(o.name.c_str(), &on)) cd.chosen = {o.id};
            ImGui::PopID();
            continue;
        }
        const auto* c = std::get_if<doc::CurveObject>(&o.shape);
        if (!c || surfaces || o.id == cd.editing) continue;
        const auto it = std::find(cd.chosen.begin(), cd.chosen.end(), o.id);
        bool on = it != cd.chosen.end();
        ImGui::PushID(static_cast<int>(o.id));
        char label[160];
        std::snprintf(label, sizeof label, "%s  (%s, degree %d, %d points)", o.name.c_str(),
                      doc::curve_plane_label(c->plane), c->curve.degree, c->curve.count());
        const bool toggled = ImGui::Checkbox(label, &on);
        report_item("construct/curve/" + o.name);
        if (toggled) {
            if (on)
                cd.chosen.push_back(o.id);
            else
                cd.chosen.erase(it);
        }
        ImGui::PopID();
    }
    ImGui::EndChild();
    if (cd.chosen.empty()) return;
    ImGui::TextUnformatted("In this order:");
    for (std::size_t q = 0; q < cd.chosen.size(); ++q) {
        const doc::Object* o = ctx.doc.find(cd.chosen[q]);
        if (!o) continue;
        ImGui::PushID(static_cast<int>(q));
        ImGui::BeginDisabled(q == 0);
        if (ImGui::ArrowButton("##up", ImGuiDir_Up)) std::swap(cd.chosen[q], cd.chosen[q - 1]);
        ImGui::EndDisabled();
        ImGui::SameLine();
        ImGui::BeginDisabled(q + 1 == cd.chosen.size());
        if (ImGui::ArrowButton("##down", ImGuiDir_Down)) std::swap(cd.chosen[q], cd.chosen[q + 1]);
        ImGui::EndDisabled();
        ImGui::SameLine();
        const int kind = cd.construct_kind;
        const bool roles = kind == 2 || kind == 3 || kind == 4;
        static const char* coons_roles[] = {"S(u, 0)", "S(u, 1)", "S(0, v)", "S(1, v)"};
        if (roles && q < 2)
            ImGui::Text("%s: %s", q == 0 ? "profile" : "trajectory", o->name.c_str());
        else if (kind == 6 && q < 4)
            ImGui::Text("%s: %s", coons_roles[q], o->name.c_str());
        else if (kind == 7)
            ImGui::Text("%s %zu: %s",
                        static_cast<int>(q) < cd.gordon_u_count ? "u-curve" : "v-curve",
                        static_cast<int>(q) < cd.gordon_u_count ? q + 1 : q + 1 - cd.gordon_u_count,
                        o->name.c_str());
        else
            ImGui::Text("%zu. %s", q + 1, o->name.c_str());
        ImGui::PopID();
    }
}

constexpr double zero_one[2] = {0.0, 1.0};

void parameters(AppContext& ctx) {
    CurveDesignerState& cd = ctx.ui.curve;
    const float k = ctx.ui.scale();
    ImGui::SetNextItemWidth(120 * k);
    switch (cd.construct_kind) {
    case 1:
        ImGui::InputDouble("Angle (degrees, 0 < a <= 360)", &cd.angle, 15, 90, "%.1f");
        break;
    case 2:
        ImGui::InputDouble("Scale", &cd.swing_scale, 0.1, 1, "%.3f");
        break;
    case 4:
        ImGui::InputInt("Sections (copies - 1)", &cd.sections);
        cd.sections = std::clamp(cd.sections, 1, 256);
        break;
    case 5: {
        ImGui::InputInt("v-degree (0: min(3, curves - 1))", &cd.skin_degree);
        cd.skin_degree = std::max(cd.skin_degree, 0);
        const char* params[] = {"chord", "centripetal", "uniform"};
        ImGui::SetNextItemWidth(120 * k);
        ImGui::Combo("Parametrization", &cd.parametrization, params, 3);
        break;
    }
    case 7:
        ImGui::InputInt("u-curves (the first in the order; the rest run along v)",
                        &cd.gordon_u_count);
        break;
    case isocurve_kind: {
        const char* dirs[] = {"u fixed (the curve runs along v)",
                              "v fixed (the curve runs along u)"};
        ImGui::SetNextItemWidth(260 * k);
        ImGui::Combo("##isodir", &cd.iso_dir, dirs, 2);
        ImGui::SetNextItemWidth(160 * k);
        ImGui::SliderScalar("where (0..1 over the domain)", ImGuiDataType_Double, &cd.iso_t,
                            &zero_one[0], &zero_one[1], "%.3f");
        break;
    }
    default:
        ImGui::Dummy(ImVec2(0, 0));
        break;
    }
}

// Runs the dialog's construction; the result is added as a new surface and selected, or the
// refusal shown in the dialog itself, which stays open so the choice can be corrected (the
// document unchanged). Returns whether it worked.
bool build(AppContext& ctx) {
    CurveDesignerState& cd = ctx.ui.curve;
    if (cd.construct_kind == make_compatible_kind) {
        const std::string before = curves_text(ctx.doc, cd.chosen);
        ctx.seal();
        const bool ok = ctx.execute(doc::make_curves_compatible(cd.chosen));
        ctx.seal();
        if (!ok) {
            cd.error = "Make compatible: not done. " + ctx.ui.status;
            return false;
        }
        cd.note = "Before:\n" + before + "After (same shapes, u in [0, 1]):\n" +
                  curves_text(ctx.doc, cd.chosen);
        ctx.ui.status = "Made " + std::to_string(cd.chosen.size()) + " curves compatible";
        return true;
    }
    doc::Recipe r;
    r.kind = static_cast<doc::Construction>(cd.construct_kind);
    r.curves = cd.chosen;
    r.angle = cd.angle;
    r.scale = cd.swing_scale;
    r.skin_degree = cd.skin_degree;
    r.parametrization = static_cast<geom::Parametrization>(cd.parametrization);
    r.sections = cd.sections;
    r.gordon_u_count = cd.gordon_u_count;
    r.iso_dir = cd.iso_dir == 0 ? geom::Dir::u : geom::Dir::v;
    r.iso_t = cd.iso_t;
    // Edit construction: the recipe changes in place (one undo step), no copy is built.
    if (const doc::Object* edited = ctx.doc.find(cd.editing); edited && edited->construction) {
        const std::string name = edited->name;
        ctx.seal();
        const bool ok = ctx.execute(doc::edit_construction(cd.editing, r));
        ctx.seal();
        if (!ok) {
            cd.error =
                std::string(doc::construction_label(r.kind)) + ": not changed. " + ctx.ui.status;
            return false;
        }
        const std::string note = doc::construction_note(*ctx.history.top());
        cd.note = "Changed '" + name + "' in place." + (note.empty() ? "" : "\n" + note);
        ctx.ui.status = "Changed the construction of '" + name + "'";
        return true;
    }
    // The same recipe built already: say so (Edit construction changes that one).
    std::string twin;
    for (const doc::Object& o : ctx.doc.objects)
        if (o.construction && o.construction->kind == r.kind && o.construction->curves == r.curves)
            twin = o.name;
    const std::string title = std::string(doc::construction_label(r.kind)) + ": not built";
    ctx.seal();
    // The recipe, not the surface: a recording (a lesson) keeps "revolve curve 2".
    const bool ok = ctx.execute(doc::construct(r));
    ctx.seal();
    if (!ok) {
        cd.error = title + ". " + ctx.ui.status;
        return false;
    }
    const std::uint64_t id = doc::constructed_id(*ctx.history.top());
    const doc::Object* made = ctx.doc.find(id);
    const std::string name = made ? made->name : "";
    const std::string note = doc::construction_note(*ctx.history.top());
    ctx.doc.view.selection = {id, -1, -1};
    fit_view(ctx);
    cd.note =
        "Added '" + name +
        "' (selected). It follows its curves: edit them and it is built "
        "again; Construct > Edit construction changes its parameters." +
        (twin.empty() ? "" : "\n'" + twin + "' was built from the same curves the same way.") +
        (note.empty() ? "" : "\n" + note);
    ctx.ui.status = "Added '" + name + "'";
    return true;
}

bool escape_pressed() {
    return ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
}

} // namespace

void draw_construct_menus(AppContext& ctx) {
    curve_menu(ctx);
    construct_menu(ctx);
}

void draw_construct_dialog(AppContext& ctx) {
    CurveDesignerState& cd = ctx.ui.curve;
    const char* id = "Construct##dialog";
    if (cd.construct_open) cd.error.clear();
    if (!begin_centered_modal(id, cd.construct_open, 520 * ctx.ui.scale(),
                              ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoTitleBar))
        return;
    const int kind = cd.construct_kind;
    const char* title = kind == make_compatible_kind
                            ? "Make compatible"
                            : doc::construction_label(static_cast<doc::Construction>(kind));
    const doc::Object* edited = ctx.doc.find(cd.editing);
    if (edited)
        ImGui::Text("Edit the construction of '%s' (%s)", edited->name.c_str(), title);
    else
        ImGui::TextUnformatted(title);
    ImGui::Separator();
    text_wrapped("%s", what_it_does(kind));
    ImGui::Spacing();
    curve_chooser(ctx);
    if (kind == make_compatible_kind && !cd.chosen.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        text_wrapped("%s", curves_text(ctx.doc, cd.chosen).c_str());
        ImGui::PopStyleColor();
    }
    parameters(ctx);
    if (!cd.note.empty()) {
        ImGui::Separator();
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.45f, 0.85f, 0.5f, 1));
        text_wrapped("%s", cd.note.c_str());
        ImGui::PopStyleColor();
    }
    if (!cd.error.empty()) {
        ImGui::Separator();
        ImGui::PushStyleColor(ImGuiCol_Text, error_text_color());
        text_wrapped("%s", cd.error.c_str());
        ImGui::PopStyleColor();
    }
    ImGui::Spacing();
    bool close = false;
    const bool build_pressed = ImGui::Button(kind == make_compatible_kind ? "Make compatible"
                                             : edited                     ? "Apply"
                                                                          : "Build");
    report_item("construct/build");
    if (build_pressed && build(ctx)) cd.error.clear();
    ImGui::SameLine();
    if (ImGui::Button("Close") || escape_pressed()) close = true;
    if (close) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

} // namespace isoparm::ui
