// The OpenCASCADE read itself: a file's text through IGESControl_Reader or STEPControl_Reader,
// its faces and free edges converted one by one (occt_convert.hpp), the records sent as they
// are ready. It runs in the sandbox's child process (sandbox.hpp), never in the program's own:
// OCCT can crash, loop or exhaust memory on a malformed file.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/exchange/cad_reader.hpp"
#include "core/exchange/cad_text_check.hpp"

namespace isoparm::exchange_occt {

// What the child is doing, in memory it shares with the parent, so that a crash can be named
// ("while converting STEP #412") and the next attempt can leave that item out.
struct ReadProgress {
    enum Stage : int { starting, reading, transferring, converting, listing, finished };
    std::atomic<int> stage{starting};
    std::atomic<std::int64_t> item{-1}; // the face or edge being converted (0-based)
    std::atomic<std::int64_t> items{0};
    char entity[120] = {}; // the item's entity, NUL-terminated ("STEP #412")
};

// An item an earlier attempt crashed on, left out this time with the reason.
struct SkipItem {
    std::int64_t item = 0;
    std::string reason;
};

struct ReadPlan {
    std::string_view text;
    exchange::CadFormat format = exchange::CadFormat::step;
    // A path OCCT's file reader opens for the text (IGES has no stream reader).
    std::string path;
    std::vector<SkipItem> skip;
    // STEP read face by face (after OCCT crashed transferring the file whole): each face and
    // geometric set is transferred on its own, under the progress's item (occt_read.cpp).
    bool careful = false;
    // IGES 126/128 entities whose parameter data failed the text check.
    std::vector<exchange::BadEntity> bad_entities;
};

// Reads and converts, calling `send` with wire bytes (core/exchange/import_wire.hpp) as they
// accumulate and once at the end (`last`), while the reader's model still exists (`send` may
// end the process after the last bytes). Throws only std::bad_alloc.
void read_with_occt(const ReadPlan& plan, ReadProgress& progress,
                    const std::function<void(std::string&& bytes, bool last)>& send);

} // namespace isoparm::exchange_occt
