// Streamed mesh answers (stream.hpp) are byte for byte the text write_json gives for
// the same answer as a JSON tree: missing vertices, non-finite values, empty meshes, answers
// longer than a chunk, and the whole text path against handle_request.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "core/json/writer.hpp"
#include "core/protocol/protocol.hpp"
#include "core/protocol/detail.hpp"
#include "core/protocol/stream.hpp"

using nlohmann::json;
using namespace isoparm;

namespace {

std::string as_tree_text(const geom::Mesh& mesh) {
    json answer = protocol::mesh_to_json(mesh);
    answer["ok"] = true;
    std::string text;
    json_io::write_json(text, answer);
    return text;
}

std::string as_streamed_text(const geom::Mesh& mesh) {
    std::ostringstream out;
    std::string buffer;
    protocol::write_mesh_answer(mesh, buffer, out);
    out << buffer;
    return out.str();
}

TEST(ProtocolStream, AMeshIsWrittenExactlyAsItsJsonTree) {
    geom::Mesh mesh;
    const double inf = std::numeric_limits<double>::infinity();
    mesh.positions = {{0, -0.0, 1.5}, {1e-300, 2, 3}, {0, 0, 0}, {inf, 1, 1}};
    mesh.normals = {{0, 0, 1}, {0.6, 0.8, 0}, {0, 0, 0}, {0, 0, 1}};
    mesh.exists = {1, 1, 0, 1}; // vertex 2 does not exist; vertex 3 is beyond doubles
    mesh.triangles = {{0, 1, 3}, {4294967295u, 0, 1}};
    EXPECT_EQ(as_streamed_text(mesh), as_tree_text(mesh));
    mesh.exists.clear();
    EXPECT_EQ(as_streamed_text(mesh), as_tree_text(mesh));
    EXPECT_EQ(as_streamed_text(geom::Mesh{}), as_tree_text(geom::Mesh{}));
}

TEST(ProtocolStream, AnswersLongerThanAChunkAreWrittenWhole) {
    geom::Mesh mesh;
    for (int k = 0; k < 60000; ++k) {
        mesh.positions.push_back({k * 0.1, std::sin(k), -k / 7.0});
        mesh.normals.push_back({0, 0, 1});
        if (k >= 2) mesh.triangles.push_back({static_cast<std::uint32_t>(k - 2), 0, 1});
    }
    const std::string streamed = as_streamed_text(mesh);
    ASSERT_GT(streamed.size(), protocol::stream_chunk_bytes);
    EXPECT_EQ(streamed, as_tree_text(mesh));
}

// The text path (which streams) and handle_request + write_json (which does not) agree, for
// the mesh ops and evaluate (curves and surfaces, every derivative order, normals, points that
// do not exist), alone and in a batch, errors included.
TEST(ProtocolStream, TheTextPathAgreesWithHandleRequest) {
    const json hill = {{"type", "nurbs"},
                       {"degree", {2, 2}},
                       {"points",
                        {{{0, 0, 0}, {0, 1, 0}, {0, 2, 0}},
                         {{1, 0, 0}, {1, 1, 2}, {1, 2, 0}},
                         {{2, 0, 0}, {2, 1, 0}, {2, 2, 0}}}},
                       {"knots", {{0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}}},
                       {"weights", {{1, 1, 1}, {1, 0, 1}, {1, 1, 1}}}};
    // The middle weight is negative: at t = 0.5 the denominator is zero and the point does not
    // exist (null), and the derivatives around it are large.
    const json curve = {{"type", "nurbs"},
                        {"degree", 2},
                        {"knots", {0, 0, 0, 1, 1, 1}},
                        {"points", {{0, 0, 0}, {1, 2, 0}, {2, 0, 0}}},
                        {"weights", {1, -1, 1}}};
    const json requests = json::array(
        {{{"op", "tessellate"}, {"surface", hill}, {"samples", {7, 5}}},
         {{"op", "polygonize"},
          {"implicit", "x^2 + y^2 + z^2 - 1"},
          {"bounds", {{-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5}}},
          {"cell", 0.25}},
         {{"op", "tessellate"}, {"surface", hill}, {"samples", {1, 5}}},
         {{"op", "evaluate"},
          {"surface", hill},
          {"params", {{0, 0}, {0.5, 0.5}, {0.3, 0.9}, {1, 1}}}},
         {{"op", "evaluate"},
          {"surface", hill},
          {"params", {{0, 0}, {0.5, 0.5}, {0.3, 0.9}, {1, 1}}},
          {"derivatives", 3},
          {"normals", true}},
         {{"op", "evaluate"},
          {"surface", hill},
          {"params", {{0.5, 0.5}, {0.2, 0.7}}},
          {"normals", true}},
         {{"op", "evaluate"}, {"surface", hill}, {"params", {{0.5, 0.5}}}, {"derivatives", 1}},
         {{"op", "evaluate"}, {"curve", curve}, {"params", {0, 0.25, 0.5, 0.75, 1}}},
         {{"op", "evaluate"},
          {"curve", curve},
          {"params", {0, 0.25, 0.5, 0.75, 1}},
          {"derivatives", 2}},
         {{"op", "evaluate"}, {"curve", curve}, {"params", {2.0}}},
         {{"op", "evaluate"}, {"curve", curve}, {"params", json::array()}, {"derivatives", 3}},
         {{"op", "polygonize"},
          {"implicit", "x +"},
          {"bounds", {{0, 0, 0}, {1, 1, 1}}},
          {"cell", 0.5}}});
    std::string expected_batch = "[";
    for (std::size_t k = 0; k < requests.size(); ++k) {
        std::string one;
        json_io::write_json(one, protocol::handle_request(requests[k]));
        std::ostringstream out, err;
        protocol::run_protocol_text(requests[k].dump(), out, err);
        EXPECT_EQ(out.str(), one + "\n") << k;
        expected_batch += (k ? ", " : "") + one;
    }
    std::ostringstream out, err;
    EXPECT_EQ(protocol::run_protocol_text(requests.dump(), out, err), 1);
    EXPECT_EQ(out.str(), expected_batch + "]\n");
}

} // namespace
