// What an import reads from an exchange file: exact curves and surfaces in file order, with
// the name the file gives each (empty where it gives none), and what was left out and why.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/exchange/iges_writer.hpp"

namespace isoparm::exchange {

struct ImportedShape {
    std::string name; // from the file (OBJ `o`/`g`, IGES entity label, STEP item name); may be ""
    ExactShape shape;
};

// One thing the file holds that isoparm did not import: which (an entity, a line) and why.
struct SkippedEntity {
    std::string entity; // "line 12: cstype bezier", "IGES entity 7 (Geom_OffsetSurface)"
    std::string reason;
};

// The budget of one import: control points of all its curves and surfaces (about 128 MB as
// geometry, and within the protocol's answer cap of 2^24 numbers), counted while the file is
// read, so a file naming the same vertices over and over is stopped before it is built.
inline constexpr std::size_t max_import_control_points = 4'000'000;

struct ImportResult {
    std::vector<ImportedShape> objects;
    std::vector<SkippedEntity> skipped;
};

} // namespace isoparm::exchange
