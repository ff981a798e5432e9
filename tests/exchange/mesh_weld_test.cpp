// Closed surfaces give closed meshes: a 360-degree revolution of a profile that meets the axis
// at both ends, a sphere and a torus, tessellated and welded, have every edge shared by exactly
// two triangles, in opposite directions (consistent orientation), and the Euler characteristic
// of their topology; the binary STL, OBJ and PLY files of them say the same.
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <glm/geometric.hpp>
#include <map>
#include <set>
#include <sstream>

#include "core/exchange/mesh_weld.hpp"
#include "core/exchange/obj_writer.hpp"
#include "core/exchange/stl_binary.hpp"
#include "core/geom/construct.hpp"
#include "core/geom/primitives.hpp"

namespace {

using namespace isoparm;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

// Every directed edge once, and its reverse once: a closed, consistently oriented 2-manifold
// edge structure. Returns "" or the first fault.
std::string closed_fault(const Triangles& triangles) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k) {
            if (t[k] == t[(k + 1) % 3]) return "a degenerate triangle";
            ++directed[{t[k], t[(k + 1) % 3]}];
        }
    for (const auto& [edge, count] : directed) {
        if (count != 1)
            return "edge " + std::to_string(edge.first) + "-" + std::to_string(edge.second) +
                   " runs the same way in " + std::to_string(count) + " triangles";
        if (!directed.count({edge.second, edge.first}))
            return "edge " + std::to_string(edge.first) + "-" + std::to_string(edge.second) +
                   " has one triangle";
    }
    return "";
}

int euler_characteristic(const Triangles& triangles) {
    std::set<std::uint32_t> vertices;
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k) {
            vertices.insert(t[k]);
            edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
        }
    return static_cast<int>(vertices.size()) - static_cast<int>(edges.size()) +
           static_cast<int>(triangles.size());
}

// The triangles of a binary STL, with vertices identified by their exact float bits.
Triangles stl_triangles(const std::string& bytes) {
    EXPECT_GE(bytes.size(), 84u);
    std::uint32_t count = 0;
    for (int k = 0; k < 4; ++k)
        count |= std::uint32_t(static_cast<unsigned char>(bytes[80 + k])) << (8 * k);
    EXPECT_EQ(bytes.size(), 84u + 50u * count);
    std::map<std::string, std::uint32_t> ids;
    Triangles out;
    for (std::uint32_t f = 0; f < count; ++f) {
        std::array<std::uint32_t, 3> t{};
        for (int v = 0; v < 3; ++v) {
            const std::string key = bytes.substr(84 + 50 * f + 12 + 12 * v, 12);
            t[v] = ids.emplace(key, static_cast<std::uint32_t>(ids.size())).first->second;
        }
        out.push_back(t);
    }
    return out;
}

Triangles obj_triangles(const std::string& text) {
    Triangles out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("f ", 0) != 0) continue;
        std::istringstream f(line.substr(2));
        std::array<std::uint32_t, 3> t{};
        for (auto& v : t) {
            std::string token;
            f >> token;
            v = static_cast<std::uint32_t>(std::stoul(token.substr(0, token.find('/'))));
        }
        out.push_back(t);
    }
    return out;
}

geom::Surface closed_vase() {
    geom::Curve profile;
    profile.type = geom::SplineType::bspline;
    profile.degree = 3;
    profile.points = {{0, 0, -1}, {1.5, 0, -1}, {0.5, 0, 0}, {1.2, 0, 1}, {0, 0, 1}};
    profile.weights.assign(5, 1.0);
    profile.knots = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
    return *geom::revolve(profile, 360);
}

void expect_closed(const char* name, const geom::Surface& s, int euler, int nu, int nv) {
    geom::Mesh mesh = geom::tessellate(s, nu, nv);
    EXPECT_NE(closed_fault(mesh.triangles), "") << name << ": the grid itself is open";
    const std::size_t merged = exchange::weld(mesh);
    EXPECT_GT(merged, 0u) << name;
    EXPECT_EQ(closed_fault(mesh.triangles), "") << name;
    EXPECT_EQ(euler_characteristic(mesh.triangles), euler) << name;
    EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
    // The files: binary STL (vertices by their float bits), OBJ, PLY.
    EXPECT_EQ(closed_fault(stl_triangles(exchange::stl_binary_bytes({mesh}, name))), "") << name;
    EXPECT_EQ(closed_fault(obj_triangles(exchange::obj_mesh_text({mesh}))), "") << name;
    const std::string ply = exchange::ply_text({mesh});
    EXPECT_NE(ply.find("element vertex " + std::to_string(mesh.positions.size()) + "\n"),
              std::string::npos);
    // Outward or inward, but the same everywhere: each triangle's normal agrees with the
    // welded vertex normals it carries.
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                        mesh.positions[t[2]] - mesh.positions[t[0]]);
        EXPECT_GT(glm::dot(n, mesh.normals[t[0]] + mesh.normals[t[1]] + mesh.normals[t[2]]), 0)
            << name;
    }
}

TEST(MeshWeld, ClosedRevolutionsAndATorusBecomeWatertightConsistentlyOrientedMeshes) {
    expect_closed("vase", closed_vase(), 2, 17, 33);
    const auto half = geom::circular_arc({0, 0, 0}, 2, -90, 90, geom::Plane::xz);
    ASSERT_TRUE(half);
    expect_closed("sphere", *geom::revolve(*half, 360), 2, 24, 48);
    const auto circle = geom::full_circle({3, 0, 0}, 1, geom::Plane::xz);
    ASSERT_TRUE(circle);
    expect_closed("torus", *geom::revolve(*circle, 360), 0, 20, 40);
}

TEST(MeshWeld, AnOpenGridKeepsEveryVertexAndItsBoundary) {
    const auto band = geom::revolve(geom::line_segment({1, 0, 0}, {2, 0, 1}), 90);
    ASSERT_TRUE(band);
    geom::Mesh mesh = geom::tessellate(*band, 5, 7);
    const geom::Mesh before = mesh;
    EXPECT_EQ(exchange::weld(mesh), 0u);
    EXPECT_EQ(mesh.positions, before.positions);
    EXPECT_EQ(mesh.triangles, before.triangles);
    EXPECT_EQ(euler_characteristic(mesh.triangles), 1); // a disc
}

TEST(StlBinary, HeaderCountAndLittleEndianFacets) {
    geom::Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}};
    m.normals.assign(3, {0, 0, 1});
    m.triangles = {{0, 1, 2}};
    const std::string bytes = exchange::stl_binary_bytes({m}, "tri");
    ASSERT_EQ(bytes.size(), 84u + 50u);
    EXPECT_EQ(bytes.substr(0, 24), "isoparm binary STL: tri ");
    EXPECT_NE(bytes.substr(0, 5), "solid");
    EXPECT_EQ(bytes.substr(80, 4), std::string("\x01\x00\x00\x00", 4));
    auto read_float = [&](std::size_t at) {
        std::uint32_t u = 0;
        for (int k = 0; k < 4; ++k)
            u |= std::uint32_t(static_cast<unsigned char>(bytes[at + k])) << (8 * k);
        return std::bit_cast<float>(u);
    };
    EXPECT_EQ(read_float(84 + 8), 1.0f);           // normal z
    EXPECT_EQ(read_float(84 + 12 + 24 + 4), 2.0f); // third vertex y
    EXPECT_EQ(bytes.substr(84 + 48, 2), std::string(2, '\0'));
}

} // namespace
