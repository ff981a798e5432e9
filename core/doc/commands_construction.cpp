// construct, edit_construction and detach: recipes kept beside the objects they build.
#include "core/doc/commands_construction.hpp"

#include <algorithm>
#include <cassert>

#include "core/doc/associative.hpp"
#include "core/doc/commands_common.hpp"
#include "core/doc/curve_constructions.hpp"
#include "core/doc/placement.hpp"

namespace isoparm::doc {

using geom::ErrorCode;
using geom::make_error;

namespace {

// A request path ("/curves/1/points/3", "/angle") as the JSON form names it under
// "/construction" ("/construction/inputs/1/points/3", "/construction/angle").
geom::Error at_construction(geom::Error e) {
    if (!e.has_path) return e;
    if (e.path == "/curves" || e.path.rfind("/curves/", 0) == 0)
        e.path = "/inputs" + e.path.substr(7);
    return e.under("/construction");
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

class Construct final : public Command {
public:
    Construct(Recipe recipe, std::string name)
        : recipe_(std::move(recipe)), name_(std::move(name)) {}

    geom::Status apply(Document& doc) override {
        if (!name_.empty())
            if (auto st = detail::validate_name(name_); !st) return st;
        if (!made_) { // the first apply; a redo adds the same object again
            auto built = build_construction(doc, recipe_);
            if (!built) return at_construction(built.error());
            Object o = std::move(built->object);
            // A rebuild of the same recipe gets a name of its own (doc::unique_name).
            o.name = name_.empty() ? unique_name(doc, o.name) : name_;
            o.construction = recipe_;
            note_ = std::move(built->note);
            made_ = std::move(o);
        }
        if (made_->id != 0 && doc.find(made_->id))
            return make_error(ErrorCode::schema,
                              "an object with id " + std::to_string(made_->id) + " already exists",
                              "/id");
        prev_next_id_ = doc.next_id;
        if (made_->id == 0) made_->id = doc.allocate_id();
        doc.next_id = std::max(doc.next_id, made_->id + 1);
        doc.objects.push_back(*made_);
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        assert(!doc.objects.empty() && doc.objects.back().id == made_->id);
        doc.objects.pop_back();
        doc.next_id = prev_next_id_;
        if (doc.view.selection.object == made_->id) doc.view.selection = Selection{};
    }

    std::string label() const override {
        return made_ ? "Build " + made_->name
                     : std::string("Build ") + lower(construction_label(recipe_.kind));
    }
    std::optional<CommandSpec> spec() const override { return ConstructSpec{recipe_, name_}; }
    std::size_t memory_bytes() const override {
        return sizeof(*this) + (made_ ? detail::shape_bytes(made_->shape) : 0);
    }

    const std::string& note() const { return note_; }
    std::uint64_t id() const { return made_ ? made_->id : 0; }

private:
    Recipe recipe_;
    std::string name_, note_;
    std::optional<Object> made_;
    std::uint64_t prev_next_id_ = 0;
};

class EditConstruction final : public Command {
public:
    EditConstruction(std::uint64_t id, Recipe recipe) : id_(id), recipe_(std::move(recipe)) {}

    geom::Status apply(Document& doc) override {
        auto found = detail::find_object(doc, id_);
        if (!found) return found.error();
        Object& o = **found;
        if (!o.construction)
            return make_error(ErrorCode::schema,
                              "'" + o.name +
                                  "' is not linked to a construction (it was never built by one, "
                                  "or it was detached); build a new one instead",
                              "/id");
        Recipe next = recipe_;
        next.refinements = o.construction->refinements;
        if (auto st = check_recipe_links(doc, id_, o, next); !st) return st;
        auto built = build_construction(doc, next);
        if (!built) return at_construction(built.error());
        Shape shape = std::move(built->object.shape);
        // A curve keeps the plane the designer shows it in (as a rebuild does).
        if (CurveObject* c = curve_object_of(shape))
            if (const CurveObject* was = o.curve_object()) c->plane = was->plane;
        note_ = built->note;
        old_shape_ = std::move(o.shape);
        old_recipe_ = std::move(o.construction);
        o.shape = std::move(shape);
        o.construction = std::move(next);
        name_ = o.name;
        sel_before_ = doc.view.selection;
        Selection& sel = doc.view.selection;
        if (sel.object == id_ && sel.has_point() && !has_control_point(o.shape, sel.i, sel.j))
            sel.i = sel.j = -1;
        sel_after_ = sel;
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        Object* o = doc.find(id_);
        assert(o && old_shape_);
        o->shape = std::move(*old_shape_);
        o->construction = std::move(old_recipe_);
        old_shape_.reset();
        if (doc.view.selection == sel_after_) doc.view.selection = sel_before_;
    }

    bool merge_with(const Command& next) override {
        const auto* m = dynamic_cast<const EditConstruction*>(&next);
        if (!m || m->id_ != id_) return false;
        recipe_ = m->recipe_; // the old shape and recipe stay: those before the whole drag
        note_ = m->note_;
        sel_after_ = m->sel_after_;
        return true;
    }

    std::string label() const override { return "Edit the construction of " + name_; }
    std::optional<CommandSpec> spec() const override { return EditConstructionSpec{id_, recipe_}; }
    std::size_t memory_bytes() const override {
        return sizeof(*this) + (old_shape_ ? detail::shape_bytes(*old_shape_) : 0);
    }
    const std::string& note() const { return note_; }

private:
    std::uint64_t id_;
    Recipe recipe_;
    std::string name_, note_;
    std::optional<Shape> old_shape_;
    std::optional<Recipe> old_recipe_;
    Selection sel_before_, sel_after_;
};

class Detach final : public Command {
public:
    explicit Detach(std::uint64_t id) : id_(id) {}

    geom::Status apply(Document& doc) override {
        auto found = detail::find_object(doc, id_);
        if (!found) return found.error();
        Object& o = **found;
        if (!o.construction)
            return make_error(ErrorCode::schema,
                              "'" + o.name + "' is not linked to a construction; nothing to detach",
                              "/id");
        name_ = o.name;
        old_ = std::move(o.construction);
        o.construction.reset();
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        Object* o = doc.find(id_);
        assert(o && old_);
        o->construction = std::move(old_);
    }

    std::string label() const override { return "Detach " + name_; }
    std::optional<CommandSpec> spec() const override { return DetachSpec{id_}; }

private:
    std::uint64_t id_;
    std::string name_;
    std::optional<Recipe> old_;
};

} // namespace

std::unique_ptr<Command> construct(Recipe recipe, std::string name) {
    return std::make_unique<Construct>(std::move(recipe), std::move(name));
}
std::unique_ptr<Command> edit_construction(std::uint64_t id, Recipe recipe) {
    return std::make_unique<EditConstruction>(id, std::move(recipe));
}
std::unique_ptr<Command> detach(std::uint64_t id) {
    return std::make_unique<Detach>(id);
}

std::string construction_note(const Command& command) {
    const Command& c = unwrapped(command);
    if (const auto* b = dynamic_cast<const Construct*>(&c)) return b->note();
    if (const auto* e = dynamic_cast<const EditConstruction*>(&c)) return e->note();
    return {};
}

std::uint64_t constructed_id(const Command& command) {
    const auto* b = dynamic_cast<const Construct*>(&unwrapped(command));
    return b ? b->id() : 0;
}

} // namespace isoparm::doc
