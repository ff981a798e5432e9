// One wording and one path rule for an unknown or missing member, wherever JSON is read:
// requests (core/protocol), geometry objects (core/json), scenes (core/scene).
#include <gtest/gtest.h>

#include <string>

#include "core/json/fields.hpp"
#include "core/json/shapes.hpp"
#include "core/protocol/protocol.hpp"
#include "core/scene/scene_io.hpp"

namespace {

using nlohmann::json;
using namespace isoparm;

TEST(JsonFields, UnknownMemberIsWordedAlikeInRequestsGeometryAndScenes) {
    const json request = json::parse(
        R"({"op": "evaluate", "curve": {"degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 1]]}, "params": [0.5], "colour": 1})");
    const json answer = protocol::handle_request(request);
    EXPECT_EQ(answer["error"]["path"], "/colour");
    EXPECT_EQ(answer["error"]["message"],
              "unknown member 'colour' in op 'evaluate' (allowed: op, curve, surface, params, "
              "derivatives, normals)");

    const auto curve = json_io::curve_from_json(
        json::parse(R"({"degree": 1, "points": [[0, 0], [1, 1]], "knots": [0, 0, 1, 1], "w": 2})"));
    ASSERT_FALSE(curve);
    EXPECT_EQ(curve.error().path, "/w");
    EXPECT_EQ(curve.error().message,
              "unknown member 'w' in a curve (allowed: type, degree, knots, points, weights)");

    const auto scene = scene::scene_from_text(
        R"({"format": "isoparm-scene", "version": 1, "objects": [], "display": {"grid": true}})");
    ASSERT_FALSE(scene);
    EXPECT_EQ(scene.error().path, "/display/grid");
    EXPECT_EQ(scene.error().message.rfind("unknown member 'grid' in display (allowed: style, ", 0),
              0u)
        << scene.error().message;
}

TEST(JsonFields, MissingMemberIsWordedAlikeAndPointsWhereItWouldBe) {
    const json answer =
        protocol::handle_request(json::parse(R"({"op": "evaluate", "params": [0]})"));
    EXPECT_EQ(answer["error"]["path"], "/curve");
    const auto curve = json_io::curve_from_json(json::parse(R"({"points": [[0, 0], [1, 1]]})"));
    ASSERT_FALSE(curve);
    EXPECT_EQ(curve.error().message, "missing member 'degree'");
    EXPECT_EQ(curve.error().path, "/degree");
    const auto scene = scene::scene_from_text(R"({"format": "isoparm-scene", "version": 1})");
    ASSERT_FALSE(scene);
    EXPECT_EQ(scene.error().message, "missing member 'objects'");
    EXPECT_EQ(scene.error().path, "/objects");
}

} // namespace
