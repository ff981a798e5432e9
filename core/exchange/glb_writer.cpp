#include "core/exchange/glb_writer.hpp"

#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <sstream>
#include <tiny_gltf.h>

namespace isoparm::exchange {

namespace {

void append_bytes(std::vector<unsigned char>& data, const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    data.insert(data.end(), b, b + n);
}

// A bufferView of `bytes` at the end of the buffer (4-byte aligned, as the GLB and the
// component types require) and an accessor over it. Returns the accessor's index.
int add_accessor(tinygltf::Model& model, const std::vector<unsigned char>& bytes, int target,
                 int component, int type, std::size_t count, std::vector<double> min = {},
                 std::vector<double> max = {}) {
    auto& data = model.buffers[0].data;
    data.resize((data.size() + 3) / 4 * 4, 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = bytes.size();
    view.target = target;
    data.insert(data.end(), bytes.begin(), bytes.end());
    model.bufferViews.push_back(view);
    tinygltf::Accessor a;
    a.bufferView = static_cast<int>(model.bufferViews.size()) - 1;
    a.byteOffset = 0;
    a.componentType = component;
    a.type = type;
    a.count = count;
    a.minValues = std::move(min);
    a.maxValues = std::move(max);
    model.accessors.push_back(a);
    return static_cast<int>(model.accessors.size()) - 1;
}

// Unit normals: a vertex normal that is not unit after rounding to float takes the geometric
// normal of a triangle using the vertex (or +z where none has an area).
std::vector<glm::vec3> unit_normals(const geom::Mesh& m) {
    std::vector<glm::vec3> out(m.positions.size(), glm::vec3(0.0f));
    std::vector<bool> ok(m.positions.size(), false);
    for (std::size_t k = 0; k < m.positions.size() && k < m.normals.size(); ++k) {
        const glm::dvec3& n = m.normals[k];
        const double length = glm::length(n);
        if (std::isfinite(length) && std::abs(length - 1.0) < 1e-6) {
            out[k] = glm::vec3(n / length);
            ok[k] = true;
        }
    }
    for (const auto& t : m.triangles) {
        const glm::dvec3 n = glm::cross(m.positions[t[1]] - m.positions[t[0]],
                                        m.positions[t[2]] - m.positions[t[0]]);
        const double length = glm::length(n);
        for (std::uint32_t v : t)
            if (!ok[v] && length > 0) {
                out[v] = glm::vec3(n / length);
                ok[v] = true;
            }
    }
    for (std::size_t k = 0; k < out.size(); ++k)
        if (!ok[k]) out[k] = glm::vec3(0.0f, 0.0f, 1.0f);
    return out;
}

} // namespace

geom::Expected<std::string> glb_bytes(const std::vector<geom::Mesh>& meshes,
                                      const std::string& name) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "isoparm";
    model.buffers.emplace_back();
    tinygltf::Scene scene;
    scene.name = name;
    for (const geom::Mesh& m : meshes) {
        if (m.triangles.empty()) continue;
        std::vector<unsigned char> positions, normals, indices;
        glm::vec3 lo(INFINITY), hi(-INFINITY);
        for (const glm::dvec3& p : m.positions) {
            const glm::vec3 f(p);
            lo = glm::min(lo, f);
            hi = glm::max(hi, f);
            append_bytes(positions, &f, sizeof f);
        }
        for (const glm::vec3& n : unit_normals(m)) append_bytes(normals, &n, sizeof n);
        for (const auto& t : m.triangles) append_bytes(indices, t.data(), sizeof t);
        tinygltf::Primitive primitive;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        primitive.attributes["POSITION"] = add_accessor(
            model, positions, TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_FLOAT,
            TINYGLTF_TYPE_VEC3, m.positions.size(), {lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z});
        primitive.attributes["NORMAL"] =
            add_accessor(model, normals, TINYGLTF_TARGET_ARRAY_BUFFER,
                         TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, m.positions.size());
        primitive.indices = add_accessor(model, indices, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER,
                                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                         m.triangles.size() * 3);
        tinygltf::Mesh mesh;
        mesh.primitives.push_back(primitive);
        model.meshes.push_back(mesh);
        tinygltf::Node node;
        node.mesh = static_cast<int>(model.meshes.size()) - 1;
        model.nodes.push_back(node);
        scene.nodes.push_back(static_cast<int>(model.nodes.size()) - 1);
    }
    model.buffers[0].data.resize((model.buffers[0].data.size() + 3) / 4 * 4, 0);
    model.scenes.push_back(scene);
    model.defaultScene = 0;
    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, false, true))
        return geom::make_error_nopath(geom::ErrorCode::internal,
                                       "tinygltf could not write the glTF binary");
    return out.str();
}

} // namespace isoparm::exchange
