// The implicit-surface panel: the expression (applied on Enter, parse errors with their
// column), a slider per named parameter, bounds and cell, presets, and the mesh's state.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <imgui.h>
#include <imgui_stdlib.h>
#include <string>
#include <variant>

#include "core/doc/commands.hpp"
#include "core/doc/placement.hpp"
#include "core/geom/implicit/expression.hpp"
#include "ui/panels/panels.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/implicit_meshes.hpp"
#include "ui/view/implicit_screen_level.hpp"
#include "ui/view/implicit_support.hpp"
#include "ui/view/text_wrap.hpp"

namespace isoparm::ui {

namespace {

const ImVec4 error_color{1.0f, 0.45f, 0.4f, 1};

// Runs one edit as its own undo step (a slider drag instead merges until released).
void edit(AppContext& ctx, std::uint64_t id, doc::ImplicitObject shape, const std::string& label) {
    ctx.seal();
    ctx.execute(doc::edit_shape(id, std::move(shape), label, label));
    ctx.seal();
}

void presets_combo(AppContext& ctx, const doc::Object& obj) {
    const auto& presets = implicit_presets();
    ImplicitForm& form = ctx.ui.implicit;
    form.preset = std::clamp(form.preset, 0, static_cast<int>(presets.size()) - 1);
    const float width = ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("Preset").x -
                        ImGui::GetStyle().ItemInnerSpacing.x;
    ImGui::SetNextItemWidth(width);
    // The preview invites a choice (the object may no longer be any preset), cut on purpose in
    // a narrow column with the whole in the tooltip.
    const std::string invite = "Replace with a preset...";
    const std::string preview =
        shortened(invite, width - ImGui::GetFrameHeight() - ImGui::GetStyle().FramePadding.x * 2,
                  [](std::string_view t) {
                      const ImVec2 v = ImGui::CalcTextSize(t.data(), t.data() + t.size());
                      return glm::vec2(v.x, v.y);
                  });
    const bool open = ImGui::BeginCombo("Preset", preview.c_str());
    report_item("implicit/preset");
    if (preview != invite && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", invite.c_str());
    if (open) {
        for (int k = 0; k < static_cast<int>(presets.size()); ++k) {
            const bool picked = ImGui::Selectable(presets[k].name, false);
            report_item(std::string("implicit/preset/") + presets[k].name);
            if (!picked) continue;
            form.preset = k;
            // Where the object is: a preset's formula is about the origin, moved to its centre.
            const doc::ImplicitObject& now = *obj.implicit();
            const doc::ImplicitObject& p = presets[k].object;
            const glm::dvec3 d = 0.5 * (now.lo + now.hi) - 0.5 * (p.lo + p.hi);
            edit(ctx, obj.id, doc::translated(p, d),
                 std::string("Apply implicit preset ") + presets[k].name);
        }
        ImGui::EndCombo();
    }
}

void expression_field(AppContext& ctx, const doc::Object& obj, const doc::ImplicitObject& im) {
    ImplicitForm& form = ctx.ui.implicit;
    ImGui::TextUnformatted("f(x, y, z) = 0, where f =");
    ImGui::SetNextItemWidth(-1);
    if (ImGui::InputText("##expression", &form.text, ImGuiInputTextFlags_EnterReturnsTrue)) {
        const doc::ImplicitObject next = with_expression(im, form.text);
        const auto program = geom::implicit::compile(next.expression, next.parameter_names);
        if (!program) {
            form.error = program.error().message; // the document stays as it was
        } else if (next.expression != im.expression) {
            form.error.clear();
            edit(ctx, obj.id, next, "Edit implicit expression");
        } else {
            form.error.clear();
        }
    }
    if (!form.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, error_color);
        text_wrapped("%s", form.error.c_str());
        ImGui::PopStyleColor();
    }
}

void parameter_sliders(AppContext& ctx, const doc::Object& obj, const doc::ImplicitObject& im) {
    if (im.parameter_names.empty()) {
        ImGui::TextDisabled("No parameters (name one, e.g. a, in the expression).");
        return;
    }
    for (std::size_t k = 0; k < im.parameter_names.size() && k < im.parameter_values.size(); ++k) {
        double v = im.parameter_values[k];
        ImGui::PushID(static_cast<int>(k));
        ImGui::SetNextItemWidth(-ImGui::CalcTextSize("MMMM").x);
        // Speed relative to the value, so 11.8 and 0.4 both move at a useful pace.
        const float speed = static_cast<float>(0.004 * std::max(1.0, std::abs(v)));
        const bool changed = ImGui::DragScalar(im.parameter_names[k].c_str(), ImGuiDataType_Double,
                                               &v, speed, nullptr, nullptr, "%.4g");
        if (ImGui::IsItemActive()) ctx.ui.implicit.dragging = true;
        if (changed && std::isfinite(v) && v != im.parameter_values[k]) {
            doc::ImplicitObject next = im;
            next.parameter_values[k] = v;
            // Not sealed: the drag's edits merge into one undo step; the frame seals once
            // the mouse is released.
            const std::string label = "Edit implicit parameter " + im.parameter_names[k];
            ctx.execute(doc::edit_shape(obj.id, next, label, label));
        }
        if (ImGui::IsItemDeactivated()) ctx.seal();
        ImGui::PopID();
    }
}

void bounds_fields(AppContext& ctx, const doc::Object& obj, const doc::ImplicitObject& im) {
    const float w = -ImGui::CalcTextSize("MMMM").x;
    double lo[3] = {im.lo.x, im.lo.y, im.lo.z}, hi[3] = {im.hi.x, im.hi.y, im.hi.z};
    double cell = im.cell;
    const auto flags = ImGuiInputTextFlags_EnterReturnsTrue;
    ImGui::SetNextItemWidth(w);
    const bool lo_changed =
        ImGui::InputScalarN("min", ImGuiDataType_Double, lo, 3, nullptr, nullptr, "%.3g", flags);
    ImGui::SetNextItemWidth(w);
    const bool hi_changed =
        ImGui::InputScalarN("max", ImGuiDataType_Double, hi, 3, nullptr, nullptr, "%.3g", flags);
    if (lo_changed || hi_changed) {
        doc::ImplicitObject next = im;
        next.lo = {lo[0], lo[1], lo[2]};
        next.hi = {hi[0], hi[1], hi[2]};
        if (next.lo != im.lo || next.hi != im.hi) edit(ctx, obj.id, next, "Edit implicit bounds");
    }
    ImGui::SetNextItemWidth(w);
    if (ImGui::InputScalar("cell", ImGuiDataType_Double, &cell, nullptr, nullptr, "%.4g", flags) &&
        cell != im.cell) {
        doc::ImplicitObject next = im;
        next.cell = cell;
        edit(ctx, obj.id, next, "Edit implicit cell");
    }
    const glm::dvec3 e = im.hi - im.lo;
    if (im.cell > 0)
        ImGui::TextDisabled("grid %.0f x %.0f x %.0f cells", std::ceil(e.x / im.cell),
                            std::ceil(e.y / im.cell), std::ceil(e.z / im.cell));
}

void mesh_state(AppContext& ctx, const doc::Object& obj, const doc::ImplicitObject& im) {
    if (!ctx.implicit_meshes) return;
    const ImplicitMeshes::View v = ctx.implicit_meshes->view(obj.id);
    if (v.progress >= 0) {
        char label[48];
        std::snprintf(label, sizeof label, "polygonizing %.0f%%", v.progress * 100);
        ImGui::ProgressBar(static_cast<float>(v.progress), ImVec2(-1, 0), label);
    }
    if (!v.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, error_color);
        text_wrapped("%s", v.error.c_str());
        ImGui::PopStyleColor();
    } else if (v.mesh) {
        ImGui::TextDisabled("%zu triangles, %zu vertices%s", v.mesh->triangles.size(),
                            v.mesh->positions.size(), v.cell != im.cell ? " (coarse preview)" : "");
    }
    // The 3D view's own grid when it draws the surface coarser (implicit_screen_level.hpp).
    const ImplicitMeshes::View drawn = ctx.implicit_meshes->drawn(obj.id);
    if (!v.mesh || !drawn.mesh) return;
    report_fact("implicit/cell", v.cell);
    report_fact("implicit/drawn_cell", drawn.cell);
    if (drawn.cell > v.cell && v.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        text_wrapped("The 3D view draws it with cell %g (%zu triangles): cell %g is under %g "
                     "pixels there.",
                     drawn.cell, drawn.mesh->triangles.size(), v.cell, screen_cell_pixels / 2);
        ImGui::PopStyleColor();
    }
}

} // namespace

void draw_implicit_panel(AppContext& ctx) {
    const doc::Object* obj = ctx.doc.selected();
    const doc::ImplicitObject* im = obj ? obj->implicit() : nullptr;
    if (!im) {
        ImGui::TextDisabled("Select an implicit surface.");
        return;
    }
    ImplicitForm& form = ctx.ui.implicit;
    // Refill the field for another object or when the document changed (undo, preset).
    if (form.object != obj->id || form.synced != im->expression) {
        form.object = obj->id;
        form.synced = im->expression;
        form.text = im->expression;
        form.error.clear();
    }
    // Copies: an edit below may replace the shape the references point into.
    const doc::Object o = *obj;
    const doc::ImplicitObject f = *im;
    ImGui::Text("%s", o.name.empty() ? "implicit surface" : o.name.c_str());
    presets_combo(ctx, o);
    ImGui::Separator();
    expression_field(ctx, o, f);
    ImGui::Separator();
    parameter_sliders(ctx, o, f);
    ImGui::Separator();
    bounds_fields(ctx, o, f);
    mesh_state(ctx, o, f);
}

} // namespace isoparm::ui
