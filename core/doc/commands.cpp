// Object, control-point, weight, knot, transform and colour commands (refinement is in
// commands_refine.cpp).
#include "core/doc/commands.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <optional>

#include "core/doc/commands_common.hpp"
#include "core/doc/patches.hpp"
#include "core/doc/shape_edit.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/trim/trim_validate.hpp"

namespace isoparm::doc {

namespace {

using geom::Dir;
using geom::ErrorCode;
using geom::make_error;

// After a command, a selection must name an object that exists and a point it has.
bool selection_valid(const Document& doc, const Selection& sel) {
    if (sel.object == 0) return !sel.has_point();
    const Object* o = doc.find(sel.object);
    if (!o) return false;
    if (!sel.has_point()) return true;
    return has_control_point(o->shape, sel.i, sel.j);
}

// Restores the selection a command found, unless the user selected something else since
// (selection is view state, not undone); a selection left dangling is dropped.
void restore_selection(Document& doc, const Selection& before, const Selection& after) {
    if (doc.view.selection == after) doc.view.selection = before;
    if (!selection_valid(doc, doc.view.selection)) {
        if (doc.find(doc.view.selection.object))
            doc.view.selection.i = doc.view.selection.j = -1;
        else
            doc.view.selection = Selection{};
    }
}

// The control point (i, j) of an object of any kind that has them (surface: P_ij; curve: P_i,
// j = -1 or 0; triangle: b_ijk, k = n - i - j), checked (`schema`, "/i", "/j").
struct PointRef {
    std::span<glm::dvec3> points;
    std::span<double> weights;
    bool rational = false;
    std::size_t index = 0;
    glm::dvec3& position() { return points[index]; }
    double& weight() { return weights[index]; }
};

geom::Expected<PointRef> control_point(Object& obj, int i, int j) {
    if (control_points_of(obj.shape).empty()) return kind_refusal(obj, "it has no control points");
    return std::visit(
        [&](auto& k) -> geom::Expected<PointRef> {
            auto index = point_index(k, i, j);
            if (!index) return index.error();
            return PointRef{control_points(k), control_weights(k), is_rational(k), *index};
        },
        obj.shape);
}

std::string vec_text(const glm::dvec3& p) {
    return "(" + geom::format_number(p.x) + ", " + geom::format_number(p.y) + ", " +
           geom::format_number(p.z) + ")";
}

// ---------------------------------------------------------------------------------------
class AddObject final : public Command {
public:
    explicit AddObject(Object object) : object_(std::move(object)) {}

    geom::Status apply(Document& doc) override {
        if (auto st = detail::validate_name(object_.name); !st) return st;
        if (auto st = detail::validate_shape(object_.shape); !st) return st.error().under("/shape");
        if (object_.id != 0 && doc.find(object_.id))
            return make_error(ErrorCode::schema,
                              "an object with id " + std::to_string(object_.id) + " already exists",
                              "/id");
        prev_next_id_ = doc.next_id;
        if (object_.id == 0) object_.id = doc.allocate_id(); // redo keeps this id
        doc.next_id = std::max(doc.next_id, object_.id + 1);
        doc.objects.push_back(object_);
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        assert(!doc.objects.empty() && doc.objects.back().id == object_.id);
        doc.objects.pop_back();
        doc.next_id = prev_next_id_;
        if (doc.view.selection.object == object_.id) doc.view.selection = Selection{};
    }

    std::string label() const override { return "Add " + object_.name; }
    std::optional<CommandSpec> spec() const override { return AddObjectSpec{object_}; }
    std::size_t memory_bytes() const override {
        return sizeof(*this) + object_.name.size() + detail::shape_bytes(object_.shape);
    }

private:
    Object object_;
    std::uint64_t prev_next_id_ = 0;
};

class RemoveObject final : public Command {
public:
    explicit RemoveObject(std::uint64_t id) : id_(id) {}

    geom::Status apply(Document& doc) override {
        auto found = detail::find_object(doc, id_);
        if (!found) return found.error();
        index_ = doc.index_of(id_);
        object_ = std::move(**found);
        doc.objects.erase(doc.objects.begin() + index_);
        sel_before_ = doc.view.selection;
        if (doc.view.selection.object == id_) doc.view.selection = Selection{};
        sel_after_ = doc.view.selection;
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        doc.objects.insert(doc.objects.begin() + index_, object_);
        restore_selection(doc, sel_before_, sel_after_);
    }

    std::string label() const override { return "Delete " + object_.name; }
    std::optional<CommandSpec> spec() const override { return RemoveObjectSpec{id_}; }
    std::size_t memory_bytes() const override {
        return sizeof(*this) + object_.name.size() + detail::shape_bytes(object_.shape);
    }

private:
    std::uint64_t id_;
    int index_ = -1;
    Object object_;
    Selection sel_before_, sel_after_;
};

class RenameObject final : public Command {
public:
    RenameObject(std::uint64_t id, std::string name) : id_(id), name_(std::move(name)) {}

    geom::Status apply(Document& doc) override {
        auto found = detail::find_object(doc, id_);
        if (!found) return found.error();
        if (auto st = detail::validate_name(name_); !st) return st;
        old_name_ = (*found)->name;
        (*found)->name = name_;
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        Object* obj = doc.find(id_);
        assert(obj);
        obj->name = old_name_;
    }

    std::string label() const override { return "Rename " + old_name_ + " to " + name_; }
    std::optional<CommandSpec> spec() const override { return RenameObjectSpec{id_, name_}; }
    std::size_t memory_bytes() const override {
        return sizeof(*this) + name_.size() + old_name_.size();
    }

private:
    std::uint64_t id_;
    std::string name_, old_name_;
};

class SetVisible final : public Command {
public:
    SetVisible(std::uint64_t id, bool visible) : id_(id), visible_(visible) {}

    geom::Status apply(Document& doc) override {
        auto found = detail::find_object(doc, id_);
        if (!found) return found.error();
        name_ = (*found)->name;
        was_ = (*found)->visible;
        (*found)->visible = visible_;
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        Object* obj = doc.find(id_);
        assert(obj);
        obj->visible = was_;
    }

    std::string label() const override { return (visible_ ? "Show " : "Hide ") + name_; }
    std::optional<CommandSpec> spec() const override { return SetVisibleSpec{id_, visible_}; }
    std::size_t memory_bytes() const override { return sizeof(*this) + name_.size(); }

private:
    std::uint64_t id_;
    bool visible_, was_ = true;
    std::string name_;
};

// ---------------------------------------------------------------------------------------
// What an edit of a subpatch's control point did to its neighbours: the points
// keep_continuity moved, to restore on undo, and the continuity setting the edit was made with
// (read once, so a redo replays the edit as it was made, whatever the setting is by then).
struct NeighbourEdits {
    std::vector<PointChange> changes;
    std::optional<Continuity> mode;

    void follow(Document& doc, std::uint64_t id, int i, int j) {
        if (!mode) mode = doc.continuity;
        changes = keep_continuity(doc, id, i, j, *mode);
    }
    void restore(Document& doc) const { restore_points(doc, changes); }
    // A drag's later step: the first recorded value of each point is the one undo needs.
    void merge(const NeighbourEdits& next) {
        for (const PointChange& c : next.changes) {
            const bool known =
                std::any_of(changes.begin(), changes.end(), [&](const PointChange& m) {
                    return m.object == c.object && m.i == c.i && m.j == c.j;
                });
            if (!known) changes.push_back(c);
        }
    }
    std::size_t bytes() const { return changes.capacity() * sizeof(PointChange); }
};

// A control point's position, weight, or both: the paper's drag in the 3D view or a plane,
// the control-point editor's fields and the weight sliders.
class EditPoint final : public Command {
public:
    explicit EditPoint(EditPointSpec spec) : spec_(std::move(spec)) {}

    geom::Status check(const Document& doc) const override {
        auto found = detail::find_object(doc, spec_.id);
        if (!found) return found.error();
        Object copy = **found; // control_point hands out mutable references
        auto ref = validate(copy);
        if (!ref) return ref.error();
        return geom::Ok{};
    }

    geom::Status apply(Document& doc) override {
        auto found = detail::find_object(doc, spec_.id);
        if (!found) return found.error();
        auto ref = validate(**found);
        if (!ref) return ref.error();
        point_name_ = point_label_of((**found).shape, PointName::position, spec_.i, spec_.j);
        weight_name_ = point_label_of((**found).shape, PointName::weight, spec_.i, spec_.j);
        old_position_ = ref->position();
        old_weight_ = ref->weight();
        if (spec_.position) ref->position() = *spec_.position;
        if (spec_.weight) ref->weight() = *spec_.weight;
        // A closed curve repeats its first p points at its end: the twin follows.
        twin_ = closed_twin(**found);
        if (twin_) {
            auto twin = control_point(**found, *twin_, -1);
            old_twin_ = {twin->position(), twin->weight()};
            twin->position() = ref->position();
            twin->weight() = ref->weight();
        }
        // Subpatches: the neighbours follow so the borders stay closed / smooth.
        if ((**found).surface()) neighbours_.follow(doc, spec_.id, spec_.i, spec_.j);
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        Object* obj = doc.find(spec_.id);
        assert(obj);
        neighbours_.restore(doc);
        auto ref = control_point(*obj, spec_.i, spec_.j);
        ref->position() = old_position_;
        ref->weight() = old_weight_;
        if (twin_) {
            auto twin = control_point(*obj, *twin_, -1);
            twin->position() = old_twin_.first;
            twin->weight() = old_twin_.second;
        }
    }

    bool merge_with(const Command& next) override {
        auto* m = dynamic_cast<const EditPoint*>(&next);
        if (!m || m->spec_.id != spec_.id || m->spec_.i != spec_.i || m->spec_.j != spec_.j ||
            m->spec_.position.has_value() != spec_.position.has_value() ||
            m->spec_.weight.has_value() != spec_.weight.has_value())
            return false;
        spec_ = m->spec_; // the old values stay: those before the whole drag
        neighbours_.merge(m->neighbours_);
        return true;
    }

    std::optional<CommandSpec> spec() const override { return spec_; }
    std::size_t memory_bytes() const override { return sizeof(*this) + neighbours_.bytes(); }

    std::string label() const override {
        // Named as the object's kind names its points ("P23", "P4", "b210"), once applied.
        const std::string point =
            point_name_.empty() ? detail::point_label('P', spec_.i, spec_.j) : point_name_;
        const std::string weight =
            weight_name_.empty() ? detail::point_label('w', spec_.i, spec_.j) : weight_name_;
        if (spec_.position && spec_.weight) return "Edit " + point;
        if (spec_.position) return "Move " + point;
        return "Set weight " + weight + " = " + geom::format_short(spec_.weight.value_or(1.0));
    }

private:
    geom::Expected<PointRef> validate(Object& obj) const {
        auto ref = control_point(obj, spec_.i, spec_.j);
        if (!ref) return ref.error();
        if (!spec_.position && !spec_.weight)
            return make_error(ErrorCode::schema,
                              "a point edit sets a position, a weight or both; this one sets "
                              "neither",
                              "/position");
        if (spec_.position)
            for (int a = 0; a < 3; ++a)
                if (!std::isfinite((*spec_.position)[a]))
                    return make_error(ErrorCode::schema,
                                      "a control point needs finite coordinates, got " +
                                          vec_text(*spec_.position),
                                      "/position/" + std::to_string(a));
        if (spec_.weight) {
            const double w = *spec_.weight;
            const std::string name = point_label_of(obj.shape, PointName::weight, spec_.i, spec_.j);
            if (!std::isfinite(w))
                return make_error(ErrorCode::weights,
                                  "weight " + name + " must be a finite number, got " +
                                      geom::format_number(w),
                                  "/weight");
            // The type tag is enforced: a non-rational object keeps unit weights.
            if (!ref->rational && w != 1.0) {
                const std::string what =
                    std::visit([](const auto& k) { return unit_weights_rule(k); }, obj.shape);
                return make_error(ErrorCode::weights,
                                  "a " + what + " to set " + name + " = " + geom::format_number(w),
                                  "/weight");
            }
        }
        return ref;
    }

    // The index of the point a closed curve repeats as point i (i < p: i + n; i >= n: i - n),
    // or none.
    std::optional<int> closed_twin(const Object& obj) const {
        const CurveObject* c = obj.curve_object();
        if (!c || c->knot_mode != CurveKnotMode::closed) return std::nullopt;
        const int p = c->curve.degree, n = c->curve.count() - p;
        if (spec_.i < p) return spec_.i + n;
        if (spec_.i >= n) return spec_.i - n;
        return std::nullopt;
    }

    EditPointSpec spec_;
    std::optional<int> twin_;
    std::pair<glm::dvec3, double> old_twin_{glm::dvec3(0), 1.0};
    glm::dvec3 old_position_{0};
    double old_weight_ = 1;
    std::string point_name_, weight_name_;
    NeighbourEdits neighbours_;
};

class SetKnot final : public Command {
public:
    SetKnot(std::uint64_t id, Dir dir, int k, int count, double value)
        : id_(id), dir_(dir), k_(k), count_(count), value_(value) {}

    geom::Status apply(Document& doc) override {
        auto found = detail::find_object(doc, id_);
        if (!found) return found.error();
        Object& obj = **found;
        geom::Knots* U = nullptr;
        int p = 0, n = 0;
        // Surfaces and curves have knots (an allow-list).
        if (geom::Surface* s = obj.surface()) {
            U = dir_ == Dir::u ? &s->knots_u : &s->knots_v;
            p = s->degree(dir_);
            n = s->count(dir_);
        } else if (geom::Curve* c = obj.curve()) {
            if (dir_ != Dir::u)
                return make_error(ErrorCode::schema, "a curve has only one direction (u)",
                                  "/direction");
            U = &c->knots;
            p = c->degree;
            n = c->count();
            curve_ = true;
        } else {
            return kind_refusal(obj, "it has no knots");
        }
        const int m = static_cast<int>(U->size());
        const std::string name = label_name();
        if (k_ < 0 || k_ >= m)
            return make_error(ErrorCode::schema,
                              "knot index " + std::to_string(k_) + " is outside 0.." +
                                  std::to_string(m - 1),
                              "/k");
        const int last = k_ + count_ - 1;
        if (count_ < 1 || last >= m)
            return make_error(ErrorCode::schema,
                              "a run of " + std::to_string(count_) + " knots from index " +
                                  std::to_string(k_) + " does not fit in 0.." +
                                  std::to_string(m - 1),
                              "/count");
        for (int q = k_ + 1; q <= last; ++q)
            if ((*U)[q] != (*U)[k_])
                return make_error(ErrorCode::schema,
                                  "knots " + std::to_string(k_) + ".." + std::to_string(last) +
                                      " are not copies of one knot (a run to move together): " +
                                      geom::format_number((*U)[k_]) + " and " +
                                      geom::format_number((*U)[q]) + " differ",
                                  "/count");
        if (!std::isfinite(value_))
            return make_error(ErrorCode::knots,
                              "knot " + name + " must be a finite number, got " +
                                  geom::format_number(value_),
                              "/value");
        const geom::Knots& K = *U;
        const bool clamped_start = K[0] == K[p];
        const bool clamped_end = K[n] == K[m - 1];
        if ((clamped_start && k_ <= p) || (clamped_end && last >= n))
            return make_error(ErrorCode::knots,
                              "knot " + name + " is a clamped end knot and cannot move", "/value");
        const double lo = k_ > 0 ? K[k_ - 1] : -INFINITY;
        const double hi = last + 1 < m ? K[last + 1] : INFINITY;
        if (value_ < lo || value_ > hi)
            return make_error(ErrorCode::knots,
                              "knot " + name + " must stay between its neighbours [" +
                                  geom::format_number(lo) + ", " + geom::format_number(hi) +
                                  "], got " + geom::format_number(value_),
                              "/value");
        geom::Knots moved = K;
        std::fill(moved.begin() + k_, moved.begin() + last + 1, value_);
        if (auto st = geom::validate_knots(moved, p, n); !st)
            return make_error(ErrorCode::knots,
                              "moving knot " + name + " to " + geom::format_number(value_) +
                                  " is not allowed: " + st.error().message,
                              "/value");
        // A trimmed surface's loops must stay inside its domain when an end knot moves.
        if (const geom::Trim* t = trim_of(obj.shape); t && !t->empty()) {
            geom::Surface moved_surface = *obj.surface();
            (dir_ == Dir::u ? moved_surface.knots_u : moved_surface.knots_v) = moved;
            if (geom::Status st = geom::validate_trim(*t, geom::domain(moved_surface)); !st)
                return make_error(
                    ErrorCode::domain,
                    "moving knot " + name + " to " + geom::format_number(value_) +
                        " would leave the trim outside the domain: " + st.error().message,
                    "/value");
        }
        old_ = K[k_];
        std::fill(U->begin() + k_, U->begin() + last + 1, value_);
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        Object* obj = doc.find(id_);
        assert(obj);
        geom::Knots& U = [&]() -> geom::Knots& {
            if (geom::Surface* s = obj->surface()) return dir_ == Dir::u ? s->knots_u : s->knots_v;
            return obj->curve()->knots;
        }();
        std::fill(U.begin() + k_, U.begin() + k_ + count_, old_);
    }

    bool merge_with(const Command& next) override {
        auto* m = dynamic_cast<const SetKnot*>(&next);
        if (!m || m->id_ != id_ || m->dir_ != dir_ || m->k_ != k_ || m->count_ != count_)
            return false;
        value_ = m->value_;
        return true;
    }

    std::optional<CommandSpec> spec() const override {
        return MoveKnotSpec{id_, dir_, k_, count_, value_};
    }

    std::string label() const override {
        std::string s = "Set knot " + label_name() + " = " + geom::format_short(value_);
        if (count_ > 1) s += " (" + std::to_string(count_) + " copies)";
        return s;
    }

private:
    std::string label_name() const {
        return std::string(curve_ ? "t" : dir_ == Dir::u ? "u" : "v") + std::to_string(k_);
    }

    std::uint64_t id_;
    Dir dir_;
    int k_, count_;
    double value_, old_ = 0;
    bool curve_ = false;
};

class TransformObject final : public Command {
public:
    TransformObject(std::uint64_t id, const glm::dmat4& m, std::string label)
        : id_(id), m_(m), label_(std::move(label)) {}

    geom::Status apply(Document& doc) override {
        auto found = detail::find_object(doc, id_);
        if (!found) return found.error();
        Object& obj = **found;
        // Every kind with control points moves with them (affine invariance holds for tensor
        // products and triangles alike); a kind without them cannot be transformed.
        const std::span<glm::dvec3> points = control_points_of(obj.shape);
        if (points.empty()) return kind_refusal(obj, "it has no control points to transform");
        if (label_.empty()) label_ = "Transform " + obj.name;
        if (!redo_) {
            // glm is column-major: m_[c][r]. The bottom row is m_[0..3][3].
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    if (!std::isfinite(m_[c][r]))
                        return make_error(ErrorCode::schema, "a transform needs finite entries",
                                          "/matrix");
            if (m_[0][3] != 0 || m_[1][3] != 0 || m_[2][3] != 0 || m_[3][3] != 1)
                return make_error(ErrorCode::schema,
                                  "a transform must be affine (bottom row 0 0 0 1)", "/matrix");
            after_.resize(points.size());
            for (std::size_t k = 0; k < points.size(); ++k) {
                // Affine maps commute with the rational combination (Piegl & Tiller 4.2.3:
                // affine invariance), so mapping the Cartesian points maps the surface.
                after_[k] = glm::dvec3(m_ * glm::dvec4(points[k], 1.0));
                for (int a = 0; a < 3; ++a)
                    if (!std::isfinite(after_[k][a]))
                        return make_error(ErrorCode::schema,
                                          "the transform would move control point " +
                                              std::to_string(k) + " to infinity",
                                          "/matrix");
            }
        }
        assert(after_.size() == points.size());
        before_.assign(points.begin(), points.end());
        std::copy(after_.begin(), after_.end(), points.begin());
        redo_ = true; // a later apply is a redo: the exact points of the first time
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        Object* obj = doc.find(id_);
        assert(obj);
        const std::span<glm::dvec3> points = control_points_of(obj->shape);
        assert(points.size() == before_.size());
        std::copy(before_.begin(), before_.end(), points.begin());
    }

    bool merge_with(const Command& next) override {
        auto* t = dynamic_cast<const TransformObject*>(&next);
        if (!t || t->id_ != id_) return false;
        after_ = t->after_;
        m_ = t->m_ * m_;
        label_ = t->label_;
        return true;
    }

    std::string label() const override { return label_; }
    std::optional<CommandSpec> spec() const override { return TransformSpec{id_, m_, label_}; }
    std::size_t memory_bytes() const override {
        return sizeof(*this) + label_.size() +
               (before_.size() + after_.size()) * sizeof(glm::dvec3);
    }

private:
    std::uint64_t id_;
    glm::dmat4 m_;
    std::string label_;
    std::vector<glm::dvec3> before_, after_;
    bool redo_ = false;
};

// ---------------------------------------------------------------------------------------
class SetColors final : public Command {
public:
    explicit SetColors(Colors colors) : colors_(colors) {}

    geom::Status apply(Document& doc) override {
        const std::pair<const char*, const Rgba*> all[] = {
            {"background", &colors_.background},
            {"surface", &colors_.surface},
            {"selected_surface", &colors_.selected_surface},
            {"control_net", &colors_.control_net},
            {"control_points", &colors_.control_points},
            {"selected_point", &colors_.selected_point},
            {"knot_curves", &colors_.knot_curves},
            {"indicator", &colors_.indicator},
        };
        for (const auto& [name, c] : all) {
            const float ch[4] = {c->r, c->g, c->b, c->a};
            for (int k = 0; k < 4; ++k)
                if (!(ch[k] >= 0.0f && ch[k] <= 1.0f))
                    return make_error(ErrorCode::schema,
                                      std::string("colour channels are between 0 and 1; ") + name +
                                          " has " + geom::format_number(ch[k]),
                                      std::string("/") + name + "/" + std::to_string(k));
        }
        old_ = doc.colors;
        doc.colors = colors_;
        return geom::Ok{};
    }

    void revert(Document& doc) override { doc.colors = old_; }

    bool merge_with(const Command& next) override {
        auto* c = dynamic_cast<const SetColors*>(&next);
        if (!c) return false;
        colors_ = c->colors_;
        return true;
    }

    std::string label() const override { return "Change colours"; }
    std::optional<CommandSpec> spec() const override { return SetColorsSpec{colors_}; }

private:
    Colors colors_, old_;
};

} // namespace

std::unique_ptr<Command> add_object(Object object) {
    return std::make_unique<AddObject>(std::move(object));
}
std::unique_ptr<Command> remove_object(std::uint64_t id) {
    return std::make_unique<RemoveObject>(id);
}
std::unique_ptr<Command> rename_object(std::uint64_t id, std::string name) {
    return std::make_unique<RenameObject>(id, std::move(name));
}
std::unique_ptr<Command> set_visible(std::uint64_t id, bool visible) {
    return std::make_unique<SetVisible>(id, visible);
}
std::unique_ptr<Command> edit_shape(std::uint64_t id, Shape shape, std::string label,
                                    std::string merge_key) {
    EditShapeSpec spec{id, shape, label, merge_key};
    detail::ShapeEditRule rule;
    rule.make = [shape = std::move(shape)](const Object&) -> geom::Expected<Shape> {
        return shape;
    };
    rule.label = [label = std::move(label)](const Shape&, const Shape&) { return label; };
    rule.merge_key = std::move(merge_key);
    return detail::shape_edit(id, std::move(spec), std::move(rule));
}
std::unique_ptr<Command> edit_point(EditPointSpec spec) {
    return std::make_unique<EditPoint>(std::move(spec));
}
std::unique_ptr<Command> move_control_point(std::uint64_t id, int i, int j, glm::dvec3 position) {
    return edit_point({id, i, j, position, std::nullopt});
}
std::unique_ptr<Command> set_weight(std::uint64_t id, int i, int j, double weight) {
    return edit_point({id, i, j, std::nullopt, weight});
}
std::unique_ptr<Command> set_knot(std::uint64_t id, geom::Dir dir, int k, double value) {
    return std::make_unique<SetKnot>(id, dir, k, 1, value);
}
std::unique_ptr<Command> move_knot_run(std::uint64_t id, geom::Dir dir, int k, int count,
                                       double value) {
    return std::make_unique<SetKnot>(id, dir, k, count, value);
}
std::unique_ptr<Command> transform_object(std::uint64_t id, const glm::dmat4& m) {
    return std::make_unique<TransformObject>(id, m, std::string());
}
std::unique_ptr<Command> transform_object(std::uint64_t id, const glm::dmat4& m,
                                          std::string label) {
    return std::make_unique<TransformObject>(id, m, std::move(label));
}
std::unique_ptr<Command> set_colors(Colors colors) {
    return std::make_unique<SetColors>(colors);
}

} // namespace isoparm::doc
