// The associative wrapper around every command: rebuild what reads an edited input, refuse
// what would break a construction's link, and undo both together.
#include "core/doc/associative.hpp"

#include <algorithm>
#include <cassert>
#include <map>
#include <set>

#include "core/doc/command_spec.hpp"
#include "core/doc/commands_common.hpp"
#include "core/doc/curve_constructions.hpp"

namespace isoparm::doc {

using geom::ErrorCode;
using geom::make_error;

namespace {

bool takes_surface(Construction kind) {
    return kind == Construction::isocurve;
}

// What the construction makes: a curve for an isocurve, a surface otherwise.
ObjectKind output_kind(Construction kind) {
    return kind == Construction::isocurve ? ObjectKind::curve : ObjectKind::surface;
}

// "'vase' (Revolve of 'profile')": how messages name a constructed object.
std::string described(const Document& doc, const Object& o) {
    std::string s = "'" + o.name + "'";
    if (!o.construction) return s;
    s += std::string(" (") + construction_label(o.construction->kind) + " of ";
    for (std::size_t k = 0; k < o.construction->curves.size(); ++k) {
        const Object* in = doc.find(o.construction->curves[k]);
        s += (k ? ", '" : "'") + (in ? in->name : "#" + std::to_string(o.construction->curves[k])) +
             "'";
    }
    return s + ")";
}

// Whether `object` may have changed `before` -> its current shape through this command: only
// by a refinement of it, which the recipe then records.
std::optional<RecipeRefinement> refinement_of(const Command& inner, std::uint64_t id) {
    const std::optional<CommandSpec> spec = inner.spec();
    if (!spec) return std::nullopt;
    if (const auto* s = std::get_if<InsertKnotSpec>(&*spec); s && s->id == id)
        return RecipeRefinement{RecipeRefinement::Kind::insert_knot, s->dir, s->t, s->times};
    if (const auto* s = std::get_if<ElevateDegreeSpec>(&*spec); s && s->id == id)
        return RecipeRefinement{RecipeRefinement::Kind::elevate_degree, s->dir, 0.0, s->times};
    return std::nullopt;
}

class Associative final : public Command {
public:
    explicit Associative(std::unique_ptr<Command> inner) : inner_(std::move(inner)) {}

    const Command& inner() const { return *inner_; }

    geom::Status check(const Document& doc) const override {
        // The inner command's own check first (cheap where it answers directly), then the
        // whole command on a copy only when constructions are involved.
        if (auto st = inner_->check(doc); !st) return st;
        if (!has_constructions(doc)) return geom::Ok{};
        std::optional<CommandSpec> again = inner_->spec();
        if (!again) return geom::Ok{};
        Document scratch = doc;
        Associative trial(make_command(std::move(*again)));
        return trial.apply(scratch);
    }

    geom::Status apply(Document& doc) override {
        changes_.clear();
        rebuilt_names_.clear();
        // The shapes and recipes the command could disturb: constructed objects and their inputs.
        std::map<std::uint64_t, Snapshot> before;
        std::set<std::uint64_t> inputs;
        for (const Object& o : doc.objects)
            if (o.construction)
                for (std::uint64_t id : o.construction->curves) inputs.insert(id);
        for (const Object& o : doc.objects)
            if (o.construction || inputs.count(o.id))
                before.emplace(o.id, Snapshot{o.shape, o.construction});
        sel_before_ = doc.view.selection;

        if (auto st = inner_->apply(doc); !st) return st;
        auto refuse = [&](geom::Error e) -> geom::Status {
            undo_changes(doc);
            inner_->revert(doc);
            doc.view.selection = sel_before_;
            return e;
        };

        std::vector<std::uint64_t> changed;
        for (Object& o : doc.objects) {
            const auto was = before.find(o.id);
            const bool recipe_changed =
                was == before.end() ||
                was->second.recipe.has_value() != o.construction.has_value() ||
                (o.construction && !same_recipe(*was->second.recipe, *o.construction));
            // A recipe new to the document (add_object, construct, edit_construction): its links.
            if (o.construction && recipe_changed)
                if (auto st = check_recipe_links(doc, o.id, o, *o.construction); !st)
                    return refuse(st.error());
            if (was == before.end() || same_shape(was->second.shape, o.shape)) continue;
            if (o.construction && !recipe_changed) {
                // The command edited a constructed object itself.
                if (auto r = refinement_of(*inner_, o.id)) {
                    changes_.push_back(Change{o.id, std::nullopt, o.construction});
                    o.construction->refinements.push_back(*r);
                } else {
                    return refuse(make_error(
                        ErrorCode::schema,
                        described(doc, o) +
                            " follows its inputs: its own control points are not edited. Detach it "
                            "first (Construct > Detach, the command detach) to edit it freely",
                        "/id"));
                }
            }
            if (inputs.count(o.id)) changed.push_back(o.id);
        }
        // Inputs that are gone (deleted, split into pieces) or no longer of the kind read: the
        // constructed objects reading them become free objects.
        for (Object& o : doc.objects) {
            if (!o.construction) continue;
            const bool broken = std::any_of(o.construction->curves.begin(),
                                            o.construction->curves.end(), [&](std::uint64_t id) {
                                                const Object* in = doc.find(id);
                                                if (!in) return true;
                                                return takes_surface(o.construction->kind)
                                                           ? !in->surface()
                                                           : !in->curve();
                                            });
            if (!broken) continue;
            changes_.push_back(Change{o.id, std::nullopt, o.construction});
            detached_names_.push_back(o.name);
            o.construction.reset();
        }

        for (std::uint64_t id : dependants_in_order(doc, changed)) {
            Object* o = doc.find(id);
            assert(o && o->construction);
            auto shape = rebuilt_shape(doc, *o);
            if (!shape)
                return refuse(geom::make_error_nopath(
                    shape.error().code, described(doc, *o) +
                                            " cannot follow this edit: " + shape.error().message +
                                            ". Detach '" + o->name + "' first to make it"));
            changes_.push_back(Change{id, std::move(o->shape), std::nullopt});
            o->shape = std::move(shape).value();
            rebuilt_names_.push_back(o->name);
        }
        // A selected point that a rebuilt object no longer has is dropped.
        Selection& sel = doc.view.selection;
        if (sel.has_point())
            if (const Object* o = doc.find(sel.object);
                o && !has_control_point(o->shape, sel.i, sel.j))
                sel.i = sel.j = -1;
        sel_after_ = doc.view.selection;
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        undo_changes(doc);
        inner_->revert(doc);
        if (doc.view.selection == sel_after_) doc.view.selection = sel_before_;
    }

    bool merge_with(const Command& next) override {
        const auto* n = dynamic_cast<const Associative*>(&next);
        if (!n || !inner_->merge_with(*n->inner_)) return false;
        // Undo needs each object as it was before the whole gesture: ours where we have one.
        for (const Change& c : n->changes_)
            if (std::none_of(changes_.begin(), changes_.end(),
                             [&](const Change& m) { return m.id == c.id; }))
                changes_.push_back(c);
        rebuilt_names_ = n->rebuilt_names_;
        detached_names_ = n->detached_names_;
        sel_after_ = n->sel_after_;
        return true;
    }

    std::string label() const override {
        std::string s = inner_->label();
        auto list = [](const std::vector<std::string>& names) {
            std::string out;
            for (std::size_t k = 0; k < names.size() && k < 3; ++k)
                out += (k ? ", " : "") + names[k];
            if (names.size() > 3) out += " and " + std::to_string(names.size() - 3) + " more";
            return out;
        };
        if (!rebuilt_names_.empty()) s += " (rebuilds " + list(rebuilt_names_) + ")";
        if (!detached_names_.empty()) s += " (detaches " + list(detached_names_) + ")";
        return s;
    }
    std::optional<CommandSpec> spec() const override { return inner_->spec(); }
    std::size_t memory_bytes() const override {
        std::size_t bytes = sizeof(*this) + inner_->memory_bytes();
        for (const Change& c : changes_)
            if (c.shape) bytes += detail::shape_bytes(*c.shape);
        return bytes;
    }

    static bool has_constructions(const Document& doc) {
        return std::any_of(doc.objects.begin(), doc.objects.end(),
                           [](const Object& o) { return o.construction.has_value(); });
    }

private:
    struct Snapshot {
        Shape shape;
        std::optional<Recipe> recipe;
    };
    // What this command did beside the inner command: a dependant's shape replaced by its
    // rebuild (`shape`: the one before), or its recipe changed (`recipe`: the one before; a
    // refinement recorded, a link broken).
    struct Change {
        std::uint64_t id = 0;
        std::optional<Shape> shape;
        std::optional<std::optional<Recipe>> recipe;
    };

    void undo_changes(Document& doc) {
        for (auto c = changes_.rbegin(); c != changes_.rend(); ++c) {
            Object* o = doc.find(c->id);
            assert(o);
            if (c->shape) o->shape = *c->shape;
            if (c->recipe) o->construction = *c->recipe;
        }
        changes_.clear();
        rebuilt_names_.clear();
        detached_names_.clear();
    }

    std::unique_ptr<Command> inner_;
    std::vector<Change> changes_;
    std::vector<std::string> rebuilt_names_, detached_names_;
    Selection sel_before_, sel_after_;
};

} // namespace

std::unique_ptr<Command> associative(std::unique_ptr<Command> inner) {
    assert(inner);
    if (dynamic_cast<Associative*>(inner.get())) return inner;
    return std::make_unique<Associative>(std::move(inner));
}

const Command& unwrapped(const Command& command) {
    const auto* a = dynamic_cast<const Associative*>(&command);
    return a ? a->inner() : command;
}

std::optional<ConstructedEdit> constructed_object_edited(const Document& doc,
                                                         const CommandSpec& spec) {
    if (!Associative::has_constructions(doc)) return std::nullopt;
    // The command alone (not wrapped) on a copy: which constructed object's shape it changes.
    Document scratch = doc;
    const std::unique_ptr<Command> inner = make_command(spec);
    if (!inner->apply(scratch)) return std::nullopt;
    for (const Object& o : doc.objects) {
        if (!o.construction) continue;
        const Object* after = scratch.find(o.id);
        if (!after || !after->construction || !same_recipe(*o.construction, *after->construction))
            continue;
        if (!same_shape(o.shape, after->shape) && !refinement_of(*inner, o.id))
            return ConstructedEdit{o.id, inner->label()};
    }
    return std::nullopt;
}

bool reads(const Document& doc, std::uint64_t reader, std::uint64_t id) {
    std::vector<std::uint64_t> stack{reader};
    std::set<std::uint64_t> seen;
    while (!stack.empty()) {
        const std::uint64_t at = stack.back();
        stack.pop_back();
        if (!seen.insert(at).second) continue;
        const Object* o = doc.find(at);
        if (!o || !o->construction) continue;
        for (std::uint64_t in : o->construction->curves) {
            if (in == id) return true;
            stack.push_back(in);
        }
    }
    return false;
}

std::vector<std::uint64_t> dependants_in_order(const Document& doc,
                                               const std::vector<std::uint64_t>& changed) {
    // Everything that reads a changed object, closed under reading.
    std::set<std::uint64_t> affected;
    bool grew = true;
    std::set<std::uint64_t> sources(changed.begin(), changed.end());
    while (grew) {
        grew = false;
        for (const Object& o : doc.objects) {
            if (!o.construction || affected.count(o.id)) continue;
            for (std::uint64_t in : o.construction->curves)
                if (sources.count(in) || affected.count(in)) {
                    affected.insert(o.id);
                    grew = true;
                    break;
                }
        }
    }
    // Each after the affected objects it reads (Kahn's order; recipes have no cycles).
    std::vector<std::uint64_t> order;
    std::set<std::uint64_t> placed;
    while (order.size() < affected.size()) {
        bool progress = false;
        for (const Object& o : doc.objects) {
            if (!affected.count(o.id) || placed.count(o.id)) continue;
            const bool ready = std::all_of(
                o.construction->curves.begin(), o.construction->curves.end(),
                [&](std::uint64_t in) { return !affected.count(in) || placed.count(in); });
            if (!ready) continue;
            order.push_back(o.id);
            placed.insert(o.id);
            progress = true;
        }
        if (!progress) break; // a cycle (refused where recipes are made); never loop
    }
    return order;
}

geom::Status check_recipe_links(const Document& doc, std::uint64_t id, const Object& object,
                                const Recipe& recipe) {
    if (output_kind(recipe.kind) != object.kind())
        return make_error(ErrorCode::schema,
                          std::string(construction_label(recipe.kind)) + " makes a " +
                              kind_name(output_kind(recipe.kind)) + "; '" + object.name +
                              "' is a " + kind_name(object.kind()),
                          "/construction/operation");
    for (std::size_t k = 0; k < recipe.curves.size(); ++k) {
        const std::string at = "/construction/inputs/" + std::to_string(k);
        const std::uint64_t in = recipe.curves[k];
        const Object* o = doc.find(in);
        if (!o)
            return make_error(ErrorCode::schema,
                              "'" + object.name + "' is built from object " + std::to_string(in) +
                                  ", which is not in the scene",
                              at);
        const bool right =
            takes_surface(recipe.kind) ? o->surface() != nullptr : o->curve() != nullptr;
        if (!right)
            return make_error(ErrorCode::schema,
                              std::string(construction_label(recipe.kind)) + " reads " +
                                  (takes_surface(recipe.kind) ? "a surface" : "curves") + "; '" +
                                  o->name + "' is a " + kind_name(o->kind()),
                              at);
        if (in == id)
            return make_error(ErrorCode::schema,
                              "'" + object.name + "' cannot be built from itself", at);
        if (reads(doc, in, id))
            return make_error(ErrorCode::schema,
                              "'" + object.name + "' cannot read '" + o->name + "': '" + o->name +
                                  "' is built from '" + object.name +
                                  "' (a cycle: neither could follow the other)",
                              at);
    }
    return geom::Ok{};
}

geom::Expected<Shape> rebuilt_shape(const Document& doc, const Object& object) {
    assert(object.construction);
    auto built = build_construction(doc, *object.construction);
    if (!built) return built.error();
    Shape shape = std::move(built->object.shape);
    // A curve keeps the plane and knot mode it was given (the designer's view of it).
    if (CurveObject* c = curve_object_of(shape))
        if (const CurveObject* was = object.curve_object()) {
            c->plane = was->plane;
        }
    return shape;
}

geom::Expected<std::vector<ReplacedShape>>
rebuild_dependants(Document& doc, const std::vector<std::uint64_t>& changed) {
    std::vector<ReplacedShape> replaced;
    for (std::uint64_t id : dependants_in_order(doc, changed)) {
        Object* o = doc.find(id);
        auto shape = rebuilt_shape(doc, *o);
        if (!shape) {
            restore_shapes(doc, replaced);
            return geom::make_error_nopath(shape.error().code,
                                           described(doc, *o) +
                                               " cannot follow: " + shape.error().message);
        }
        replaced.push_back({id, std::move(o->shape)});
        o->shape = std::move(shape).value();
    }
    return replaced;
}

void restore_shapes(Document& doc, std::vector<ReplacedShape>& replaced) {
    for (auto r = replaced.rbegin(); r != replaced.rend(); ++r)
        if (Object* o = doc.find(r->id)) o->shape = std::move(r->before);
    replaced.clear();
}

} // namespace isoparm::doc
