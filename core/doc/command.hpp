// The command layer: every edit of the document, with undo and redo.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/doc/command_spec.hpp"
#include "core/doc/document.hpp"
#include "core/geom/status.hpp"

namespace isoparm::doc {

class Command {
public:
    virtual ~Command() = default;
    // What apply would answer on doc, without changing anything: menus grey an item and show
    // this reason instead of repeating the command's rules. By default the command is built
    // again from its spec and applied to a copy of the document (exact, at the price of the
    // copy); commands whose checks stand apart from their work answer directly.
    virtual geom::Status check(const Document& doc) const;
    // Validates first and refuses without touching anything.
    virtual geom::Status apply(Document& doc) = 0;
    // Restores exactly the state before apply (bit-identical geometry).
    virtual void revert(Document& doc) = 0;
    virtual std::string label() const = 0;
    // The command as data (command_spec.hpp); after a merge, the whole drag's final value.
    // Nothing for an edit that no script makes (restoring a recovery file).
    virtual std::optional<CommandSpec> spec() const = 0;
    // Absorb `next` (already applied) into this command, so a drag is one undo step.
    virtual bool merge_with(const Command& /*next*/) { return false; }
    // Approximate heap bytes held, for the history's memory bound.
    virtual std::size_t memory_bytes() const { return sizeof(*this); }
};

class History {
public:
    explicit History(std::size_t memory_limit_bytes = 256u << 20) : limit_(memory_limit_bytes) {}

    // Applies cmd; on success it joins the undo stack (merging with the top command unless
    // sealed) and clears redo. On failure nothing changes and the error is returned.
    geom::Status execute(Document& doc, std::unique_ptr<Command> cmd);
    // The next command will not merge with the current top (end of a drag gesture).
    void seal() { sealed_ = true; }

    // The command the next undo reverts (nullptr when none), and whether the last successful
    // execute merged into it instead of adding a step (a recording keeps one step per drag).
    const Command* top() const { return undo_.empty() ? nullptr : undo_.back().get(); }
    bool last_merged() const { return last_merged_; }

    bool can_undo() const { return !undo_.empty(); }
    bool can_redo() const { return !redo_.empty(); }
    std::string undo_label() const;
    std::string redo_label() const;
    bool undo(Document& doc);
    bool redo(Document& doc);

    void mark_clean();
    bool is_clean() const;
    void clear();
    std::size_t size() const { return undo_.size(); }

private:
    void enforce_limit();
    std::vector<std::unique_ptr<Command>> undo_, redo_;
    std::size_t limit_;
    bool sealed_ = true;
    bool last_merged_ = false;
    // Position of the clean state in "commands applied" terms; -1 when unreachable.
    long clean_index_ = 0;
    long dropped_ = 0; // commands dropped from the bottom by the memory bound
};

} // namespace isoparm::doc
