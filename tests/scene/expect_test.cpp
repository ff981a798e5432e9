// Expectations at a parameter: the point there, a basis function, their sum and the
// curvatures, with their refusals when written without what they need.
#include <gtest/gtest.h>

#include "core/geom/basis.hpp"
#include "core/geom/curvature.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/trim/trim.hpp"
#include "core/scene/expect.hpp"

using namespace isoparm;
using nlohmann::json;

namespace {

scene::ExpectStep read(const char* text) {
    auto e = scene::expect_from_json(json::parse(text), "/expect");
    EXPECT_TRUE(e.ok()) << text << ": " << (e ? "" : e.error().message);
    return e ? *e : scene::ExpectStep{};
}

TEST(Expect, ValuesAtAParameterHoldAndSayHowTheyDiffer) {
    const doc::Document d = doc::default_document();
    const geom::Surface& s = *d.objects[0].surface();
    const glm::dvec3 p = *geom::surface_point(s, 0.3, 0.6);
    const double r22 = *geom::rational_basis_ij(s, 2, 2, 0.3, 0.6);
    const double K = geom::surface_curvature(s, 0.3, 0.6)->gaussian;
    scene::ExpectStep e;
    e.id = 1;
    e.at = glm::dvec2(0.3, 0.6);
    e.position = p;
    e.basis_sum = 1;
    e.i = 2;
    e.j = 2;
    e.basis = r22;
    e.position.reset(); // with a point named, position would be the control point's
    e.gaussian = K;
    EXPECT_TRUE(scene::unmet_expectations(e, d).empty());
    scene::ExpectStep at_point;
    at_point.id = 1;
    at_point.at = glm::dvec2(0.3, 0.6);
    at_point.position = p;
    EXPECT_TRUE(scene::unmet_expectations(at_point, d).empty());
    at_point.position = p + glm::dvec3(0, 0, 0.01);
    const auto unmet = scene::unmet_expectations(at_point, d);
    ASSERT_EQ(unmet.size(), 1u);
    EXPECT_NE(unmet[0].find("expected the point of 'hill' at (u, v) = (0.3, 0.6)"),
              std::string::npos)
        << unmet[0];
    e.basis = r22 + 0.1;
    e.basis_sum = 0.9;
    const auto two = scene::unmet_expectations(e, d);
    ASSERT_EQ(two.size(), 2u);
    EXPECT_NE(two[0].find("sum to 0.9"), std::string::npos) << two[0];
    EXPECT_NE(two[1].find("expected R2,2 of 'hill'"), std::string::npos) << two[1];
    scene::ExpectStep outside;
    outside.id = 1;
    outside.at = glm::dvec2(1.5, 0.5);
    outside.basis_sum = 1;
    EXPECT_EQ(scene::unmet_expectations(outside, d),
              std::vector<std::string>{"(u, v) = (1.5, 0.5) is outside the domain of 'hill'"});
}

TEST(Expect, KindAndTheJsonFormReadBack) {
    const doc::Document d = doc::default_document();
    const scene::ExpectStep e = read(
        R"({"id": 1, "kind": "surface", "at": [0.5, 0.5], "basis_sum": 1, "tolerance": 1e-12})");
    EXPECT_TRUE(scene::unmet_expectations(e, d).empty());
    const json back = scene::expect_to_json(e);
    EXPECT_EQ(back, json::parse(R"({"id": 1, "kind": "surface", "at": [0.5, 0.5],
                                    "basis_sum": 1, "tolerance": 1e-12})"));
    const scene::ExpectStep curve = read(R"({"id": 1, "kind": "curve"})");
    EXPECT_EQ(scene::unmet_expectations(curve, d),
              std::vector<std::string>{"expected 'hill' to be a curve, it is a surface"});
}

// "side": where (u, v) lies against a surface's trim; an untrimmed surface keeps everything.
TEST(Expect, TheSideOfATrimHoldsAndSaysWhereThePointIs) {
    doc::Document d = doc::default_document();
    const scene::ExpectStep kept = read(R"({"id": 1, "at": [0.5, 0.5], "side": "kept"})");
    EXPECT_TRUE(scene::unmet_expectations(kept, d).empty());
    auto& surface = std::get<doc::SurfaceObject>(d.objects[0].shape);
    surface.trim.holes.push_back(*geom::circle_loop({0.5, 0.5}, 0.2, true));
    EXPECT_EQ(scene::unmet_expectations(kept, d),
              std::vector<std::string>{"expected (u, v) = (0.5, 0.5) to be kept on 'hill', it "
                                       "is cut"});
    EXPECT_TRUE(scene::unmet_expectations(read(R"({"id": 1, "at": [0.5, 0.5], "side": "cut"})"), d)
                    .empty());
    EXPECT_TRUE(
        scene::unmet_expectations(read(R"({"id": 1, "at": [0.7, 0.5], "side": "boundary"})"), d)
            .empty());
    EXPECT_EQ(scene::expect_to_json(kept)["side"], "kept");
}

TEST(Expect, WhatAnExpectationNeedsIsRefusedWithTheMemberToAdd) {
    struct Case {
        const char* text;
        const char* words;
    };
    for (const Case& c : {Case{R"({"id": 1, "basis_sum": 1})", "add \"at\""},
                          Case{R"({"id": 1, "at": [0.5, 0.5], "basis": 0.2})", "add \"point\""},
                          Case{R"({"at": [0.5, 0.5], "gaussian": 0})", "add \"id\""},
                          Case{R"({"id": 1, "at": [0.1, 0.2, 0.3]})", "[u, v]"},
                          Case{R"({"id": 1, "kind": "blob"})", "surface, curve"},
                          Case{R"({"id": 1, "side": "cut"})", "add \"at\""},
                          Case{R"({"id": 1, "at": [0.5, 0.5], "side": "in"})", "kept, cut"},
                          Case{R"({"id": 1, "at": [0.5, 0.5], "point": [1, 1],
                                   "position": [0, 0, 0]})",
                               "leave out"}}) {
        auto e = scene::expect_from_json(json::parse(c.text), "/expect");
        ASSERT_FALSE(e.ok()) << c.text;
        EXPECT_NE(e.error().message.find(c.words), std::string::npos) << e.error().message;
    }
}

} // namespace
