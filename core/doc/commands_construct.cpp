// construct: a surface built from the document's curves (curve_constructions.hpp) added as a
// new object, one undo step. Redo builds it again from the same curves, which undo left as
// they were, so it is the same surface with the same id.
#include <cassert>

#include "core/doc/commands.hpp"
#include "core/doc/commands_common.hpp"

namespace isoparm::doc {

namespace {

using geom::ErrorCode;
using geom::make_error;

class Construct final : public Command {
public:
    Construct(ConstructionRequest request, std::string name)
        : request_(std::move(request)), name_(std::move(name)) {}

    geom::Status apply(Document& doc) override {
        auto built = build_construction(doc, request_);
        if (!built) return built.error();
        Object o = std::move(built->object);
        if (!name_.empty()) o.name = name_;
        if (auto st = detail::validate_name(o.name); !st) return st;
        // What add_object would check of the same surface (sizes, weights, knots).
        if (auto st = detail::validate_shape(o.shape); !st) return st.error().under("/curves");
        prev_next_id_ = doc.next_id;
        if (id_ == 0) id_ = doc.allocate_id(); // redo keeps this id
        o.id = id_;
        doc.next_id = std::max(doc.next_id, id_ + 1);
        made_name_ = o.name;
        note_ = built->note;
        bytes_ = detail::shape_bytes(o.shape);
        doc.objects.push_back(std::move(o));
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        assert(!doc.objects.empty() && doc.objects.back().id == id_);
        doc.objects.pop_back();
        doc.next_id = prev_next_id_;
        if (doc.view.selection.object == id_) doc.view.selection = Selection{};
    }

    // "Build revolve profile", "Build vase": what Undo takes away.
    std::string label() const override {
        if (!made_name_.empty()) return "Build " + made_name_;
        return std::string("Build a ") + geom::name_of(request_.kind) + " surface";
    }
    std::optional<CommandSpec> spec() const override { return ConstructSpec{request_, name_}; }
    std::size_t memory_bytes() const override { return sizeof(*this) + bytes_ + note_.size(); }

private:
    ConstructionRequest request_;
    std::string name_;
    std::uint64_t id_ = 0, prev_next_id_ = 0;
    std::string made_name_, note_;
    std::size_t bytes_ = 0;
};

} // namespace

std::unique_ptr<Command> construct(ConstructionRequest request, std::string name) {
    return std::make_unique<Construct>(std::move(request), std::move(name));
}

} // namespace isoparm::doc
