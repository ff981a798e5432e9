// The Construct menu's work: chosen curves of the document in, a new surface object out.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/doc/document.hpp"
#include "core/geom/construct.hpp"

namespace isoparm::doc {

enum class Construction { ruled, revolve, swing, sweep, oriented_sweep, skin, coons, gordon };
inline constexpr geom::EnumName<Construction> construction_names[] = {
    {Construction::ruled, "ruled", "Ruled"},
    {Construction::revolve, "revolve", "Revolve"},
    {Construction::swing, "swing", "Swing"},
    {Construction::sweep, "sweep", "Sweep"},
    {Construction::oriented_sweep, "oriented_sweep", "Oriented sweep"},
    {Construction::skin, "skin", "Skin"},
    {Construction::coons, "coons", "Coons"},
    {Construction::gordon, "gordon", "Gordon"},
};
static_assert(geom::in_declaration_order(construction_names));
constexpr std::span<const geom::EnumName<Construction>> enum_names(Construction) {
    return construction_names;
}
// "Ruled", "Revolve", ... (the table's label).
inline const char* construction_label(Construction kind) {
    return geom::label_of(kind);
}

struct ConstructionRequest {
    Construction kind = Construction::ruled;
    // ruled: 2 curves; revolve: 1 (the profile); swing, sweep, oriented sweep: profile then
    // trajectory; skin: 2 or more sections, in order; coons: the boundaries S(u, 0), S(u, 1),
    // S(0, v), S(1, v); gordon: the curves of constant v (gordon_u_count of them), then the
    // curves of constant u.
    std::vector<std::uint64_t> curves;
    double angle = 360.0; // revolve, degrees in (0, 360]
    double scale = 1.0;   // swing
    int skin_degree = 0;  // skin v-degree, 1..count - 1; 0: min(3, count - 1)
    geom::Parametrization parametrization = geom::Parametrization::chord; // skin
    int sections = 16;                                                    // oriented sweep
    int gordon_u_count = 2; // gordon: how many of the curves run along u (at least 2 each)
};

struct ConstructionResult {
    Object object;    // the new surface (id 0: add_object assigns one)
    std::string note; // for the user: the oriented sweep's deviation, the skin's parameters
};

// Runs the construction on the document's curves (core/geom/construct.hpp). The document is
// not changed: the caller adds the object with add_object. Errors name the curve and the
// reason in the message; the path points into the request: "/curves" (wrong count),
// "/curves/k" (no such curve, not a curve, or the geometry's complaint about that curve:
// "/curves/1/points/3"; a Coons corner that does not meet, a Gordon pair that does not
// intersect), "/angle", "/scale", "/degree", "/sections", "/gordon_u_count".
geom::Expected<ConstructionResult> build_construction(const Document& doc,
                                                      const ConstructionRequest& request);

} // namespace isoparm::doc
