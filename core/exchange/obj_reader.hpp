// Wavefront OBJ free-form geometry in: `cstype [rat] bspline` curves and surfaces (`deg`,
// `curv`/`surf`, `parm u/v`, `end`) on `v x y z [w]` vertices, the subset obj_writer.hpp
// writes and CAD programs export for NURBS. No third-party code: the grammar is the OBJ
// specification's (Wavefront Technologies, "Object Files (.obj)", Appendix B1 of the
// Advanced Visualizer manual, sections "Free-form curve/surface attributes" and "Elements").
#pragma once

#include <string_view>

#include "core/exchange/import_result.hpp"
#include "core/geom/status.hpp"

namespace isoparm::exchange {

// Reads every bspline `curv` and `surf` of `text`, in file order, named by the last `o` (or
// else `g`) statement before them. Left out, and listed in `skipped`: other curve and surface
// types (bezier, cardinal, taylor, bmatrix), trimming loops (`trim`, `hole`: the surface comes
// in untrimmed), 2D curves (`curv2`), and polygonal data (`f`, `l`, `p`), one entry per kind.
// Errors (code `parse`, path "" so a caller can place it, e.g. under "/text"): a message that
// begins "line N:" and names the offending value: a number that is not one, a vertex index out
// of range, a missing `deg`/`parm`/`end`, a knot vector or weight that geom::validate_* refuses.
// Nothing is returned on error: a file imports whole or not at all.
geom::Expected<ImportResult> read_obj_freeform(std::string_view text);

} // namespace isoparm::exchange
