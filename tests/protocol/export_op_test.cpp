// The export op: IGES records read back to the same numbers, the positive-weight rule, OBJ
// free-form and mesh formats with the counts their headers promise.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "core/exchange/real_text.hpp"
#include "core/protocol/protocol.hpp"

namespace {

using nlohmann::json;
using namespace isoparm;

const json surface = {
    {"type", "nurbs"},
    {"degree", {1, 2}},
    {"knots", {{0, 0, 1, 1}, {0, 0, 0, 1, 1, 1}}},
    {"points", {{{0, 0, 0}, {0, 1, 1}, {0, 2, 0}}, {{1, 0, 0}, {1, 1, 1}, {1, 2, 1e-5}}}},
    {"weights", {{1, 0.5, 1}, {1, 2, 1}}}};

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

TEST(RealText, ShortestDigitsWithAPointAndAnUpperCaseExponent) {
    EXPECT_EQ(exchange::real_text(0.5), "0.5");
    EXPECT_EQ(exchange::real_text(3), "3.0");
    EXPECT_EQ(exchange::real_text(-0.0), "0.0");
    EXPECT_EQ(exchange::real_text(1e-5), "1.0E-05");
    EXPECT_EQ(exchange::real_text(1.5e16), "1.5E+16");
    EXPECT_EQ(std::stod(exchange::real_text(0.1 + 0.2)), 0.1 + 0.2);
}

TEST(ExportOp, IgesHasEightyColumnRecordsAndTheSurfacesNumbers) {
    const json a =
        protocol::handle_request({{"op", "export"}, {"surface", surface}, {"format", "iges"}});
    ASSERT_TRUE(a["ok"].get<bool>()) << a.dump();
    const auto lines = lines_of(a["text"].get<std::string>());
    std::string parameters;
    for (const std::string& line : lines) {
        ASSERT_EQ(line.size(), 80u) << line;
        if (line[72] == 'P') parameters += line.substr(0, 64);
    }
    EXPECT_EQ(lines.back()[72], 'T');
    // Entity 128: K1, K2, M1, M2, 5 flags (PROP3 = 0: rational), knots, weights u-fastest.
    std::vector<std::string> tokens;
    std::istringstream in(parameters.substr(0, parameters.find(';')));
    for (std::string t; std::getline(in, t, ',');)
        tokens.push_back(t.substr(t.find_first_not_of(' ')));
    ASSERT_EQ(tokens.size(), 10u + 4 + 6 + 6 + 18 + 4);
    EXPECT_EQ(tokens[0], "128");
    EXPECT_EQ(tokens[7], "0");
    EXPECT_EQ(std::stod(tokens[10 + 10 + 2]), 0.5);       // W(0, 1)
    EXPECT_EQ(std::stod(tokens[10 + 10 + 3]), 2.0);       // W(1, 1)
    EXPECT_EQ(std::stod(tokens[10 + 10 + 6 + 17]), 1e-5); // Z(1, 2)
}

TEST(ExportOp, ExactFormatsRefuseWeightsThatAreNotPositive) {
    json s = surface;
    s["weights"][1][2] = -1;
    const json a = protocol::handle_request({{"op", "export"}, {"surface", s}, {"format", "iges"}});
    EXPECT_EQ(a["error"]["code"], "weights");
    EXPECT_EQ(a["error"]["path"], "/surface/weights/1/2");
    // A mesh of the same surface is fine.
    const json m = protocol::handle_request(
        {{"op", "export"}, {"surface", s}, {"format", "ply"}, {"samples", {4, 5}}});
    EXPECT_TRUE(m["ok"].get<bool>()) << m.dump();
}

TEST(ExportOp, ObjFreeformListsControlVerticesWithWeights) {
    const json a =
        protocol::handle_request({{"op", "export"}, {"surface", surface}, {"format", "obj"}});
    const std::string text = a["text"].get<std::string>();
    EXPECT_NE(text.find("cstype rat bspline\ndeg 1 2\nsurf 0.0 1.0 0.0 1.0 1 2 3 4 5 6\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("v 0.0 1.0 1.0 0.5\n"), std::string::npos); // P(0, 1), weight 0.5
    EXPECT_NE(text.find("parm v 0.0 0.0 0.0 1.0 1.0 1.0\n"), std::string::npos);
}

TEST(ExportOp, MeshFormatsHoldTheGrid) {
    const json ply = protocol::handle_request(
        {{"op", "export"}, {"surface", surface}, {"format", "ply"}, {"samples", {4, 5}}});
    const std::string text = ply["text"].get<std::string>();
    EXPECT_NE(text.find("element vertex 20\n"), std::string::npos);
    EXPECT_NE(text.find("element face 24\n"), std::string::npos);
    const json stl = protocol::handle_request(
        {{"op", "export"}, {"surface", surface}, {"format", "stl_ascii"}, {"samples", {3, 3}}});
    const std::string s = stl["text"].get<std::string>();
    std::size_t facets = 0;
    for (std::size_t at = s.find("facet normal"); at != std::string::npos;
         at = s.find("facet normal", at + 1))
        ++facets;
    EXPECT_EQ(facets, 8u);
    const json tri = protocol::handle_request(
        {{"op", "export"},
         {"triangle",
          {{"type", "triangle_bezier"}, {"degree", 1}, {"points", {{0, 0}, {1, 0}, {0, 1}}}}},
         {"format", "obj_mesh"},
         {"samples", {2, 2}}});
    const std::string o = tri["text"].get<std::string>();
    std::size_t faces = 0;
    for (const std::string& line : lines_of(o)) faces += line.rfind("f ", 0) == 0;
    EXPECT_EQ(faces, 4u); // 2^2 triangles
    const json curve_mesh = protocol::handle_request(
        {{"op", "export"},
         {"curve", {{"degree", 1}, {"knots", {0, 0, 1, 1}}, {"points", {{0, 0}, {1, 1}}}}},
         {"format", "ply"}});
    EXPECT_EQ(curve_mesh["error"]["path"], "/format");
}

// STEP through the op: the writer's file (tests/exchange/step_writer_test.cpp checks its
// records), and the positive-weight rule at the request's path.
TEST(ExportOp, StepAnswersAFileAndRefusesANonPositiveWeight) {
    const nlohmann::json surface = {{"type", "bspline"},
                                    {"degree", {1, 1}},
                                    {"knots", {{0, 0, 1, 1}, {0, 0, 1, 1}}},
                                    {"points", {{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 1}}}}};
    const auto a =
        protocol::handle_request({{"op", "export"}, {"surface", surface}, {"format", "step"}});
    ASSERT_TRUE(a["ok"].get<bool>()) << a.dump();
    const std::string text = a["text"].get<std::string>();
    EXPECT_EQ(text.rfind("ISO-10303-21;\nHEADER;\n", 0), 0u);
    EXPECT_EQ(text.substr(text.size() - 26), "ENDSEC;\nEND-ISO-10303-21;\n");
    nlohmann::json bad = surface;
    bad["type"] = "nurbs";
    bad["weights"] = {{1, 1}, {-2, 1}};
    const auto b =
        protocol::handle_request({{"op", "export"}, {"surface", bad}, {"format", "step"}});
    ASSERT_FALSE(b["ok"].get<bool>());
    EXPECT_EQ(b["error"]["code"], "weights") << b.dump();
    EXPECT_EQ(b["error"]["path"], "/surface/weights/1/0");
}

} // namespace
