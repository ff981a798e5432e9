// Lessons and exercises in the window (course_actions.hpp).
#include "ui/course_actions.hpp"

#include <filesystem>
#include <memory>

#include "core/json/input_file.hpp"
#include "core/json/reader.hpp"
#include "core/scene/atomic_file.hpp"
#include "core/scene/scene_io.hpp"
#include "core/scene/script.hpp"
#include "ui/actions.hpp"
#include "ui/lesson.hpp"
#include "ui/platform/files.hpp"
#include "ui/view/course_files.hpp"

namespace isoparm::ui {

namespace fs = std::filesystem;

namespace {

FileDialog& open_dialog(AppContext& ctx, FileDialog::Mode mode, const std::string& dir) {
    FileDialog& fd = ctx.ui.file_dialog;
    fd.mode = mode;
    fd.just_opened = true;
    fd.error.clear();
    std::error_code ec;
    fd.directory = dir.empty() ? fs::current_path(ec).string() : dir;
    return fd;
}

std::string error_text(const geom::Error& e) {
    return e.message + (e.has_path && !e.path.empty() ? " (at " + e.path + ")" : "");
}

std::string folder_of(const std::string& path) {
    const std::string dir = fs::path(path).parent_path().string();
    return dir.empty() ? "." : dir;
}

// The editor's lesson as a script, ready to play (its scene read).
geom::Expected<scene::Script> draft_script(const LessonEditorState& e) {
    return scene::script_from_json(e.draft->to_json(), e.base_dir.empty() ? "." : e.base_dir);
}

void fill_editor(AppContext& ctx, scene::LessonDraft draft, const std::string& path,
                 const std::string& base_dir) {
    LessonEditorState& e = ctx.ui.course.editor;
    e = {};
    e.open = true;
    e.draft = std::move(draft);
    e.path = path;
    e.base_dir = base_dir;
    e.problem = draft_problem(e);
}

} // namespace

// ---------------------------------------------------------------------------------------
// Exercises.

void request_open_exercise_dialog(AppContext& ctx) {
    open_dialog(ctx, FileDialog::Mode::open_exercise, shipped_exercises_dir()).name.clear();
}

void request_open_exercise(AppContext& ctx, const std::string& path) {
    ctx.ui.pending = {PendingAction::Kind::open_exercise, path, 0};
    if (ctx.dirty())
        ctx.ui.confirm_unsaved = true;
    else
        run_pending(ctx);
}

bool open_exercise(AppContext& ctx, const std::string& path) {
    auto ex = scene::load_exercise(path);
    if (!ex) {
        show_error(ctx, "Could not open exercise",
                   "'" + path + "' was not opened; the current scene is unchanged.\n\n" +
                       error_text(ex.error()));
        return false;
    }
    // The starting scene as an untitled copy: saving never writes over the exercise's files.
    adopt_document(ctx, ex->start, "");
    ExerciseState& s = ctx.ui.course.exercise;
    s = {};
    s.path = path;
    s.exercise = std::move(ex).value();
    ctx.ui.course.exercise_open = true;
    ctx.ui.status = "Exercise: " + (s.exercise->title.empty() ? path : s.exercise->title);
    return true;
}

void check_exercise(AppContext& ctx) {
    ExerciseState& s = ctx.ui.course.exercise;
    if (!s.exercise) return;
    s.grade = scene::grade(*s.exercise, ctx.doc);
    s.history_at_check = ctx.history.size();
    s.top_at_check = ctx.history.top();
}

void close_exercise(AppContext& ctx) {
    ctx.ui.course.exercise = {};
    ctx.ui.course.exercise_open = false;
}

// ---------------------------------------------------------------------------------------
// Playing from any stop.

void lesson_goto(AppContext& ctx, std::size_t stop) {
    if (!ctx.ui.lesson) return;
    restart_lesson(ctx); // the first stop
    for (std::size_t k = 0;
         k < stop && ctx.ui.lesson && !ctx.ui.lesson->finished() && ctx.ui.lesson->refused.empty();
         ++k)
        lesson_next(ctx);
}

// ---------------------------------------------------------------------------------------
// Writing lessons while recording.

void request_add_stop(AppContext& ctx) {
    if (!ctx.recorder) return;
    ctx.ui.course.add_stop_request = true;
    ctx.ui.course.stop_caption.clear();
}

void add_stop_here(AppContext& ctx, const std::string& caption) {
    if (!ctx.recorder) return;
    ctx.observe_for_recording(); // the view as it is now comes before the stop
    nlohmann::json steps = nlohmann::json::array();
    scene::add_stop(steps, caption);
    ctx.recorder->add_steps(steps);
    ctx.ui.status = "Stop " + std::to_string(ctx.recorder->stop_count()) + " added";
}

void request_add_expectation(AppContext& ctx) {
    if (!ctx.recorder) return;
    CourseState& c = ctx.ui.course;
    c.add_expectation_request = true;
    c.facts = scene::document_facts(ctx.doc);
    c.chosen.assign(c.facts.size(), 0);
}

void add_expectations(AppContext& ctx, const std::vector<scene::Fact>& facts) {
    if (!ctx.recorder || facts.empty()) return;
    ctx.observe_for_recording();
    nlohmann::json steps = nlohmann::json::array();
    for (const scene::Fact& f : facts)
        steps.push_back({{"expect", scene::expect_to_json(f.expect)}});
    ctx.recorder->add_steps(steps);
    ctx.ui.status = std::to_string(facts.size()) +
                    (facts.size() == 1 ? " expectation added" : " expectations added");
}

// ---------------------------------------------------------------------------------------
// The lesson editor.

void save_recording_as_lesson(AppContext& ctx) {
    if (!ctx.recorder) return;
    ctx.observe_for_recording();
    auto draft = scene::lesson_draft_from_json(ctx.recorder->script());
    ctx.recorder.reset();
    if (!draft) return; // a recorder writes its own format: cannot happen
    fill_editor(ctx, std::move(draft).value(), "", "");
    request_save_lesson_dialog(ctx);
}

void open_lesson_editor(AppContext& ctx) {
    LessonEditorState& e = ctx.ui.course.editor;
    if (ctx.ui.lesson && ctx.ui.lesson->path != e.path) {
        const std::string& path = ctx.ui.lesson->path;
        auto text = json_io::read_input_file(path, 64u << 20);
        auto read =
            text ? json_io::read_json(*text) : geom::Expected<json_io::ReadJson>(text.error());
        auto draft = read ? scene::lesson_draft_from_json(read->value)
                          : geom::Expected<scene::LessonDraft>(read.error());
        if (draft) {
            fill_editor(ctx, std::move(draft).value(), path, folder_of(path));
            return;
        }
        show_error(ctx, "Could not edit the lesson",
                   "'" + path + "': " + error_text(draft.error()));
        return;
    }
    if (!e.draft) {
        scene::LessonDraft blank;
        blank.stops.push_back({});
        blank.stops.back().paused = false;
        fill_editor(ctx, std::move(blank), "", "");
        e.note = "An empty lesson: Lessons > Start recording, then Add stop here while you "
                 "work, makes one.";
    }
    e.open = true;
}

void request_save_lesson_dialog(AppContext& ctx) {
    LessonEditorState& e = ctx.ui.course.editor;
    const std::string mine = user_lessons_dir();
    std::string dir = mine;
    std::string name = "my-lesson.json";
    if (!e.path.empty()) {
        name = fs::path(e.path).filename().string();
        if (mine.empty() || fs::path(e.path).parent_path() == fs::path(mine))
            dir = folder_of(e.path);
    }
    if (!mine.empty()) {
        std::error_code ec;
        fs::create_directories(mine, ec); // the folder the Lessons menu lists as "My lessons"
    }
    open_dialog(ctx, FileDialog::Mode::save_lesson, dir).name = name;
}

bool save_lesson(AppContext& ctx, const std::string& path) {
    LessonEditorState& e = ctx.ui.course.editor;
    if (!e.draft) return false;
    scene::LessonDraft out = *e.draft;
    // A starting scene named relative to the old folder would not be found from another one:
    // written inline instead.
    const bool moved = folder_of(path) != (e.base_dir.empty() ? "." : e.base_dir);
    if (out.scene.is_string() && moved) {
        auto script = draft_script(e);
        if (!script) {
            ctx.ui.file_dialog.error = "Not saved: " + error_text(script.error());
            return false;
        }
        out.scene = scene::scene_to_json(script->start);
    }
    if (const geom::Status st =
            scene::write_file_atomically(path, scene::pretty_json_text(out.to_json()));
        !st) {
        ctx.ui.file_dialog.error = "Not saved: " + st.error().message;
        return false;
    }
    files::hand_over(path); // the browser downloads it
    e.draft = std::move(out);
    e.path = path;
    e.base_dir = folder_of(path);
    e.dirty = false;
    e.note = "Saved " + path + " (" + std::to_string(e.draft->size()) +
             " stops; Lessons lists it, isoparm script replays it)";
    ctx.ui.status = e.note;
    return true;
}

std::string draft_problem(const LessonEditorState& e) {
    if (!e.draft) return {};
    auto script = draft_script(e);
    if (!script) return error_text(script.error());
    scene::ScriptState trial(script->start);
    const scene::ScriptResult r = scene::run_script(*script, trial, {}, /*dry_run=*/true);
    if (r.stopped) return error_text(*r.stopped);
    return {};
}

void request_play_draft(AppContext& ctx, std::size_t stop) {
    ctx.ui.pending = {PendingAction::Kind::play_draft, {}, stop};
    if (ctx.dirty())
        ctx.ui.confirm_unsaved = true;
    else
        run_pending(ctx);
}

void play_draft_from(AppContext& ctx, std::size_t stop) {
    LessonEditorState& e = ctx.ui.course.editor;
    if (!e.draft) return;
    auto script = draft_script(e);
    if (!script) {
        e.problem = error_text(script.error());
        return;
    }
    auto lesson = std::make_unique<Lesson>();
    lesson->path = e.path.empty() ? "(unsaved lesson)" : e.path;
    lesson->script = std::move(script).value();
    prepare_lesson(*lesson);
    adopt_document(ctx, lesson->script.start, "");
    ctx.ui.lesson = std::move(lesson);
    lesson_goto(ctx, stop);
    e.note = "Playing from stop " + std::to_string(stop + 1);
}

} // namespace isoparm::ui
