#include "core/exchange/stl_binary.hpp"

#include <bit>
#include <cstdint>
#include <glm/geometric.hpp>

namespace isoparm::exchange {

namespace {

// Little-endian whatever the host's byte order: the bytes are shifted out one by one.
void put_u32(std::string& out, std::uint32_t x) {
    for (int k = 0; k < 4; ++k) out += static_cast<char>((x >> (8 * k)) & 0xff);
}

void put_vector(std::string& out, const glm::dvec3& v) {
    for (int a = 0; a < 3; ++a)
        put_u32(out, std::bit_cast<std::uint32_t>(static_cast<float>(v[a])));
}

} // namespace

std::string stl_binary_bytes(const std::vector<geom::Mesh>& meshes, const std::string& name) {
    std::string header = "isoparm binary STL: " + name;
    header.resize(80, ' ');
    std::size_t count = 0;
    for (const geom::Mesh& m : meshes) count += m.triangles.size();
    std::string out = header;
    out.reserve(84 + 50 * count);
    put_u32(out, static_cast<std::uint32_t>(count));
    for (const geom::Mesh& m : meshes)
        for (const auto& t : m.triangles) {
            const glm::dvec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
            const glm::dvec3 n = glm::cross(b - a, c - a);
            const double length = glm::length(n);
            put_vector(out, length > 0 ? n / length : glm::dvec3(0.0));
            put_vector(out, a);
            put_vector(out, b);
            put_vector(out, c);
            out += std::string(2, '\0'); // attribute byte count
        }
    return out;
}

} // namespace isoparm::exchange
