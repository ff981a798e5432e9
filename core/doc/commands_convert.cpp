// Type conversion (Surface > Convert to, the `convert` command): an object as another spline
// type, or its Bezier pieces in its place.
#include <algorithm>
#include <cassert>
#include <functional>
#include <optional>

#include "core/doc/commands.hpp"
#include "core/doc/commands_common.hpp"
#include "core/doc/placement.hpp"
#include "core/geom/convert.hpp"

namespace isoparm::doc {

namespace {

using geom::ErrorCode;
using geom::make_error;
using geom::SplineType;

bool all_weights_equal(const std::vector<double>& w) {
    return std::adjacent_find(w.begin(), w.end(), std::not_equal_to<>()) == w.end();
}

// Surfaces and curves have a spline type (an allow-list): every other kind is refused.
bool has_spline_type(const Object& obj) {
    return obj.surface() || obj.curve();
}
geom::Error no_spline_type(const Object& obj) {
    return kind_refusal(obj, "only surfaces and curves have a spline type to convert");
}

template <class S> auto* weights_of(S& shape) {
    if (auto* s = surface_of(shape)) return &s->weights;
    auto* c = curve_of(shape);
    return c ? &c->weights : nullptr;
}

std::optional<SplineType> type_of(const Shape& shape) {
    if (const geom::Surface* s = surface_of(shape)) return s->type;
    if (const geom::Curve* c = curve_of(shape)) return c->type;
    return std::nullopt;
}

// The pieces of the object's shape as `to` (one, or its Bezier pieces); weights set to 1
// first when asked. Errors at the command's members.
geom::Expected<std::vector<Shape>> converted(const Object& obj, SplineType to, bool reset) {
    if (!has_spline_type(obj)) return no_spline_type(obj);
    Shape shape = obj.shape;
    if (auto* w = weights_of(shape); w && reset) std::fill(w->begin(), w->end(), 1.0);
    std::vector<Shape> out;
    auto rehome = [&](geom::Error e) {
        // The geometry names the weight ("/weights/3"); the command's member is "to".
        e.message = "object '" + obj.name + "' cannot become " + geom::label_of(to) + ": " +
                    e.message + " (reset the weights to 1 to convert anyway; the shape changes)";
        e.path = "/to";
        return e;
    };
    if (const geom::Surface* s = surface_of(shape)) {
        auto pieces = geom::convert(*s, to);
        if (!pieces) return rehome(pieces.error());
        const geom::Trim& trim = *trim_of(obj.shape);
        if (!trim.empty() && pieces->size() > 1)
            return geom::make_error(geom::ErrorCode::schema,
                                    "object '" + obj.name + "' is trimmed: as " +
                                        geom::label_of(to) + " it would be " +
                                        std::to_string(pieces->size()) +
                                        " pieces, and a trim is not divided among pieces "
                                        "(remove the trim first)",
                                    "/to");
        for (geom::Surface& p : *pieces) out.push_back(SurfaceObject{std::move(p), trim});
    } else {
        const CurveObject& c = *curve_object_of(shape);
        auto pieces = geom::convert(c.curve, to);
        if (!pieces) return rehome(pieces.error());
        // The pieces' knots are their own (custom): no knot rule made them.
        for (geom::Curve& p : *pieces) out.push_back(CurveObject{std::move(p), c.plane});
    }
    return out;
}

class ConvertObject final : public Command {
public:
    ConvertObject(std::uint64_t id, SplineType to, bool reset) : id_(id), to_(to), reset_(reset) {}

    geom::Status apply(Document& doc) override {
        auto found = detail::find_object(doc, id_);
        if (!found) return found.error();
        Object& obj = **found;
        auto pieces = converted(obj, to_, reset_);
        if (!pieces) return pieces.error();
        if (pieces->size() == 1 && type_of(obj.shape) == to_ && !reset_)
            return make_error(ErrorCode::schema,
                              "object '" + obj.name + "' is already " + geom::label_of(to_), "/to");
        index_ = doc.index_of(id_);
        count_ = pieces->size();
        prev_next_id_ = doc.next_id;
        sel_before_ = doc.view.selection;
        before_ = obj;
        type_before_ = geom::label_of(*type_of(obj.shape));
        if (ids_.empty()) {
            // One piece keeps the object's id; several get fresh ones (a redo: the same again).
            if (count_ == 1)
                ids_.push_back(id_);
            else
                for (std::size_t k = 0; k < count_; ++k) ids_.push_back(doc.allocate_id());
        } else if (count_ > 1) {
            doc.next_id = std::max(doc.next_id, ids_.back() + 1);
        }
        std::vector<Object> made;
        const bool surface = obj.surface() != nullptr;
        for (std::size_t k = 0; k < count_; ++k) {
            Object o = obj;
            o.id = ids_[k];
            o.shape = std::move((*pieces)[k]);
            if (count_ > 1) {
                o.name = unique_name(doc, obj.name + "." + std::to_string(k + 1), obj.id);
                // The pieces share the original domain, as the pieces of a split do.
                if (surface && o.patch_group == 0) o.patch_group = obj.id;
            }
            made.push_back(std::move(o));
        }
        doc.objects.erase(doc.objects.begin() + index_);
        doc.objects.insert(doc.objects.begin() + index_, std::make_move_iterator(made.begin()),
                           std::make_move_iterator(made.end()));
        Selection& sel = doc.view.selection;
        if (sel.object == id_) {
            sel.object = ids_.front();
            // One piece has the same control net; pieces have new ones.
            if (count_ > 1) sel.i = sel.j = -1;
        }
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        assert(index_ >= 0 && index_ + count_ <= doc.objects.size());
        doc.objects.erase(doc.objects.begin() + index_, doc.objects.begin() + index_ + count_);
        doc.objects.insert(doc.objects.begin() + index_, before_);
        doc.next_id = prev_next_id_;
        const auto& sel = doc.view.selection;
        if (std::find(ids_.begin(), ids_.end(), sel.object) != ids_.end())
            doc.view.selection = sel_before_;
    }

    std::string label() const override {
        std::string s =
            "Convert " + before_.name + " from " + type_before_ + " to " + geom::label_of(to_);
        if (count_ > 1) s += " (" + std::to_string(count_) + " Bezier pieces)";
        if (reset_) s += ", weights reset to 1";
        return s;
    }
    std::size_t memory_bytes() const override {
        return sizeof(*this) + before_.name.size() + detail::shape_bytes(before_.shape) * 2;
    }
    std::optional<CommandSpec> spec() const override { return ConvertSpec{id_, to_, reset_}; }

private:
    std::uint64_t id_;
    SplineType to_;
    bool reset_;
    int index_ = -1;
    std::size_t count_ = 0;
    std::uint64_t prev_next_id_ = 0;
    std::vector<std::uint64_t> ids_;
    Object before_;
    std::string type_before_;
    Selection sel_before_;
};

} // namespace

std::unique_ptr<Command> convert_object(std::uint64_t id, SplineType to, bool reset_weights) {
    return std::make_unique<ConvertObject>(id, to, reset_weights);
}

geom::Expected<ConversionLosses> conversion_losses(const Object& object, SplineType to) {
    ConversionLosses out;
    const std::vector<double>* w = weights_of(object.shape);
    if (!w) return no_spline_type(object);
    out.weights_differ = !geom::is_rational(to) && !all_weights_equal(*w);
    auto pieces = converted(object, to, out.weights_differ);
    if (!pieces) return pieces.error();
    out.pieces = static_cast<int>(pieces->size());
    if (out.weights_differ)
        out.text += "The weights are not all equal: a " + std::string(geom::label_of(to)) +
                    " has none, so every weight becomes 1 and the shape changes. ";
    if (out.pieces > 1)
        out.text += "A " + std::string(geom::label_of(to)) + " is one span: '" + object.name +
                    "' becomes its " + std::to_string(out.pieces) + " Bezier pieces (" +
                    object.name + ".1 .. " + object.name + "." + std::to_string(out.pieces) +
                    "), each on its part of the domain; the shape is unchanged. ";
    if (!out.text.empty()) out.text.pop_back();
    return out;
}

} // namespace isoparm::doc
