// Scripts: every step's form is checked with its path before anything runs; the runner applies
// commands through one history, sets the view, and reports expectations that do not hold.
#include <gtest/gtest.h>

#include "core/doc/commands.hpp"
#include "core/scene/script.hpp"

using namespace isoparm;
using nlohmann::json;

namespace {

json script_with(json steps) {
    return {{"format", "isoparm-script"}, {"version", 1}, {"steps", std::move(steps)}};
}

geom::Error refusal(json steps) {
    auto r = scene::script_from_json(script_with(std::move(steps)), ".");
    EXPECT_FALSE(r.ok());
    return r ? geom::Error{} : r.error();
}

TEST(Script, EveryMalformedStepIsRefusedWithItsPath) {
    struct Case {
        json step;
        const char* path;
        const char* words;
    };
    const Case cases[] = {
        {json::parse(R"({"explode": true})"), "/steps/1", "a step is a command"},
        {json::parse(R"({"undo": true, "redo": true})"), "/steps/1", "does one thing"},
        {json::parse(R"({"undo": false})"), "/steps/1/undo", "written true"},
        {json::parse(R"({"indicator": [0.5, 2]})"), "/steps/1/indicator/1", "[0, 1]"},
        {json::parse(R"({"display": {"wires": true}})"), "/steps/1/display/wires",
         "unknown member 'wires'"},
        {json::parse(R"({"continuity": "C2"})"), "/steps/1/continuity", "off, C0 or C1"},
        {json::parse(R"({"camera": {"yaw": 0, "pitch": 95}})"), "/steps/1/camera/pitch",
         "between -90 and 90"},
        {json::parse(R"({"deboor_step": -3})"), "/steps/1/deboor_step", "between 0 and 64"},
        {json::parse(R"({"screenshot": "../up.png"})"), "/steps/1/screenshot", "without folders"},
        {json::parse(R"({"screenshot": "a.jpg"})"), "/steps/1/screenshot", "ending in .png"},
        {json::parse(R"({"screenshot": "a.png", "size": [8, 8]})"), "/steps/1/size/0",
         "between 16 and 8192"},
        {json::parse(R"({"screenshot": "a.png", "view": "top"})"), "/steps/1/view", "\"3d\""},
        {json::parse(R"({"caption": 3})"), "/steps/1/caption", "must be a string"},
        {json::parse(R"({"expect": {"point": [1, 1], "weight": 2}})"), "/steps/1/expect",
         "add \"id\""},
        {json::parse(R"({"expect": {"id": 1, "weight": 2}})"), "/steps/1/expect", "add \"point\""},
        {json::parse(R"({"expect": {"borders": "C1"}})"), "/steps/1/expect", "add \"group\""},
        {json::parse(R"({"expect": {"id": 1, "colour": 2}})"), "/steps/1/expect/colour",
         "unknown member"},
        {json::parse(R"({"command": "insert_knot", "id": 1, "direction": "u"})"), "/steps/1/knot",
         "missing member 'knot'"},
    };
    for (const Case& c : cases) {
        const geom::Error e = refusal(json::array({json::parse(R"({"pause": true})"), c.step}));
        EXPECT_EQ(e.path, c.path) << c.step.dump() << ": " << e.message;
        EXPECT_NE(e.message.find(c.words), std::string::npos) << c.step.dump() << ": " << e.message;
    }
}

TEST(Script, TheScriptItselfIsCheckedToo) {
    auto wrong_format = scene::script_from_json(json::parse(R"({"format": "x", "version": 1,
                                                                "steps": []})"),
                                                ".");
    ASSERT_FALSE(wrong_format.ok());
    EXPECT_EQ(wrong_format.error().path, "/format");
    auto newer = scene::script_from_json(
        json::parse(R"({"format": "isoparm-script", "version": 2, "steps": []})"), ".");
    ASSERT_FALSE(newer.ok());
    EXPECT_EQ(newer.error().path, "/version");
    auto bad_inline = scene::script_from_json(
        json::parse(R"({"format": "isoparm-script", "version": 1, "scene": {"format": 1},
                        "steps": []})"),
        ".");
    ASSERT_FALSE(bad_inline.ok());
    EXPECT_EQ(bad_inline.error().path.rfind("/scene", 0), 0u) << bad_inline.error().path;
}

scene::Script parse(json steps) {
    auto r = scene::script_from_json(script_with(std::move(steps)), ".");
    EXPECT_TRUE(r.ok()) << (r ? "" : r.error().message + " at " + r.error().path);
    return r ? std::move(r).value() : scene::Script{};
}

TEST(Script, StepsRunThroughOneHistoryAndTheViewFollows) {
    const scene::Script s = parse(json::parse(R"([
        {"command": "edit_point", "id": 1, "i": 2, "j": 2, "position": [0, 0, 3]},
        {"command": "insert_knot", "id": 1, "direction": "v", "knot": 0.25},
        {"undo": true},
        {"select": {"object": 1, "point": [1, 3]}},
        {"indicator": [0.25, 0.75]},
        {"display": {"knot_curves": true}},
        {"continuity": "C0"},
        {"camera": {"yaw": 10, "pitch": 20, "zoom": 150}},
        {"deboor_step": 2},
        {"caption": "done"},
        {"expect": {"objects": 1, "id": 1, "point": [2, 2], "position": [0, 0, 3], "weight": 2,
                    "direction": "v", "degree": 3, "type": "nurbs"}}
    ])"));
    scene::ScriptState state(s.start);
    int shots = 0;
    scene::ScriptHooks hooks;
    hooks.screenshot = [&](const scene::ScriptState&, const scene::ScreenshotStep&) {
        ++shots;
        return std::string();
    };
    const scene::ScriptResult r = scene::run_script(s, state, hooks);
    EXPECT_TRUE(r.ok()) << (r.failed_expects.empty() ? "" : r.failed_expects.front());
    EXPECT_EQ(state.history.size(), 1u); // the insertion was undone
    EXPECT_TRUE(state.history.can_redo());
    EXPECT_EQ(state.doc.view.selection, (doc::Selection{1, 1, 3}));
    EXPECT_EQ(state.doc.view.indicator, glm::dvec2(0.25, 0.75));
    EXPECT_TRUE(state.doc.view.display.knot_curves);
    EXPECT_TRUE(state.doc.view.display.control_net); // members not named keep their value
    EXPECT_EQ(state.doc.continuity, doc::Continuity::c0);
    ASSERT_TRUE(state.camera.has_value());
    EXPECT_EQ(state.camera->zoom_percent, 150.0);
    EXPECT_EQ(state.deboor_step, 2);
    EXPECT_EQ(state.caption, "done");
    EXPECT_EQ(shots, 0);
}

TEST(Script, ExpectationsThatDoNotHoldAreEachNamed) {
    const scene::Script s = parse(json::parse(R"([
        {"expect": {"objects": 2}},
        {"expect": {"id": 1, "point": [2, 2], "weight": 5, "tolerance": 0}},
        {"expect": {"id": 1, "direction": "u", "knots": [0, 1]}},
        {"expect": {"id": 7}},
        {"expect": {"id": 1, "point": [9, 9]}},
        {"expect": {"id": 1, "point": [0, 0], "position": [-2, -2, 0.0]}}
    ])"));
    scene::ScriptState state(s.start);
    const scene::ScriptResult r = scene::run_script(s, state, {});
    ASSERT_EQ(r.failed_expects.size(), 5u);
    EXPECT_EQ(r.failed_expects[0], "/steps/0: expected 2 objects, found 1");
    EXPECT_NE(r.failed_expects[1].find("/steps/1: expected the weight of P2,2"), std::string::npos)
        << r.failed_expects[1];
    EXPECT_NE(r.failed_expects[2].find("/steps/2: expected 'hill''s knots in u [0, 1]"),
              std::string::npos)
        << r.failed_expects[2];
    EXPECT_EQ(r.failed_expects[3], "/steps/3: expected an object with id 7, found none");
    EXPECT_EQ(r.failed_expects[4], "/steps/4: 'hill' has no control point P9,9");
    EXPECT_FALSE(r.stopped);
}

TEST(Script, ARefusedStepStopsTheRunWithTheStepsPathAndADryRunCallsNoHook) {
    const scene::Script s = parse(json::parse(R"([
        {"screenshot": "a.png"},
        {"select": {"object": 42}},
        {"screenshot": "b.png"}
    ])"));
    int shots = 0;
    scene::ScriptHooks hooks;
    hooks.screenshot = [&](const scene::ScriptState&, const scene::ScreenshotStep&) {
        ++shots;
        return std::string();
    };
    scene::ScriptState trial(s.start);
    const scene::ScriptResult dry = scene::run_script(s, trial, hooks, /*dry_run=*/true);
    ASSERT_TRUE(dry.stopped.has_value());
    EXPECT_EQ(dry.stopped->path, "/steps/1/select/object");
    EXPECT_EQ(shots, 0);
    scene::ScriptState state(s.start);
    const scene::ScriptResult run = scene::run_script(s, state, hooks);
    EXPECT_EQ(shots, 1); // the first screenshot; the run stopped at the selection
    EXPECT_EQ(run.screenshots, std::vector<std::string>{"a.png"});
    // Undo with nothing to undo is a refusal too, at the step.
    const scene::Script u = parse(json::parse(R"([{"undo": true}])"));
    scene::ScriptState fresh(u.start);
    const scene::ScriptResult nothing = scene::run_script(u, fresh, {});
    ASSERT_TRUE(nothing.stopped.has_value());
    EXPECT_EQ(nothing.stopped->path, "/steps/0");
}

// The trial run has a time budget: the step it reaches after that is a `limit` naming the step
// and the seconds (a budget of 0 s stops at the first step; the real one is 120 s).
TEST(Script, TheTrialRunStopsAtItsTimeBudget) {
    const scene::Script s = parse(json::parse(R"([
        {"screenshot": "a.png"},
        {"screenshot": "b.png"}
    ])"));
    scene::ScriptState trial(s.start);
    const scene::ScriptResult dry = scene::run_script(s, trial, {}, /*dry_run=*/true, 0.0);
    ASSERT_TRUE(dry.stopped.has_value());
    EXPECT_EQ(dry.stopped->code, geom::ErrorCode::limit);
    EXPECT_EQ(dry.stopped->path, "/steps/0");
    EXPECT_NE(dry.stopped->message.find("took more than 0 s to try"), std::string::npos)
        << dry.stopped->message;
    // With the default budget the same trial passes.
    scene::ScriptState again(s.start);
    EXPECT_FALSE(scene::run_script(s, again, {}, /*dry_run=*/true).stopped.has_value());
}

} // namespace
