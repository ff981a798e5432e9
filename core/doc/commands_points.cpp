// move_points and transform_points: one command moves a whole selection.
#include "core/doc/commands_points.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <set>

#include "core/doc/commands_common.hpp"
#include "core/doc/commands_curve.hpp"
#include "core/doc/patches.hpp"
#include "core/geom/reshape.hpp"

namespace isoparm::doc {

using geom::ErrorCode;
using geom::make_error;

namespace {

std::string point_name(const Shape& shape, PointIndex p) {
    if (const geom::TrianglePatch* t = triangle_of(shape))
        return detail::triangle_point_label('b', t->degree, p.i, p.j);
    return detail::point_label('P', p.i, curve_of(shape) ? -1 : p.j);
}

geom::Status check_points(const Object& obj, const std::vector<PointIndex>& points) {
    if (obj.implicit())
        return make_error(
            ErrorCode::schema,
            "object '" + obj.name + "' is an implicit surface; it has no control points", "/id");
    if (points.empty())
        return make_error(ErrorCode::schema, "name at least one control point to move", "/points");
    std::set<PointIndex> seen;
    const bool curve = obj.curve() != nullptr;
    for (std::size_t k = 0; k < points.size(); ++k) {
        PointIndex p = points[k];
        if (curve && p.j == 0) p.j = -1;
        const std::string at = "/points/" + std::to_string(k);
        if (!has_control_point(obj.shape, p.i, p.j))
            return make_error(
                ErrorCode::schema,
                "object '" + obj.name + "' has no control point " +
                    (curve ? "[" + std::to_string(p.i) + "]"
                           : "[" + std::to_string(p.i) + ", " + std::to_string(p.j) + "]"),
                at);
        if (!seen.insert(p).second)
            return make_error(ErrorCode::schema,
                              "control point " + point_name(obj.shape, p) + " is named twice", at);
    }
    return geom::Ok{};
}

void set_position(Shape& shape, PointIndex p, const glm::dvec3& x) {
    if (geom::Surface* s = surface_of(shape))
        s->point(p.i, p.j) = x;
    else if (geom::Curve* c = curve_of(shape))
        c->points[static_cast<std::size_t>(p.i)] = x;
    else if (geom::TrianglePatch* t = triangle_of(shape))
        t->points[static_cast<std::size_t>(geom::TrianglePatch::index(t->degree, p.i, p.j))] = x;
}

// The shape with the points moved; a curve's knots follow its knot mode as the curve
// designer's moves do (a closed curve's repeated points are its polygon's).
geom::Expected<Shape> moved(const Object& obj, const std::vector<PointIndex>& points,
                            const std::vector<glm::dvec3>& targets) {
    Shape shape = obj.shape;
    CurveObject* c = curve_object_of(shape);
    if (c && c->knot_mode == CurveKnotMode::closed) {
        const int n = std::max(c->curve.count() - c->curve.degree, 1);
        for (std::size_t k = 0; k < points.size(); ++k)
            c->curve.points[static_cast<std::size_t>(points[k].i % n)] = targets[k];
        c->curve.points.resize(static_cast<std::size_t>(n));
        c->curve.weights.resize(static_cast<std::size_t>(n));
        c->curve = geom::close_periodic(c->curve);
        return shape;
    }
    for (std::size_t k = 0; k < points.size(); ++k) set_position(shape, points[k], targets[k]);
    if (c && !geom::is_bezier(c->curve.type) &&
        (c->knot_mode == CurveKnotMode::chord || c->knot_mode == CurveKnotMode::centripetal)) {
        auto knots = knots_for_mode(c->curve, c->knot_mode);
        if (!knots)
            return make_error(knots.error().code,
                              "curve '" + obj.name + "' with " + knot_mode_label(c->knot_mode) +
                                  " knots: " + knots.error().message,
                              "/positions");
        c->curve.knots = std::move(knots).value();
    }
    return shape;
}

class PointsEdit final : public Command {
public:
    explicit PointsEdit(MovePointsSpec s) : move_(std::move(s)) {}
    explicit PointsEdit(TransformPointsSpec s) : transform_(std::move(s)) {}

    geom::Status apply(Document& doc) override {
        auto found = detail::find_object(doc, id());
        if (!found) return found.error();
        Object& obj = **found;
        std::vector<PointIndex> pts = points();
        if (auto st = check_points(obj, pts); !st) return st;
        if (obj.curve())
            for (PointIndex& p : pts) p.j = -1;
        auto targets = targets_for(obj, pts);
        if (!targets) return targets.error();
        auto shape = moved(obj, pts, *targets);
        if (!shape) return shape.error();
        if (auto st = detail::validate_shape(*shape); !st) return st.error().under("/positions");
        count_ = pts.size();
        first_ = point_name(obj.shape, pts.front());
        old_ = std::move(obj.shape);
        obj.shape = std::move(shape).value();
        // Subpatches: each moved point's neighbours follow, as for one point.
        neighbours_.clear();
        if (obj.surface() && obj.patch_group != 0) {
            if (!mode_) mode_ = doc.continuity;
            for (PointIndex p : pts) {
                auto changes = keep_continuity(doc, id(), p.i, p.j, *mode_);
                neighbours_.insert(neighbours_.end(), changes.begin(), changes.end());
            }
        }
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        Object* obj = doc.find(id());
        assert(obj && old_);
        restore_points(doc, neighbours_);
        neighbours_.clear();
        obj->shape = std::move(*old_);
        old_.reset();
    }

    bool merge_with(const Command& next) override {
        const auto* m = dynamic_cast<const PointsEdit*>(&next);
        if (!m || !move_ || !m->move_ || m->move_->id != move_->id ||
            m->move_->points != move_->points)
            return false;
        move_ = m->move_; // old_ stays: the shape before the whole drag
        // The first recorded value of each neighbour point is the one undo needs.
        for (const PointChange& c : m->neighbours_)
            if (std::none_of(neighbours_.begin(), neighbours_.end(), [&](const PointChange& n) {
                    return n.object == c.object && n.i == c.i && n.j == c.j;
                }))
                neighbours_.push_back(c);
        return true;
    }

    std::string label() const override {
        const std::string& given = move_ ? move_->label : transform_->label;
        if (!given.empty()) return given;
        const std::string what = count_ == 1 ? first_ : std::to_string(count_) + " points";
        return (move_ ? "Move " : "Transform ") + what;
    }
    std::optional<CommandSpec> spec() const override {
        if (move_) return *move_;
        return *transform_;
    }
    std::size_t memory_bytes() const override {
        return sizeof(*this) + (old_ ? detail::shape_bytes(*old_) : 0) +
               neighbours_.capacity() * sizeof(PointChange) +
               (move_ ? move_->positions.capacity() * sizeof(glm::dvec3) : 0);
    }

private:
    std::uint64_t id() const { return move_ ? move_->id : transform_->id; }
    const std::vector<PointIndex>& points() const {
        return move_ ? move_->points : transform_->points;
    }

    geom::Expected<std::vector<glm::dvec3>> targets_for(const Object& obj,
                                                        const std::vector<PointIndex>& pts) const {
        std::vector<glm::dvec3> out;
        if (move_) {
            if (move_->positions.size() != pts.size())
                return make_error(ErrorCode::schema,
                                  "one position per point: " + std::to_string(pts.size()) +
                                      " points, " + std::to_string(move_->positions.size()) +
                                      " positions",
                                  "/positions");
            for (std::size_t k = 0; k < pts.size(); ++k)
                for (int a = 0; a < 3; ++a)
                    if (!std::isfinite(move_->positions[k][a]))
                        return make_error(
                            ErrorCode::schema, "a control point needs finite coordinates",
                            "/positions/" + std::to_string(k) + "/" + std::to_string(a));
            return move_->positions;
        }
        const glm::dmat4& m = transform_->matrix;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(m[c][r]))
                    return make_error(ErrorCode::schema, "a transform needs finite entries",
                                      "/matrix");
        if (m[0][3] != 0 || m[1][3] != 0 || m[2][3] != 0 || m[3][3] != 1)
            return make_error(ErrorCode::schema, "a transform must be affine (bottom row 0 0 0 1)",
                              "/matrix");
        glm::dvec3 pivot(0);
        if (transform_->about == Pivot::centroid) pivot = centroid(obj.shape, pts);
        if (transform_->about == Pivot::point) {
            pivot = transform_->pivot;
            for (int a = 0; a < 3; ++a)
                if (!std::isfinite(pivot[a]))
                    return make_error(ErrorCode::schema, "the pivot needs finite coordinates",
                                      "/about/" + std::to_string(a));
        }
        // About the pivot: p -> pivot + M (p - pivot), with M's linear part and translation, so
        // a point at the pivot stays exactly there.
        const glm::dmat3 linear(m);
        const glm::dvec3 shift(m[3]);
        for (PointIndex p : pts) {
            const glm::dvec3 x = pivot + (linear * (position_of(obj.shape, p) - pivot) + shift);
            for (int a = 0; a < 3; ++a)
                if (!std::isfinite(x[a]))
                    return make_error(ErrorCode::schema,
                                      "the transform would move control point " +
                                          point_name(obj.shape, p) + " to infinity",
                                      "/matrix");
            out.push_back(x);
        }
        return out;
    }

    std::optional<MovePointsSpec> move_;
    std::optional<TransformPointsSpec> transform_;
    std::optional<Shape> old_;
    std::optional<Continuity> mode_;
    std::vector<PointChange> neighbours_;
    std::size_t count_ = 0;
    std::string first_;
};

} // namespace

std::unique_ptr<Command> move_points(MovePointsSpec spec) {
    return std::make_unique<PointsEdit>(std::move(spec));
}
std::unique_ptr<Command> transform_points(TransformPointsSpec spec) {
    return std::make_unique<PointsEdit>(std::move(spec));
}

} // namespace isoparm::doc
