// Refinement commands (knot insertion, degree elevation, split) and their selection remapping.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <optional>
#include <set>
#include <tuple>

#include "core/doc/commands.hpp"
#include "core/doc/commands_common.hpp"
#include "core/doc/commands_triangle.hpp"
#include "core/doc/patches.hpp"
#include "core/doc/placement.hpp"
#include "core/doc/refinement_edit.hpp"
#include "core/doc/shape_edit.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/refine.hpp"
#include "core/geom/refine_within_limits.hpp"
#include "core/geom/validate.hpp"

namespace isoparm::doc {

namespace {

using geom::Dir;
using geom::ErrorCode;
using geom::make_error;

using namespace detail;

// ---------------------------------------------------------------------------------------
// Borders made to conform by knot insertion (shape unchanged), shared by the split and
// conform_borders: what was inserted, for the label and for undo.
struct Conforming {
    std::vector<std::unique_ptr<Command>> applied; // insert_knot commands, in order
    std::vector<std::uint64_t> objects;            // the patches refined, first refinement order
    std::string summary;                           // "wave.2: v = 0.5 x2"

    void revert(Document& doc) {
        for (auto it = applied.rbegin(); it != applied.rend(); ++it) (*it)->revert(doc);
    }
    void clear() {
        applied.clear();
        objects.clear();
        summary.clear();
    }
    std::size_t memory_bytes() const {
        std::size_t bytes = summary.size() + objects.size() * sizeof(std::uint64_t);
        for (const auto& c : applied) bytes += c->memory_bytes();
        return bytes;
    }
};

// Inserts knots, round after round, until the group's `wanted` borders conform
// (conforming_insertions). A refusal (a size cap) reverts what this call inserted and is
// returned. The number of rounds is bounded: a round only inserts knot values the group
// already holds, up to the degree, so the plan soon comes back empty.
geom::Status refine_until_conforming(Document& doc, std::uint64_t group,
                                     const std::function<bool(const SharedBorder&)>& wanted,
                                     Conforming& out) {
    out.clear();
    for (int round = 0; round < 64; ++round) {
        const std::vector<KnotInsertion> plan = conforming_insertions(doc, group, wanted);
        if (plan.empty()) return geom::Ok{};
        for (const KnotInsertion& k : plan) {
            auto cmd = insert_knot(k.object, k.dir, k.t, k.times);
            if (auto st = cmd->apply(doc); !st) {
                out.revert(doc);
                out.clear();
                return st;
            }
            out.applied.push_back(std::move(cmd));
            if (std::find(out.objects.begin(), out.objects.end(), k.object) == out.objects.end())
                out.objects.push_back(k.object);
            const Object* o = doc.find(k.object);
            if (!out.summary.empty()) out.summary += ", ";
            out.summary += (o ? o->name : std::string("?")) + ": " + dir_name(k.dir) + " = " +
                           geom::format_short(k.t) +
                           (k.times > 1 ? " x" + std::to_string(k.times) : std::string());
            // A (rational) Bezier neighbour becomes a B-spline (NURBS): never silently.
            if (const std::string change = refinement_type_change(*out.applied.back());
                !change.empty())
                out.summary += ", " + change;
        }
    }
    return geom::Ok{};
}

// ---------------------------------------------------------------------------------------
// The group's borders made to conform where knot insertion can do it (continuity switched
// on after the patches were made, or borders an insertion broke).
class ConformBorders final : public Command {
public:
    explicit ConformBorders(std::uint64_t group) : group_(group) {}

    geom::Status apply(Document& doc) override {
        return refine_until_conforming(doc, group_, {}, done_);
    }
    void revert(Document& doc) override { done_.revert(doc); }
    std::string label() const override {
        return done_.summary.empty() ? "Borders already pair up"
                                     : "Refine so the borders pair up (" + done_.summary + ")";
    }
    std::size_t memory_bytes() const override { return sizeof(*this) + done_.memory_bytes(); }
    std::optional<CommandSpec> spec() const override { return ConformBordersSpec{group_}; }

private:
    std::uint64_t group_;
    Conforming done_;
};

// ---------------------------------------------------------------------------------------
// Split into two pieces that keep their original parameters (through geom::split).
class SplitObject final : public Command {
public:
    SplitObject(std::uint64_t id, Dir dir, double t) : id_(id), dir_(dir), t_(t) {}

    geom::Status apply(Document& doc) override {
        auto found = refinable(doc, id_, dir_, "splitting");
        if (!found) return found.error();
        Object& obj = **found;
        Shape first, second;
        if (is_trimmed(obj))
            return geom::make_error(geom::ErrorCode::schema,
                                    "object '" + obj.name +
                                        "' is trimmed: a split does not divide its trim loops "
                                        "(remove the trim first)",
                                    "/id");
        if (const geom::Surface* s = obj.surface()) {
            auto r = geom::split(*s, dir_, t_);
            if (!r) return r.error();
            first = SurfaceObject{std::move(r->first)};
            second = SurfaceObject{std::move(r->second)};
        } else {
            const CurveObject& c = *obj.curve_object(); // refinable: a surface or a curve
            auto r = geom::split(c.curve, t_);
            if (!r) return r.error();
            first = CurveObject{std::move(r->first), c.plane};
            second = CurveObject{std::move(r->second), c.plane};
        }

        curve_ = is_curve(obj.shape);
        // The setting is read once: a redo replays the split as it was made.
        if (!mode_) mode_ = doc.continuity;
        // Which borders conform now: the split must not leave one of them broken.
        const std::uint64_t old_group = obj.patch_group;
        std::set<std::tuple<std::uint64_t, std::uint64_t, int>> conformed_before;
        for (const SharedBorder& b : shared_borders(doc, old_group))
            if (b.conforming) conformed_before.insert({b.low, b.high, static_cast<int>(b.across)});
        sel_before_ = doc.view.selection;
        index_ = doc.index_of(id_);
        prev_next_id_ = doc.next_id;
        if (ids_.first == 0) {
            ids_.first = doc.allocate_id();
            ids_.second = doc.allocate_id();
        } else {
            // Redo: the same ids as the first time, so later commands still find the pieces.
            doc.next_id = std::max(doc.next_id, ids_.second + 1);
        }

        remap_forward(doc.view.selection, obj.shape, first, second);
        sel_after_ = doc.view.selection;

        // Surface pieces stay one patch structure over the original domain; the
        // first split names the group after the surface it started from.
        const std::uint64_t group = curve_ ? 0 : obj.patch_group != 0 ? obj.patch_group : obj.id;
        // Names no other object has (a scene may already hold a "hill.1").
        Object a{ids_.first, unique_name(doc, obj.name + ".1", obj.id), std::move(first),
                 obj.visible, group};
        Object b{ids_.second, unique_name(doc, obj.name + ".2", obj.id), std::move(second),
                 obj.visible, group};
        before_ = std::move(obj);
        doc.objects[index_] = std::move(a);
        doc.objects.insert(doc.objects.begin() + index_ + 1, std::move(b));

        // With continuity on, the borders the pieces now share with their neighbours (the new
        // split line ends on a neighbour's border, or the pieces' edges meet a refined
        // neighbour) get the knots they lack, on either side, so every one pairs up point for
        // point; borders that conformed before stay so. The paper's split at u = 0.75 and then
        // the left part at v = 0.5: the right part gains v = 0.5 to multiplicity 3.
        conforming_.clear();
        if (!curve_ && *mode_ != Continuity::off) {
            auto wanted = [&](const SharedBorder& sb) {
                const bool piece = sb.low == ids_.first || sb.low == ids_.second ||
                                   sb.high == ids_.first || sb.high == ids_.second;
                return piece ||
                       conformed_before.count({sb.low, sb.high, static_cast<int>(sb.across)}) > 0;
            };
            if (auto st = refine_until_conforming(doc, group, wanted, conforming_); !st) {
                revert_split(doc);
                return st;
            }
        }
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        // The refinements after the split first, then the split itself.
        conforming_.revert(doc);
        revert_split(doc);
    }

    std::string label() const override {
        std::string s = std::string("Split at ") + (curve_ ? "t" : dir_name(dir_)) + " = " +
                        geom::format_short(t_);
        if (conforming_.objects.empty()) return s;
        // Neighbours refined (the pieces may be refined too: they are not counted).
        const auto neighbours = static_cast<std::size_t>(
            std::count_if(conforming_.objects.begin(), conforming_.objects.end(),
                          [&](std::uint64_t id) { return id != ids_.first && id != ids_.second; }));
        s += " (and " + std::to_string(neighbours) +
             (neighbours == 1 ? " neighbour" : " neighbours") +
             " refined so every border pairs up: " + conforming_.summary + ")";
        return s;
    }

    std::size_t memory_bytes() const override {
        return sizeof(*this) + before_.name.size() + detail::shape_bytes(before_.shape) +
               conforming_.memory_bytes();
    }

    std::optional<CommandSpec> spec() const override { return SplitSpec{id_, dir_, t_}; }
    std::pair<std::uint64_t, std::uint64_t> ids() const { return ids_; }

private:
    void revert_split(Document& doc) {
        assert(index_ >= 0 && index_ + 1 < static_cast<int>(doc.objects.size()));
        assert(doc.objects[index_].id == ids_.first && doc.objects[index_ + 1].id == ids_.second);
        if (doc.view.selection == sel_after_) {
            doc.view.selection = sel_before_;
        } else if (doc.view.selection.object == ids_.first ||
                   doc.view.selection.object == ids_.second) {
            const Object& piece =
                doc.objects[doc.view.selection.object == ids_.first ? index_ : index_ + 1];
            doc.view.selection.object = id_;
            if (int* idx = selected_index(doc.view.selection, id_, curve_, dir_))
                *idx = nearest_greville(line_of(before_.shape, dir_),
                                        greville(line_of(piece.shape, dir_), *idx));
        }
        doc.objects.erase(doc.objects.begin() + index_ + 1);
        doc.objects[index_] = before_;
        doc.next_id = prev_next_id_;
    }

    // A selected control point goes to the piece on its side of t (by Greville abscissa; a
    // point exactly at t, the shared border, stays with the first piece) and there to the
    // point with the nearest Greville abscissa: the same point where the piece kept it.
    void remap_forward(Selection& sel, const Shape& whole, const Shape& first,
                       const Shape& second) const {
        if (sel.object != id_) return;
        sel.object = ids_.first;
        int* idx = selected_index(sel, ids_.first, curve_, dir_);
        if (!idx) return;
        const double g = greville(line_of(whole, dir_), *idx);
        if (g > t_) sel.object = ids_.second;
        *idx = nearest_greville(line_of(g > t_ ? second : first, dir_), g);
    }

    std::uint64_t id_;
    Dir dir_;
    double t_;
    bool curve_ = false;
    Conforming conforming_;
    std::optional<Continuity> mode_;
    int index_ = -1;
    std::uint64_t prev_next_id_ = 0;
    std::pair<std::uint64_t, std::uint64_t> ids_{0, 0};
    Object before_;
    Selection sel_before_, sel_after_;
};

} // namespace

// Knot insertion (Boehm; Piegl & Tiller A5.1 through geom::insert_knot).
std::unique_ptr<Command> insert_knot(std::uint64_t id, geom::Dir dir, double t, int times) {
    Refinement r;
    r.dir = dir;
    r.what = "knot insertion";
    r.surface = [=](const geom::Surface& s) {
        return geom::insert_knot_within_limits(s, dir, t, times);
    };
    r.curve = [=](const geom::Curve& c) { return geom::insert_knot_within_limits(c, t, times); };
    r.label = [=](const Shape& before, const Shape&) {
        const bool curve = is_curve(before);
        std::string s = std::string("Insert knot ") + (curve ? "t" : dir_name(dir)) + " = " +
                        geom::format_short(t);
        if (times > 1) s += " (" + std::to_string(times) + " times)";
        return s;
    };
    // Piegl & Tiller A5.1: with k the span of t (last knot <= t) and s its multiplicity,
    // Q[i] = P[i] for i <= k - p and Q[i + r] = P[i] for i >= k - s; the points between are
    // replaced, and go to the new point with the nearest Greville abscissa.
    auto span_and_multiplicity = [t](const Line& old_line) {
        const geom::Knots& U = *old_line.U;
        const int k = static_cast<int>(std::upper_bound(U.begin(), U.end(), t) - U.begin()) - 1;
        return std::pair{k, geom::multiplicity(U, t)};
    };
    r.forward = [=](const Line& old_line, const Line& new_line, int i) {
        const auto [k, s] = span_and_multiplicity(old_line);
        if (i <= k - old_line.p) return clamp_index(i, new_line.n);
        if (i >= k - s) return clamp_index(i + times, new_line.n);
        return nearest_greville(new_line, greville(old_line, i));
    };
    r.backward = [=](const Line& old_line, const Line& new_line, int i) {
        const auto [k, s] = span_and_multiplicity(old_line);
        if (i <= k - old_line.p) return clamp_index(i, old_line.n);
        if (i >= k - s + times) return clamp_index(i - times, old_line.n);
        return nearest_greville(old_line, greville(new_line, i));
    };
    return refinement_command(id, InsertKnotSpec{id, dir, t, times}, std::move(r));
}

// Degree elevation (Piegl & Tiller A5.9 through geom::elevate_degree).
std::unique_ptr<Command> elevate_degree(std::uint64_t id, geom::Dir dir, int times) {
    Refinement r;
    r.dir = dir;
    r.what = "degree elevation";
    r.surface = [=](const geom::Surface& s) {
        return geom::elevate_degree_within_limits(s, dir, times);
    };
    r.curve = [=](const geom::Curve& c) { return geom::elevate_degree_within_limits(c, times); };
    // A triangle has one degree: the direction means nothing to it (Farin 17.6).
    r.triangle = [=](const geom::TrianglePatch& t) -> geom::Expected<geom::TrianglePatch> {
        if (times < 1)
            return geom::make_error(geom::ErrorCode::schema,
                                    "times must be at least 1, got " + std::to_string(times),
                                    "/times");
        if (times > geom::max_triangle_degree - t.degree)
            return geom::make_error(geom::ErrorCode::limit,
                                    "elevating a degree-" + std::to_string(t.degree) +
                                        " triangle " + std::to_string(times) +
                                        " times is above the cap of degree " +
                                        std::to_string(geom::max_triangle_degree),
                                    "/times");
        return geom::elevate_triangle(t, times);
    };
    r.label = [=](const Shape& before, const Shape&) {
        // A tensor-product surface has two degrees; curves and triangles one.
        const bool one_degree = !surface_of(before);
        std::string s =
            one_degree ? "Elevate degree" : std::string("Elevate degree in ") + dir_name(dir);
        if (times > 1) s += " by " + std::to_string(times);
        return s;
    };
    return refinement_command(id, ElevateDegreeSpec{id, dir, times}, std::move(r));
}

std::unique_ptr<Command> split_object(std::uint64_t id, geom::Dir dir, double t) {
    return std::make_unique<SplitObject>(id, dir, t);
}

std::unique_ptr<Command> conform_borders(std::uint64_t group) {
    return std::make_unique<ConformBorders>(group);
}

std::string refinement_type_change(const Command& refine_command) {
    return detail::shape_edit_type_change(refine_command);
}

std::pair<std::uint64_t, std::uint64_t> split_piece_ids(const Command& split_command) {
    if (auto* s = dynamic_cast<const SplitObject*>(&split_command)) return s->ids();
    return {0, 0};
}

} // namespace isoparm::doc
