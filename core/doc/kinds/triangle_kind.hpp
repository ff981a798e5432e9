// The triangle kind: a triangular Bezier patch (the paper's future work; Farin ch. 17), its
// control point b_ijk addressed as (i, j), k = n - i - j (the selection uses the same pair),
// and every fact the document asks of it (kind_facts.hpp).
#pragma once

#include <array>

#include "core/doc/kinds/kind_facts.hpp"
#include "core/geom/triangle.hpp"

namespace isoparm::doc {

struct TriangleObject {
    geom::TrianglePatch patch;

    static constexpr ObjectKind kind = ObjectKind::triangle;
    static constexpr std::array<std::string_view, 1> shape_members{"triangle"};
    static constexpr bool in_patch_groups = false;
    static constexpr bool constructed = false;
};

ISOPARM_KIND_FACTS(TriangleObject);

} // namespace isoparm::doc
