// Uniform-grid tessellation of a whole surface (the one-shot form of GridTessellator).
#include "core/geom/tessellate.hpp"

#include <cassert>

#include "core/geom/grid_tessellator.hpp"

namespace isoparm::geom {

std::vector<double> uniform_params(double a, double b, int n) {
    std::vector<double> t(n);
    for (int i = 0; i < n; ++i) t[i] = a + (b - a) * i / (n - 1);
    t.front() = a;
    t.back() = b;
    return t;
}

Mesh tessellate(const Surface& s, int samples_u, int samples_v) {
    assert(samples_u >= 2 && samples_v >= 2);
    Mesh mesh;
    GridTessellator(s, samples_u, samples_v).evaluate(s, mesh, 1);
    return mesh;
}

} // namespace isoparm::geom
