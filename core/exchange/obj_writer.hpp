// Wavefront OBJ: exact free-form geometry (`cstype [rat] bspline`, `curv`/`surf` with `parm`
// lines) and triangle meshes (`v`, `vn`, `f`).
#pragma once

#include <string>

#include "core/exchange/iges_writer.hpp"
#include "core/geom/tessellate.hpp"

namespace isoparm::exchange {

// Control vertices `v x y z w` (Cartesian, with the weight for rational types); surfaces list
// them with u varying fastest, as the OBJ free-form convention asks. Any finite weight is
// written (OBJ readers take what the file says), so this exact format has no weight rule.
std::string obj_freeform_text(const std::vector<ExactShape>& shapes);

// Triangle meshes; vertices that do not exist (Mesh::exists) are written at the origin and no
// face uses them. obj: v, vn, f a//a b//b c//c. stl_ascii: one facet per triangle with its
// geometric normal. ply: ASCII, vertex x y z nx ny nz, face vertex_indices.
std::string obj_mesh_text(const std::vector<geom::Mesh>& meshes);
std::string stl_ascii_text(const std::vector<geom::Mesh>& meshes, const std::string& name);
std::string ply_text(const std::vector<geom::Mesh>& meshes);

} // namespace isoparm::exchange
