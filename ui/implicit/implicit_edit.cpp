// edit_implicit: replace_shape that merges a drag's edits (doc::replace_shape never merges).
#include "ui/implicit/implicit_edit.hpp"

#include <cassert>
#include <variant>

#include "core/doc/commands.hpp"

namespace isoparm::ui {

namespace {

class EditImplicit final : public doc::Command {
public:
    EditImplicit(std::uint64_t id, doc::ImplicitObject shape, std::string label)
        : id_(id), shape_(std::move(shape)), label_(std::move(label)) {}

    geom::Status apply(doc::Document& d) override {
        const doc::Object* o = d.find(id_);
        if (!o || !std::holds_alternative<doc::ImplicitObject>(o->shape))
            return geom::make_error(geom::ErrorCode::schema,
                                    "object " + std::to_string(id_) +
                                        " is not an implicit surface of the document",
                                    "/id");
        const doc::Shape before = o->shape;
        // replace_shape validates (expression, parameters, bounds, cell) and applies.
        auto inner = doc::replace_shape(id_, shape_, label_);
        const geom::Status s = inner->apply(d);
        if (!s) return s;
        old_ = std::get<doc::ImplicitObject>(before);
        return s;
    }

    void revert(doc::Document& d) override {
        doc::Object* o = d.find(id_);
        assert(o);
        o->shape = old_;
    }

    bool merge_with(const doc::Command& next) override {
        const auto* e = dynamic_cast<const EditImplicit*>(&next);
        if (!e || e->id_ != id_ || e->label_ != label_) return false;
        shape_ = e->shape_; // old_ stays: the object before the whole drag
        return true;
    }

    std::string label() const override { return label_; }
    std::size_t memory_bytes() const override {
        return sizeof(*this) + shape_.expression.size() + old_.expression.size() +
               (shape_.parameter_values.size() + old_.parameter_values.size()) * 40;
    }

private:
    std::uint64_t id_;
    doc::ImplicitObject shape_, old_;
    std::string label_;
};

} // namespace

std::unique_ptr<doc::Command> edit_implicit(std::uint64_t id, doc::ImplicitObject shape,
                                            std::string label) {
    return std::make_unique<EditImplicit>(id, std::move(shape), std::move(label));
}

} // namespace isoparm::ui
