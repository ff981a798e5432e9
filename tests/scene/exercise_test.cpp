// Exercises: strict reading with paths, and every kind of check passing on a right answer and
// failing on a wrong one with a message that says what was found.
#include <gtest/gtest.h>

#include "core/doc/commands.hpp"
#include "core/doc/curve_constructions.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/primitives.hpp"
#include "core/scene/exercise.hpp"
#include "core/scene/scene_io.hpp"

using namespace isoparm;
using nlohmann::json;

namespace {

json exercise_with(json checks) {
    return {{"format", "isoparm-exercise"},
            {"version", 1},
            {"title", "t"},
            {"task", "Do it."},
            {"scene", scene::scene_to_json(doc::default_document())},
            {"checks", std::move(checks)}};
}

scene::Exercise parse(json checks) {
    auto e = scene::exercise_from_json(exercise_with(std::move(checks)), ".");
    EXPECT_TRUE(e.ok()) << (e ? "" : e.error().message + " at " + e.error().path);
    return e ? std::move(e).value() : scene::Exercise{};
}

// The one check's result on `d`.
scene::CheckResult one(const char* check, const doc::Document& d) {
    const scene::Exercise ex = parse(json::array({json::parse(check)}));
    const scene::Grade g = scene::grade(ex, d);
    EXPECT_EQ(g.checks.size(), 1u);
    return g.checks.empty() ? scene::CheckResult{} : g.checks[0];
}

void expect_pass(const char* check, const doc::Document& d) {
    const scene::CheckResult r = one(check, d);
    EXPECT_TRUE(r.passed) << check << ": " << r.message;
}

void expect_fail(const char* check, const doc::Document& d, const std::string& words) {
    const scene::CheckResult r = one(check, d);
    EXPECT_FALSE(r.passed) << check;
    EXPECT_NE(r.message.find(words), std::string::npos) << check << ": " << r.message;
}

TEST(Exercise, MalformedExercisesAreRefusedWithTheirPaths) {
    struct Case {
        json check;
        const char* path;
        const char* words;
    };
    const Case cases[] = {
        {json::parse(R"({"check": "colour"})"), "/checks/0/check", "check is one of"},
        {json::parse(R"({"check": "degree"})"), "/checks/0", "needs a value"},
        {json::parse(R"({"check": "degree", "degree": 3, "knots": 1})"), "/checks/0/knots",
         "unknown member"},
        {json::parse(R"({"check": "weight", "value": 1})"), "/checks/0/point",
         "missing member 'point'"},
        {json::parse(R"({"check": "border"})"), "/checks/0/continuity",
         "missing member 'continuity'"},
        {json::parse(R"({"check": "border", "continuity": "C2"})"), "/checks/0/continuity",
         "\"G1\""},
        {json::parse(R"({"check": "near_shape", "target": "vase", "distance": 0.1})"),
         "/checks/0/target", "no object named 'vase'"},
        {json::parse(R"({"check": "objects", "object": "hill", "count": 1})"), "/checks/0/object",
         "names a kind"},
        {json::parse(R"({"check": "weights", "min": 2, "max": 1})"), "/checks/0/min", "above max"},
        {json::parse(R"({"check": "point_on_surface", "points": []})"), "/checks/0/points",
         "at least one"},
    };
    for (const Case& c : cases) {
        auto e = scene::exercise_from_json(exercise_with(json::array({c.check})), ".");
        ASSERT_FALSE(e.ok()) << c.check.dump();
        EXPECT_EQ(e.error().path, c.path) << c.check.dump() << ": " << e.error().message;
        EXPECT_NE(e.error().message.find(c.words), std::string::npos) << e.error().message;
    }
    json no_task = exercise_with(json::array({json::parse(R"({"check": "objects", "count": 1})")}));
    no_task.erase("task");
    auto e = scene::exercise_from_json(no_task, ".");
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error().path, "/task");
}

TEST(Exercise, CountsTypesDegreesAndKnots) {
    doc::Document d = doc::default_document();
    expect_pass(R"({"check": "objects", "kind": "surface", "count": 1})", d);
    expect_fail(R"({"check": "objects", "min": 2})", d, "the scene holds 1 objects");
    expect_pass(R"({"check": "type", "type": "nurbs"})", d);
    expect_fail(R"({"check": "type", "object": "hill", "type": "bspline"})", d,
                "'hill' is a NURBS, not a B-spline");
    expect_fail(R"({"check": "type", "object": "vase", "type": "bspline"})", d,
                "there is no object named 'vase'");
    expect_pass(R"({"check": "degree", "degree": 3})", d);
    expect_fail(R"({"check": "degree", "direction": "v", "min": 4})", d,
                "'hill' has degree 3 in v; the task asks for at least 4");
    expect_pass(R"({"check": "control_points", "count": 5})", d);
    expect_fail(R"({"check": "knot", "value": 0.5, "multiplicity": 2})", d,
                "'hill' has the knot 0.5 in u 1 time; the task asks for 2");
    doc::History h;
    ASSERT_TRUE(h.execute(d, doc::insert_knot(1, geom::Dir::u, 0.5, 1)).ok());
    expect_pass(R"({"check": "knot", "value": 0.5, "multiplicity": 2})", d);
    expect_fail(R"({"check": "knot", "direction": "v", "value": 0.25})", d,
                "'hill' has no knot 0.25 in v");
}

TEST(Exercise, WeightsAndPositions) {
    doc::Document d = doc::default_document(); // w22 = 2, w13 = 0.5
    expect_pass(R"({"check": "weight", "point": [2, 2], "min": 1.5, "max": 3})", d);
    expect_fail(R"({"check": "weight", "point": [2, 2], "value": 5})", d,
                "the weight of P2,2 of 'hill' is 2; the task asks for 5");
    expect_fail(R"({"check": "weight", "point": [7, 2], "value": 5})", d,
                "'hill' has no control point P7,2");
    expect_fail(R"({"check": "weights", "min": 1})", d, "the weight of P1,3 of 'hill' is 0.5");
    expect_pass(R"({"check": "no_negative_weight"})", d);
    doc::History h;
    ASSERT_TRUE(h.execute(d, doc::edit_point({1, 0, 4, std::nullopt, -1.0})).ok());
    expect_fail(R"({"check": "no_negative_weight"})", d, "the weight of P0,4 of 'hill' is -1");
    expect_pass(R"({"check": "position", "point": [2, 2], "position": [0, 0, 1.6]})", d);
    expect_fail(R"({"check": "position", "point": [2, 2], "position": [0, 0, 2]})", d,
                "P2,2 of 'hill' is at (0, 0, 1.6), 0.4 from (0, 0, 2)");
}

TEST(Exercise, PointsOnTheSurfaceAndCurvesThroughPoints) {
    doc::Document d = doc::default_document();
    const glm::dvec3 on = *geom::surface_point(*d.objects[0].surface(), 0.3, 0.7);
    const std::string pass = R"({"check": "point_on_surface", "points": [[)" +
                             std::to_string(on.x) + "," + std::to_string(on.y) + "," +
                             std::to_string(on.z) + R"(]], "tolerance": 1e-5})";
    expect_pass(pass.c_str(), d);
    expect_fail(R"({"check": "point_on_surface", "points": [[0, 0, 3]], "tolerance": 0.01})", d,
                "(0, 0, 3) is ");
    expect_fail(R"({"check": "interpolates", "points": [[0, 0, 0]]})", d,
                "there is no curve in the scene");
    doc::Object line;
    line.name = "line";
    line.shape = doc::CurveObject{geom::line_segment({0, 0, 0}, {2, 2, 0}), doc::CurvePlane::xy};
    doc::History h;
    ASSERT_TRUE(h.execute(d, doc::add_object(line)).ok());
    expect_pass(R"({"check": "interpolates", "points": [[0, 0, 0], [1, 1, 0], [2, 2, 0]]})", d);
    expect_fail(R"({"check": "interpolates", "points": [[0, 0, 0], [1, 1.5, 0]]})", d,
                "'line' passes 0.35");
}

TEST(Exercise, BordersBetweenPatches) {
    doc::Document d = doc::default_document();
    expect_fail(R"({"check": "border", "continuity": "C0"})", d, "there is no border");
    d.continuity = doc::Continuity::c1;
    doc::History h;
    ASSERT_TRUE(h.execute(d, doc::split_object(1, geom::Dir::u, 0.75)).ok());
    expect_pass(R"({"check": "border", "continuity": "C1"})", d);
    expect_fail(R"({"check": "border", "continuity": "C1", "borders": 3})", d,
                "there are 1 borders between patches; the task needs at least 3");
    // A point moved with the borders left alone: the join breaks.
    d.continuity = doc::Continuity::off;
    const std::uint64_t piece = d.objects[0].id;
    const geom::Surface& s = *d.objects[0].surface();
    ASSERT_TRUE(h.execute(d, doc::move_control_point(piece, s.n_u - 1, 2, {0.9, 0, 2.5})).ok());
    expect_fail(R"({"check": "border", "continuity": "C0"})", d, "is open: a gap of");
}

TEST(Exercise, NearAShapeBothWays) {
    doc::Document d = doc::default_document();
    // The target: the hill as it starts (the exercise's starting scene), by name.
    expect_pass(R"({"check": "near_shape", "target": "hill", "distance": 1e-9})", d);
    doc::History h;
    // Knot insertion keeps the shape: still within 1e-9.
    ASSERT_TRUE(h.execute(d, doc::insert_knot(1, geom::Dir::v, 0.3, 1)).ok());
    expect_pass(R"({"check": "near_shape", "target": "hill", "distance": 1e-9})", d);
    ASSERT_TRUE(h.execute(d, doc::edit_point({1, 2, 2, glm::dvec3(0, 0, 2.6), std::nullopt})).ok());
    expect_fail(R"({"check": "near_shape", "target": "hill", "distance": 0.01})", d, "'hill' is ");
}

TEST(Exercise, AGradeSaysWhichChecksPassAndTheFirstFailuresHint) {
    const scene::Exercise ex = parse(json::parse(R"([
        {"check": "objects", "count": 1},
        {"check": "weight", "point": [2, 2], "min": 4, "hint": "Drag the weight slider of P22."},
        {"check": "no_negative_weight", "label": "no negative weight"}
    ])"));
    const scene::Grade g = scene::grade(ex, doc::default_document());
    ASSERT_EQ(g.checks.size(), 3u);
    EXPECT_FALSE(g.passed());
    EXPECT_EQ(g.passed_count(), 2u);
    ASSERT_NE(g.first_failure(), nullptr);
    EXPECT_EQ(g.first_failure()->hint, "Drag the weight slider of P22.");
    EXPECT_EQ(g.checks[0].label, "the scene holds 1 object");
    EXPECT_EQ(g.checks[1].label, "the weight of P2,2 of a surface or curve is at least 4");
    EXPECT_EQ(g.checks[2].label, "no negative weight");
}

} // namespace
