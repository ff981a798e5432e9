// Commands as JSON: every command has a JSON form that reads back to the same command, the
// reader refuses bad steps with their paths, and a drag's spec is its final value.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <set>

#include "core/doc/commands.hpp"
#include "core/doc/commands_curve.hpp"
#include "core/geom/trim/trim.hpp"
#include "core/scene/command_json.hpp"
#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::doc::testing;
using geom::Dir;
using nlohmann::json;

namespace {

// One spec of every command kind, each valid on sample_document_with_triangle() (in this order).
// The sample curve revolved by 90 degrees, its u-knot 0.75 inserted after.
Recipe revolve_profile() {
    Recipe r;
    r.kind = Construction::revolve;
    r.curves = {curve_id};
    r.angle = 90;
    r.refinements.push_back({RecipeRefinement::Kind::insert_knot, Dir::u, 0.75, 1});
    return r;
}

std::vector<CommandSpec> one_of_each() {
    Object added;
    added.name = "added";
    added.shape = SurfaceObject{make_planar_grid(3, 3, 2, 2, geom::SplineType::nurbs)};
    geom::Surface grid = make_planar_grid(3, 3, 2, 2, geom::SplineType::bspline);
    Colors colors;
    colors.background = {0.5f, 0.25f, 0.125f, 1};
    glm::dmat4 shift(1.0);
    shift[3] = glm::dvec4(1, 2, 3, 1);
    return {
        AddObjectSpec{added},
        RemoveObjectSpec{grid_id},
        RenameObjectSpec{hill_id, "mountain"},
        SetVisibleSpec{patch_id, true},
        EditShapeSpec{grid_id, SurfaceObject{grid}, "Smaller grid", ""},
        EditPointSpec{hill_id, 1, 2, glm::dvec3(0.5, -1, 2), 0.25},
        MoveKnotSpec{curve_id, Dir::u, 4, 1, 0.3},
        TransformSpec{hill_id, shift, "Translate hill"},
        InsertKnotSpec{hill_id, Dir::v, 0.3, 2},
        ElevateDegreeSpec{grid_id, Dir::u, 1},
        SplitSpec{hill_id, Dir::u, 0.5},
        ConformBordersSpec{hill_id},
        SetColorsSpec{colors},
        InsertCurvePointSpec{curve_id, 2, glm::dvec3(1, 1, 0)},
        DeleteCurvePointSpec{curve_id, 6},
        MoveCurvePointSpec{curve_id, 3, glm::dvec3(3, 2, 0)},
        SetCurveDegreeSpec{curve_id, 2},
        SetCurveKnotModeSpec{curve_id, CurveKnotMode::chord},
        SetCurvePlaneSpec{curve_id, CurvePlane::xz, true},
        MakeCompatibleSpec{{curve_id, curve_id + 100}},
        RemoveKnotSpec{grid_id, Dir::u, 0.5, 2, 0.25},
        ReduceDegreeSpec{grid_id, Dir::v, 1e-3},
        SplitKnotSpec{curve_id, Dir::u, 0.5, 0.02},
        CloseSpec{curve_id, Dir::u},
        ConvertSpec{grid_id, geom::SplineType::bezier, true},
        AddObjectsSpec{{added, added}, "Import two"},
        MultiresEditSpec{curve_id, 1, std::nullopt, 2, -1, glm::dvec3(1, 1, 0), std::nullopt},
        SplitTriangleSpec{tri_id, {0.25, 0.25, 0.5}},
        ConstructSpec{revolve_profile(), "vase"},
        EditConstructionSpec{grid_id, revolve_profile()},
        DetachSpec{grid_id},
        MovePointsSpec{grid_id, {{0, 0}, {1, 2}}, {{0, 0, 1}, {0.5, 0.5, -1}}, "Raise two"},
        TransformPointsSpec{hill_id,
                            {{2, 0}, {2, 1}, {2, 2}},
                            scaling({2, 2, 2}),
                            Pivot::centroid,
                            glm::dvec3(0),
                            ""},
        TransformPointsSpec{
            curve_id, {{1, -1}, {2, -1}}, mirror(0), Pivot::point, glm::dvec3(0.5, 0, 0), "Mirror"},
        SetTrimSpec{grid_id,
                    geom::Trim{std::nullopt, {geom::circle_loop({0.5, 0.5}, 0.25, true).value()}}},
        RemoveTrimSpec{grid_id},
    };
}

TEST(CommandJson, EveryCommandHasAJsonFormThatReadsBackToTheSameCommand) {
    std::set<std::size_t> kinds;
    for (const CommandSpec& spec : one_of_each()) {
        kinds.insert(spec.index());
        const json written = scene::command_to_json(spec);
        EXPECT_EQ(written.at("command"), command_name(spec));
        auto read = scene::command_from_json(written);
        ASSERT_TRUE(read.ok()) << written.dump() << ": " << read.error().message;
        EXPECT_EQ(read->index(), spec.index());
        EXPECT_EQ(scene::command_to_json(*read), written);
        // Built from the JSON or from the spec, the command does the same to a document.
        Document a = sample_document_with_triangle(), b = sample_document_with_triangle();
        const auto sa = make_command(spec)->apply(a);
        const auto sb = make_command(std::move(read).value())->apply(b);
        EXPECT_EQ(sa.ok(), sb.ok()) << written.dump();
        EXPECT_TRUE(same_document(a, b)) << written.dump();
    }
    EXPECT_EQ(kinds.size(), std::variant_size_v<CommandSpec>) << "a command without a case here";
}

TEST(CommandJson, AnAppliedCommandGivesBackItsSpecAndCheckAgreesWithApply) {
    for (const CommandSpec& spec : one_of_each()) {
        Document doc = sample_document_with_triangle();
        auto cmd = make_command(spec);
        const Document before = doc;
        const auto checked = cmd->check(doc);
        EXPECT_TRUE(same_document(doc, before));
        const auto applied = cmd->apply(doc);
        EXPECT_EQ(checked.ok(), applied.ok()) << command_name(spec);
        if (!applied.ok()) {
            EXPECT_EQ(checked.error().path, applied.error().path) << command_name(spec);
            EXPECT_EQ(checked.error().message, applied.error().message);
            continue;
        }
        ASSERT_TRUE(cmd->spec().has_value()) << command_name(spec);
        EXPECT_EQ(scene::command_to_json(*cmd->spec()).at("command"), command_name(spec));
    }
}

TEST(CommandJson, ADragIsOneStepWhoseSpecIsTheFinalValue) {
    Document doc = sample_document_with_triangle();
    const Document start = doc;
    History h;
    ASSERT_TRUE(h.execute(doc, move_control_point(hill_id, 2, 2, {0, 0, 1})).ok());
    ASSERT_TRUE(h.execute(doc, move_control_point(hill_id, 2, 2, {0, 0, 2})).ok());
    ASSERT_TRUE(h.execute(doc, move_control_point(hill_id, 2, 2, {0, 0.5, 3})).ok());
    EXPECT_EQ(h.size(), 1u);
    // The merged command's spec: what a recording keeps of the drag.
    auto merged = move_control_point(hill_id, 2, 2, {0, 0, 1});
    Document scratch = start;
    ASSERT_TRUE(merged->apply(scratch).ok());
    auto next = move_control_point(hill_id, 2, 2, {0, 0.5, 3});
    ASSERT_TRUE(next->apply(scratch).ok());
    ASSERT_TRUE(merged->merge_with(*next));
    const json step = scene::command_to_json(*merged->spec());
    EXPECT_EQ(step, json::parse(R"({"command":"edit_point","id":1,"i":2,"j":2,
                                     "position":[0,0.5,3]})"));
    Document replay = start;
    ASSERT_TRUE(make_command(*scene::command_from_json(step))->apply(replay).ok());
    EXPECT_TRUE(same_document(replay, doc));
}

TEST(CommandJson, WeightsAndPositionsAreOneEdit) {
    Document doc = sample_document_with_triangle();
    const json step = json::parse(
        R"({"command":"edit_point","id":1,"i":0,"j":1,"position":[1,2,3],"weight":-0.5})");
    auto spec = scene::command_from_json(step);
    ASSERT_TRUE(spec.ok()) << spec.error().message;
    History h;
    ASSERT_TRUE(h.execute(doc, make_command(*spec)).ok());
    EXPECT_EQ(surface_of(doc, hill_id).point(0, 1), glm::dvec3(1, 2, 3));
    EXPECT_EQ(surface_of(doc, hill_id).weight(0, 1), -0.5);
    EXPECT_EQ(h.undo_label(), "Edit P01");
    // Neither a position nor a weight: refused by the command, at the member it lacks.
    expect_refused(doc, edit_point({hill_id, 0, 1, std::nullopt, std::nullopt}),
                   geom::ErrorCode::schema, "/position");
}

struct BadStep {
    const char* json;
    const char* path;
    const char* words; // part of the message
};

TEST(CommandJson, BadStepsAreRefusedWithTheirPath) {
    const BadStep cases[] = {
        {R"([1])", "/steps/4", "must be a JSON object"},
        {R"({"id":1})", "/steps/4/command", "missing member 'command'"},
        {R"({"command":"explode","id":1})", "/steps/4/command", "unknown command 'explode'"},
        {R"({"command":7})", "/steps/4/command", "must be a string"},
        {R"({"command":"remove_object","id":1,"colour":2})", "/steps/4/colour",
         "unknown member 'colour' in command 'remove_object'"},
        {R"({"command":"remove_object"})", "/steps/4/id", "missing member 'id'"},
        {R"({"command":"remove_object","id":0})", "/steps/4/id", "between 1 and"},
        {R"({"command":"rename_object","id":1,"name":3})", "/steps/4/name", "must be a string"},
        {R"({"command":"edit_point","id":1,"i":1.5,"position":[0,0,0]})", "/steps/4/i",
         "must be an integer"},
        {R"({"command":"edit_point","id":1,"i":1,"position":[0,"a",0]})", "/steps/4/position/1",
         ""},
        {R"({"command":"insert_knot","id":1,"direction":"w","knot":0.5})", "/steps/4/direction",
         "one of u, v, got 'w'"},
        {R"({"command":"insert_knot","id":1,"direction":"u"})", "/steps/4/knot",
         "missing member 'knot'"},
        {R"({"command":"transform","id":1,"matrix":[[1,0,0],[0,1,0],[0,0,1]]})", "/steps/4/matrix",
         "4 rows"},
        {R"({"command":"set_curve_knot_mode","id":2,"knot_mode":"uniform"})", "/steps/4/knot_mode",
         "clamped_uniform, chord, centripetal, custom"},
        {R"({"command":"make_compatible","ids":[2,"x"]})", "/steps/4/ids/1", "an object id"},
        {R"({"command":"edit_shape","id":1,"shape":{"kind":"surface"}})", "/steps/4/shape/surface",
         "missing member 'surface'"},
        {R"({"command":"set_colors","colors":{"background":[2,0,0,1]}})",
         "/steps/4/colors/background/0", ""},
        {R"({"command":"add_object","object":{"kind":"curve","name":"c","curve":{}}})",
         "/steps/4/object/curve", ""},
    };
    for (const BadStep& c : cases) {
        auto r = scene::command_from_json(json::parse(c.json), "/steps/4");
        ASSERT_FALSE(r.ok()) << c.json;
        EXPECT_EQ(r.error().code, geom::ErrorCode::schema) << c.json << ": " << r.error().message;
        EXPECT_EQ(r.error().path.rfind(c.path, 0), 0u)
            << c.json << ": " << r.error().path << " (" << r.error().message << ")";
        EXPECT_NE(r.error().message.find(c.words), std::string::npos)
            << c.json << ": " << r.error().message;
    }
}

TEST(CommandJson, ACommandThatReadsButDoesNotApplyIsRefusedByItsCheckAtTheSamePath) {
    // The reader checks JSON types; the document's rules are the command's, with the member's
    // path, so a script can say which step and which member.
    const Document doc = sample_document_with_triangle();
    auto spec = scene::command_from_json(
        json::parse(R"({"command":"edit_point","id":1,"i":9,"j":0,"position":[0,0,0]})"));
    ASSERT_TRUE(spec.ok());
    const auto st = make_command(*spec)->check(doc);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().path, "/i");
    EXPECT_NE(st.error().message.find("i = 9"), std::string::npos) << st.error().message;
}

} // namespace

namespace {

// The commands of docs/commands.md: every row of its table names a command this build reads,
// and its example runs on the default scene.
TEST(CommandJson, TheDocumentationNamesEveryCommandAndItsExampleRuns) {
    std::ifstream in(std::string(ISOPARM_SOURCE_DIR) + "/docs/commands.md");
    ASSERT_TRUE(in) << "docs/commands.md";
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const char* name : command_names)
        EXPECT_NE(text.find("| `" + std::string(name) + "` |"), std::string::npos) << name;
    const std::size_t example = text.find("## Example");
    ASSERT_NE(example, std::string::npos);
    const std::size_t open = text.find("```json\n", example) + 8;
    const std::size_t close = text.find("```", open);
    const json steps = json::parse(text.substr(open, close - open));
    Document doc = default_document();
    History h;
    for (std::size_t k = 0; k < steps.size(); ++k) {
        auto spec = scene::command_from_json(steps[k], "/" + std::to_string(k));
        ASSERT_TRUE(spec.ok()) << spec.error().message;
        const auto st = h.execute(doc, make_command(std::move(spec).value()));
        ASSERT_TRUE(st.ok()) << st.error().message;
    }
    EXPECT_EQ(h.size(), 3u);
    const geom::Surface& s = *doc.objects[0].surface();
    EXPECT_EQ(geom::multiplicity(s.knots_u, 0.25), 1);
}

} // namespace
