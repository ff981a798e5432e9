// Lessons and exercises through the window's actions (no window): stops played and replayed,
// a recording played one step at a time, a lesson written while recording, edited, saved and
// played from a stop, and an exercise failed, fixed and passed.
#include <gtest/gtest.h>

#include "core/doc/commands.hpp"
#include "core/scene/script.hpp"
#include "tests/support/temp_dir.hpp"
#include "ui/actions.hpp"
#include "ui/app_context.hpp"
#include "ui/course_actions.hpp"
#include "ui/lesson.hpp"

using namespace isoparm;
using namespace isoparm::ui;

namespace {

const std::string lessons = ISOPARM_SOURCE_DIR "/assets/lessons/";
const std::string exercises = ISOPARM_SOURCE_DIR "/assets/exercises/";

double weight22(const AppContext& ctx) {
    return ctx.doc.objects.front().surface()->weight(2, 2);
}

TEST(CourseActions, ALessonGoesFromStopToStopAndBack) {
    AppContext ctx;
    ASSERT_TRUE(open_lesson(ctx, lessons + "02-weights-and-convex-hull.json"));
    ASSERT_TRUE(ctx.ui.lesson);
    EXPECT_EQ(ctx.ui.lesson->stop, 1u);
    EXPECT_EQ(ctx.ui.lesson->stops(), 6u); // 5 pauses and the end
    EXPECT_EQ(weight22(ctx), 1);
    lesson_next(ctx);
    lesson_next(ctx);
    EXPECT_EQ(ctx.ui.lesson->stop, 3u);
    EXPECT_EQ(weight22(ctx), 0.3);
    EXPECT_TRUE(ctx.ui.lesson->unmet.empty());
    EXPECT_NE(ctx.ui.lesson->caption.find("w2,2 = 0.3"), std::string::npos);
    lesson_goto(ctx, 1); // Back: replayed from the start to the second stop
    EXPECT_EQ(ctx.ui.lesson->stop, 2u);
    EXPECT_EQ(weight22(ctx), 5);
    while (!ctx.ui.lesson->finished()) lesson_next(ctx);
    EXPECT_EQ(weight22(ctx), -3);
    EXPECT_TRUE(ctx.ui.lesson->unmet.empty()) << ctx.ui.lesson->unmet.front();
}

TEST(CourseActions, ARecordingWithoutStopsIsPlayedOneStepAtATime) {
    test::TempDir tmp("isoparm-course");
    AppContext ctx;
    ctx.doc = doc::default_document();
    start_recording(ctx);
    ASSERT_TRUE(ctx.execute(doc::insert_knot(1, geom::Dir::u, 0.25, 1)));
    ctx.seal();
    const double w22_after_knot = weight22(ctx); // 1.25: P2,2 blended with P1,2 (w 2 and 1)
    ASSERT_TRUE(ctx.execute(doc::edit_point({1, 2, 2, std::nullopt, 4.0})));
    request_stop_recording(ctx);
    ASSERT_TRUE(save_recording(ctx, tmp.path("recording.json")));
    ASSERT_TRUE(open_lesson(ctx, tmp.path("recording.json")));
    const Lesson& l = *ctx.ui.lesson;
    EXPECT_EQ(l.stops(), 3u); // the starting scene, then each of the two commands
    EXPECT_NE(l.caption.find("starting scene"), std::string::npos) << l.caption;
    EXPECT_NE(l.caption.find("(2 steps)"), std::string::npos) << l.caption;
    EXPECT_EQ(ctx.doc.objects.front().surface()->n_u, 5);
    lesson_next(ctx);
    EXPECT_EQ(ctx.doc.objects.front().surface()->n_u, 6); // the knot, not yet the weight
    EXPECT_EQ(weight22(ctx), w22_after_knot);
    EXPECT_EQ(l.caption.rfind("Step 1 of 2: ", 0), 0u) << l.caption;
    lesson_next(ctx);
    EXPECT_EQ(l.caption.rfind("Step 2 of 2: ", 0), 0u) << l.caption;
    EXPECT_EQ(weight22(ctx), 4);
    EXPECT_TRUE(l.finished());
}

TEST(CourseActions, ALessonWrittenWhileRecordingIsSavedEditedAndPlayedFromAStop) {
    test::TempDir tmp("isoparm-course");
    AppContext ctx;
    ctx.doc = doc::default_document();
    start_recording(ctx);
    ASSERT_TRUE(ctx.execute(doc::insert_knot(1, geom::Dir::u, 0.25, 1)));
    add_stop_here(ctx, "First:\n**a knot**");
    request_add_expectation(ctx);
    ASSERT_FALSE(ctx.ui.course.facts.empty());
    add_expectations(ctx, {ctx.ui.course.facts.front()}); // the number of objects
    ctx.seal();
    ASSERT_TRUE(ctx.execute(doc::edit_point({1, 2, 2, std::nullopt, 4.0})));
    add_stop_here(ctx, "Second: w22 = 4");
    EXPECT_EQ(ctx.recorder->stop_count(), 2u);
    save_recording_as_lesson(ctx);
    EXPECT_FALSE(ctx.recorder);
    LessonEditorState& e = ctx.ui.course.editor;
    ASSERT_TRUE(e.open && e.draft);
    EXPECT_EQ(ctx.ui.file_dialog.mode, FileDialog::Mode::save_lesson);
    ASSERT_GE(e.draft->size(), 2u);
    EXPECT_EQ(e.draft->caption(0), "First:\n**a knot**");
    EXPECT_EQ(e.draft->caption(1), "Second: w22 = 4");
    EXPECT_EQ(e.problem, "");
    e.draft->title = "My knot";
    ASSERT_TRUE(save_lesson(ctx, tmp.path("knot.json")));
    auto script = scene::load_script(tmp.path("knot.json"));
    ASSERT_TRUE(script.ok()) << script.error().message;
    EXPECT_EQ(script->title, "My knot");
    // Played from the second stop on a fresh copy of the scene: the knot and the weight.
    play_draft_from(ctx, 1);
    ASSERT_TRUE(ctx.ui.lesson);
    EXPECT_EQ(ctx.ui.lesson->stop, 2u);
    EXPECT_EQ(ctx.ui.lesson->caption, "Second: w22 = 4");
    EXPECT_EQ(weight22(ctx), 4);
    EXPECT_TRUE(ctx.ui.lesson->unmet.empty());
    // Stops reordered so that the weight comes before the knot: still a lesson that replays.
    ASSERT_TRUE(e.draft->move(1, true));
    EXPECT_EQ(draft_problem(e), "");
}

TEST(CourseActions, AMoveThatBreaksTheReplayIsNamed) {
    AppContext ctx;
    ctx.doc = doc::default_document();
    start_recording(ctx);
    ASSERT_TRUE(ctx.execute(doc::split_object(1, geom::Dir::u, 0.5)));
    add_stop_here(ctx, "split");
    ctx.seal();
    ASSERT_TRUE(ctx.execute(doc::edit_point({2, 1, 1, std::nullopt, 3.0}))); // the new piece
    add_stop_here(ctx, "edit the piece");
    save_recording_as_lesson(ctx);
    LessonEditorState& e = ctx.ui.course.editor;
    ASSERT_TRUE(e.draft->move(1, true)); // the edit before the split that makes its object
    const std::string problem = draft_problem(e);
    EXPECT_NE(problem.find("(at /steps/"), std::string::npos) << problem;
    EXPECT_NE(problem.find("/id)"), std::string::npos) << problem; // no object 2 yet
}

TEST(CourseActions, AnExerciseFailsThenIsFixedAndPasses) {
    AppContext ctx;
    ASSERT_TRUE(open_exercise(ctx, exercises + "pull-with-a-weight.json"));
    EXPECT_TRUE(ctx.ui.course.exercise_open);
    EXPECT_TRUE(ctx.file_path.empty()); // an untitled copy
    check_exercise(ctx);
    ASSERT_TRUE(ctx.ui.course.exercise.grade);
    EXPECT_FALSE(ctx.ui.course.exercise.grade->passed());
    ASSERT_TRUE(ctx.execute(doc::edit_point({1, 2, 2, std::nullopt, 16.0 / 3})));
    check_exercise(ctx);
    EXPECT_TRUE(ctx.ui.course.exercise.grade->passed());
    // Another scene opened: the panel stays, to check a saved answer.
    new_document(ctx);
    EXPECT_TRUE(ctx.ui.course.exercise_open);
    check_exercise(ctx);
    EXPECT_FALSE(ctx.ui.course.exercise.grade->passed());
}

TEST(CourseActions, ALessonSavedElsewhereTakesItsSceneAlong) {
    test::TempDir tmp("isoparm-course");
    AppContext ctx;
    ASSERT_TRUE(open_lesson(ctx, lessons + "05-knot-curves.json"));
    open_lesson_editor(ctx);
    LessonEditorState& e = ctx.ui.course.editor;
    ASSERT_TRUE(e.open && e.draft);
    EXPECT_TRUE(e.draft->scene.is_string()); // "../scenes/fig5a-knot-curves.json"
    ASSERT_TRUE(save_lesson(ctx, tmp.path("copy.json")));
    EXPECT_TRUE(e.draft->scene.is_object()); // inline: the relative path would not be found
    auto script = scene::load_script(tmp.path("copy.json"));
    ASSERT_TRUE(script.ok()) << script.error().message;
    EXPECT_EQ(script->title, "Knot curves and moving a knot");
}

} // namespace
