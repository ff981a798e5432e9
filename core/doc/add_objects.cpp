// add_objects: several new objects as one undo step (an import, a paste). Every object is
// checked before any is added, so a refusal leaves the document as it was.
#include <algorithm>
#include <cassert>

#include "core/doc/commands.hpp"
#include "core/doc/commands_common.hpp"

namespace isoparm::doc {

namespace {

using geom::ErrorCode;
using geom::make_error;

class AddObjects final : public Command {
public:
    AddObjects(std::vector<Object> objects, std::string label)
        : objects_(std::move(objects)), label_(std::move(label)) {}

    geom::Status apply(Document& doc) override {
        if (objects_.empty())
            return make_error(ErrorCode::schema, "add_objects needs at least one object",
                              "/objects");
        std::uint64_t next = doc.next_id;
        for (std::size_t k = 0; k < objects_.size(); ++k) {
            const Object& o = objects_[k];
            const std::string at = "/objects" + geom::pointer_step(static_cast<long>(k));
            if (auto st = detail::validate_name(o.name); !st) return st.error().under(at);
            if (auto st = detail::validate_shape(o.shape); !st)
                return st.error().under(at + "/shape");
            if (o.id == 0) continue;
            const bool repeated = std::any_of(objects_.begin(), objects_.begin() + k,
                                              [&](const Object& p) { return p.id == o.id; });
            if (doc.find(o.id) || repeated)
                return make_error(ErrorCode::schema,
                                  "an object with id " + std::to_string(o.id) + " already exists",
                                  at + "/id");
            next = std::max(next, o.id + 1);
        }
        // Objects without an id get fresh ones after every id in use (redo keeps them).
        prev_next_id_ = doc.next_id;
        for (Object& o : objects_)
            if (o.id == 0) o.id = next++;
        doc.next_id = next;
        for (const Object& o : objects_) doc.objects.push_back(o);
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        assert(doc.objects.size() >= objects_.size());
        for (std::size_t k = 0; k < objects_.size(); ++k) {
            if (doc.view.selection.object == doc.objects.back().id)
                doc.view.selection = Selection{};
            doc.objects.pop_back();
        }
        doc.next_id = prev_next_id_;
    }

    std::string label() const override {
        if (!label_.empty()) return label_;
        return "Add " + std::to_string(objects_.size()) + " objects";
    }
    std::optional<CommandSpec> spec() const override { return AddObjectsSpec{objects_, label_}; }
    std::size_t memory_bytes() const override {
        std::size_t bytes = sizeof(*this) + label_.size();
        for (const Object& o : objects_) bytes += o.name.size() + detail::shape_bytes(o.shape);
        return bytes;
    }

private:
    std::vector<Object> objects_;
    std::string label_;
    std::uint64_t prev_next_id_ = 0;
};

} // namespace

std::unique_ptr<Command> add_objects(std::vector<Object> objects, std::string label) {
    return std::make_unique<AddObjects>(std::move(objects), std::move(label));
}

} // namespace isoparm::doc
