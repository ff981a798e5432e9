// The start-up recovery dialog and restoring autosaved work through the history.
#include "ui/recovery.hpp"

#include <ctime>
#include <filesystem>
#include <imgui.h>
#include <string>
#include <utility>

#include "core/doc/restore_command.hpp"
#include "core/scene/scene_io.hpp"
#include "ui/actions.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

namespace {

constexpr const char* title = "Restore unsaved work?";

std::string local_time(std::chrono::system_clock::time_point t) {
    const std::time_t tt = std::chrono::system_clock::to_time_t(t);
    std::tm tm{};
    localtime_r(&tt, &tm);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M", &tm);
    return text;
}

void hold_all(RecoveryPrompt& r) {
    for (const scene::RecoveryInfo& o : r.offers) r.held.push_back(o.origin);
    r.offers.clear();
}

} // namespace

bool restore_recovery(AppContext& ctx, const scene::RecoveryInfo& recovery) {
    geom::Expected<doc::Document> recovered = scene::load_scene(recovery.path);
    if (!recovered.ok()) {
        std::string why = recovered.error().message;
        show_error(ctx, "Could not restore the autosaved work",
                   "The recovery file '" + recovery.path +
                       "' did not load; it is kept, and the current scene is unchanged.\n\n" + why);
        return false;
    }
    new_document(ctx);
    if (!recovery.origin.empty()) {
        // Undo goes back to the scene as saved; a scene that no longer loads (or never was
        // saved there) starts from the new document instead, under the same path.
        geom::Expected<doc::Document> saved = scene::load_scene(recovery.origin);
        if (saved.ok()) ctx.doc = std::move(saved).value();
        ctx.file_path = recovery.origin;
        ctx.file_stamp = json_io::stamp_of(recovery.origin); // the file as loaded for Undo
    }
    ctx.seal();
    const bool ok = ctx.execute(doc::restore_document(std::move(recovered).value()));
    ctx.seal();
    normalize_selection(ctx.doc);
    ctx.ui.camera_needs_fit = true;
    if (ok) ctx.ui.recovery.restored.push_back(recovery.origin);
    return ok;
}

void draw_recovery_dialog(AppContext& ctx) {
    RecoveryPrompt& r = ctx.ui.recovery;
    if (!ImGui::IsPopupOpen(title)) {
        // One modal at a time: an error from the start-up's scene comes first.
        if (r.offers.empty() || ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopupId)) return;
        ImGui::OpenPopup(title);
    }
    center_next_window(480 * ctx.ui.scale());
    if (!ImGui::BeginPopupModal(title, nullptr, 0)) return;
    if (r.offers.empty()) { // answered elsewhere (cannot happen today; keeps the popup honest)
        ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
        return;
    }
    const scene::RecoveryInfo offer = r.offers.front();
    const std::string name = offer.origin.empty()
                                 ? std::string("an untitled scene")
                                 : std::filesystem::path(offer.origin).filename().string();
    text_wrapped("isoparm did not close normally last time. Unsaved changes to %s were "
                 "autosaved at %s.",
                 name.c_str(), local_time(offer.written).c_str());
    if (!offer.origin.empty()) ImGui::TextDisabled("%s", offer.origin.c_str());
    if (offer.older_than_scene)
        ImGui::TextColored(ImVec4(1, 0.6f, 0.3f, 1),
                           "The scene file was saved after this autosave: the file on disk is "
                           "probably newer.");
    if (r.offers.size() > 1)
        ImGui::TextDisabled("%zu more autosaved scenes follow.", r.offers.size() - 1);
    ImGui::Spacing();
    text_wrapped("Restore opens them as unsaved changes (Undo returns to %s).",
                 offer.origin.empty() ? "a new scene" : "the saved scene");
    ImGui::Spacing();
    const bool restore = ImGui::Button("Restore");
    report_item("recovery/restore");
    if (restore) {
        ImGui::CloseCurrentPopup();
        r.offers.erase(r.offers.begin());
        hold_all(r); // one document at a time: the others are offered at the next start
        restore_recovery(ctx, offer);
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) {
        ImGui::CloseCurrentPopup();
        r.offers.erase(r.offers.begin());
        if (const geom::Status st = scene::discard_recovery(offer.origin); !st.ok())
            ctx.ui.status = st.error().message;
    }
    ImGui::SameLine();
    if (ImGui::Button("Decide later") ||
        ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
        ImGui::CloseCurrentPopup();
        hold_all(r);
    }
    ImGui::EndPopup();
}

} // namespace isoparm::ui
