// De Boor's algorithm with every intermediate point kept: what the teaching views show.
#pragma once

#include <optional>
#include <vector>

#include "core/geom/types.hpp"

namespace isoparm::geom {

// The full triangle on the span of t (protocol convention 4): levels[0] holds the p + 1
// control points P[s-p..s], levels[k] holds p + 1 - k points, levels[p] the curve point.
// Computed in homogeneous space.
struct DeBoorTriangle {
    int first_index = 0;
    int span = 0;
    std::vector<std::vector<HPoint>> levels;
    // Cartesian point of a level entry; nullopt where its homogeneous weight is 0.
    static std::optional<glm::dvec3> cartesian(const HPoint& h);
};

// Precondition: valid curve (or homogeneous points with knots), t in the domain.
DeBoorTriangle deboor_curve(const Curve& c, double t);
DeBoorTriangle deboor_homogeneous(const Knots& U, int p, const std::vector<HPoint>& Pw, double t);

// The same triangle with a different argument at each level: level k uses args[k - 1]. Its
// apex is the blossom (polar form) f(args[0], ..., args[p-1]) of the polynomial piece on the
// non-empty span [U[span], U[span+1]) (Ramshaw; Farin ch. 4, Piegl & Tiller sec. 5.5): symmetric
// and multi-affine in its arguments, f(t, ..., t) the curve point, f(U[i+1], ..., U[i+p]) the
// control point P_i for span - p <= i <= span. Arguments outside the span extend the
// polynomial. Preconditions: p <= span < n, U[span] < U[span+1], args.size() == p.
DeBoorTriangle deboor_polar(const Knots& U, int p, const std::vector<HPoint>& Pw, int span,
                            const std::vector<double>& args);

// As the paper does it: each u-row curve (through P_{*,j}) at u, then the curve through
// those results at v.
struct DeBoorSurfaceTrace {
    std::vector<DeBoorTriangle> u_stage; // one per j = 0..n_v - 1
    DeBoorTriangle v_stage;
    std::optional<glm::dvec3> point() const;
};
DeBoorSurfaceTrace deboor_surface(const Surface& s, double u, double v);

} // namespace isoparm::geom
