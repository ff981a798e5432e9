// Command::check by trial, and the undo/redo history: merging of drags, the clean mark and the
// memory bound.
#include "core/doc/command.hpp"

#include <cassert>

#include "core/doc/associative.hpp"

namespace isoparm::doc {

geom::Status Command::check(const Document& doc) const {
    std::optional<CommandSpec> again = spec();
    if (!again) return geom::Ok{};
    Document scratch = doc;
    return make_command(std::move(*again))->apply(scratch);
}

// Positions are counted in "commands applied since the history began" (dropped_ included),
// so the clean mark survives the memory bound dropping the oldest commands.

geom::Status History::execute(Document& doc, std::unique_ptr<Command> cmd) {
    assert(cmd);
    // Constructions follow their inputs inside the same command (associative.hpp).
    cmd = associative(std::move(cmd));
    geom::Status st = cmd->apply(doc);
    if (!st) return st; // the command refused and left the document alone

    const long before = dropped_ + static_cast<long>(undo_.size());
    // A redo stack that held the clean state makes it unreachable.
    if (clean_index_ > before) clean_index_ = -1;
    redo_.clear();

    last_merged_ = !sealed_ && !undo_.empty() && undo_.back()->merge_with(*cmd);
    if (last_merged_) {
        // The top command now ends in a new state: if that state was the clean one, the
        // clean state can no longer be reached (undo goes back to the state before the top).
        if (clean_index_ == before) clean_index_ = -1;
    } else {
        undo_.push_back(std::move(cmd));
    }
    sealed_ = false;
    enforce_limit();
    return st;
}

std::string History::undo_label() const {
    return undo_.empty() ? "" : undo_.back()->label();
}

std::string History::redo_label() const {
    return redo_.empty() ? "" : redo_.back()->label();
}

bool History::undo(Document& doc) {
    if (undo_.empty()) return false;
    undo_.back()->revert(doc);
    redo_.push_back(std::move(undo_.back()));
    undo_.pop_back();
    sealed_ = true; // a later drag must not merge into a command below the undone one
    return true;
}

bool History::redo(Document& doc) {
    if (redo_.empty()) return false;
    // Redo replays a command that applied before on exactly this state; it cannot refuse.
    [[maybe_unused]] geom::Status st = redo_.back()->apply(doc);
    assert(st.ok() && "a command refused to redo on the state it was applied to");
    undo_.push_back(std::move(redo_.back()));
    redo_.pop_back();
    sealed_ = true;
    return true;
}

void History::mark_clean() {
    clean_index_ = dropped_ + static_cast<long>(undo_.size());
    // The saved state must stay reachable by undo: the next edit starts a new command.
    sealed_ = true;
}

bool History::is_clean() const {
    return clean_index_ == dropped_ + static_cast<long>(undo_.size());
}

void History::clear() {
    const bool clean = is_clean();
    undo_.clear();
    redo_.clear();
    dropped_ = 0;
    clean_index_ = clean ? 0 : -1;
    sealed_ = true;
}

void History::enforce_limit() {
    std::size_t total = 0;
    for (const auto& c : undo_) total += c->memory_bytes();
    for (const auto& c : redo_) total += c->memory_bytes();
    // Drop from the bottom, but always keep the most recent command undoable.
    std::size_t drop = 0;
    while (total > limit_ && drop + 1 < undo_.size()) total -= undo_[drop++]->memory_bytes();
    if (drop == 0) return;
    undo_.erase(undo_.begin(), undo_.begin() + static_cast<long>(drop));
    dropped_ += static_cast<long>(drop);
    if (clean_index_ >= 0 && clean_index_ < dropped_) clean_index_ = -1;
}

} // namespace isoparm::doc
