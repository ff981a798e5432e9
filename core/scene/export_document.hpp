// A scene's objects as the bytes of an exchange file: what `isoparm export` and File > Export
// write (the formats themselves are core/exchange's; this picks the objects, tessellates or
// polygonizes them and applies each format's rules).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/doc/document.hpp"
#include "core/geom/status.hpp"
#include "core/scene/format_extensions.hpp"

namespace isoparm::scene {

enum class ExportFormat {
    iges,     // .igs .iges: exact (entities 126, 128)
    step,     // .stp .step: exact (AP214)
    obj,      // .obj: exact (OBJ free-form)
    obj_mesh, // .obj with mesh = true: triangles with normals
    stl,      // .stl: binary STL
    ply,      // .ply: ASCII PLY with normals
    glb,      // .glb: glTF 2.0 binary
};
inline constexpr geom::EnumName<ExportFormat> export_format_names[] = {
    {ExportFormat::iges, "iges", "IGES"},        {ExportFormat::step, "step", "STEP"},
    {ExportFormat::obj, "obj", "OBJ free-form"}, {ExportFormat::obj_mesh, "obj_mesh", "OBJ mesh"},
    {ExportFormat::stl, "stl", "binary STL"},    {ExportFormat::ply, "ply", "PLY"},
    {ExportFormat::glb, "glb", "glTF binary"},
};
static_assert(geom::in_declaration_order(export_format_names));
constexpr std::span<const geom::EnumName<ExportFormat>> enum_names(ExportFormat) {
    return export_format_names;
}
// The extensions each format is written to (.obj: free-form; an OBJ mesh when asked).
inline constexpr ExtensionOf<ExportFormat> export_extension_table[] = {
    {".igs", ExportFormat::iges},  {".iges", ExportFormat::iges}, {".stp", ExportFormat::step},
    {".step", ExportFormat::step}, {".obj", ExportFormat::obj},   {".stl", ExportFormat::stl},
    {".ply", ExportFormat::ply},   {".glb", ExportFormat::glb},
};

// The format a file name asks for, from its extension (any case); `mesh` turns .obj into an
// OBJ mesh and is refused with the exact-only extensions. nullopt for an unknown extension.
std::optional<ExportFormat> export_format_for(const std::string& path, bool mesh);
bool is_mesh_format(ExportFormat f);
// "IGES", "STEP", "OBJ free-form", "OBJ mesh", "binary STL", "PLY", "glTF binary".
inline const char* export_format_label(ExportFormat f) {
    return geom::label_of(f);
}
// The extensions, for messages: ".igs/.iges, .stp/.step, .obj, .stl, .ply, .glb".
std::string export_extensions();

// The objects to export: every visible object when `which` is empty, else the one object whose
// id (decimal digits) or name is `which` (an id wins over a name; two objects of that name are
// an error naming their ids). Errors: `schema` with a message naming `which`.
geom::Expected<std::vector<const doc::Object*>> export_objects(const doc::Document& doc,
                                                               const std::string& which);

// What one export may use at its peak (checked for mesh formats before any tessellation).
inline constexpr double max_export_bytes = 1024.0 * 1024 * 1024;

struct ExportOptions {
    ExportFormat format = ExportFormat::step;
    int samples = 32; // tessellation points per direction of a parametric surface (2..1000)
    std::string name; // the product / model name written into the file
};

struct ExportResult {
    std::string bytes;
    // Objects left out, one sentence each ("'Hat' is a curve: a mesh has no curves"), for the
    // caller to show; the file holds the others.
    std::vector<std::string> skipped;
};

// Exact formats take curves and surfaces (an implicit surface is skipped: it has no exact
// form); IGES and STEP refuse a non-positive weight (`weights`, naming the object and the
// control point and suggesting a mesh format). Mesh formats take surfaces, tessellated
// samples x samples over their domain, and implicit surfaces, polygonized with their own box
// and cell; a curve is skipped. The vertices are charged first (`limit` when they would take
// more than max_export_bytes, saying how many samples fit). Every mesh is welded
// (core/exchange/mesh_weld.hpp), so closed surfaces give closed meshes. Nothing left to write is an
// error (`schema`) that says why.
geom::Expected<ExportResult> export_document(const std::vector<const doc::Object*>& objects,
                                             const ExportOptions& options);

} // namespace isoparm::scene
