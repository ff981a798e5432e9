// One shape-replacing command: compute the new shape once (redo reuses it), check it, swap it
// in, and swap the old one back on undo.
#include "core/doc/shape_edit.hpp"

#include <cassert>
#include <optional>

#include "core/doc/commands_common.hpp"

namespace isoparm::doc::detail {

using geom::ErrorCode;
using geom::make_error;

namespace {

std::optional<geom::SplineType> spline_type(const Shape& shape) {
    if (const geom::Surface* s = surface_of(shape)) return s->type;
    if (const geom::Curve* c = curve_of(shape)) return c->type;
    return std::nullopt;
}

// A selected control point of `shape`'s object that the shape does not have is dropped.
void drop_missing_point(Selection& sel, std::uint64_t id, const Shape& shape) {
    if (sel.object != id || !sel.has_point()) return;
    if (!has_control_point(shape, sel.i, sel.j)) sel.i = sel.j = -1;
}

class ShapeEdit final : public Command {
public:
    ShapeEdit(std::uint64_t id, CommandSpec spec, ShapeEditRule rule)
        : id_(id), spec_(std::move(spec)), rule_(std::move(rule)) {}

    geom::Status check(const Document& doc) const override {
        const Object* obj = doc.find(id_);
        if (!obj) return missing();
        auto made = make(*obj);
        if (!made) return made.error();
        return geom::Ok{};
    }

    geom::Status apply(Document& doc) override {
        Object* obj = doc.find(id_);
        if (!obj) return missing();
        if (!new_) { // the first apply; a redo swaps in the same shape again
            auto made = make(*obj);
            if (!made) return made.error();
            new_ = std::move(made).value();
            label_ = rule_.label(obj->shape, *new_);
            type_change_ = type_change_text(obj->shape, *new_);
        }
        sel_before_ = doc.view.selection;
        if (rule_.forward)
            doc.view.selection = rule_.forward(doc.view.selection, obj->shape, *new_);
        drop_missing_point(doc.view.selection, id_, *new_);
        sel_after_ = doc.view.selection;
        old_ = std::move(obj->shape);
        obj->shape = *new_;
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        Object* obj = doc.find(id_);
        assert(obj && old_);
        // Selection is view state: put it back unless the user selected something since.
        if (doc.view.selection == sel_after_)
            doc.view.selection = sel_before_;
        else if (rule_.backward)
            doc.view.selection = rule_.backward(doc.view.selection, obj->shape, *old_);
        drop_missing_point(doc.view.selection, id_, *old_);
        obj->shape = std::move(*old_);
        old_.reset();
    }

    bool merge_with(const Command& next) override {
        auto* m = dynamic_cast<const ShapeEdit*>(&next);
        if (!m || rule_.merge_key.empty() || m->id_ != id_ || m->rule_.merge_key != rule_.merge_key)
            return false;
        // old_ stays: the shape before the whole drag.
        new_ = m->new_;
        spec_ = m->spec_;
        label_ = m->label_;
        sel_after_ = m->sel_after_;
        return true;
    }

    std::optional<CommandSpec> spec() const override { return spec_; }
    std::string label() const override { return label_; }
    std::size_t memory_bytes() const override {
        std::size_t bytes = sizeof(*this) + label_.size();
        if (old_) bytes += shape_bytes(*old_);
        if (new_) bytes += shape_bytes(*new_);
        return bytes;
    }

    const std::string& type_change() const { return type_change_; }

private:
    geom::Error missing() const {
        return make_error(ErrorCode::schema, "there is no object with id " + std::to_string(id_),
                          "/id");
    }

    geom::Expected<Shape> make(const Object& obj) const {
        auto made = rule_.make(obj);
        if (!made) return made.error();
        if (kind_of(*made) != obj.kind())
            return make_error(ErrorCode::schema,
                              "object '" + obj.name + "' is " + kind_noun(obj.kind()) +
                                  "; an edit keeps the kind of object (got " +
                                  kind_noun(kind_of(*made)) + ")",
                              rule_.shape_path);
        if (auto st = validate_shape(*made); !st) return st.error().under(rule_.shape_path);
        return made;
    }

    std::uint64_t id_;
    CommandSpec spec_;
    ShapeEditRule rule_;
    std::optional<Shape> old_, new_;
    std::string label_, type_change_;
    Selection sel_before_, sel_after_;
};

} // namespace

std::unique_ptr<Command> shape_edit(std::uint64_t id, CommandSpec spec, ShapeEditRule rule) {
    return std::make_unique<ShapeEdit>(id, std::move(spec), std::move(rule));
}

std::string type_change_text(const Shape& before, const Shape& after) {
    const auto a = spline_type(before), b = spline_type(after);
    if (!a || !b || *a == *b) return {};
    return std::string(geom::label_of(*a)) + " becomes " + geom::label_of(*b);
}

std::string shape_edit_type_change(const Command& command) {
    const auto* edit = dynamic_cast<const ShapeEdit*>(&command);
    return edit ? edit->type_change() : std::string();
}

} // namespace isoparm::doc::detail
