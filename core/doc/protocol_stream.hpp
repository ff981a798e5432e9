// The largest answers (the meshes of `tessellate` and `polygonize`, up to 1,000,000 vertices)
// written as text while they are read out of the mesh, never held as a JSON tree: a
// 1000 x 1000 tessellation took ~0.7 GB as a tree and its whole text; streamed, it takes the
// mesh (~75 MB) and a 1 MiB buffer. The text is byte for byte what write_json writes for
// mesh_to_json (tests/protocol/protocol_stream_test.cpp checks it).
#pragma once

#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>

#include "core/geom/status.hpp"
#include "core/geom/tessellate.hpp"

namespace isoparm::doc {

// How a mesh op turns a request into its mesh (the op's checks and work budget included).
using MeshOp = geom::Expected<geom::Mesh> (*)(const nlohmann::json& request);

// The mesh op of a request whose "op" is "tessellate" or "polygonize", else null (every other
// request, and anything that is not a well-formed request, goes through handle_request).
MeshOp mesh_op_of(const nlohmann::json& request);

// Bytes collected before they are written out.
inline constexpr std::size_t stream_chunk_bytes = std::size_t{1} << 20;

// Appends {"ok": true, "positions": [...], "normals": [...], "triangles": [...]} to `buffer`,
// writing the buffer to `out` (and emptying it) whenever it passes stream_chunk_bytes. The
// buffer should have room for a chunk beforehand: then nothing here allocates, so nothing can
// fail once the first byte is out.
void write_mesh_answer(const geom::Mesh& mesh, std::string& buffer, std::ostream& out);

} // namespace isoparm::doc
