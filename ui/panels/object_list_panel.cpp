// The object list: every object of the scene with its kind; select, rename (double-click),
// hide / show and delete, each through the command layer (undoable).
#include <cstdio>
#include <imgui.h>
#include <string>

#include "core/doc/commands.hpp"
#include "core/doc/placement.hpp"
#include "ui/panels/panels.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/kinds/kind_view.hpp"
#include "ui/view/text_wrap.hpp"

namespace isoparm::ui {

namespace {

// One edit, one undo step, apart from whatever gesture came before.
bool run_alone(AppContext& ctx, std::unique_ptr<doc::Command> cmd) {
    ctx.seal();
    const bool ok = ctx.execute(std::move(cmd));
    ctx.seal();
    return ok;
}

} // namespace

void draw_object_list_panel(AppContext& ctx) {
    ObjectListState& st = ctx.ui.object_list;
    if (ctx.doc.objects.empty()) {
        text_wrapped("The scene is empty: Surface > New Surface (Ctrl+Shift+N) or "
                     "Curve > New curve adds an object.");
        return;
    }
    std::uint64_t remove = 0, select = 0;
    std::pair<std::uint64_t, bool> show{0, false};
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH |
                                  ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingStretchProp;
    if (ImGui::BeginTable("##objects", 4, flags)) {
        const float icon = ImGui::GetFrameHeight();
        ImGui::TableSetupColumn("##shown", ImGuiTableColumnFlags_WidthFixed, icon);
        // The kind as wide as its longest word; the name takes the rest (on a projector the
        // column is narrow: a trimmed surface says "trimmed" there, its type in the tooltip).
        ImGui::TableSetupColumn("Name", ImGuiTableColumnFlags_WidthStretch, 1);
        ImGui::TableSetupColumn("Kind", ImGuiTableColumnFlags_WidthFixed,
                                ImGui::CalcTextSize("triangle").x);
        ImGui::TableSetupColumn("##delete", ImGuiTableColumnFlags_WidthFixed, icon);
        ImGui::TableSetupScrollFreeze(0, 1);
        ImGui::TableHeadersRow();
        for (const doc::Object& o : ctx.doc.objects) {
            ImGui::PushID(static_cast<int>(o.id));
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            bool visible = o.visible;
            if (ImGui::Checkbox("##shown", &visible)) show = {o.id, visible};
            report_item("objects/shown/" + o.name);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip(o.visible ? "Hide" : "Show");
            ImGui::TableNextColumn();
            const std::string label = o.name.empty() ? "object " + std::to_string(o.id) : o.name;
            if (st.renaming == o.id) {
                ImGui::SetNextItemWidth(-1);
                if (st.focus_rename) {
                    ImGui::SetKeyboardFocusHere();
                    st.focus_rename = false;
                }
                const bool enter = ImGui::InputText("##rename", st.name, sizeof st.name,
                                                    ImGuiInputTextFlags_EnterReturnsTrue |
                                                        ImGuiInputTextFlags_AutoSelectAll);
                if (enter) {
                    // A name another object has gets a number: names stay unique.
                    const std::string name = doc::unique_name(ctx.doc, st.name, o.id);
                    if (name != o.name) run_alone(ctx, doc::rename_object(o.id, name));
                    st.renaming = 0;
                } else if (ImGui::IsItemDeactivated()) {
                    st.renaming = 0; // Esc or a click elsewhere: the name stays
                }
            } else {
                const bool selected = o.id == ctx.doc.view.selection.object;
                // Cut in the middle where the column is narrow, so names that differ at their
                // end stay apart; the whole name in the tooltip.
                const std::string shown = shortened_middle(
                    label, ImGui::GetContentRegionAvail().x, [](std::string_view t) {
                        const ImVec2 v = ImGui::CalcTextSize(t.data(), t.data() + t.size());
                        return glm::vec2(v.x, v.y);
                    });
                ImGui::PushID("name");
                const bool clicked = ImGui::Selectable((shown + "##" + label).c_str(), selected,
                                                       ImGuiSelectableFlags_AllowDoubleClick);
                ImGui::PopID();
                report_item("objects/" + label);
                if (clicked) {
                    select = o.id;
                    if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
                        st.renaming = o.id;
                        st.focus_rename = true;
                        std::snprintf(st.name, sizeof st.name, "%s", o.name.c_str());
                    }
                }
                if (ImGui::IsItemHovered() && st.renaming == 0)
                    ImGui::SetTooltip("%s\nClick: select. Double-click: rename.", label.c_str());
            }
            ImGui::TableNextColumn();
            if (const KindTraits kind = traits_of(o.shape); *kind.note) {
                ImGui::TextDisabled("%s", kind.note);
                if (ImGui::IsItemHovered())
                    ImGui::SetTooltip("%s surface, %s", kind.label, kind.note);
            } else {
                ImGui::TextDisabled("%s", kind.label);
            }
            ImGui::TableNextColumn();
            if (ImGui::SmallButton("x")) remove = o.id;
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("Delete %s (Ctrl+Z brings it back)", label.c_str());
            ImGui::PopID();
        }
        ImGui::EndTable();
    }
    // Applied after the loop: the commands change the list being drawn.
    if (select != 0 && select != ctx.doc.view.selection.object)
        ctx.doc.view.selection = {select, -1, -1};
    if (show.first != 0) run_alone(ctx, doc::set_visible(show.first, show.second));
    if (remove != 0 && run_alone(ctx, doc::remove_object(remove))) normalize_selection(ctx.doc);
}

} // namespace isoparm::ui
