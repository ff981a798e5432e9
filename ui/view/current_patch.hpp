// Which subpatch is current, decided every frame from where the indicator is: the tracing
// square shows a patch group's whole domain (core/doc/patches.hpp), and moving the indicator
// into another patch's part of it makes that patch current. View state only (selection and
// indicator), never an undoable edit.
#pragma once

#include <cstdint>

#include <glm/vec2.hpp>

#include "core/doc/document.hpp"

namespace isoparm::ui {

// Moving the indicator into another subpatch's part of the square makes that subpatch
// current: the object the indicator (normalized over the group's domain) falls in, given the
// current object. Returns `current` itself outside a group or when it already holds it.
std::uint64_t patch_for_indicator(const doc::Document& doc, std::uint64_t current);

// Makes that subpatch current (the selection, view state; its control point selection is
// dropped). Returns whether the current patch changed.
bool follow_indicator(doc::Document& doc, std::uint64_t current);

// Keeps the current patch and the indicator in step from frame to frame: when the indicator
// moved (it differs from `last_indicator`; NaN on the first frame) the patch under it becomes
// current (follow_indicator); when the current patch changed otherwise (picked in the 3D view
// or a menu), the indicator moves into that patch's part of the square (its nearest point
// there). Returns the current object afterwards.
std::uint64_t sync_patch_and_indicator(doc::Document& doc, std::uint64_t current,
                                       glm::dvec2 last_indicator, std::uint64_t last_current);

} // namespace isoparm::ui
