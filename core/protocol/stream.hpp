// The largest answers written as text while they are read out of compact results, never held
// as a JSON tree: meshes (`tessellate`, `polygonize`, up to 1,000,000 vertices) and `evaluate`
// (up to millions of points and derivative tables). A 1000 x 1000 tessellation took ~0.7 GB
// as a tree and its whole text; streamed, it takes the mesh (~75 MB) and a 1 MiB buffer. The
// text is byte for byte what write_json writes for the op's JSON answer
// (tests/protocol/protocol_stream_test.cpp checks it).
#pragma once

#include <functional>
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>

#include "core/geom/status.hpp"
#include "core/geom/tessellate.hpp"

namespace isoparm::protocol {

// Bytes collected before they are written out.
inline constexpr std::size_t stream_chunk_bytes = std::size_t{1} << 20;

// Writes an answer's text into `buffer`, handing full chunks to `out`. Given a buffer with
// room for a chunk it allocates nothing, so it cannot fail once the first byte is out.
using StreamedAnswer = std::function<void(std::string& buffer, std::ostream& out)>;
// Checks a request and does all its work (errors and std::bad_alloc come out of here, before
// anything is written), returning the writer of its answer.
using StreamedOp = geom::Expected<StreamedAnswer> (*)(const nlohmann::json& request);

// The streamed op of a request whose "op" is "tessellate", "polygonize" or "evaluate", else
// null (every other request, and anything that is not a well-formed request, goes through
// handle_request and a JSON tree).
StreamedOp streamed_op_of(const nlohmann::json& request);

// Appends {"ok": true, "positions": [...], "normals": [...], "triangles": [...]}.
void write_mesh_answer(const geom::Mesh& mesh, std::string& buffer, std::ostream& out);

// Pieces for writers (op_evaluate.cpp): the buffer goes out once it holds a chunk (clear()
// keeps its capacity); a point as point_to_json writes it (null unless it exists and is
// finite); whether it would be written as a point.
void flush_if_full(std::string& buffer, std::ostream& out);
void append_point(std::string& buffer, const glm::dvec3& p, bool exists = true);
bool writable_point(const glm::dvec3& p);

} // namespace isoparm::protocol
