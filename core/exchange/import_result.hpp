// What an import reads from an exchange file: exact curves and surfaces in file order, with
// the name the file gives each (empty where it gives none), and what was left out and why.
#pragma once

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

struct ImportResult {
    std::vector<ImportedShape> objects;
    std::vector<SkippedEntity> skipped;
};

} // namespace isoparm::exchange
