// Modal dialogs: new surface, open / save as, unsaved changes, errors, mouse and keys help.
#include <algorithm>
#include <filesystem>
#include <imgui.h>
#include <imgui_stdlib.h>
#include <iterator>
#include <string>
#include <system_error>
#include <tuple>
#include <vector>

#include "core/doc/commands.hpp"
#include "core/doc/placement.hpp"
#include "ui/actions.hpp"
#include "ui/course_actions.hpp"
#include "ui/exchange_actions.hpp"
#include "ui/fit_actions.hpp"
#include "ui/panels/enum_combo.hpp"
#include "ui/panels/panels.hpp"
#include "ui/platform/files.hpp"
#include "ui/recovery.hpp"
#include "ui/theme.hpp"
#include "ui/toolbox_actions.hpp"
#include "ui/ui_report.hpp"
#include "ui/uploads.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

namespace fs = std::filesystem;

namespace {

bool escape_pressed() {
    return ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
}

void center_next(float w_units, float scale) {
    center_next_window(w_units > 0 ? w_units * scale : 0);
}

std::string new_surface_error(const NewSurfaceForm& f) {
    const bool bezier = f.type <= 1;
    for (auto [n, p, dir] :
         {std::tuple{f.rows, f.degree_u, "u"}, std::tuple{f.cols, f.degree_v, "v"}}) {
        if (p < 1) return std::string("The degree in ") + dir + " must be at least 1.";
        if (n < p + 1)
            return std::string("The degree in ") + dir + " is " + std::to_string(p) +
                   ": it needs at least " + std::to_string(p + 1) +
                   " control points in that direction.";
        if (n > 64) return std::string("At most 64 control points per direction here.");
        if (bezier && n != p + 1)
            return std::string("A Bezier surface of degree ") + std::to_string(p) + " in " + dir +
                   " has exactly " + std::to_string(p + 1) + " points in that direction.";
    }
    return {};
}

void new_surface_dialog(AppContext& ctx) {
    NewSurfaceForm& f = ctx.ui.new_surface;
    if (f.open) {
        ImGui::OpenPopup("New surface");
        f.open = false;
        f.error.clear();
    }
    center_next(360, ctx.ui.scale());
    if (!ImGui::BeginPopupModal("New surface", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    text_wrapped("A flat grid of control points in the xy-plane; shape it by moving points.");
    auto type = static_cast<geom::SplineType>(f.type);
    if (enum_combo("Type", type, ItemCase::capitalized)) f.type = static_cast<int>(type);
    report_item("new_surface/type");
    const bool bezier = f.type <= 1;
    ImGui::InputInt("Rows (u)", &f.rows);
    ImGui::InputInt("Columns (v)", &f.cols);
    f.rows = std::clamp(f.rows, 2, 64);
    f.cols = std::clamp(f.cols, 2, 64);
    // A Bezier patch's degree follows from its point count; the B-spline degrees are kept for
    // when the type changes back (the dialog used to keep rows - 1 then).
    f.degree_u = bezier ? f.rows - 1 : f.spline_degree_u;
    f.degree_v = bezier ? f.cols - 1 : f.spline_degree_v;
    ImGui::BeginDisabled(bezier);
    ImGui::InputInt("Degree in u", &f.degree_u);
    ImGui::InputInt("Degree in v", &f.degree_v);
    ImGui::EndDisabled();
    f.degree_u = std::clamp(f.degree_u, 1, 63);
    f.degree_v = std::clamp(f.degree_v, 1, 63);
    if (!bezier) {
        f.spline_degree_u = f.degree_u;
        f.spline_degree_v = f.degree_v;
    }
    report_fact("new_surface/degree_u", f.degree_u);
    report_fact("new_surface/degree_v", f.degree_v);
    const std::string err = new_surface_error(f);
    if (!err.empty()) ImGui::TextColored(error_text_color(), "%s", err.c_str());
    ImGui::BeginDisabled(!err.empty());
    const bool create = ImGui::Button("Create");
    report_item("new_surface/create");
    if (create) {
        doc::Object o;
        o.name = fresh_name(ctx.doc, "Surface"); // unique, whatever was deleted or renamed
        o.shape = doc::SurfaceObject{doc::make_planar_grid(f.rows, f.cols, f.degree_u, f.degree_v,
                                                           static_cast<geom::SplineType>(f.type))};
        doc::place_beside_scene(ctx.doc, o.shape);
        ctx.seal();
        if (ctx.execute(doc::add_object(std::move(o)))) {
            ctx.doc.view.selection = {ctx.doc.objects.back().id, -1, -1};
            fit_view(ctx);
        }
        ctx.seal();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || escape_pressed()) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

struct Entry {
    std::string name;
    bool directory;
};

// Scenes, or (exchange = true) the exchange formats' files.
std::vector<Entry> list_directory(const std::string& dir, bool exchange = false) {
    std::vector<Entry> out;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        std::error_code e2;
        const bool is_dir = it->is_directory(e2);
        if (is_dir || (exchange ? is_exchange_file(name) : it->path().extension() == ".json"))
            out.push_back({name, is_dir});
    }
    std::sort(out.begin(), out.end(), [](const Entry& a, const Entry& b) {
        return a.directory != b.directory ? a.directory : a.name < b.name;
    });
    return out;
}

// What the dialog is for, read once from its mode.
struct FileDialogKind {
    bool recording, lesson, points, lesson_out, exercise, saving, exporting, importing;

    explicit FileDialogKind(FileDialog::Mode m)
        : recording(m == FileDialog::Mode::save_recording),
          lesson(m == FileDialog::Mode::open_lesson), points(m == FileDialog::Mode::load_points),
          lesson_out(m == FileDialog::Mode::save_lesson),
          exercise(m == FileDialog::Mode::open_exercise),
          saving(m == FileDialog::Mode::save || recording || lesson_out),
          exporting(m == FileDialog::Mode::export_file),
          importing(m == FileDialog::Mode::import_file) {}
};

// Each mode's title and confirming button, in the order of FileDialog::Mode.
struct FileDialogText {
    FileDialog::Mode mode;
    const char* title;
    const char* button;
};
constexpr FileDialogText file_dialog_texts[] = {
    {FileDialog::Mode::closed, "Open scene", "Open"},
    {FileDialog::Mode::open, "Open scene", "Open"},
    {FileDialog::Mode::save, "Save scene as", "Save"},
    {FileDialog::Mode::save_recording, "Save recording as script", "Save"},
    {FileDialog::Mode::open_lesson, "Open lesson (a script)", "Open"},
    {FileDialog::Mode::load_points, "Load data points (CSV or XYZ)", "Open"},
    {FileDialog::Mode::export_file, "Export visible objects (.step .igs .obj .stl .ply .glb)",
     "Export"},
    {FileDialog::Mode::import_file, "Import curves and surfaces (.step .igs .obj)", "Import"},
    {FileDialog::Mode::save_lesson, "Save lesson as", "Save"},
    {FileDialog::Mode::open_exercise, "Open exercise", "Open"},
};
static_assert(std::size(file_dialog_texts) ==
              static_cast<std::size_t>(FileDialog::Mode::open_exercise) + 1);
static_assert([] {
    for (std::size_t k = 0; k < std::size(file_dialog_texts); ++k)
        if (static_cast<std::size_t>(file_dialog_texts[k].mode) != k) return false;
    return true;
}());

const FileDialogText& file_dialog_text(FileDialog::Mode m) {
    return file_dialog_texts[static_cast<std::size_t>(m)];
}

// The folder line and the list of its files; returns the name double-clicked, if any.
std::string draw_file_list(FileDialog& fd, bool exchange) {
    if (ImGui::Button("Up")) {
        const fs::path parent = fs::path(fd.directory).parent_path();
        if (!parent.empty()) fd.directory = parent.string();
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    ImGui::InputText("##dir", &fd.directory);
    std::string chosen;
    const float list_h = ImGui::GetTextLineHeightWithSpacing() * 14;
    if (ImGui::BeginChild("##files", ImVec2(0, list_h), true)) {
        for (const Entry& e : list_directory(fd.directory, exchange)) {
            const std::string label = e.directory ? e.name + "/" : e.name;
            if (ImGui::Selectable(label.c_str(), !e.directory && e.name == fd.name,
                                  ImGuiSelectableFlags_AllowDoubleClick)) {
                if (e.directory) {
                    fd.directory = (fs::path(fd.directory) / e.name).string();
                } else {
                    fd.name = e.name;
                    if (ImGui::IsMouseDoubleClicked(0)) chosen = e.name;
                }
            }
        }
    }
    ImGui::EndChild();
    return chosen;
}

// The name field and what is said under it; returns the name if Enter confirmed it.
std::string draw_name_field(AppContext& ctx, const FileDialogKind& k) {
    FileDialog& fd = ctx.ui.file_dialog;
    ImGui::SetNextItemWidth(-1);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere(); // type a name right away
    // A click on the name selects all of it, so typing replaces it (a file name is most often
    // typed anew).
    const bool enter =
        ImGui::InputText("##name", &fd.name,
                         ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
    report_item("file/name");
    fs::path target = fs::path(fd.directory) / fd.name;
    if (k.saving && !fd.name.empty() && target.extension().empty()) target += ".json";
    std::error_code ec;
    if ((k.saving || k.exporting) && !fd.name.empty() && fs::exists(target, ec))
        ImGui::TextDisabled("%s exists and will be replaced.", target.filename().string().c_str());
    if (!fd.error.empty()) { // wrapped: a refused export names the extensions it knows
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(error_text_color(), "%s", fd.error.c_str());
        report_item("file/error");
        ImGui::PopTextWrapPos();
    }
    if (k.recording && ctx.ui.finished_recording)
        ImGui::TextDisabled("A script of %zu steps. Cancel goes on recording; Discard drops it.",
                            ctx.ui.finished_recording->step_count());
    return enter && !fd.name.empty() ? fd.name : std::string();
}

// The dialog's buttons; returns true when one of them closes it (the name confirmed goes to
// `chosen`).
bool draw_file_buttons(AppContext& ctx, const FileDialogKind& k, std::string& chosen) {
    FileDialog& fd = ctx.ui.file_dialog;
    ImGui::BeginDisabled(fd.name.empty());
    if (ImGui::Button(file_dialog_text(fd.mode).button)) chosen = fd.name;
    ImGui::EndDisabled();
    ImGui::SameLine();
    bool close = false;
    if (ImGui::Button("Cancel") || escape_pressed()) {
        close = true;
        ctx.ui.pending = {};
        // Nothing is lost: the recording goes on where it stopped.
        if (k.recording && ctx.ui.finished_recording && !ctx.recorder)
            ctx.recorder = std::move(ctx.ui.finished_recording);
    }
    if (k.recording) {
        ImGui::SameLine();
        if (ImGui::Button("Discard")) {
            close = true;
            discard_recording(ctx);
        }
    }
    // In a browser the list shows the page's own files (the examples, the lessons, uploads);
    // the user's are reached through the browser's picker, and what is written downloads.
    if (files::in_browser()) {
        if (!k.saving && !k.exporting) {
            ImGui::SameLine();
            const bool upload = ImGui::Button("From this computer...");
            report_item("file/upload");
            if (upload && request_upload_for(fd.mode)) close = true;
        } else {
            ImGui::TextDisabled("The browser downloads the file.");
        }
    }
    return close;
}

// Does with the file chosen what the dialog was opened for; `close` becomes true when that
// closes the dialog (a refusal keeps it open with the reason).
void take_chosen_file(AppContext& ctx, const FileDialogKind& k, const std::string& chosen,
                      bool& close) {
    FileDialog& fd = ctx.ui.file_dialog;
    fs::path target = fs::path(fd.directory) / chosen;
    if (k.saving && target.extension().empty()) target += ".json";
    if (k.lesson_out) {
        close = save_lesson(ctx, target.string());
    } else if (k.exercise) {
        close = true;
        request_open_exercise(ctx, target.string());
    } else if (k.exporting || k.importing) {
        // A refusal keeps the dialog open with the reason; nothing was written or added.
        close = k.exporting ? export_visible_objects(ctx, target.string(), fd.error)
                            : import_objects(ctx, target.string(), fd.error);
    } else if (k.recording) {
        if (save_recording(ctx, target.string())) close = true;
    } else if (k.saving) {
        if (save_as(ctx, target.string())) {
            close = true;
            run_pending(ctx); // e.g. quit after "Save" in the unsaved-changes dialog
        }
    } else if (k.lesson) {
        close = true;
        request_open_lesson(ctx, target.string());
    } else if (k.points) {
        // A file that is not points keeps the dialog open with the line at fault.
        close = load_fit_points(ctx, target.string(), fd.error);
    } else {
        close = true;
        open_file(ctx, target.string());
    }
}

void file_dialog(AppContext& ctx) {
    FileDialog& fd = ctx.ui.file_dialog;
    // A stopped recording is saved as a script; another scene opened while recording asks too.
    if (ctx.ui.offer_recording_save && fd.mode == FileDialog::Mode::closed) {
        ctx.ui.offer_recording_save = false;
        request_stop_recording(ctx);
    }
    const FileDialogKind k(fd.mode);
    const char* title = file_dialog_text(fd.mode).title;
    if (fd.just_opened) {
        ImGui::OpenPopup(title);
        fd.just_opened = false;
    }
    center_next(560, ctx.ui.scale());
    if (!ImGui::BeginPopupModal(title, nullptr, 0)) return;
    std::string chosen = draw_file_list(fd, k.exporting || k.importing);
    if (std::string typed = draw_name_field(ctx, k); !typed.empty()) chosen = std::move(typed);
    bool close = draw_file_buttons(ctx, k, chosen);
    // A folder typed or picked (a path in the name field too) is opened in the dialog, never
    // taken as the file: nothing is asked or refused for it.
    std::error_code ec;
    if (!chosen.empty() && fs::is_directory(fs::path(fd.directory) / chosen, ec)) {
        fd.directory = (fs::path(fd.directory) / chosen).lexically_normal().string();
        if (fd.directory.size() > 1 && fd.directory.back() == '/') fd.directory.pop_back();
        fd.name.clear();
        fd.error.clear();
        chosen.clear();
    }
    if (!chosen.empty()) take_chosen_file(ctx, k, chosen, close);
    if (close) {
        fd.mode = FileDialog::Mode::closed;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

// Opens the centred modal `title` when `requested` (once), and begins it.
bool begin_modal(const char* title, bool& requested, float w_units, float scale,
                 ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize) {
    return begin_centered_modal(title, requested, w_units > 0 ? w_units * scale : 0, flags);
}

// Cancel (or Escape) closes a question and forgets what was to follow its answer.
void cancel_pending_button(AppContext& ctx) {
    if (ImGui::Button("Cancel") || escape_pressed()) {
        ImGui::CloseCurrentPopup();
        ctx.ui.pending = {};
    }
}

void unsaved_dialog(AppContext& ctx) {
    if (!begin_modal("Unsaved changes", ctx.ui.confirm_unsaved, 0, ctx.ui.scale())) return;
    const std::string name =
        ctx.file_path.empty() ? "this untitled scene" : fs::path(ctx.file_path).filename().string();
    ImGui::Text("Save the changes to %s first?", name.c_str());
    ImGui::Spacing();
    if (ImGui::Button("Save")) {
        ImGui::CloseCurrentPopup();
        if (save(ctx)) run_pending(ctx); // untitled: the save dialog runs it after saving
    }
    ImGui::SameLine();
    const bool discard = ImGui::Button("Discard changes");
    report_item("unsaved/discard");
    if (discard) {
        ImGui::CloseCurrentPopup();
        run_pending(ctx);
    }
    ImGui::SameLine();
    cancel_pending_button(ctx);
    ImGui::EndPopup();
}

// Save found the file changed on disk since it was loaded or last saved (another window or
// program wrote it): replacing it would silently lose that work, so ask.
void overwrite_changed_dialog(AppContext& ctx) {
    if (!begin_modal("File changed on disk", ctx.ui.confirm_overwrite_changed, 480, ctx.ui.scale()))
        return;
    text_wrapped("'%s' was changed on disk since it was opened or last saved (by another "
                 "window or program). Saving now replaces those changes with this scene.",
                 ctx.file_path.c_str());
    ImGui::Spacing();
    if (ImGui::Button("Save anyway")) {
        ImGui::CloseCurrentPopup();
        if (save_as(ctx, ctx.file_path) && ctx.ui.pending.kind != PendingAction::Kind::none)
            run_pending(ctx); // the unsaved-changes question asked for this save
    }
    ImGui::SameLine();
    if (ImGui::Button("Save as...")) {
        ImGui::CloseCurrentPopup();
        request_save_as(ctx);
    }
    ImGui::SameLine();
    cancel_pending_button(ctx);
    ImGui::EndPopup();
}

void error_dialog(AppContext& ctx) {
    if (!begin_modal("##error", ctx.ui.show_error, 480, ctx.ui.scale(),
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoTitleBar))
        return;
    ImGui::TextUnformatted(ctx.ui.error_title.c_str());
    ImGui::Separator();
    text_wrapped("%s", ctx.ui.error_message.c_str());
    ImGui::Spacing();
    // Keys count only once the dialog is up: the Enter that confirmed a file name must not
    // also dismiss the error it caused.
    const bool key =
        !ImGui::IsWindowAppearing() &&
        (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) || escape_pressed());
    if (ImGui::Button("OK") || key) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

void help_dialog(AppContext& ctx) {
    if (ctx.ui.show_about) {
        ImGui::OpenPopup("Mouse and keys");
        ctx.ui.show_about = false;
    }
    // As wide as it reads well, never wider than the window; long entries wrap in their
    // column and the list scrolls on a short screen, so no line is ever cut.
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    const float width = std::min(640 * ctx.ui.scale(), vp->Size.x * 0.92f);
    const float height = std::min(560 * ctx.ui.scale(), vp->Size.y * 0.85f);
    ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + vp->Size.x * 0.5f, vp->Pos.y + vp->Size.y * 0.5f),
                            ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Always);
    if (!ImGui::BeginPopupModal("Mouse and keys", nullptr, ImGuiWindowFlags_NoResize)) return;
    struct Entry {
        const char* keys;
        const char* action;
    };
    static const Entry entries[] = {
        {"Left-drag", "orbit the 3D view"},
        {"Right-drag, Shift+left", "pan"},
        {"Wheel", "zoom"},
        {"Click a point", "select it; drag it to move it in the view plane"},
        {"X / Y / Z held", "move along that axis while dragging; Shift locks the axis the drag "
                           "started along"},
        {"Tracing square", "press or drag to move the indicator (u, v)"},
        {"Knot tick", "drag a tick below / left of the square to move that knot"},
        {"Control-point panel", "drag the red disk in the xy, xz or yz plane"},
        {"F", "fit to view"},
        {"P", "presentation mode (large text, thick lines, high contrast)"},
        {"Shift+P", "the 3D view alone (Shift+P or Esc returns)"},
        {"F11", "full screen"},
        {"1 / 2 / 3", "shaded / wireframe / both"},
        {"C / N / I / K", "control points / control net / point IDs / knot curves"},
        {"U / V", "insert the indicator's u / v as a knot (shape unchanged)"},
        {"Shift+U / Shift+V", "elevate the degree in u / v (shape unchanged)"},
        {"S / Shift+S", "split the current patch at the indicator's u / v; subpatches share "
                        "the square, Surface > Continuity keeps their borders C0 or C1"},
        {"D", "de Boor's construction; [ / ] step back / forward, Space plays"},
        {"Curve designer", "click adds a point, Ctrl+click a leg inserts, drag moves, Del "
                           "removes"},
        {"Construct menu", "ruled, revolve, swing, sweep, skin from designed curves"},
        {"Objects tab", "select, rename (double-click), hide / show, delete"},
        {"Ctrl+Z / Ctrl+Y", "undo / redo"},
        {"Ctrl+N / O / S", "new scene / open / save (Ctrl+Shift+S: save as)"},
    };
    const float footer = ImGui::GetFrameHeightWithSpacing() + ImGui::GetStyle().ItemSpacing.y;
    if (ImGui::BeginTable("##keys", 2,
                          ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY |
                              ImGuiTableFlags_SizingStretchProp,
                          ImVec2(0, -footer))) {
        ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthStretch, 1);
        ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch, 2);
        for (const Entry& e : entries) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            text_wrapped("%s", e.keys);
            ImGui::TableNextColumn();
            text_wrapped("%s", e.action);
        }
        ImGui::EndTable();
    }
    if (ImGui::Button("Close") || escape_pressed()) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

} // namespace

void draw_dialogs(AppContext& ctx) {
    receive_uploads(ctx); // the browser's: before the dialogs they may open
    new_surface_dialog(ctx);
    file_dialog(ctx);
    unsaved_dialog(ctx);
    overwrite_changed_dialog(ctx);
    error_dialog(ctx);
    help_dialog(ctx);
    draw_convert_dialog(ctx);
    draw_recovery_dialog(ctx); // last: it waits until no other dialog is up
}

} // namespace isoparm::ui
