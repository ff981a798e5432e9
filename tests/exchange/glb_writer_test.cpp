// The glTF binary writer: a GLB container (header, JSON chunk, BIN chunk) holding a welded
// torus. The Khronos validator checks the files themselves (cli_export_gltf_validator).
#include <gtest/gtest.h>

#include "core/exchange/glb_writer.hpp"
#include "core/exchange/mesh_weld.hpp"
#include "core/geom/construct.hpp"
#include "core/geom/primitives.hpp"

namespace {

TEST(GlbWriter, AGlbContainerWithAJsonAndABinaryChunk) {
    const auto circle = isoparm::geom::full_circle({3, 0, 0}, 1, isoparm::geom::Plane::xz);
    ASSERT_TRUE(circle);
    isoparm::geom::Mesh torus =
        isoparm::geom::tessellate(*isoparm::geom::revolve(*circle, 360), 9, 17);
    isoparm::exchange::weld(torus);
    const auto bytes = isoparm::exchange::glb_bytes({torus}, "torus");
    ASSERT_TRUE(bytes) << bytes.error().message;
    auto u32 = [&](std::size_t at) {
        std::uint32_t u = 0;
        for (int k = 0; k < 4; ++k)
            u |= std::uint32_t(static_cast<unsigned char>((*bytes)[at + k])) << (8 * k);
        return u;
    };
    // GLB header: magic "glTF", version 2, total length; then the JSON chunk ("JSON").
    EXPECT_EQ(bytes->substr(0, 4), "glTF");
    EXPECT_EQ(u32(4), 2u);
    EXPECT_EQ(u32(8), bytes->size());
    EXPECT_EQ(bytes->substr(16, 4), "JSON");
    const std::string json = bytes->substr(20, u32(12));
    EXPECT_NE(json.find("\"POSITION\""), std::string::npos);
    EXPECT_NE(json.find("\"NORMAL\""), std::string::npos);
    EXPECT_NE(json.find("\"max\""), std::string::npos);
    // The binary chunk: positions, normals (12 bytes a vertex each), indices (12 a triangle).
    const std::size_t bin = 20 + u32(12);
    EXPECT_EQ(bytes->substr(bin + 4, 3), "BIN");
    EXPECT_GE(u32(bin), 24 * torus.positions.size() + 12 * torus.triangles.size());
}

} // namespace
