#include "core/exchange/cad_reader.hpp"

#include <atomic>

namespace isoparm::exchange {

namespace {
// Installed once at start-up, read from any thread afterwards.
std::atomic<CadReader> installed{nullptr};
} // namespace

void install_cad_reader(CadReader reader) {
    installed.store(reader);
}

bool has_cad_reader() {
    return installed.load() != nullptr;
}

geom::Expected<ImportResult> read_cad(std::string_view text, CadFormat format) {
    if (CadReader reader = installed.load()) return reader(text, format);
    return geom::make_error(
        geom::ErrorCode::schema,
        std::string("this isoparm was built without OpenCASCADE, which reads ") +
            (format == CadFormat::iges ? "IGES" : "STEP") +
            " files (install libocct-data-exchange-dev and rebuild); OBJ free-form imports "
            "without it");
}

} // namespace isoparm::exchange
