// Lessons as stops: cut at the pauses and joined again without losing or changing a step.
#include <gtest/gtest.h>

#include "core/scene/lesson_draft.hpp"
#include "core/scene/script.hpp"

using namespace isoparm;
using nlohmann::json;

namespace {

const json three_stops = json::parse(R"({
    "format": "isoparm-script", "version": 1, "title": "Weights", "summary": "w pulls",
    "scene": "../scenes/fig3a-bspline.json",
    "steps": [
        {"caption": "first"}, {"select": {"object": 1, "point": [2, 2]}}, {"pause": true},
        {"command": "edit_point", "id": 1, "i": 2, "j": 2, "weight": 5},
        {"caption": "second"}, {"pause": true},
        {"caption": "the end"}, {"expect": {"objects": 1}}
    ]})");

TEST(LessonDraft, StopsAreTheStretchesBetweenPausesAndWriteBackUnchanged) {
    auto d = scene::lesson_draft_from_json(three_stops);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d->title, "Weights");
    EXPECT_EQ(d->summary, "w pulls");
    ASSERT_EQ(d->size(), 3u);
    EXPECT_EQ(d->caption(0), "first");
    EXPECT_EQ(d->caption(1), "second");
    EXPECT_EQ(d->caption(2), "the end");
    EXPECT_TRUE(d->stops[0].paused);
    EXPECT_FALSE(d->stops[2].paused);
    EXPECT_EQ(d->actions(1), 1u);
    EXPECT_EQ(d->first_step(1), 3u);
    EXPECT_EQ(d->pause_step(1), 5u);
    EXPECT_EQ(d->to_json(), three_stops);
}

TEST(LessonDraft, CaptionsAreEditedInPlaceAndStopsMoveWithTheirSteps) {
    scene::LessonDraft d = *scene::lesson_draft_from_json(three_stops);
    d.set_caption(1, "Raise w22 to 5:\n**the surface is pulled** toward P22");
    EXPECT_EQ(d.caption(1), "Raise w22 to 5:\n**the surface is pulled** toward P22");
    EXPECT_EQ(d.to_json()["steps"][4]["caption"], d.caption(1)); // where it was
    d.set_caption(0, "");
    EXPECT_EQ(d.caption(0), "");
    d.set_caption(0, "again");
    EXPECT_EQ(d.to_json()["steps"][0], json({{"caption", "again"}}));
    ASSERT_TRUE(d.move(1, true));
    EXPECT_EQ(d.caption(0), d.to_json()["steps"][1]["caption"]);
    EXPECT_EQ(d.to_json()["steps"][0]["command"], "edit_point");
    EXPECT_FALSE(d.move(0, true));
    EXPECT_FALSE(d.move(2, false));
    // The last stop stays the lesson's end (no pause) wherever its steps go.
    ASSERT_TRUE(d.move(2, true));
    EXPECT_FALSE(d.stops[2].paused);
    EXPECT_EQ(d.caption(1), "the end");
    d.remove(2);
    ASSERT_EQ(d.size(), 2u);
    EXPECT_FALSE(d.stops[1].paused);
    // What the editor writes reads back as a script.
    auto script = scene::script_from_json(d.to_json(), ISOPARM_SOURCE_DIR "/assets/lessons");
    ASSERT_TRUE(script.ok()) << script.error().message;
    EXPECT_EQ(script->title, "Weights");
}

TEST(LessonDraft, ARecordingWithoutPausesIsOneStopAndAddStopEndsOne) {
    json steps =
        json::array({{{"command", "insert_knot"}, {"id", 1}, {"direction", "u"}, {"knot", 0.25}}});
    scene::add_stop(steps, "Inserted u = 0.25");
    steps.push_back({{"indicator", {0.5, 0.5}}});
    scene::add_stop(steps, "");
    const json script = {{"format", "isoparm-script"}, {"version", 1}, {"steps", steps}};
    auto d = scene::lesson_draft_from_json(script);
    ASSERT_TRUE(d.ok());
    ASSERT_EQ(d->size(), 2u);
    EXPECT_EQ(d->caption(0), "Inserted u = 0.25");
    EXPECT_EQ(d->caption(1), "");
    auto bare = scene::lesson_draft_from_json(
        {{"format", "isoparm-script"}, {"version", 1}, {"steps", json::array()}});
    ASSERT_TRUE(bare.ok());
    EXPECT_EQ(bare->size(), 1u);
    EXPECT_FALSE(scene::lesson_draft_from_json({{"format", "x"}}).ok());
}

} // namespace
