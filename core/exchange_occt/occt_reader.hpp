// IGES and STEP files read through OpenCASCADE (OCCT), the one part of isoparm that links it:
// built only where CMake finds OCCT (core/CMakeLists.txt), installed into core/exchange's
// read_cad at start-up (app/main.cpp). Everything else reaches it through cad_reader.hpp.
#pragma once

#include <string_view>

#include "core/exchange/cad_reader.hpp"

namespace isoparm::exchange_occt {

// OCCT's readers (IGESControl_Reader, STEPControl_Reader) run in a child process
// (core/exchange/sandbox.hpp: address-space and CPU limits, a wall-clock timeout) that hands
// the converted curves and surfaces back through a pipe (core/exchange/import_wire.hpp); a
// crash, a limit or a timeout there is an error naming the signal and what OCCT was doing,
// and this process is unaffected. A face or edge whose conversion crashed the child is left
// out (with the signal as its reason) and the file read again, up to 8 times. The text is
// checked first (core/exchange/cad_text_check.hpp): a cut file says so in `skipped`, and IGES
// B-spline entities with garbled numbers are not read at all. Faces and the edges outside
// every face become surfaces and curves, in the order of the entities they came from
// (occt_read.hpp), each converted on its own (occt_convert.hpp); what OCCT refused to
// transfer is listed in `skipped` with OCCT's own words and the entity.
geom::Expected<exchange::ImportResult> read(std::string_view text, exchange::CadFormat format);

// install_cad_reader(read).
void install();

} // namespace isoparm::exchange_occt
