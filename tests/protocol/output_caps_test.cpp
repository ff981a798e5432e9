// The answer-size caps (docs/protocol.md, "Size caps"): meshes above max_mesh_vertices /
// max_mesh_triangles are `limit` errors, found before (tessellate) or while (polygonize) the
// mesh is built, so no request can make the answer grow without bound.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "core/geom/implicit/expression.hpp"
#include "core/geom/implicit/polygonize.hpp"
#include "core/protocol/protocol.hpp"

namespace {

using nlohmann::json;

json run(const std::string& text) {
    std::istringstream in(text);
    std::ostringstream out, err;
    const int status = isoparm::protocol::run_protocol(in, out, err);
    EXPECT_EQ(status, 1) << out.str();
    return json::parse(out.str());
}

const std::string kSurface =
    R"({"degree": [1, 1], "knots": [[0, 0, 1, 1], [0, 0, 1, 1]], "points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]})";

std::string tessellate(int nu, int nv) {
    return R"({"op": "tessellate", "surface": )" + kSurface + R"(, "samples": [)" +
           std::to_string(nu) + ", " + std::to_string(nv) + "]}";
}

TEST(OutputCaps, TessellationAboveTheVertexCap) {
    // 1001 x 1000 = 1,001,000 vertices: within the 10,000,000 evaluation points, above the mesh
    // cap.
    const json r = run(tessellate(1001, 1000));
    EXPECT_EQ(r["ok"], false);
    EXPECT_EQ(r["error"]["code"], "limit");
    EXPECT_EQ(r["error"]["path"], "/samples");
    const std::string message = r["error"]["message"];
    EXPECT_NE(message.find("1001000"), std::string::npos) << message;
    EXPECT_NE(message.find("1000000"), std::string::npos) << message;
}

TEST(OutputCaps, TheGigabyteTessellationIsRefused) {
    // 3162 x 3162 was valid and built ~6.7 GB of JSON.
    const json r = run(tessellate(3162, 3162));
    EXPECT_EQ(r["error"]["code"], "limit");
    EXPECT_EQ(r["error"]["path"], "/samples");
}

TEST(OutputCaps, ThinTessellationCountsVerticesNotSides) {
    const json r = run(tessellate(2, 500001));
    EXPECT_EQ(r["error"]["code"], "limit");
    EXPECT_EQ(r["error"]["path"], "/samples");
}

TEST(OutputCaps, RippledPolygonizationStopsAtTheCap) {
    // A 214^3 grid (9.8M points, within the evaluation cap) with the surface in almost every
    // cell: this grew to 24 GB before the cap; now it stops after a few planes.
    const json r = run(
        R"j({"op": "polygonize", "implicit": "sin(300*x)*sin(300*y)*sin(300*z)", "bounds": [[-1, -1, -1], [1, 1, 1]], "cell": 0.0094})j");
    EXPECT_EQ(r["ok"], false);
    EXPECT_EQ(r["error"]["code"], "limit");
    EXPECT_EQ(r["error"]["path"], "/cell");
    const std::string message = r["error"]["message"];
    EXPECT_NE(message.find("more than 1000000 vertices"), std::string::npos) << message;
}

using isoparm::geom::implicit::compile;
using isoparm::geom::implicit::polygonize;
using isoparm::geom::implicit::PolygonizeOptions;

PolygonizeOptions sphere_options(int threads) {
    PolygonizeOptions o;
    o.cell = 0.1;
    o.threads = threads;
    return o;
}

TEST(PolygonizeCaps, UnderTheCapsTheMeshIsWhole) {
    const auto f = compile("x^2 + y^2 + z^2 - 0.81");
    ASSERT_TRUE(f.ok());
    const auto mesh = polygonize(*f, sphere_options(1));
    ASSERT_TRUE(mesh.ok());
    EXPECT_GT(mesh->positions.size(), 500u);
    EXPECT_LT(mesh->positions.size(), isoparm::geom::max_mesh_vertices);
}

TEST(PolygonizeCaps, VertexCapStopsTheRunOnAnyThreadCount) {
    const auto f = compile("x^2 + y^2 + z^2 - 0.81");
    ASSERT_TRUE(f.ok());
    for (int threads : {1, 2, 4}) {
        PolygonizeOptions o = sphere_options(threads);
        o.max_vertices = 100;
        const auto mesh = polygonize(*f, o);
        ASSERT_FALSE(mesh.ok()) << threads;
        EXPECT_EQ(mesh.error().code, isoparm::geom::ErrorCode::limit);
        EXPECT_EQ(mesh.error().path, "/cell");
        EXPECT_NE(mesh.error().message.find("more than 100 vertices"), std::string::npos)
            << mesh.error().message;
    }
}

TEST(PolygonizeCaps, TriangleCapIsNamed) {
    const auto f = compile("x^2 + y^2 + z^2 - 0.81");
    ASSERT_TRUE(f.ok());
    PolygonizeOptions o = sphere_options(2);
    o.max_triangles = 50;
    const auto mesh = polygonize(*f, o);
    ASSERT_FALSE(mesh.ok());
    EXPECT_EQ(mesh.error().code, isoparm::geom::ErrorCode::limit);
    EXPECT_NE(mesh.error().message.find("more than 50 triangles"), std::string::npos)
        << mesh.error().message;
}

} // namespace
