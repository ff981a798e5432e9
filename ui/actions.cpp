// User actions: file handling with unsaved-change guards, undo/redo, view helpers.
#include "ui/actions.hpp"

#include <filesystem>

#include "core/scene/atomic_file.hpp"
#include "core/scene/scene_io.hpp"
#include "core/scene/script.hpp"
#include "ui/animation_actions.hpp"
#include "ui/course_actions.hpp"
#include "ui/lesson.hpp"
#include "ui/platform/files.hpp"
#include "ui/view/course_files.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/scene_budget.hpp"
#include "ui/view/scene_builder.hpp"

namespace isoparm::ui {

namespace {

// The file dialog opened in `mode` at the next frame, its last error cleared.
FileDialog& open_file_dialog(AppContext& ctx, FileDialog::Mode mode) {
    FileDialog& fd = ctx.ui.file_dialog;
    fd.mode = mode;
    fd.just_opened = true;
    fd.error.clear();
    return fd;
}

void guard(AppContext& ctx, PendingAction action) {
    ctx.ui.pending = std::move(action);
    if (ctx.dirty())
        ctx.ui.confirm_unsaved = true;
    else
        run_pending(ctx);
}

std::string error_text(const geom::Error& e) {
    std::string s = e.message;
    if (e.has_path && !e.path.empty()) s += "\n(at " + e.path + ")";
    return s;
}

void adopt(AppContext& ctx, doc::Document d, const std::string& path) {
    // A recording belongs to the scene it started on: it ends here, and is offered for saving.
    if (ctx.recorder) {
        ctx.observe_for_recording();
        ctx.ui.finished_recording = std::move(ctx.recorder);
        ctx.ui.offer_recording_save = true;
    }
    ctx.doc = std::move(d);
    ctx.ui.lesson.reset(); // a lesson belongs to its scene (open_lesson sets it again)
    normalize_selection(ctx.doc);
    ctx.history.clear();
    ctx.history.mark_clean();
    ctx.file_path = path;
    ctx.file_stamp = json_io::stamp_of(path);
    ctx.ui.drag = {};
    ctx.ui.sliders = {};
    ctx.ui.plane_drag = {};
    ctx.ui.camera_needs_fit = true;
}

} // namespace

void adopt_document(AppContext& ctx, doc::Document d, const std::string& path) {
    adopt(ctx, std::move(d), path);
}

void request_new_document(AppContext& ctx) {
    guard(ctx, {PendingAction::Kind::new_document, {}});
}
void request_open_dialog(AppContext& ctx) {
    guard(ctx, {PendingAction::Kind::open_dialog, {}});
}
void request_open_file(AppContext& ctx, const std::string& path) {
    guard(ctx, {PendingAction::Kind::open_file, path});
}
void request_quit(AppContext& ctx) {
    guard(ctx, {PendingAction::Kind::quit, {}});
}

void run_pending(AppContext& ctx) {
    const PendingAction a = std::move(ctx.ui.pending);
    ctx.ui.pending = {};
    switch (a.kind) {
    case PendingAction::Kind::none:
        break;
    case PendingAction::Kind::new_document:
        new_document(ctx);
        break;
    case PendingAction::Kind::open_file:
        open_file(ctx, a.path);
        break;
    case PendingAction::Kind::open_dialog: {
        FileDialog& fd = open_file_dialog(ctx, FileDialog::Mode::open);
        if (fd.directory.empty()) {
            std::error_code ec;
            fd.directory = ctx.file_path.empty()
                               ? std::filesystem::current_path(ec).string()
                               : std::filesystem::path(ctx.file_path).parent_path().string();
        }
        break;
    }
    case PendingAction::Kind::open_lesson:
        open_lesson(ctx, a.path);
        break;
    case PendingAction::Kind::open_exercise:
        open_exercise(ctx, a.path);
        break;
    case PendingAction::Kind::play_draft:
        play_draft_from(ctx, a.stop);
        break;
    case PendingAction::Kind::quit:
        ctx.ui.quit_now = true;
        break;
    }
}

bool open_file(AppContext& ctx, const std::string& path) {
    geom::Expected<doc::Document> loaded = scene::load_scene(path);
    if (!loaded.ok()) {
        show_error(ctx, "Could not open scene",
                   "'" + path + "' was not opened; the current scene is unchanged.\n\n" +
                       error_text(loaded.error()));
        return false;
    }
    // A scene that would freeze the window is refused with the same sentence as render's.
    std::string too_large = scene_over_budget(*loaded);
    if (too_large.empty()) too_large = memory_limit_problem(*loaded, 0); // driver already loaded
    if (!too_large.empty()) {
        show_error(ctx, "Could not open scene",
                   "'" + path + "' was not opened; the current scene is unchanged.\n\n" +
                       too_large);
        return false;
    }
    adopt(ctx, std::move(loaded).value(), path);
    add_recent(ctx.settings.recent, std::filesystem::absolute(path).lexically_normal().string());
    store_settings(ctx);
    return true;
}

// File > New: an empty scene, and the new-surface dialog offered straight away (Cancel
// leaves the scene empty; Curve > New curve is the other way to begin).
void new_document(AppContext& ctx) {
    adopt(ctx, doc::Document{}, "");
    if (!ctx.ui.headless) ctx.ui.new_surface.open = true;
}

bool save(AppContext& ctx) {
    if (ctx.file_path.empty()) {
        request_save_as(ctx);
        return false;
    }
    // Someone else wrote the file since we loaded or saved it: ask before replacing their work.
    if (json_io::changed_on_disk(ctx.file_path, ctx.file_stamp)) {
        ctx.ui.confirm_overwrite_changed = true;
        return false;
    }
    return save_as(ctx, ctx.file_path);
}

void request_save_as(AppContext& ctx) {
    FileDialog& fd = open_file_dialog(ctx, FileDialog::Mode::save);
    std::error_code ec;
    if (ctx.file_path.empty()) {
        if (fd.directory.empty()) fd.directory = std::filesystem::current_path(ec).string();
        fd.name = "scene.json";
    } else {
        const std::filesystem::path p(ctx.file_path);
        fd.directory = p.parent_path().empty() ? std::filesystem::current_path(ec).string()
                                               : p.parent_path().string();
        fd.name = p.filename().string();
    }
}

bool save_as(AppContext& ctx, const std::string& path) {
    suspend_animation(ctx); // the scene as it is, not an animation's frame
    const geom::Status st = scene::save_scene(ctx.doc, path);
    if (!st.ok()) {
        show_error(ctx, "Could not save scene",
                   "'" + path + "' was not written.\n\n" + error_text(st.error()));
        return false;
    }
    ctx.file_path = path;
    ctx.file_stamp = json_io::stamp_of(path);
    ctx.history.mark_clean();
    add_recent(ctx.settings.recent, std::filesystem::absolute(path).lexically_normal().string());
    store_settings(ctx);
    ctx.ui.status = "Saved " + path;
    files::hand_over(path); // the browser downloads it
    return true;
}

void undo(AppContext& ctx) {
    ctx.seal();
    ctx.observe_for_recording();
    if (!ctx.history.undo(ctx.doc)) return;
    if (ctx.recorder) ctx.recorder->undone(ctx.doc);
    normalize_selection(ctx.doc);
}

void redo(AppContext& ctx) {
    ctx.seal();
    ctx.observe_for_recording();
    if (!ctx.history.redo(ctx.doc)) return;
    if (ctx.recorder) ctx.recorder->redone(ctx.doc);
    normalize_selection(ctx.doc);
}

void request_open_lesson_dialog(AppContext& ctx) {
    FileDialog& fd = open_file_dialog(ctx, FileDialog::Mode::open_lesson);
    // In the lessons: the user's own when there are any, else the shipped ones.
    fd.directory = lesson_dialog_dir();
    fd.name.clear();
    std::error_code ec;
    if (fd.directory.empty()) fd.directory = std::filesystem::current_path(ec).string();
}

void request_load_points_dialog(AppContext& ctx) {
    FileDialog& fd = open_file_dialog(ctx, FileDialog::Mode::load_points);
    std::error_code ec;
    if (fd.directory.empty()) fd.directory = std::filesystem::current_path(ec).string();
}

void request_open_lesson(AppContext& ctx, const std::string& path) {
    guard(ctx, {PendingAction::Kind::open_lesson, path});
}

bool open_lesson(AppContext& ctx, const std::string& path) {
    geom::Expected<scene::Script> script = scene::load_script(path);
    if (!script) {
        show_error(ctx, "Could not open lesson",
                   "'" + path + "' was not opened; the current scene is unchanged.\n\n" +
                       error_text(script.error()));
        return false;
    }
    auto lesson = std::make_unique<Lesson>();
    lesson->path = path;
    lesson->script = std::move(script).value();
    prepare_lesson(*lesson);
    // A lesson opened to be played, not edited: the editor (if open) gives it the view. Edit...
    // in the caption box brings it back on this lesson.
    ctx.ui.course.editor.open = false;
    // The lesson's scene is a copy, untitled: saving never writes over the lesson's files.
    adopt(ctx, lesson->script.start, "");
    ctx.ui.lesson = std::move(lesson);
    lesson_next(ctx); // up to the first pause: the introduction
    return true;
}

void restart_lesson(AppContext& ctx) {
    if (!ctx.ui.lesson) return;
    std::unique_ptr<Lesson> lesson = std::move(ctx.ui.lesson);
    lesson->next = 0;
    lesson->stop = 0;
    lesson->caption.clear();
    adopt(ctx, lesson->script.start, "");
    ctx.ui.lesson = std::move(lesson);
    lesson_next(ctx);
}

void start_recording(AppContext& ctx) {
    ctx.seal(); // the first recorded edit does not merge with one made before
    ctx.recorder = std::make_unique<scene::Recorder>(ctx.doc);
    ctx.ui.status = "Recording: every edit from now on is kept as a script step";
}

void request_stop_recording(AppContext& ctx) {
    if (!ctx.recorder && !ctx.ui.finished_recording) return;
    if (ctx.recorder) {
        ctx.observe_for_recording();
        ctx.ui.finished_recording = std::move(ctx.recorder);
    }
    FileDialog& fd = open_file_dialog(ctx, FileDialog::Mode::save_recording);
    std::error_code ec;
    // Beside the scene it replays on, by default.
    const std::filesystem::path scene_dir = std::filesystem::path(ctx.file_path).parent_path();
    if (!scene_dir.empty())
        fd.directory = scene_dir.string();
    else if (fd.directory.empty())
        fd.directory = std::filesystem::current_path(ec).string();
    fd.name = "recording.json";
}

bool save_recording(AppContext& ctx, const std::string& path) {
    if (!ctx.ui.finished_recording) return false;
    if (const geom::Status distinct = scene::check_output_is_not_input(path, {ctx.file_path});
        !ctx.file_path.empty() && !distinct) {
        ctx.ui.file_dialog.error = "That is the open scene: choose another name for the script.";
        return false;
    }
    const std::size_t steps = ctx.ui.finished_recording->step_count();
    const geom::Status st = scene::write_file_atomically(
        path, scene::pretty_json_text(ctx.ui.finished_recording->script()));
    if (!st.ok()) {
        show_error(ctx, "Could not save the recording",
                   "'" + path + "' was not written.\n\n" + error_text(st.error()));
        return false;
    }
    ctx.ui.finished_recording.reset();
    ctx.ui.status = "Recording saved: " + path + " (" + std::to_string(steps) +
                    " steps; isoparm script replays it)";
    files::hand_over(path);
    return true;
}

void discard_recording(AppContext& ctx) {
    ctx.ui.finished_recording.reset();
    ctx.ui.status = "Recording discarded";
}

void fit_view(AppContext& ctx) {
    const std::vector<glm::dvec3> pts = scene_points(ctx.doc);
    if (pts.empty()) return;
    const double aspect =
        ctx.ui.view_rect.h > 0 ? static_cast<double>(ctx.ui.view_rect.w) / ctx.ui.view_rect.h : 1.6;
    fit_to_points(ctx.ui.camera, pts, aspect);
    ctx.ui.fit_distance = ctx.ui.camera.distance;
}

void toggle_presentation(AppContext& ctx) {
    ctx.ui.presentation = !ctx.ui.presentation;
    ctx.ui.camera_needs_fit = true; // the view changes size with the larger panels
}

void toggle_view_only(AppContext& ctx) {
    ctx.ui.view_mode =
        ctx.ui.view_mode == ViewMode::view3d_only ? ViewMode::workstation : ViewMode::view3d_only;
    ctx.ui.camera_needs_fit = true;
}

void show_error(AppContext& ctx, const std::string& title, const std::string& message) {
    ctx.ui.show_error = true;
    ctx.ui.error_title = title;
    ctx.ui.error_message = message;
}

void store_settings(AppContext& ctx) {
    if (ctx.remember_settings && save_settings(ctx.settings, settings_path()))
        files::keep_settings(); // the browser's local storage
}

} // namespace isoparm::ui
