// What the commands' runs share: out of memory as an error, and the end of a run that writes
// one file.
#pragma once

#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "core/geom/status.hpp"
#include "core/json/out_of_memory.hpp"

namespace isoparm::app {

// Out of memory is an error, never an abort, in every command: a reserve of address space is
// released on the first failed allocation so the unwinding finds memory
// (core/json/out_of_memory.hpp). `run()`'s exit status; out of memory, 1 after the line
// "<prefix><the message><after>".
template <class Run>
int run_memory_guarded(Run&& run, const std::string& prefix, const std::string& after = "") {
    json_io::arm_memory_reserve();
    try {
        return run();
    } catch (const std::bad_alloc&) {
        std::cerr << prefix << json_io::out_of_memory_message << after << "\n";
        return 1;
    }
}

// The end of a run that wrote one file: each entity it skipped named, then the write's refusal
// (exit status 1), or 0.
inline int report_written(const std::string& prefix, const std::vector<std::string>& skipped,
                          const geom::Status& written) {
    for (const std::string& s : skipped) std::cerr << prefix << "skipped " << s << "\n";
    if (!written) {
        std::cerr << prefix << written.error().message << "\n";
        return 1;
    }
    return 0;
}

} // namespace isoparm::app
