// The surface kind: a tensor-product Bezier, rational Bezier, B-spline or NURBS surface, and
// every fact the document asks of it (kind_facts.hpp).
#pragma once

#include <array>

#include "core/doc/kinds/kind_facts.hpp"

namespace isoparm::doc {

struct SurfaceObject {
    geom::Surface surface;

    static constexpr ObjectKind kind = ObjectKind::surface;
    static constexpr std::array<std::string_view, 1> shape_members{"surface"};
    static constexpr bool in_patch_groups = true; // split surfaces share a domain
    static constexpr bool constructed = true;     // a recipe builds surfaces
};

ISOPARM_KIND_FACTS(SurfaceObject);

} // namespace isoparm::doc
