// An animated parameter's target and its preview: the value shown on the document without a
// command (a teacher's "watch the surface as w goes from 0 to 5"), taken back exactly, and the
// one command that keeps a value when the teacher wants it (one undo step). The player's clock
// is ui/view/animation.hpp; lessons name the target in an `animate` step (core/scene/script).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/doc/associative.hpp"
#include "core/doc/command.hpp"
#include "core/doc/document.hpp"

namespace isoparm::doc {

enum class AnimatedKind {
    weight,
    knot,
    indicator_line,
    indicator_circle,
    deboor_step,
    implicit_parameter
};
inline constexpr geom::EnumName<AnimatedKind> animated_kind_names[] = {
    {AnimatedKind::weight, "weight"},
    {AnimatedKind::knot, "knot"},
    {AnimatedKind::indicator_line, "indicator_line", "(u, v) along a line"},
    {AnimatedKind::indicator_circle, "indicator_circle", "(u, v) around a circle"},
    {AnimatedKind::deboor_step, "deboor_step", "de Boor step"},
    {AnimatedKind::implicit_parameter, "parameter", "implicit parameter"},
};
static_assert(geom::in_declaration_order(animated_kind_names));
constexpr std::span<const geom::EnumName<AnimatedKind>> enum_names(AnimatedKind) {
    return animated_kind_names;
}

// What an animation moves and its range. The value runs from `from` to `to` (a weight, a
// knot, a parameter's value, the de Boor step's first and last); the indicator runs along the
// segment uv_from -> uv_to or around the circle of `radius` about `centre` (the normalised
// domain [0, 1]^2, from angle 0 counter-clockwise).
struct AnimationTarget {
    AnimatedKind kind = AnimatedKind::weight;
    std::uint64_t object = 0;
    int i = 0, j = -1;            // weight: the control point (curves: j = -1)
    geom::Dir dir = geom::Dir::u; // knot: the direction (curves: u)
    int k = 0;                    // knot: its index (its run of equal copies moves together)
    std::string parameter;        // implicit_parameter: its name
    double from = 0, to = 1;
    glm::dvec2 uv_from{0.1, 0.5}, uv_to{0.9, 0.5};
    glm::dvec2 centre{0.5, 0.5};
    double radius = 0.3;
};

// How the value comes back: once (stops at the end), loop (jumps back to the start), bounce
// (runs back and forth).
enum class Repeat { once, loop, bounce };
inline constexpr geom::EnumName<Repeat> repeat_names[] = {
    {Repeat::once, "once"}, {Repeat::loop, "loop"}, {Repeat::bounce, "bounce"}};
static_assert(geom::in_declaration_order(repeat_names));
constexpr std::span<const geom::EnumName<Repeat>> enum_names(Repeat) {
    return repeat_names;
}

// The value at phase s in [0, 1]: from + s (to - from) (exactly `from` at 0 and `to` at 1).
double value_at(const AnimationTarget& t, double s);
// The de Boor step at phase s: each integer from `from` to `to` gets an equal share.
int step_at(const AnimationTarget& t, double s);
// The indicator at phase s: along the segment, or around the circle (clamped to [0, 1]^2).
glm::dvec2 indicator_at(const AnimationTarget& t, double s);
// "w23 from 0 to 5", "knot u4 from 0.25 to 0.5", "(u, v) around (0.5, 0.5), radius 0.3": for
// the panel and the lesson bar.
std::string describe(const AnimationTarget& t);

// Whether the target can be shown on this document: the object exists and has the part (a
// rational object's weight; an interior knot whose every value from `from` to `to` stays
// between its neighbours; the implicit's parameter), and the range is finite. Errors name the
// member as an `animate` step writes it ("/object", "/point", "/k", "/to", "/parameter").
geom::Status check_target(const Document& doc, const AnimationTarget& target);

// The document as it was before a preview, for restore_preview: the shape of the animated
// object and of the dependants rebuilt with it, and the indicator.
struct PreviewUndo {
    std::optional<std::uint64_t> object;
    std::optional<Shape> shape;
    std::vector<ReplacedShape> dependants;
    std::optional<glm::dvec2> indicator;
};
// Shows `value` (a weight, a knot, a parameter) or `uv` (the indicator) on the document
// without a command: the object's constructions that read it follow (rebuild_dependants). The
// de Boor step is not in the document (the caller shows it). Precondition: check_target.
// Returns what restore_preview needs; a value a dependant cannot follow is an error and
// changes nothing.
geom::Expected<PreviewUndo> show_preview(Document& doc, const AnimationTarget& target, double value,
                                         glm::dvec2 uv);
// Puts the document back bit for bit (restore before any command runs).
void restore_preview(Document& doc, PreviewUndo& undo);

// The command that keeps `value` (set_weight, move_knot, an implicit's edit_shape), to run on
// the restored document: one undo step. None for the indicator and the de Boor step (view
// state, kept as they are).
std::unique_ptr<Command> keep_value(const Document& doc, const AnimationTarget& target,
                                    double value);

} // namespace isoparm::doc
