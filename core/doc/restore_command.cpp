// RestoreDocument: swaps the whole document with the recovered one (and back on undo).
#include "core/doc/restore_command.hpp"

#include <utility>

#include "core/doc/commands_common.hpp"

namespace isoparm::doc {

namespace {

class RestoreDocument final : public Command {
public:
    explicit RestoreDocument(Document d) : other_(std::move(d)) {}

    // Nothing to validate: the recovered document came through load_scene's checks.
    geom::Status apply(Document& doc) override {
        std::swap(doc, other_);
        return geom::Ok{};
    }
    void revert(Document& doc) override { std::swap(doc, other_); }
    std::optional<CommandSpec> spec() const override { return std::nullopt; }
    std::string label() const override { return "Restore unsaved changes"; }
    std::size_t memory_bytes() const override {
        std::size_t total = sizeof(*this);
        for (const Object& o : other_.objects)
            total += sizeof(Object) + o.name.size() + detail::shape_bytes(o.shape);
        return total;
    }

private:
    Document other_; // before apply: the recovered document; after: the one it replaced
};

} // namespace

std::unique_ptr<Command> restore_document(Document recovered) {
    return std::make_unique<RestoreDocument>(std::move(recovered));
}

} // namespace isoparm::doc
