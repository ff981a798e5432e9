// construct: the Construct menu's surfaces as a command whose data is the recipe.
#include <gtest/gtest.h>

#include "core/doc/curve_constructions.hpp"
#include "core/scene/command_json.hpp"
#include "tests/doc/doc_fixtures.hpp"

namespace isoparm::doc {
namespace {

using namespace testing;

ConstructionRequest revolve_profile(double degrees) {
    ConstructionRequest r;
    r.kind = Construction::revolve;
    r.curves = {curve_id};
    r.angle = degrees;
    return r;
}

TEST(ConstructCommand, AddsTheBuiltSurfaceAndUndoesExactly) {
    Document doc = sample_document();
    const auto built = build_construction(doc, revolve_profile(270));
    ASSERT_TRUE(built.ok());
    const Document after = expect_undo_redo_exact(doc, construct(revolve_profile(270), "vase"));
    ASSERT_EQ(after.objects.size(), doc.objects.size());
    const Object& added = after.objects.back();
    EXPECT_EQ(added.name, "vase");
    // The same surface the Construct menu's build gives, in a new object with a fresh id.
    ASSERT_NE(added.surface(), nullptr);
    EXPECT_EQ(added.surface()->points, built->object.surface()->points);
    EXPECT_EQ(added.surface()->weights, built->object.surface()->weights);
    EXPECT_EQ(added.surface()->knots_v, built->object.surface()->knots_v);
    EXPECT_EQ(added.id, sample_document().next_id);
}

TEST(ConstructCommand, ItsJsonFormIsTheRecipe) {
    ConstructSpec spec{revolve_profile(90), ""};
    const nlohmann::json j = scene::command_to_json(spec);
    EXPECT_EQ(j,
              nlohmann::json::parse(
                  R"({"command":"construct","construction":"revolve","curves":[2],"angle":90})"));
    auto read = scene::command_from_json(
        nlohmann::json::parse(R"({"command":"construct","construction":"skin","curves":[2,2],
                                  "parametrization":"centripetal","degree":1})"));
    ASSERT_TRUE(read.ok()) << read.error().message;
    const auto& back = std::get<ConstructSpec>(*read).request;
    EXPECT_EQ(back.kind, Construction::skin);
    EXPECT_EQ(back.parametrization, geom::Parametrization::centripetal);
    EXPECT_EQ(back.skin_degree, 1);
    auto wrong = scene::command_from_json(
        nlohmann::json::parse(R"({"command":"construct","construction":"extrude","curves":[2]})"));
    ASSERT_FALSE(wrong.ok());
    EXPECT_EQ(wrong.error().path, "/construction");
}

TEST(ConstructCommand, RefusalsNameTheCurveOrTheParameter) {
    Document doc = sample_document();
    ConstructionRequest not_a_curve = revolve_profile(360);
    not_a_curve.curves = {grid_id};
    expect_refused(doc, construct(not_a_curve), geom::ErrorCode::schema, "/curves/0");
    expect_refused(doc, construct(revolve_profile(400)), geom::ErrorCode::schema, "/angle");
    ConstructionRequest one_for_ruled = revolve_profile(360);
    one_for_ruled.kind = Construction::ruled;
    expect_refused(doc, construct(one_for_ruled), geom::ErrorCode::schema, "/curves");
}

TEST(ConstructCommand, TheLabelSaysWhatWasBuilt) {
    Document doc = sample_document();
    History h;
    ASSERT_TRUE(h.execute(doc, construct(revolve_profile(360))).ok());
    EXPECT_EQ(h.undo_label(), "Build revolve profile");
}

} // namespace
} // namespace isoparm::doc
