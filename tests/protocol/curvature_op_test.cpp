// The `curvature` op (geom-protocol-2.md) against `evaluate`'s second derivatives and normals:
// K and H recomputed here from the fundamental forms must agree; errors follow the protocol.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geom/knots.hpp"
#include "core/json/shapes.hpp"
#include "core/protocol/protocol.hpp"
#include "tests/support/random_geometry.hpp"

namespace {

using nlohmann::json;
using namespace isoparm;

double dot(const json& a, const json& b) {
    return a[0].get<double>() * b[0].get<double>() + a[1].get<double>() * b[1].get<double>() +
           a[2].get<double>() * b[2].get<double>();
}

TEST(CurvatureOp, AgreesWithTheFundamentalFormsOfEvaluate) {
    isoparm::testing::RandomGeometry g(77);
    geom::Surface s = g.surface(3, 3, 6, 6, true);
    s.knots_u = s.knots_v = geom::clamped_uniform_knots(6, 3); // the domain [0, 1]^2
    json params = json::array();
    for (int k = 0; k < 25; ++k) params.push_back(json::array({g.uniform(0, 1), g.uniform(0, 1)}));
    const json surface = json_io::surface_to_json(s);
    const json curvature =
        protocol::handle_request({{"op", "curvature"}, {"surface", surface}, {"params", params}});
    const json evaluated = protocol::handle_request({{"op", "evaluate"},
                                                     {"surface", surface},
                                                     {"params", params},
                                                     {"derivatives", 2},
                                                     {"normals", true}});
    ASSERT_TRUE(curvature["ok"].get<bool>()) << curvature.dump();
    ASSERT_TRUE(evaluated["ok"].get<bool>());
    for (std::size_t i = 0; i < params.size(); ++i) {
        const json& D = evaluated["derivatives"][i];
        const json& n = evaluated["normals"][i];
        const json& k = curvature["curvatures"][i];
        if (n.is_null()) {
            EXPECT_TRUE(k["gaussian"].is_null());
            continue;
        }
        const double E = dot(D[1][0], D[1][0]), F = dot(D[1][0], D[0][1]),
                     G = dot(D[0][1], D[0][1]);
        const double L = dot(D[2][0], n), M = dot(D[1][1], n), N = dot(D[0][2], n);
        const double K = (L * N - M * M) / (E * G - F * F);
        const double H = (E * N - 2 * F * M + G * L) / (2 * (E * G - F * F));
        const double scale = std::max({1.0, std::abs(K), std::abs(H)});
        EXPECT_NEAR(k["gaussian"].get<double>(), K, 1e-12 * scale);
        EXPECT_NEAR(k["mean"].get<double>(), H, 1e-12 * scale);
        EXPECT_GE(k["k1"].get<double>(), k["k2"].get<double>());
    }
}

TEST(CurvatureOp, RefusesLikeEvaluate) {
    const json curve = {{"degree", 1}, {"knots", {0, 0, 1, 1}}, {"points", {{0, 0}, {1, 1}}}};
    json a = protocol::handle_request({{"op", "curvature"}, {"curve", curve}, {"params", {2.0}}});
    EXPECT_EQ(a["error"]["code"], "domain");
    EXPECT_EQ(a["error"]["path"], "/params/0");
    a = protocol::handle_request(
        {{"op", "curvature"}, {"curve", curve}, {"params", {0.5}}, {"derivatives", 1}});
    EXPECT_EQ(a["error"]["code"], "schema");
    EXPECT_EQ(a["error"]["path"], "/derivatives");
    a = protocol::handle_request({{"op", "curvature"}, {"curve", curve}});
    EXPECT_EQ(a["error"]["path"], "/params");
}

} // namespace

namespace {

TEST(BlossomOp, AnswersThePolarFormAndItsSpan) {
    const json curve = {{"degree", 2},
                        {"knots", {0, 0, 0, 0.5, 1, 1, 1}},
                        {"points", {{0, 0}, {1, 2}, {2, 0}, {3, 1}}}};
    // f(t_2, t_3) on piece 2 ([0, 0.5)) is P_1 = (1, 2).
    json a = protocol::handle_request({{"op", "blossom"}, {"curve", curve}, {"args", {0, 0.5}}});
    ASSERT_TRUE(a["ok"].get<bool>()) << a.dump();
    EXPECT_EQ(a["span"], 2);
    EXPECT_EQ(a["point"], json::array({1.0, 2.0, 0.0}));
    // The same arguments on the next piece: f(t_3, t_4) = P_2 needs (0.5, 1).
    a = protocol::handle_request(
        {{"op", "blossom"}, {"curve", curve}, {"args", {0.5, 1}}, {"span", 3}});
    EXPECT_EQ(a["point"], json::array({2.0, 0.0, 0.0}));
    a = protocol::handle_request({{"op", "blossom"}, {"curve", curve}, {"args", {0.5}}});
    EXPECT_EQ(a["error"]["code"], "schema");
    EXPECT_EQ(a["error"]["path"], "/args");
    a = protocol::handle_request(
        {{"op", "blossom"}, {"curve", curve}, {"args", {0.5, 0.5}}, {"span", 1}});
    EXPECT_EQ(a["error"]["path"], "/span");
    a = protocol::handle_request(
        {{"op", "blossom"}, {"curve", curve}, {"args", {0.5, 0.5}}, {"u_args", {1}}});
    EXPECT_EQ(a["error"]["path"], "/u_args");
}

TEST(BlossomOp, SurfacePieceIsNamedByBothSpans) {
    const json surface = {{"degree", {1, 1}},
                          {"knots", {{0, 0, 1, 1}, {0, 0, 1, 1}}},
                          {"points", {{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 1}}}}};
    json a = protocol::handle_request(
        {{"op", "blossom"}, {"surface", surface}, {"u_args", {0.5}}, {"v_args", {0.5}}});
    ASSERT_TRUE(a["ok"].get<bool>()) << a.dump();
    EXPECT_EQ(a["span"], json::array({1, 1}));
    EXPECT_EQ(a["point"], json::array({0.5, 0.5, 0.25}));
    a = protocol::handle_request({{"op", "blossom"},
                                  {"surface", surface},
                                  {"u_args", {0.5}},
                                  {"v_args", {0.5}},
                                  {"span", {1, 2}}});
    EXPECT_EQ(a["error"]["path"], "/span/1");
}

} // namespace
