// Recipes compared bit for bit.
#include "core/doc/recipe.hpp"

#include <bit>

namespace isoparm::doc {

namespace {

bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

} // namespace

bool same_recipe(const Recipe& a, const Recipe& b) {
    if (a.refinements.size() != b.refinements.size()) return false;
    for (std::size_t k = 0; k < a.refinements.size(); ++k) {
        const RecipeRefinement &r = a.refinements[k], &s = b.refinements[k];
        if (r.kind != s.kind || r.dir != s.dir || !same_bits(r.t, s.t) || r.times != s.times)
            return false;
    }
    return a.kind == b.kind && a.curves == b.curves && same_bits(a.angle, b.angle) &&
           same_bits(a.scale, b.scale) && a.skin_degree == b.skin_degree &&
           a.parametrization == b.parametrization && a.sections == b.sections &&
           a.gordon_u_count == b.gordon_u_count && a.iso_dir == b.iso_dir &&
           same_bits(a.iso_t, b.iso_t);
}

} // namespace isoparm::doc
