// Read helpers over the document for panels: the current surface, a valid selection, the
// indicator in parameter space.
#pragma once

#include <optional>
#include <string>

#include <glm/vec2.hpp>

#include "core/doc/document.hpp"

namespace isoparm::ui {

// The surface the tracing and basis panels work on: the selected object when it is a
// surface, else the first visible surface; its object in `object` when asked.
const geom::Surface* current_surface(const doc::Document& d, const doc::Object** object = nullptr);
// The selected control point when it exists in the current selection object.
bool has_valid_point(const doc::Document& d);
// Selection made consistent after undo, redo or loading (view state, not undoable): an
// object that no longer exists or a point out of range is dropped.
void normalize_selection(doc::Document& d);

// A name not yet used by an object: "curve 3" for base "curve".
std::string fresh_name(const doc::Document& d, const std::string& base);

// "P22" as the paper writes it; "P26,11" once an index has two digits; "P3" for curves
// (j < 0). prefix: 'P', 'w', 'R'.
std::string point_name(char prefix, int i, int j, const doc::Document& d);
// Of this object's point: a triangle's b_ijk (prefix P) or w_ijk, k = n - i - j.
std::string point_name(char prefix, int i, int j, const doc::Object* o);
std::string point_name(char prefix, int i, int j, int n_u, int n_v);

// The indicator's (u, v) in the surface's own parameters, always inside its domain.
// doc.view.indicator is normalized over the tracing domain: the surface's own, or for a subpatch
// the whole original domain its group tiles (core/doc/patches.hpp); outside the subpatch's
// own part it is clamped to the nearest point of that part.
glm::dvec2 indicator_params(const doc::Document& d, const doc::Object& surface_object);
// The indicator normalized over the object's own domain (for panels that show one patch),
// and back to doc.view.indicator's normalization.
glm::dvec2 indicator_in_own_domain(const doc::Document& d, const doc::Object& surface_object);
glm::dvec2 indicator_from_own_domain(const doc::Document& d, const doc::Object& surface_object,
                                     glm::dvec2 own);

} // namespace isoparm::ui
