// What a CAD file's text says about itself before any reader sees it: whether it is whole
// (IGES: the Terminate section's line counts; STEP: the end of the exchange structure), and
// which IGES B-spline entities (126, 128) have parameter data that is not all numbers. A
// reader may take a garbled number for another and move the control points behind it, or
// read a cut file in part without a word: these checks say so instead.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/exchange/cad_reader.hpp"
#include "core/exchange/import_result.hpp"

namespace isoparm::exchange {

struct BadEntity {
    int directory_line = 0; // the IGES DE sequence number (odd: 1, 3, 5, ...)
    std::string reason;     // "parameter 17 '1.0X5' is not a number"
};

struct CadTextCheck {
    // About the whole file ("the file ends inside its Parameter Data section ..."), for the
    // import's skipped list: what follows the cut is not imported.
    std::vector<SkippedEntity> notes;
    // IGES 126 and 128 entities whose parameter data a reader would misread.
    std::vector<BadEntity> bad_entities;
    // A STEP file without its end (to be completed with step_completed before reading).
    bool step_cut_short = false;
    // The text is not a file of the format at all (no IGES Start/Global records, no STEP
    // header): the spec's settled reading makes that `parse`.
    bool not_the_format = false;
    std::string why_not; // for not_the_format
};

// The IGES text with `bad` entities made null entities (type 0 in both of their directory
// records, IGES 5.3 4.2), which readers skip: what refers to them loses them instead of a
// reader misreading (or crashing on) their parameter data.
std::string iges_without_entities(std::string_view text, const std::vector<BadEntity>& bad);

// A STEP text cut short (check_cad_text's note) completed so a reader takes what is there:
// cut after its last complete entity instance and closed with ENDSEC; and END-ISO-10303-21;.
// The text unchanged where it was whole or where even its header is cut.
std::string step_completed(std::string_view text);

// IGES 5.3 (US PRO/IPO-100, sections 2.2: the fixed 80-column records, the Global section's
// delimiters, 4.23 entity 126 and 4.24 entity 128) and ISO 10303-21 (sections 7 and 8: the
// exchange structure's header and its end).
CadTextCheck check_cad_text(std::string_view text, CadFormat format);

} // namespace isoparm::exchange
