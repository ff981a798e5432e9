// The surface kind: a tensor-product Bezier, rational Bezier, B-spline or NURBS surface, with
// the trim loops that say which part of its domain it keeps (none: all of it), and every fact
// the document asks of it (kind_facts.hpp).
#pragma once

#include <array>

#include "core/doc/kinds/kind_facts.hpp"
#include "core/geom/trim/trim.hpp"

namespace isoparm::doc {

struct SurfaceObject {
    geom::Surface surface;
    // Empty: the whole domain. Scenes write "trim" only when it is not empty, so an untrimmed
    // surface saves as it always did.
    geom::Trim trim{};

    static constexpr ObjectKind kind = ObjectKind::surface;
    static constexpr std::array<std::string_view, 2> shape_members{"surface", "trim"};
    static constexpr bool in_patch_groups = true; // split surfaces share a domain
    static constexpr bool constructed = true;     // a recipe builds surfaces
};

ISOPARM_KIND_FACTS(SurfaceObject);

} // namespace isoparm::doc
