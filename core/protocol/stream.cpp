// Mesh answers written as text, chunk by chunk (see stream.hpp).
#include "core/protocol/stream.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <memory>
#include <ostream>
#include <string_view>

#include "core/json/writer.hpp"
#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

void flush_if_full(std::string& buffer, std::ostream& out) {
    if (buffer.size() < stream_chunk_bytes) return;
    out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    buffer.clear();
}

bool writable_point(const glm::dvec3& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

void append_point(std::string& buffer, const glm::dvec3& p, bool exists) {
    if (!exists || !writable_point(p)) {
        buffer += "null";
        return;
    }
    buffer += '[';
    append_double(buffer, p.x);
    buffer += ", ";
    append_double(buffer, p.y);
    buffer += ", ";
    append_double(buffer, p.z);
    buffer += ']';
}

namespace {

void append_index(std::string& buffer, std::uint32_t k) {
    std::array<char, 16> digits{};
    const auto res = std::to_chars(digits.data(), digits.data() + digits.size(), k);
    buffer.append(digits.data(), static_cast<std::size_t>(res.ptr - digits.data()));
}

template <class AppendOne>
void append_array(std::string& buffer, std::ostream& out, std::size_t count, AppendOne one) {
    buffer += '[';
    for (std::size_t k = 0; k < count; ++k) {
        if (k > 0) buffer += ", ";
        one(k);
        flush_if_full(buffer, out);
    }
    buffer += ']';
}

// A mesh op's answer: the mesh, kept until it is written.
template <geom::Expected<geom::Mesh> (*make)(const nlohmann::json&)>
geom::Expected<StreamedAnswer> streamed_mesh(const nlohmann::json& request) {
    geom::Expected<geom::Mesh> mesh = make(request);
    if (!mesh) return mesh.error();
    auto kept = std::make_shared<const geom::Mesh>(std::move(mesh).value());
    return StreamedAnswer(
        [kept](std::string& buffer, std::ostream& out) { write_mesh_answer(*kept, buffer, out); });
}

} // namespace

StreamedOp streamed_op_of(const nlohmann::json& request) {
    if (!request.is_object()) return nullptr;
    const auto op = request.find("op");
    if (op == request.end() || !op->is_string()) return nullptr;
    const std::string& name = op->get_ref<const std::string&>();
    if (name == "tessellate") return streamed_mesh<protocol::tessellate_mesh>;
    if (name == "polygonize") return streamed_mesh<protocol::polygonize_mesh>;
    // A triangle's evaluation is answered as a tree (op_triangle.cpp), not streamed.
    if (name == "evaluate" && !request.contains("triangle")) return protocol::streamed_evaluate;
    return nullptr;
}

void write_mesh_answer(const geom::Mesh& mesh, std::string& buffer, std::ostream& out) {
    const auto exists = [&](std::size_t k) { return mesh.exists.empty() || mesh.exists[k]; };
    // Members in write_json's order for this answer: ok, positions, normals, triangles.
    buffer += "{\"ok\": true, \"positions\": ";
    append_array(buffer, out, mesh.positions.size(),
                 [&](std::size_t k) { append_point(buffer, mesh.positions[k], exists(k)); });
    buffer += ", \"normals\": ";
    append_array(buffer, out, mesh.positions.size(),
                 [&](std::size_t k) { append_point(buffer, mesh.normals[k], exists(k)); });
    buffer += ", \"triangles\": ";
    append_array(buffer, out, mesh.triangles.size(), [&](std::size_t k) {
        const auto& t = mesh.triangles[k];
        buffer += '[';
        append_index(buffer, t[0]);
        buffer += ", ";
        append_index(buffer, t[1]);
        buffer += ", ";
        append_index(buffer, t[2]);
        buffer += ']';
    });
    buffer += '}';
}

} // namespace isoparm::protocol
