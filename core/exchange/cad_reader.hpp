// IGES and STEP files in, through a reader installed at start-up. Reading them means their
// whole topology and geometry (IGES 5.3 and ISO 10303-21/-42), which isoparm does not
// reimplement: the reader is OpenCASCADE's, in core/exchange_occt (built only where OCCT is
// installed), and the program installs it (app/main.cpp). The core stays free of OCCT; without
// an installed reader these formats are a clear error.
#pragma once

#include <string_view>

#include "core/exchange/import_result.hpp"
#include "core/geom/status.hpp"

namespace isoparm::exchange {

enum class CadFormat { iges, step };

// Reads the whole text of an IGES or STEP file. Errors: `parse` naming the entity (or the
// reader's complaint); an error means nothing is imported.
using CadReader = geom::Expected<ImportResult> (*)(std::string_view text, CadFormat format);

void install_cad_reader(CadReader reader);
bool has_cad_reader();

// The installed reader's answer; without one, `schema`: "... built without OpenCASCADE ...".
geom::Expected<ImportResult> read_cad(std::string_view text, CadFormat format);

} // namespace isoparm::exchange
