// A construction's recipe: what built an object (the operation, its input objects, its
// parameters, and the shape-keeping refinements made on it since), kept beside the object so
// that an edit of an input builds it again (core/doc/associative.hpp).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/geom/enum_names.hpp"
#include "core/geom/interpolate.hpp"
#include "core/geom/types.hpp"

namespace isoparm::doc {

// The constructions of the Construct menu, and the isocurve: a curve of a surface at a fixed
// parameter (a construction whose input is a surface, so that constructions can be chained:
// profile -> vase -> its rim -> a ruled collar).
enum class Construction {
    ruled,
    revolve,
    swing,
    sweep,
    oriented_sweep,
    skin,
    coons,
    gordon,
    isocurve
};
inline constexpr geom::EnumName<Construction> construction_names[] = {
    {Construction::ruled, "ruled", "Ruled"},
    {Construction::revolve, "revolve", "Revolve"},
    {Construction::swing, "swing", "Swing"},
    {Construction::sweep, "sweep", "Sweep"},
    {Construction::oriented_sweep, "oriented_sweep", "Oriented sweep"},
    {Construction::skin, "skin", "Skin"},
    {Construction::coons, "coons", "Coons"},
    {Construction::gordon, "gordon", "Gordon"},
    {Construction::isocurve, "isocurve", "Isocurve"},
};
static_assert(geom::in_declaration_order(construction_names));
constexpr std::span<const geom::EnumName<Construction>> enum_names(Construction) {
    return construction_names;
}
// "Ruled", "Revolve", ... (the table's label).
inline const char* construction_label(Construction kind) {
    return geom::label_of(kind);
}

// A refinement made on a constructed object after it was built: knot insertion or degree
// elevation, which keep its shape, so the object stays its recipe's result and a rebuild
// repeats them (a 64 x 64 vase refined from an 11 x 9 revolution follows its profile).
struct RecipeRefinement {
    enum class Kind { insert_knot, elevate_degree } kind = Kind::insert_knot;
    geom::Dir dir = geom::Dir::u;
    double t = 0;  // insert_knot: the knot, in the object's own parameters
    int times = 1; // insertions, or degrees added
};

struct ConstructionRequest {
    Construction kind = Construction::ruled;
    // The input objects, by id. ruled: 2 curves; revolve: 1 (the profile); swing, sweep,
    // oriented sweep: profile then trajectory; skin: 2 or more sections, in order; coons: the
    // boundaries S(u, 0), S(u, 1), S(0, v), S(1, v); gordon: the curves of constant v
    // (gordon_u_count of them), then the curves of constant u; isocurve: one surface.
    std::vector<std::uint64_t> curves;
    double angle = 360.0; // revolve, degrees in (0, 360]
    double scale = 1.0;   // swing
    int skin_degree = 0;  // skin v-degree, 1..count - 1; 0: min(3, count - 1)
    geom::Parametrization parametrization = geom::Parametrization::chord; // skin
    int sections = 16;                                                    // oriented sweep
    int gordon_u_count = 2; // gordon: how many of the curves run along u (at least 2 each)
    // isocurve: S(t, .) with iso_dir u (the curve runs along v), S(., t) with v; iso_t in
    // [0, 1] over the surface's domain, so the curve stays put when the domain changes.
    geom::Dir iso_dir = geom::Dir::u;
    double iso_t = 0.5;
    // Refinements made since the construction, in order.
    std::vector<RecipeRefinement> refinements;
};
// What a constructed object keeps: the request that built it.
using Recipe = ConstructionRequest;

// Bit for bit (as same_object compares objects).
bool same_recipe(const Recipe& a, const Recipe& b);

} // namespace isoparm::doc
