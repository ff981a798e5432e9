// When the workstation writes and discards its recovery file: a policy with no clock or file
// access of its own (times, the document's state and its fingerprint come in as arguments), so
// it is tested without a window, a disk or a sleep.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <string>

#include "core/doc/document.hpp"

namespace isoparm::scene {

// A 64-bit FNV-1a of the document's scene text: "changed since the last autosave" compares
// these, so an edit undone back to the written state does not write again.
std::uint64_t document_fingerprint(const doc::Document& doc);

class AutosaveTimer {
public:
    using Clock = std::chrono::steady_clock;

    explicit AutosaveTimer(Clock::time_point start,
                           Clock::duration interval = std::chrono::minutes(1));

    struct Step {
        enum class Kind { none, write, discard } kind = Kind::none;
        std::string path;              // the scene path whose recovery file to write or discard
        std::uint64_t fingerprint = 0; // write: the document's fingerprint (pass it to wrote())
    };

    // Called every frame; cheap unless a check is due. In this order:
    //  - discard: a recovery file this session wrote (or restored from) is no longer needed,
    //    because the document has no unsaved changes any more (saved, undone to the saved
    //    state, a new or opened document) or belongs to another path now (Save As). It is
    //    forgotten here, so a failing discard is not retried every frame.
    //  - write: once per interval, when the document has unsaved changes, its path is not held
    //    and its fingerprint (computed only then) differs from the last write for that path.
    //    The caller writes and calls wrote() on success (a failure is retried next interval).
    Step poll(Clock::time_point now, bool dirty, const std::string& path,
              const std::function<std::uint64_t()>& fingerprint);

    // The recovery file of `path` now holds the document with `fingerprint`: after a write, or
    // after restoring from that file (it stays until the work is saved or discarded).
    void wrote(const std::string& path, std::uint64_t fingerprint);

    // A recovery file of `path` that the user chose to decide about later: this session
    // neither overwrites nor removes it (so its autosaves of that path are off).
    void hold(const std::string& path);
    bool held(const std::string& path) const { return held_.count(path) != 0; }

    // On a normal exit (the unsaved-changes question answered): the recovery file to discard.
    std::optional<std::string> on_exit() const { return written_path_; }

private:
    Clock::time_point next_check_;
    Clock::duration interval_;
    std::optional<std::string> written_path_;
    std::uint64_t written_fingerprint_ = 0;
    std::set<std::string> held_;
};

} // namespace isoparm::scene
