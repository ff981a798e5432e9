// The implicit kind: a surface f(x, y, z) = 0 from an expression, polygonized in a box, and
// every fact the document asks of it (kind_facts.hpp). It has no control points.
#pragma once

#include <array>
#include <vector>

#include "core/doc/kinds/kind_facts.hpp"

namespace isoparm::doc {

struct ImplicitObject {
    std::string expression;
    std::vector<std::string> parameter_names;
    std::vector<double> parameter_values;
    glm::dvec3 lo{-1, -1, -1}, hi{1, 1, 1};
    double cell = 0.05;

    static constexpr ObjectKind kind = ObjectKind::implicit;
    static constexpr std::array<std::string_view, 1> shape_members{"implicit"};
    static constexpr bool in_patch_groups = false;
    static constexpr bool constructed = false;
};

// translate: moved with its formula (in absolute coordinates: moving its box alone would cut
// the field): its box moves by d and x, y, z become (x - d.x), ... (translated).
ISOPARM_KIND_FACTS(ImplicitObject);

// An implicit surface moved by d: its box moved and every x, y, z of its expression replaced
// by (x - d.x), (y - d.y), (z - d.z) (a zero component leaves its coordinate as it is).
ImplicitObject translated(const ImplicitObject& f, const glm::dvec3& d);

} // namespace isoparm::doc
