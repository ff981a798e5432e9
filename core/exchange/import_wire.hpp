// An import's answer as bytes: how a reader running in a child process (the OpenCASCADE
// sandbox, core/exchange_occt/sandbox.cpp) hands its curves and surfaces back through a pipe.
// The child writes records as it goes: what arrived before it died is still read.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "core/exchange/import_result.hpp"
#include "core/geom/status.hpp"

namespace isoparm::exchange {

// Appends records to a buffer the caller sends (take() empties it).
class ImportWireWriter {
public:
    ImportWireWriter();
    // The file was read and its shapes built: `items` faces and edges follow.
    void transferred(std::size_t items);
    void object(const ImportedShape& shape);
    void skipped(const SkippedEntity& entity);
    // The whole read failed (nothing is imported).
    void error(const geom::Error& error);
    // The last record: everything was sent.
    void done();
    std::string take();
    std::size_t size() const { return buffer_.size(); }

private:
    std::string buffer_;
};

// What a (possibly cut short) stream of records says.
struct ImportWireReading {
    ImportResult result;              // objects and skipped entities received, in order
    std::optional<geom::Error> error; // the reader's own error record
    bool transferred = false;         // the file was read and its shapes built
    std::size_t items = 0;            // as announced by `transferred`
    bool done = false;                // the last record arrived
    bool garbled = false;             // bytes that are no record (never from a healthy child)
};

// Reads records until the bytes end or stop making sense. Sizes are checked against the bytes
// left, so a cut or garbled stream never allocates more than it holds.
ImportWireReading read_import_wire(std::string_view bytes);

} // namespace isoparm::exchange
