// An exchange file as new scene objects: what `isoparm import` and File > Import read (the
// formats themselves are core/exchange's: obj_reader.hpp, and cad_reader.hpp for IGES and
// STEP through OpenCASCADE where the program installed it).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/doc/document.hpp"
#include "core/exchange/import_result.hpp"
#include "core/geom/status.hpp"
#include "core/scene/format_extensions.hpp"

namespace isoparm::scene {

enum class ImportFormat { iges, step, obj };
inline constexpr geom::EnumName<ImportFormat> import_format_names[] = {
    {ImportFormat::iges, "iges", "IGES"},
    {ImportFormat::step, "step", "STEP"},
    {ImportFormat::obj, "obj", "OBJ free-form"},
};
static_assert(geom::in_declaration_order(import_format_names));
constexpr std::span<const geom::EnumName<ImportFormat>> enum_names(ImportFormat) {
    return import_format_names;
}
// The extensions each format is read from.
inline constexpr ExtensionOf<ImportFormat> import_extension_table[] = {
    {".igs", ImportFormat::iges},  {".iges", ImportFormat::iges}, {".stp", ImportFormat::step},
    {".step", ImportFormat::step}, {".obj", ImportFormat::obj},
};

// The format a file name asks for, from its extension (any case): .igs/.iges, .stp/.step,
// .obj. nullopt for any other.
std::optional<ImportFormat> import_format_for(const std::string& path);
// "IGES", "STEP", "OBJ free-form".
inline const char* import_format_label(ImportFormat f) {
    return geom::label_of(f);
}
// For messages: ".igs/.iges, .stp/.step, .obj".
std::string import_extensions();

struct ImportedObjects {
    std::vector<doc::Object> objects; // ids 0: the document assigns them
    // What the file held and isoparm left out, one sentence each, for the caller to show.
    std::vector<std::string> skipped;
};

// The text of a file in `format` as objects, in file order: curves (custom knots, free 3D
// plane) and surfaces, B-spline or NURBS (rational ones). Names: the file's where it gives one
// (control characters made spaces), else "<format> k" ("iges 1", "step 2", "obj 3") counting
// the imported objects. Every object is checked by the document's own rules, and one they
// refuse is left out with the reason in `skipped` (each face of a CAD file stands on its own).
// Errors: the reader's (the line or entity named) and a file with nothing to import (`schema`,
// saying what was skipped). On error there are no objects at all.
geom::Expected<ImportedObjects> import_text(std::string_view text, ImportFormat format);

// The file at `path` (a regular file of at most 256 MiB, read_input_file's rules) in the format
// of its extension. Errors name the file.
geom::Expected<ImportedObjects> import_file(const std::string& path);

} // namespace isoparm::scene
