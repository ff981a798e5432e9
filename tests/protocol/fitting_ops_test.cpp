// The fitting and refinement ops of geom-protocol-2.md through handle_request: interpolate,
// approximate, remove_knot and reduce_degree answer as the spec says, agree with the other ops
// (evaluate, insert_knot, elevate_degree), and refuse bad requests with the right code and path.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/geom/status.hpp"
#include "core/protocol/protocol.hpp"

namespace {

using nlohmann::json;
using namespace isoparm;

double distance(const json& a, const json& b) {
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
        const double d = a[k].get<double>() - b[k].get<double>();
        sum += d * d;
    }
    return std::sqrt(sum);
}

json point3(const json& p) {
    return json::array({p[0], p[1], p.size() > 2 ? p[2] : json(0.0)});
}

json ok(const json& request) {
    json a = protocol::handle_request(request);
    EXPECT_TRUE(a["ok"].get<bool>()) << request.dump() << "\n-> " << a.dump();
    return a;
}

void expect_error(const json& request, const std::string& code, const std::string& path) {
    const json a = protocol::handle_request(request);
    ASSERT_FALSE(a["ok"].get<bool>()) << request.dump();
    EXPECT_EQ(a["error"]["code"], code) << request.dump() << "\n-> " << a.dump();
    EXPECT_EQ(a["error"]["path"], path) << request.dump() << "\n-> " << a.dump();
}

const json points = {{0, 0}, {1, 2}, {3, 3}, {4, 1}, {6, 0}, {7, 2}};

const json cubic = {{"degree", 3},
                    {"knots", {0, 0, 0, 0, 0.5, 1, 1, 1, 1}},
                    {"points", {{0, 0, 0}, {1, 2, 0}, {3, 2, 1}, {4, 0, 0}, {5, 1, 0}}}};

const json rational_quadratic = {{"type", "nurbs"},
                                 {"degree", 2},
                                 {"knots", {0, 0, 0, 0.4, 1, 1, 1}},
                                 {"points", {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 1, 1}}},
                                 {"weights", {1, 0.7, 1.3, 1}}};

} // namespace

TEST(InterpolateOp, PassesThroughThePointsAtTheParameters) {
    for (const char* mode : {"chord", "centripetal", "uniform"}) {
        const json a = ok(
            {{"op", "interpolate"}, {"points", points}, {"degree", 3}, {"parametrization", mode}});
        const json& curve = a["curve"];
        EXPECT_EQ(curve["type"], "bspline");
        EXPECT_EQ(curve["knots"].front(), 0.0);
        EXPECT_EQ(curve["knots"].back(), 1.0);
        ASSERT_EQ(a["params"].size(), points.size());
        const json at = ok({{"op", "evaluate"}, {"curve", curve}, {"params", a["params"]}});
        for (std::size_t k = 0; k < points.size(); ++k)
            EXPECT_LT(distance(at["points"][k], point3(points[k])), 1e-12 * 7);
    }
}

TEST(InterpolateOp, MeetsTheEndDerivatives) {
    const json d0 = {1, 5, 0}, d1 = {3, -4, 2};
    const json a = ok(
        {{"op", "interpolate"}, {"points", points}, {"degree", 3}, {"end_derivatives", {d0, d1}}});
    EXPECT_EQ(a["curve"]["points"].size(), points.size() + 2);
    const json at = ok(
        {{"op", "evaluate"}, {"curve", a["curve"]}, {"params", a["params"]}, {"derivatives", 1}});
    for (std::size_t k = 0; k < points.size(); ++k)
        EXPECT_LT(distance(at["points"][k], point3(points[k])), 1e-11);
    EXPECT_LT(distance(at["derivatives"].front()[1], d0), 1e-10);
    EXPECT_LT(distance(at["derivatives"].back()[1], d1), 1e-10);
}

TEST(InterpolateOp, ASurfaceThroughAGrid) {
    json grid = json::array();
    for (int k = 0; k < 5; ++k) {
        json row = json::array();
        for (int l = 0; l < 4; ++l) row.push_back({k, l + 0.3 * k, std::sin(k + 2.0 * l)});
        grid.push_back(row);
    }
    const json a = ok({{"op", "interpolate"}, {"grid", grid}, {"degree", {3, 2}}});
    const json& s = a["surface"];
    EXPECT_EQ(s["degree"], json({3, 2}));
    ASSERT_EQ(a["params"].size(), 2u);
    const json& u = a["params"][0];
    const json& v = a["params"][1];
    ASSERT_EQ(u.size(), 5u);
    ASSERT_EQ(v.size(), 4u);
    json uv = json::array();
    for (int k = 0; k < 5; ++k)
        for (int l = 0; l < 4; ++l) uv.push_back({u[k], v[l]});
    const json at = ok({{"op", "evaluate"}, {"surface", s}, {"params", uv}});
    for (int k = 0; k < 5; ++k)
        for (int l = 0; l < 4; ++l)
            EXPECT_LT(distance(at["points"][k * 4 + l], grid[k][l]), 1e-12 * 5) << k << "," << l;
}

TEST(ApproximateOp, KeepsTheEndsAndReportsItsErrors) {
    json many = json::array();
    for (int k = 0; k <= 30; ++k) many.push_back({k / 3.0, std::sin(k / 4.0), 0});
    const json a = ok({{"op", "approximate"}, {"points", many}, {"degree", 3}, {"count", 7}});
    const json& c = a["curve"];
    ASSERT_EQ(c["points"].size(), 7u);
    EXPECT_EQ(c["points"].front(), many.front());
    EXPECT_EQ(c["points"].back(), many.back());
    const json at = ok({{"op", "evaluate"}, {"curve", c}, {"params", a["params"]}});
    double worst = 0, sum = 0;
    for (std::size_t k = 0; k < many.size(); ++k) {
        const double e = distance(at["points"][k], many[k]);
        worst = std::max(worst, e);
        sum += e * e;
    }
    EXPECT_NEAR(a["max_error"].get<double>(), worst, 1e-15);
    EXPECT_NEAR(a["rms_error"].get<double>(), std::sqrt(sum / many.size()), 1e-15);
    EXPECT_GT(a["max_error"].get<double>(), 0.0);
}

TEST(RemoveKnotOp, UndoesInsertKnot) {
    for (const json& curve : {cubic, rational_quadratic}) {
        const json inserted =
            ok({{"op", "insert_knot"}, {"curve", curve}, {"knot", 0.7}, {"times", 2}});
        const json a =
            ok({{"op", "remove_knot"}, {"curve", inserted["curve"]}, {"knot", 0.7}, {"times", 2}});
        EXPECT_EQ(a["removed"], 2);
        EXPECT_LE(a["max_deviation"].get<double>(), 1e-9);
        EXPECT_EQ(a["curve"]["knots"], curve["knots"]);
        for (std::size_t i = 0; i < curve["points"].size(); ++i)
            EXPECT_LT(distance(a["curve"]["points"][i], curve["points"][i]), 1e-12);
    }
}

TEST(RemoveKnotOp, AnEssentialKnotStays) {
    const json a = ok({{"op", "remove_knot"}, {"curve", cubic}, {"knot", 0.5}, {"times", 3}});
    EXPECT_EQ(a["removed"], 0);
    EXPECT_EQ(a["max_deviation"], 0.0);
    EXPECT_EQ(a["curve"]["knots"], cubic["knots"]);
    // A loose tolerance lets it go, within that tolerance.
    const json loose =
        ok({{"op", "remove_knot"}, {"curve", cubic}, {"knot", 0.5}, {"tolerance", 10}});
    EXPECT_EQ(loose["removed"], 1);
    EXPECT_LE(loose["max_deviation"].get<double>(), 10.0);
}

TEST(RemoveKnotOp, SurfacesInADirection) {
    const json surface = {
        {"degree", {2, 1}},
        {"knots", {{0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}}},
        {"points", {{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 1}, {1, 1, 2}}, {{2, 0, 0}, {2, 1, 0}}}}};
    const json inserted =
        ok({{"op", "insert_knot"}, {"surface", surface}, {"direction", "u"}, {"knot", 0.25}});
    const json a = ok({{"op", "remove_knot"},
                       {"surface", inserted["surface"]},
                       {"direction", "u"},
                       {"knot", 0.25}});
    EXPECT_EQ(a["removed"], 1);
    EXPECT_EQ(a["surface"]["knots"], surface["knots"]);
}

TEST(ReduceDegreeOp, UndoesElevateDegree) {
    for (const json& curve : {cubic, rational_quadratic}) {
        const json elevated = ok({{"op", "elevate_degree"}, {"curve", curve}});
        const json a = ok({{"op", "reduce_degree"}, {"curve", elevated["curve"]}});
        EXPECT_LE(a["max_error"].get<double>(), 1e-9);
        EXPECT_EQ(a["curve"]["degree"], curve["degree"]);
        EXPECT_EQ(a["curve"]["knots"], curve["knots"]);
        for (std::size_t i = 0; i < curve["points"].size(); ++i)
            EXPECT_LT(distance(a["curve"]["points"][i], curve["points"][i]), 1e-12);
    }
    const json surface = {
        {"degree", {2, 1}},
        {"knots", {{0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}}},
        {"points", {{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 1}, {1, 1, 2}}, {{2, 0, 0}, {2, 1, 0}}}}};
    const json elevated =
        ok({{"op", "elevate_degree"}, {"surface", surface}, {"direction", "v"}, {"times", 1}});
    const json a =
        ok({{"op", "reduce_degree"}, {"surface", elevated["surface"]}, {"direction", "v"}});
    EXPECT_EQ(a["surface"]["degree"], json({2, 1}));
    EXPECT_LE(a["max_error"].get<double>(), 1e-9);
}

TEST(ReduceDegreeOp, RefusesBeyondTheToleranceNamingTheBound) {
    const json a = protocol::handle_request({{"op", "reduce_degree"}, {"curve", cubic}});
    ASSERT_FALSE(a["ok"].get<bool>());
    EXPECT_EQ(a["error"]["code"], "geometry");
    EXPECT_EQ(a["error"]["path"], "/curve");
    const json loose = ok({{"op", "reduce_degree"}, {"curve", cubic}, {"tolerance", 100}});
    const std::string message = a["error"]["message"];
    const std::string bound = geom::format_number(loose["max_error"].get<double>());
    EXPECT_NE(message.find(bound), std::string::npos) << message << " / " << bound;
    EXPECT_EQ(loose["curve"]["degree"], 2);
}

TEST(FittingOps, RefuseBadRequestsWithCodeAndPath) {
    const json line = {
        {"degree", 1}, {"knots", {0, 0, 0.5, 1, 1}}, {"points", {{0, 0}, {1, 1}, {2, 0}}}};
    // interpolate
    expect_error({{"op", "interpolate"}, {"points", points}}, "schema", "/degree");
    expect_error({{"op", "interpolate"}, {"degree", 2}}, "schema", "/points");
    expect_error({{"op", "interpolate"}, {"points", points}, {"grid", {points}}, {"degree", 2}},
                 "schema", "/grid");
    expect_error({{"op", "interpolate"}, {"points", {{0, 0}}}, {"degree", 1}}, "schema", "/points");
    expect_error({{"op", "interpolate"}, {"points", points}, {"degree", 6}}, "degree", "/degree");
    expect_error({{"op", "interpolate"}, {"points", points}, {"degree", 0}}, "degree", "/degree");
    expect_error({{"op", "interpolate"}, {"points", points}, {"degree", 2.5}}, "schema", "/degree");
    expect_error(
        {{"op", "interpolate"}, {"points", points}, {"degree", 2}, {"parametrization", "arc"}},
        "schema", "/parametrization");
    expect_error(
        {{"op", "interpolate"}, {"points", {{0, 0}, {1, 1}, {1, 1}, {2, 0}}}, {"degree", 2}},
        "geometry", "/points/2");
    expect_error({{"op", "interpolate"}, {"points", {{0, 0}, {1, "x"}}}, {"degree", 1}}, "schema",
                 "/points/1/1");
    expect_error({{"op", "interpolate"},
                  {"points", points},
                  {"degree", 2},
                  {"end_derivatives", json::array({json::array({1, 0})})}},
                 "schema", "/end_derivatives");
    expect_error({{"op", "interpolate"},
                  {"points", points},
                  {"degree", 2},
                  {"end_derivatives", {{1, 0}, {1}}}},
                 "schema", "/end_derivatives/1");
    expect_error({{"op", "interpolate"},
                  {"points", points},
                  {"degree", 1},
                  {"end_derivatives", {{1, 0}, {1, 0}}}},
                 "degree", "/degree");
    expect_error({{"op", "interpolate"},
                  {"grid", {points, points}},
                  {"degree", {1, 2}},
                  {"end_derivatives", {{1, 0}, {1, 0}}}},
                 "schema", "/end_derivatives");
    expect_error({{"op", "interpolate"}, {"grid", {points, {{0, 0}}}}, {"degree", {1, 1}}},
                 "schema", "/grid/1");
    expect_error({{"op", "interpolate"}, {"grid", {points, points}}, {"degree", 2}}, "schema",
                 "/degree");
    expect_error({{"op", "interpolate"}, {"grid", {points, points}}, {"degree", {2, 2}}}, "degree",
                 "/degree/0");
    expect_error({{"op", "interpolate"}, {"grid", {points, points}}, {"degree", {1, 2}}},
                 "geometry", "/grid/1");
    expect_error({{"op", "interpolate"}, {"points", points}, {"degree", 2}, {"smooth", true}},
                 "schema", "/smooth");
    // approximate
    expect_error({{"op", "approximate"}, {"points", points}, {"degree", 3}}, "schema", "/count");
    expect_error({{"op", "approximate"}, {"points", points}, {"degree", 3}, {"count", 7}}, "schema",
                 "/count");
    expect_error({{"op", "approximate"}, {"points", points}, {"degree", 3}, {"count", 3}}, "degree",
                 "/count");
    expect_error({{"op", "approximate"}, {"points", points}, {"degree", 3}, {"count", 5000}},
                 "limit", "/count");
    // remove_knot
    expect_error({{"op", "remove_knot"}, {"curve", line}, {"knot", 0.3}}, "schema", "/knot");
    expect_error({{"op", "remove_knot"}, {"curve", line}, {"knot", 1}}, "domain", "/knot");
    expect_error({{"op", "remove_knot"}, {"curve", line}}, "schema", "/knot");
    expect_error({{"op", "remove_knot"}, {"curve", line}, {"knot", 0.5}, {"times", 0}}, "schema",
                 "/times");
    expect_error({{"op", "remove_knot"}, {"curve", line}, {"knot", 0.5}, {"tolerance", -1}},
                 "schema", "/tolerance");
    expect_error({{"op", "remove_knot"},
                  {"curve", line},
                  {"knot", 0.5},
                  {"tolerance", std::numeric_limits<double>::infinity()}},
                 "schema", "/tolerance");
    expect_error({{"op", "remove_knot"}, {"curve", line}, {"knot", 0.5}, {"direction", "u"}},
                 "schema", "/direction");
    // reduce_degree
    expect_error({{"op", "reduce_degree"}, {"curve", line}}, "degree", "/curve/degree");
    expect_error({{"op", "reduce_degree"}, {"curve", cubic}, {"tolerance", "big"}}, "schema",
                 "/tolerance");
    expect_error({{"op", "reduce_degree"},
                  {"surface",
                   {{"degree", {1, 2}},
                    {"knots", {{0, 0, 1, 1}, {0, 0, 0, 1, 1, 1}}},
                    {"points", {{{0, 0}, {0, 1}, {0, 2}}, {{1, 0}, {1, 1}, {1, 2}}}}}},
                  {"direction", "u"}},
                 "degree", "/surface/degree/0");
}

TEST(FittingOps, SizeCapsAndTheWorkBudget) {
    json many = json::array();
    for (int k = 0; k < 4097; ++k) many.push_back({k, k % 7});
    expect_error({{"op", "interpolate"}, {"points", many}, {"degree", 3}}, "limit", "/points");
    many.erase(many.end() - 2, many.end());
    expect_error({{"op", "interpolate"},
                  {"points", many},
                  {"degree", 3},
                  {"end_derivatives", {{1, 0}, {1, 0}}}},
                 "limit", "/points");
    // 4000 points at degree 3999: about 2e11 basis steps.
    many.erase(many.begin() + 4000, many.end());
    expect_error({{"op", "interpolate"}, {"points", many}, {"degree", 3999}}, "limit", "/points");
    // The same points at degree 3 are cheap.
    const json a = ok({{"op", "interpolate"}, {"points", many}, {"degree", 3}});
    EXPECT_EQ(a["curve"]["points"].size(), 4000u);
}
