// The construction ops through the protocol: valid requests checked by sampling, every error
// code and path.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>
#include <string>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/json/shapes.hpp"
#include "core/protocol/protocol.hpp"

namespace {

using isoparm::protocol::handle_request;
using nlohmann::json;
namespace geom = isoparm::geom;

const json kLine =
    json::parse(R"({"degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0, 0], [2, 0, 0]]})");
const json kArch = json::parse(
    R"({"degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": [[0, 0, 1], [1, 0, 3], [2, 0, 1]]})");
const json kWavy = json::parse(
    R"({"degree": 3, "knots": [0, 0, 0, 0, 0.5, 1, 1, 1, 1], "points": [[0, 1, 0], [1, 2, 0], [2, 0, 0], [3, 1, 0], [4, 1, 0]]})");
// The quarter circle of radius 1 in the xy-plane, rational.
const json kQuarter = json::parse(
    R"({"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": [[1, 0], [1, 1], [0, 1]], "weights": [1, 0.7071067811865476, 1]})");
// A profile in the xz-plane on its own domain [2, 4].
const json kProfile = json::parse(
    R"({"type": "nurbs", "degree": 2, "knots": [2, 2, 2, 3, 4, 4, 4], "points": [[1, 0, 0], [2, 0, 1], [1.5, 0, 2], [0.5, 0, 3]], "weights": [1, 2, 0.5, 1]})");

geom::Curve curve(const json& j) {
    return *isoparm::json_io::curve_from_json(j);
}
geom::Surface surface(const json& j) {
    auto s = isoparm::json_io::surface_from_json(j);
    EXPECT_TRUE(s.ok()) << s.error().message;
    return *s;
}
glm::dvec3 at(const geom::Curve& c, double s01) {
    const geom::Interval d = geom::domain(c);
    return *geom::curve_point(c, s01 >= 1 ? d.hi : d.lo + (d.hi - d.lo) * s01);
}

void expect_ok(const json& r) {
    ASSERT_TRUE(r.at("ok").get<bool>()) << r.dump();
    EXPECT_EQ(r.find("error"), r.end());
}

void expect_error(const json& request, const char* code, const char* path) {
    const json r = handle_request(request);
    ASSERT_FALSE(r.at("ok").get<bool>()) << request.dump() << " -> " << r.dump();
    EXPECT_EQ(r.at("error").at("code"), code) << r.dump();
    if (path) {
        ASSERT_TRUE(r.at("error").contains("path")) << r.dump();
        EXPECT_EQ(r.at("error").at("path"), path) << r.dump();
    } else {
        EXPECT_FALSE(r.at("error").contains("path")) << r.dump();
    }
    EXPECT_FALSE(r.at("error").at("message").get<std::string>().empty());
}

} // namespace

TEST(ConstructOps, MakeCompatible) {
    const json r = handle_request({{"op", "make_compatible"}, {"curves", {kLine, kArch, kWavy}}});
    expect_ok(r);
    ASSERT_EQ(r.at("curves").size(), 3u);
    const json& first = r["curves"][0];
    for (const json& c : r["curves"]) {
        EXPECT_EQ(c["degree"], 3);
        EXPECT_EQ(c["knots"], first["knots"]);
        EXPECT_EQ(c["points"].size(), first["points"].size());
    }
    const json inputs[] = {kLine, kArch, kWavy};
    for (int k = 0; k < 3; ++k) {
        const geom::Curve in = curve(inputs[k]), out = curve(r["curves"][k]);
        for (int i = 0; i <= 20; ++i)
            EXPECT_LT(glm::distance(at(in, i / 20.0), *geom::curve_point(out, i / 20.0)), 1e-12);
    }
}

TEST(ConstructOps, RuledBetweenTwoCurves) {
    const json r = handle_request({{"op", "ruled"}, {"curves", {kLine, kWavy}}});
    expect_ok(r);
    const geom::Surface s = surface(r["surface"]);
    EXPECT_EQ(r["surface"]["degree"], json({3, 1}));
    EXPECT_EQ(r["surface"]["knots"][1], json({0, 0, 1, 1}));
    const geom::Curve a = curve(kLine), b = curve(kWavy);
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 4; ++j) {
            const double u = i / 10.0, v = j / 4.0;
            const glm::dvec3 want = (1 - v) * at(a, u) + v * at(b, u);
            EXPECT_LT(glm::distance(*geom::surface_point(s, u, v), want), 1e-12);
        }
}

TEST(ConstructOps, RevolveDefaultsToAFullTurn) {
    json r = handle_request({{"op", "revolve"}, {"curve", kProfile}});
    expect_ok(r);
    EXPECT_EQ(r["surface"]["type"], "nurbs");
    EXPECT_EQ(r["surface"]["knots"][0], kProfile["knots"]); // u: the curve's own domain
    EXPECT_EQ(r["surface"]["knots"][1].size(), 12u);
    r = handle_request({{"op", "revolve"}, {"curve", kProfile}, {"angle", 90}});
    expect_ok(r);
    const geom::Surface s = surface(r["surface"]);
    const geom::Curve c = curve(kProfile);
    EXPECT_EQ(s.n_v, 3);
    for (int i = 0; i <= 10; ++i) {
        const double u = 2 + i / 5.0;
        const glm::dvec3 C = *geom::curve_point(c, u);
        for (int j = 0; j <= 8; ++j) {
            const glm::dvec3 S = *geom::surface_point(s, u, j / 8.0);
            EXPECT_NEAR(std::hypot(S.x, S.y), std::hypot(C.x, C.y), 1e-12);
            EXPECT_NEAR(S.z, C.z, 1e-12);
        }
        const glm::dvec3 end = *geom::surface_point(s, u, 1.0); // C turned by 90 degrees
        EXPECT_LT(glm::distance(end, glm::dvec3{-C.y, C.x, C.z}), 1e-12);
    }
}

TEST(ConstructOps, SwingMatchesItsFormula) {
    const json r = handle_request(
        {{"op", "swing"}, {"profile", kProfile}, {"trajectory", kQuarter}, {"scale", 0.5}});
    expect_ok(r);
    const geom::Surface s = surface(r["surface"]);
    const geom::Curve P = curve(kProfile), T = curve(kQuarter);
    for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 8; ++j) {
            const glm::dvec3 p = at(P, i / 8.0), t = at(T, j / 8.0);
            const glm::dvec3 want{0.5 * p.x * t.x, 0.5 * p.x * t.y, p.z};
            EXPECT_LT(glm::distance(*geom::surface_point(s, 2 + i / 4.0, j / 8.0), want), 1e-12);
        }
}

TEST(ConstructOps, SweepMatchesItsFormula) {
    const json r = handle_request({{"op", "sweep"}, {"profile", kProfile}, {"trajectory", kWavy}});
    expect_ok(r);
    const geom::Surface s = surface(r["surface"]);
    const geom::Curve P = curve(kProfile), T = curve(kWavy);
    for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 8; ++j) {
            const glm::dvec3 want = at(P, i / 8.0) + at(T, j / 8.0) - at(T, 0);
            EXPECT_LT(glm::distance(*geom::surface_point(s, 2 + i / 4.0, j / 8.0), want), 1e-12);
        }
}

TEST(ConstructOps, SkinReturnsItsParameters) {
    json arch2 = kArch, arch3 = kArch;
    for (auto& p : arch2["points"]) p[1] = 2;
    for (auto& p : arch3["points"]) p[1] = 3, p[2] = p[2].get<double>() * 2;
    const json curves = {kArch, arch2, arch3};
    json r = handle_request({{"op", "skin"}, {"curves", curves}});
    expect_ok(r);
    EXPECT_EQ(r["surface"]["degree"], json({2, 2})); // default min(3, 3 - 1)
    ASSERT_EQ(r["params"].size(), 3u);
    EXPECT_EQ(r["params"][0], 0.0);
    EXPECT_EQ(r["params"][2], 1.0);
    const geom::Surface s = surface(r["surface"]);
    for (int k = 0; k < 3; ++k) {
        const geom::Curve c = curve(curves[k]);
        for (int i = 0; i <= 10; ++i) {
            const glm::dvec3 S = *geom::surface_point(s, i / 10.0, r["params"][k].get<double>());
            EXPECT_LT(glm::distance(S, at(c, i / 10.0)), 1e-12);
        }
    }
    r = handle_request(
        {{"op", "skin"}, {"curves", curves}, {"degree", 1}, {"parametrization", "uniform"}});
    expect_ok(r);
    EXPECT_EQ(r["params"], json({0.0, 0.5, 1.0}));
    EXPECT_EQ(r["surface"]["degree"], json({2, 1}));
    r = handle_request(
        {{"op", "skin"}, {"curves", curves}, {"degree", 2.0}, {"parametrization", "centripetal"}});
    expect_ok(r);
}

TEST(ConstructOps, SchemaErrors) {
    expect_error({{"op", "make_compatible"}}, "schema", "/curves");
    expect_error({{"op", "make_compatible"}, {"curves", kLine}}, "schema", "/curves");
    expect_error({{"op", "make_compatible"}, {"curves", {kLine}}}, "schema", "/curves");
    expect_error({{"op", "make_compatible"}, {"curves", {kLine, kArch}}, {"degree", 2}}, "schema",
                 "/degree");
    expect_error({{"op", "ruled"}, {"curves", {kLine, kArch, kWavy}}}, "schema", "/curves");
    expect_error({{"op", "ruled"}, {"curves", {kLine, 3}}}, "schema", "/curves/1");
    expect_error({{"op", "revolve"}}, "schema", "/curve");
    expect_error({{"op", "revolve"}, {"curve", kArch}, {"angle", 0}}, "schema", "/angle");
    expect_error({{"op", "revolve"}, {"curve", kArch}, {"angle", -90}}, "schema", "/angle");
    expect_error({{"op", "revolve"}, {"curve", kArch}, {"angle", 360.5}}, "schema", "/angle");
    expect_error({{"op", "revolve"}, {"curve", kArch}, {"angle", "90"}}, "schema", "/angle");
    expect_error({{"op", "revolve"}, {"curve", kArch}, {"direction", "u"}}, "schema", "/direction");
    expect_error({{"op", "swing"}, {"profile", kArch}}, "schema", "/trajectory");
    expect_error({{"op", "swing"}, {"trajectory", kQuarter}}, "schema", "/profile");
    expect_error({{"op", "swing"}, {"profile", kArch}, {"trajectory", kQuarter}, {"scale", true}},
                 "schema", "/scale");
    expect_error({{"op", "sweep"}, {"profile", kArch}, {"trajectory", kWavy}, {"scale", 2}},
                 "schema", "/scale");
    expect_error({{"op", "skin"}, {"curves", {kArch}}}, "schema", "/curves");
    expect_error({{"op", "skin"}, {"curves", {kLine, kArch, kWavy}}, {"degree", 0}}, "schema",
                 "/degree");
    expect_error({{"op", "skin"}, {"curves", {kLine, kArch, kWavy}}, {"degree", 3}}, "schema",
                 "/degree");
    expect_error({{"op", "skin"}, {"curves", {kLine, kArch, kWavy}}, {"degree", 1.5}}, "schema",
                 "/degree");
    expect_error({{"op", "skin"}, {"curves", {kLine, kArch}}, {"parametrization", "arc"}}, "schema",
                 "/parametrization");
    expect_error({{"op", "skin"}, {"curves", {kLine, kArch}}, {"parametrization", 1}}, "schema",
                 "/parametrization");
}

TEST(ConstructOps, CurveErrorsArePathedInsideTheRequest) {
    json bad_knots = kWavy;
    bad_knots["knots"][5] = 0.2;
    expect_error({{"op", "skin"}, {"curves", {kLine, kArch, bad_knots}}}, "knots",
                 "/curves/2/knots/5");
    json bad_degree = kArch;
    bad_degree["degree"] = 5;
    expect_error({{"op", "make_compatible"}, {"curves", {bad_degree, kArch}}}, "degree",
                 "/curves/0/degree");
    json bad_weight = kQuarter;
    bad_weight["weights"] = {1, 2};
    expect_error({{"op", "swing"}, {"profile", kProfile}, {"trajectory", bad_weight}}, "weights",
                 "/trajectory/weights");
    expect_error({{"op", "revolve"}, {"curve", {{"degree", 1}}}}, "schema", "/curve/points");
}

TEST(ConstructOps, GeometryErrors) {
    // Off the plane the construction needs: the first offending control point.
    json off = kProfile;
    off["points"][2][1] = 0.25;
    off["points"][3][1] = 0.5;
    expect_error({{"op", "swing"}, {"profile", off}, {"trajectory", kQuarter}}, "geometry",
                 "/profile/points/2");
    json lifted = kQuarter;
    lifted["points"][1] = {1, 1, 0.1};
    expect_error({{"op", "swing"}, {"profile", kProfile}, {"trajectory", lifted}}, "geometry",
                 "/trajectory/points/1");
    // A 2D trajectory is in the xy-plane; a 2D profile is off the xz-plane where y != 0.
    expect_error({{"op", "swing"}, {"profile", kWavy}, {"trajectory", kQuarter}}, "geometry",
                 "/profile/points/0");
    // Coincident sections.
    expect_error({{"op", "skin"}, {"curves", {kArch, kArch}}}, "geometry", "/curves");
    json arch2 = kArch;
    for (auto& p : arch2["points"]) p[1] = 2;
    expect_error({{"op", "skin"}, {"curves", {kArch, arch2, arch2}}}, "geometry", "/curves/2");
    expect_error(
        {{"op", "skin"}, {"curves", {kArch, arch2, arch2}}, {"parametrization", "centripetal"}},
        "geometry", "/curves/2");
    expect_ok(handle_request(
        {{"op", "skin"}, {"curves", {kArch, arch2, arch2}}, {"parametrization", "uniform"}}));
}

TEST(ConstructOps, WeightsErrorForAPointAtInfinity) {
    // Weights 1 and -1: merging the other curve's knot 0.5 needs a point at infinity.
    const json signed_line = json::parse(
        R"({"type": "nurbs", "degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 0]], "weights": [1, -1]})");
    const json kinked = json::parse(
        R"({"degree": 1, "knots": [0, 0, 0.5, 1, 1], "points": [[0, 1], [1, 2], [2, 1]]})");
    expect_error({{"op", "ruled"}, {"curves", {kinked, signed_line}}}, "weights", "/curves/1");
    expect_error({{"op", "make_compatible"}, {"curves", {signed_line, kinked}}}, "weights",
                 "/curves/0");
}

TEST(ConstructOps, LimitOnTheResultSize) {
    // 2000 x 1000 control points: each curve is fine, the surface is above 1,000,000.
    auto polyline = [](int n, int axis) {
        json c = {{"degree", 1}, {"points", json::array()}, {"knots", json::array({0})}};
        for (int i = 0; i < n; ++i) {
            json p = {0, 0, 0};
            p[axis] = i;
            c["points"].push_back(p);
            c["knots"].push_back(i);
        }
        c["knots"].push_back(n - 1);
        return c;
    };
    const json long_curve = polyline(2000, 0), other = polyline(1000, 1);
    expect_error({{"op", "sweep"}, {"profile", long_curve}, {"trajectory", other}}, "limit",
                 nullptr);
}

TEST(ConstructOps, BatchExitStatus) {
    std::istringstream in(json::array({{{"op", "ruled"}, {"curves", {kLine, kArch}}},
                                       {{"op", "revolve"}, {"curve", kArch}, {"angle", 400}}})
                              .dump());
    std::ostringstream out, err;
    EXPECT_EQ(isoparm::protocol::run_protocol(in, out, err), 1);
    const json r = json::parse(out.str());
    ASSERT_EQ(r.size(), 2u);
    EXPECT_TRUE(r[0]["ok"].get<bool>());
    EXPECT_EQ(r[1]["error"]["path"], "/angle");
}
