// The toolbox's commands: knot removal, degree reduction, knot splitting, closing and type
// conversion. The first four are refinement-like shape edits (refinement_edit.hpp) whose label
// says how far the shape moved; conversion may replace an object by its Bezier pieces.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/doc/commands.hpp"
#include "core/doc/commands_common.hpp"
#include "core/doc/refinement_edit.hpp"
#include "core/geom/convert.hpp"
#include "core/geom/degree_reduction.hpp"
#include "core/geom/knot_removal.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/reshape.hpp"

namespace isoparm::doc {

namespace {

using geom::Dir;
using geom::ErrorCode;
using geom::make_error;
using namespace detail;

// What the geometry reported on the first apply, for the label: how many removals, how far the
// shape moved. Shared by the refinement's lambdas (the label is made right after the shape).
struct Outcome {
    int count = 0;
    double moved = 0;
};

// The knot named in a refusal (full precision) or in an undo label (geom::format_short).
std::string where(bool curve, Dir dir, double t, bool label = false) {
    return std::string(curve ? "t" : dir_name(dir)) + " = " +
           (label ? geom::format_short(t) : geom::format_number(t));
}

// Three significant digits: a bound read by a person (the exact value is in no decision).
std::string moved_text(double moved) {
    if (moved == 0) return "shape unchanged";
    return "moves at most " + geom::format_short(moved, 3);
}

// A removal that removed nothing: the knot is essential within the tolerance. How far a single
// removal would move the shape (the same removal with no bound) tells the student why.
// With a weight <= 0 no bound on the movement is known (P&T eq. 5.30 needs w_min > 0), so only
// removals that change nothing pass.
template <class Removal>
geom::Error essential(bool curve, Dir dir, double t, double tolerance,
                      const std::vector<double>& weights, Removal unbounded) {
    std::string text = "knot " + where(curve, dir, t) + " cannot be removed within tolerance " +
                       geom::format_number(tolerance);
    if (auto r = unbounded(); r && r->removed > 0)
        text += ": removing it once would move the " + std::string(curve ? "curve" : "surface") +
                " by " + geom::format_number(r->max_deviation);
    else if (std::any_of(weights.begin(), weights.end(), [](double w) { return !(w > 0); }))
        text += ": with a weight <= 0 no bound on how far a removal moves the shape is known, so "
                "only a removal that changes nothing is made";
    return make_error(ErrorCode::geometry, text + " (raise the tolerance, or keep the knot)",
                      "/knot");
}

// A tolerance with no bound, for "how far would it move" (the geometry refuses infinity).
constexpr double no_bound = 1e300;

} // namespace

std::unique_ptr<Command> remove_knot(std::uint64_t id, Dir dir, double t, int times,
                                     double tolerance) {
    auto outcome = std::make_shared<Outcome>();
    Refinement r;
    r.dir = dir;
    r.what = "knot removal";
    r.surface = [=](const geom::Surface& s) -> geom::Expected<geom::Surface> {
        auto done = geom::remove_knot(s, dir, t, times, tolerance);
        if (!done) return done.error();
        if (done->removed == 0)
            return essential(false, dir, t, tolerance, s.weights,
                             [&] { return geom::remove_knot(s, dir, t, 1, no_bound); });
        *outcome = {done->removed, done->max_deviation};
        return std::move(done->surface);
    };
    r.curve = [=](const geom::Curve& c) -> geom::Expected<geom::Curve> {
        auto done = geom::remove_knot(c, t, times, tolerance);
        if (!done) return done.error();
        if (done->removed == 0)
            return essential(true, dir, t, tolerance, c.weights,
                             [&] { return geom::remove_knot(c, t, 1, no_bound); });
        *outcome = {done->removed, done->max_deviation};
        return std::move(done->curve);
    };
    r.label = [=](const Shape& before, const Shape&) {
        std::string s = "Remove knot " + where(is_curve(before), dir, t, true);
        if (times > 1 || outcome->count > 1)
            s += " (" + std::to_string(outcome->count) + " of " + std::to_string(times) +
                 (times == 1 ? " time" : " times") + ")";
        return s + ", " + moved_text(outcome->moved);
    };
    return refinement_command(id, RemoveKnotSpec{id, dir, t, times, tolerance}, std::move(r));
}

std::unique_ptr<Command> reduce_degree(std::uint64_t id, Dir dir, double tolerance) {
    auto outcome = std::make_shared<Outcome>();
    Refinement r;
    r.dir = dir;
    r.what = "degree reduction";
    r.surface = [=](const geom::Surface& s) -> geom::Expected<geom::Surface> {
        auto done = geom::reduce_degree(s, dir, tolerance);
        if (!done) return done.error();
        outcome->moved = done->max_error;
        return std::move(done->surface);
    };
    r.curve = [=](const geom::Curve& c) -> geom::Expected<geom::Curve> {
        auto done = geom::reduce_degree(c, tolerance);
        if (!done) return done.error();
        outcome->moved = done->max_error;
        return std::move(done->curve);
    };
    r.label = [=](const Shape& before, const Shape&) {
        const bool curve = is_curve(before);
        const Line old_line = line_of(before, dir);
        // A5.11's bound, not a measured distance: "at most".
        return std::string(curve ? "Reduce degree"
                                 : std::string("Reduce degree in ") + dir_name(dir)) +
               " (" + std::to_string(old_line.p) + " to " + std::to_string(old_line.p - 1) + "), " +
               moved_text(outcome->moved);
    };
    return refinement_command(id, ReduceDegreeSpec{id, dir, tolerance}, std::move(r));
}

std::unique_ptr<Command> split_knot(std::uint64_t id, Dir dir, double t,
                                    std::optional<double> delta) {
    auto outcome = std::make_shared<Outcome>();
    Refinement r;
    r.dir = dir;
    r.what = "knot splitting";
    r.surface = [=](const geom::Surface& s) -> geom::Expected<geom::Surface> {
        auto done = geom::split_knot(s, dir, t, delta);
        if (!done) return done.error();
        outcome->moved = done->max_change;
        return std::move(done->result);
    };
    r.curve = [=](const geom::Curve& c) -> geom::Expected<geom::Curve> {
        auto done = geom::split_knot(c, t, delta);
        if (!done) return done.error();
        outcome->moved = done->max_change;
        return std::move(done->result);
    };
    r.label = [=](const Shape& before, const Shape&) {
        const Line old_line = line_of(before, dir);
        const int m = geom::multiplicity(*old_line.U, t);
        return "Split knot " + where(is_curve(before), dir, t, true) + " (x" + std::to_string(m) +
               " becomes x" + std::to_string(m - 1) + " and a simple knot before it), " +
               moved_text(outcome->moved);
    };
    // The control points stay; only the knots change: the selection keeps its index.
    r.forward = r.backward = [](const Line&, const Line&, int i) { return i; };
    return refinement_command(id, SplitKnotSpec{id, dir, t, delta}, std::move(r));
}

std::unique_ptr<Command> close_object(std::uint64_t id, Dir dir) {
    Refinement r;
    r.dir = dir;
    r.what = "closing";
    r.curve_mode = CurveKnotMode::closed;
    auto already = [dir](bool curve) {
        return make_error(ErrorCode::schema,
                          std::string(curve ? "the curve" : "the surface") + " is already closed" +
                              (curve ? "" : std::string(" in ") + dir_name(dir)),
                          "/direction");
    };
    r.surface = [=](const geom::Surface& s) -> geom::Expected<geom::Surface> {
        const int across = s.count(dir == Dir::u ? Dir::v : Dir::u);
        bool closed = true;
        for (int k = 0; k < across && closed; ++k)
            closed = geom::is_closed_periodic(geom::surface_line(s, dir, k));
        if (closed) return already(false);
        return geom::close_periodic(s, dir);
    };
    r.curve = [=](const geom::Curve& c) -> geom::Expected<geom::Curve> {
        if (geom::is_closed_periodic(c)) return already(true);
        return geom::close_periodic(c);
    };
    r.label = [=](const Shape& before, const Shape&) {
        const bool curve = is_curve(before);
        const int p = line_of(before, dir).p;
        return std::string(curve ? "Close the curve" : std::string("Close in ") + dir_name(dir)) +
               " (periodic, C" + std::to_string(std::max(p - 1, 0)) + " at the seam)";
    };
    // The original control points keep their indices; the repeated ones follow.
    r.forward = [](const Line&, const Line& new_line, int i) { return clamp_index(i, new_line.n); };
    r.backward = [](const Line& old_line, const Line&, int i) {
        return clamp_index(i % std::max(old_line.n, 1), old_line.n);
    };
    return refinement_command(id, CloseSpec{id, dir}, std::move(r));
}

} // namespace isoparm::doc
