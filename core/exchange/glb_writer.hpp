// glTF 2.0 binary (.glb, Khronos glTF 2.0 specification, "GLB File Format Specification"),
// written through Debian's tinygltf: one glTF mesh and node per mesh, each a triangle
// primitive with POSITION and NORMAL (float VEC3) and uint32 indices, in one binary buffer.
#pragma once

#include <string>
#include <vector>

#include "core/geom/status.hpp"
#include "core/geom/tessellate.hpp"

namespace isoparm::exchange {

// The file's bytes. Coordinates are rounded to binary32 (glTF's only float type); POSITION
// carries its min/max (the specification requires them); a normal that is not unit (a zero
// normal where the surface degenerates) is replaced by its triangle's geometric normal, as
// validators require unit normals. `name` names the scene. An error (`internal`) only if
// tinygltf fails to write.
geom::Expected<std::string> glb_bytes(const std::vector<geom::Mesh>& meshes,
                                      const std::string& name);

} // namespace isoparm::exchange
