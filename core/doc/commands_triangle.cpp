// Triangular patches as document objects: a new flat patch and the split at a point (Farin
// 17.5 through geom::split_triangle), with the selection following its control point.
#include "core/doc/commands_triangle.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/doc/commands_common.hpp"

namespace isoparm::doc {

using geom::ErrorCode;
using geom::make_error;

geom::Expected<geom::TrianglePatch> make_flat_triangle(int degree, bool rational) {
    if (degree < 1 || degree > max_new_triangle_degree)
        return make_error(ErrorCode::degree,
                          "a new triangular patch takes a degree from 1 to " +
                              std::to_string(max_new_triangle_degree) + ", got " +
                              std::to_string(degree),
                          "/degree");
    // The corners b_n00, b_0n0, b_00n: an equilateral triangle of side 2*sqrt(3) about the
    // origin in the xy-plane, counter-clockwise, so the normal S_r x S_s points up (+z).
    const glm::dvec3 corner[3] = {{2, 0, 0}, {-1, std::sqrt(3.0), 0}, {-1, -std::sqrt(3.0), 0}};
    geom::TrianglePatch t;
    t.rational = rational;
    t.degree = degree;
    const int n = degree;
    t.points.resize(static_cast<std::size_t>(geom::TrianglePatch::count_for(n)));
    t.weights.assign(t.points.size(), 1.0);
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
            const int k = n - i - j;
            t.points[geom::TrianglePatch::index(n, i, j)] =
                (static_cast<double>(i) * corner[0] + static_cast<double>(j) * corner[1] +
                 static_cast<double>(k) * corner[2]) /
                static_cast<double>(n);
        }
    return t;
}

geom::Barycentric control_point_domain(int n, int i, int j) {
    return {static_cast<double>(i) / n, static_cast<double>(j) / n,
            static_cast<double>(n - i - j) / n};
}

std::pair<int, int> nearest_control_point(int m, const geom::Barycentric& q) {
    int best_i = 0, best_j = 0;
    double best = INFINITY;
    for (int i = 0; i <= m; ++i)
        for (int j = 0; i + j <= m; ++j) {
            const geom::Barycentric c = control_point_domain(m, i, j);
            const double d = (c[0] - q[0]) * (c[0] - q[0]) + (c[1] - q[1]) * (c[1] - q[1]) +
                             (c[2] - q[2]) * (c[2] - q[2]);
            if (d < best) best = d, best_i = i, best_j = j; // ties keep the first
        }
    return {best_i, best_j};
}

namespace {

// The protocol's tolerance on r + s + t = 1 (geom-protocol-2.md).
constexpr double barycentric_tolerance = 1e-12;

// q in piece v's own coordinates (the split point p in place of vertex v): q = a_v p +
// sum_{w != v} a_w e_w, so a_v = q_v / p_v and a_w = q_w - a_v p_w.
geom::Barycentric piece_coordinates(const geom::Barycentric& p, const geom::Barycentric& q, int v) {
    geom::Barycentric a{};
    a[v] = q[v] / p[v];
    for (int w = 0; w < 3; ++w)
        if (w != v) a[w] = q[w] - a[v] * p[w];
    return a;
}

class SplitTriangle final : public Command {
public:
    SplitTriangle(std::uint64_t id, geom::Barycentric at) : id_(id), at_(at) {}

    geom::Status check(const Document& doc) const override {
        auto found = detail::find_object(doc, id_);
        if (!found) return found.error();
        auto pieces = pieces_of(**found);
        if (!pieces) return pieces.error();
        return geom::Ok{};
    }

    geom::Status apply(Document& doc) override {
        auto found = detail::find_object(doc, id_);
        if (!found) return found.error();
        Object& obj = **found;
        auto pieces = pieces_of(obj);
        if (!pieces) return pieces.error();

        sel_before_ = doc.view.selection;
        index_ = doc.index_of(id_);
        prev_next_id_ = doc.next_id;
        if (ids_[0] == 0) {
            for (std::uint64_t& id : ids_) id = doc.allocate_id();
        } else {
            // Redo: the same ids as the first time, so later commands still find the pieces.
            doc.next_id = std::max(doc.next_id, ids_[2] + 1);
        }
        if (doc.view.selection.object == id_) {
            Selection& sel = doc.view.selection;
            if (sel.has_point()) {
                const int v = piece_holding(obj.triangle()->degree, sel.i, sel.j);
                const geom::Barycentric local = piece_coordinates(
                    at_, control_point_domain(obj.triangle()->degree, sel.i, sel.j), v);
                const auto [i, j] = nearest_control_point(obj.triangle()->degree, local);
                sel = Selection{ids_[v], i, j};
            } else {
                sel.object = ids_[0];
            }
        }
        sel_after_ = doc.view.selection;

        before_ = obj;
        std::vector<Object> made;
        for (int v = 0; v < 3; ++v)
            made.push_back(Object{ids_[v], obj.name + "." + std::to_string(v + 1),
                                  TriangleObject{std::move((*pieces)[v])}, obj.visible, 0});
        doc.objects[index_] = std::move(made[0]);
        doc.objects.insert(doc.objects.begin() + index_ + 1,
                           std::make_move_iterator(made.begin() + 1),
                           std::make_move_iterator(made.end()));
        return geom::Ok{};
    }

    void revert(Document& doc) override {
        assert(index_ >= 0 && index_ + 2 < static_cast<int>(doc.objects.size()));
        assert(doc.objects[index_].id == ids_[0] && doc.objects[index_ + 2].id == ids_[2]);
        doc.objects.erase(doc.objects.begin() + index_ + 1, doc.objects.begin() + index_ + 3);
        doc.objects[index_] = before_;
        doc.next_id = prev_next_id_;
        if (doc.view.selection == sel_after_)
            doc.view.selection = sel_before_;
        else if (std::find(ids_.begin(), ids_.end(), doc.view.selection.object) != ids_.end())
            doc.view.selection = Selection{id_};
    }

    std::string label() const override {
        return "Split triangle at (" + geom::format_short(at_[0]) + ", " +
               geom::format_short(at_[1]) + ", " + geom::format_short(at_[2]) + ")";
    }
    std::size_t memory_bytes() const override {
        return sizeof(*this) + before_.name.size() + detail::shape_bytes(before_.shape);
    }
    std::optional<CommandSpec> spec() const override { return SplitTriangleSpec{id_, at_}; }
    std::array<std::uint64_t, 3> ids() const { return ids_; }

private:
    geom::Expected<std::array<geom::TrianglePatch, 3>> pieces_of(const Object& obj) const {
        const geom::TrianglePatch* t = obj.triangle();
        if (!t) return kind_refusal(obj, "split_triangle splits a triangular patch");
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(at_[k]))
                return make_error(ErrorCode::schema, "a barycentric coordinate must be finite",
                                  "/param/" + std::to_string(k));
        const double sum = at_[0] + at_[1] + at_[2];
        if (!(at_[0] > 0 && at_[1] > 0 && at_[2] > 0) ||
            !(std::abs(sum - 1) <= barycentric_tolerance))
            return make_error(ErrorCode::domain,
                              "[" + geom::format_number(at_[0]) + ", " +
                                  geom::format_number(at_[1]) + ", " + geom::format_number(at_[2]) +
                                  "] is not strictly inside the triangle (each coordinate > 0, "
                                  "sum 1)",
                              "/param");
        return geom::split_triangle(*t, at_);
    }

    // The piece whose domain holds control point (i, j)'s domain point: the one in whose
    // coordinates it has no negative coordinate (the first such, on a shared edge).
    int piece_holding(int n, int i, int j) const {
        const geom::Barycentric q = control_point_domain(n, i, j);
        for (int v = 0; v < 3; ++v) {
            const geom::Barycentric a = piece_coordinates(at_, q, v);
            if (a[0] >= -1e-12 && a[1] >= -1e-12 && a[2] >= -1e-12) return v;
        }
        return 0;
    }

    std::uint64_t id_;
    geom::Barycentric at_;
    std::array<std::uint64_t, 3> ids_{0, 0, 0};
    Object before_;
    int index_ = -1;
    std::uint64_t prev_next_id_ = 0;
    Selection sel_before_, sel_after_;
};

} // namespace

std::unique_ptr<Command> split_triangle(std::uint64_t id, geom::Barycentric at) {
    return std::make_unique<SplitTriangle>(id, at);
}

std::array<std::uint64_t, 3> split_triangle_ids(const Command& split_command) {
    if (auto* s = dynamic_cast<const SplitTriangle*>(&split_command)) return s->ids();
    return {0, 0, 0};
}

} // namespace isoparm::doc
