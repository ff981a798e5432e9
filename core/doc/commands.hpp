// The concrete commands. Each validates in apply() and refuses without touching anything.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <utility>

#include "core/doc/command.hpp"
#include "core/doc/command_spec.hpp"

namespace isoparm::doc {

// Refusals name the argument at fault as a JSON Pointer: "/id" (no such object, or an object
// of the wrong kind), "/i", "/j" (control point index; curves take j = -1), "/position/0..2",
// "/weight", "/k" and "/value" (set_knot), "/direction", "/name", "/matrix", "/times",
// "/shape/..." (the geometry given to add_object / edit_shape, as validate_* reports it),
// "/<colour>/<channel>" (set_colors). Codes as in the geometry protocol.

std::unique_ptr<Command> add_object(Object object); // id assigned on apply if 0
// Several objects as one undo step (File > Import), in order; each checked as add_object
// checks it, every one before any is added ("/objects/k/..."); objects without an id get fresh
// ids after every id in use. label: the undo label (empty: "Add N objects"). add_objects.cpp.
std::unique_ptr<Command> add_objects(std::vector<Object> objects, std::string label = {});
std::unique_ptr<Command> remove_object(std::uint64_t id);
std::unique_ptr<Command> rename_object(std::uint64_t id, std::string name);
// Hidden objects are neither drawn nor picked; they stay in the scene (the object list).
std::unique_ptr<Command> set_visible(std::uint64_t id, bool visible);
// The object's shape becomes `shape` (type changes, an implicit's fields), which must be the
// same kind of object (`schema` at "/shape"); label names the edit. Consecutive edits of one
// object with the same non-empty merge_key are one undo step (a slider drag).
std::unique_ptr<Command> edit_shape(std::uint64_t id, Shape shape, std::string label,
                                    std::string merge_key = {});

// A control point's position, weight or both ("/position" when neither is given). Drags:
// consecutive edits of the same point setting the same fields merge into one undo step. A
// subpatch's neighbours follow under the continuity setting (patches.hpp: keep_continuity).
std::unique_ptr<Command> edit_point(EditPointSpec spec);
// edit_point with the position only, or with the weight only.
std::unique_ptr<Command> move_control_point(std::uint64_t id, int i, int j, glm::dvec3 position);
std::unique_ptr<Command> set_weight(std::uint64_t id, int i, int j, double weight);
// Consecutive edits of the same knot merge into one undo step.
// Knot k of direction dir (curves: Dir::u) moves to value; it must stay within its
// neighbours and keep the knot vector valid (error `knots`).
std::unique_ptr<Command> set_knot(std::uint64_t id, geom::Dir dir, int k, double value);
// The same for a knot of multiplicity `count` (indices k .. k + count - 1, all equal): the
// copies move together, so dragging a double knot keeps it double ("/count" if they are not
// one run).
std::unique_ptr<Command> move_knot_run(std::uint64_t id, geom::Dir dir, int k, int count,
                                       double value);
// Affine map of every control point (the paper's translate / rotate sliders). The matrix
// must be finite and affine (bottom row 0 0 0 1; error `schema`, path "/matrix"). Consecutive
// transforms of the same object merge; redo restores exactly the points the drag produced.
std::unique_ptr<Command> transform_object(std::uint64_t id, const glm::dmat4& m);
// The same with the label the history shows ("Rotate hill", "Translate hill").
std::unique_ptr<Command> transform_object(std::uint64_t id, const glm::dmat4& m, std::string label);

// Refinement: shape unchanged; the selection is remapped to the same control point where
// it still exists (insertion at span k: indices up to k - p stay, indices from k - s on
// shift by `times`; elevation and the points insertion replaces: the control point whose
// Greville abscissa is nearest). Curves take Dir::u (Dir::v is a `schema` error at
// "/direction"). Errors of the geometry pass through with their paths ("/knot", "/times").
// `times` < 1 is `schema` at "/times"; a result above the size caps is `limit` at "/times".
// A (rational) Bezier given an interior knot becomes a B-spline (NURBS): the label then ends
// "(rational Bezier becomes NURBS)" and refinement_type_change says it.
std::unique_ptr<Command> insert_knot(std::uint64_t id, geom::Dir dir, double t, int times = 1);
std::unique_ptr<Command> elevate_degree(std::uint64_t id, geom::Dir dir, int times = 1);
// "rational Bezier becomes NURBS" when an applied shape edit (insert_knot, elevate_degree,
// edit_shape) changed the kind of spline; empty otherwise (and for any other command).
std::string refinement_type_change(const Command& refine_command);
// Replaces the object with its two pieces (names "<name>.1", "<name>.2", fresh ids): the
// first piece ([a, t]) takes the original's place in Document::objects and the second
// ([t, b]) follows it immediately, so after a successful apply
// objects[index] is ".1" and objects[index + 1] is ".2". split_piece_ids gives the ids too.
// The selection follows its control point into the piece that holds it.
// With continuity C0 or C1 (the setting when the split is first applied; redo replays it),
// the split also inserts knots (shape unchanged) into the neighbours, and into the pieces where
// a neighbour has knots they lack, until every border of the pieces pairs up control point for
// control point (patches.hpp: conforming_insertions); borders that conformed before still do.
// The label names what was inserted; undo takes the split and those insertions back at once.
std::unique_ptr<Command> split_object(std::uint64_t id, geom::Dir dir, double t);
// Inserts knots into the patches of `group` until every border that knot insertion can fix
// conforms (shape unchanged): for continuity switched on after the patches were made. Its
// label lists the insertions ("Borders already pair up" when there were none).
std::unique_ptr<Command> conform_borders(std::uint64_t group);
// The ids of the two pieces made by a split_object command after it applied ({0, 0} before,
// or for any other command). Redo gives the pieces the same ids again.
std::pair<std::uint64_t, std::uint64_t> split_piece_ids(const Command& split_command);

// The toolbox (commands_reshape.cpp): edits that may change the shape, each within a stated
// bound. Curves take Dir::u. The geometry's refusals pass through with the command's paths
// ("/knot", "/times", "/tolerance", "/delta").
// Knot removal (Piegl & Tiller A5.8) of `t` up to `times` times, each removal moving the shape
// by at most `tolerance` (model units): fewer removals than asked is not an error (the label
// says how many), none at all is refused (`geometry` at "/knot": the knot is essential, and
// the message says how far one removal would move the shape).
std::unique_ptr<Command> remove_knot(std::uint64_t id, geom::Dir dir, double t, int times,
                                     double tolerance);
// Degree reduction by one (A5.11); refused with its error bound when over `tolerance`.
std::unique_ptr<Command> reduce_degree(std::uint64_t id, geom::Dir dir, double tolerance);
// DesignMentor's knot splitting (geom/reshape.hpp): the first copy of the multiple knot `t`
// moves to t - delta (default 1% of the span before it); the label says how far the shape moved.
std::unique_ptr<Command> split_knot(std::uint64_t id, geom::Dir dir, double t,
                                    std::optional<double> delta);
// The closed (periodic) curve or surface of the same control polygon (geom::close_periodic):
// the first p control points repeated, uniform unclamped knots; C^(p-1) at the seam. Refused
// (`schema` at "/direction") when it is already closed that way.
std::unique_ptr<Command> close_object(std::uint64_t id, geom::Dir dir);
// Type conversion (geom::convert): one object, or the Bezier pieces of a multi-span object
// (names "<name>.1".., fresh ids, in the original's place; surface pieces form a patch group
// over the original domain). A rational object becomes non-rational only when its weights are
// all equal (`weights` at "/to", naming the first that differs) unless reset_weights, which
// sets every weight to 1 first (the shape then changes). conversion_losses says beforehand
// what a conversion loses, for the question the UI asks.
std::unique_ptr<Command> convert_object(std::uint64_t id, geom::SplineType to,
                                        bool reset_weights = false);
struct ConversionLosses {
    bool weights_differ = false; // to a non-rational type: the weights would be reset
    int pieces = 1;              // > 1: the object becomes its Bezier pieces
    std::string text;            // the question's words; empty when nothing is lost
};
geom::Expected<ConversionLosses> conversion_losses(const Object& object, geom::SplineType to);

std::unique_ptr<Command> set_colors(Colors colors);

} // namespace isoparm::doc
