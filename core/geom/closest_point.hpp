// The point of a curve or a surface closest to a given point: point inversion and projection
// (Piegl & Tiller section 6.1), for exercises that ask "does the surface pass through P?" and
// for the sampled distance between two shapes.
#pragma once

#include <optional>
#include <vector>

#include "core/geom/types.hpp"

namespace isoparm::geom {

struct CurveFoot {
    double t = 0;
    glm::dvec3 point{0};
    double distance = 0;
};
struct SurfaceFoot {
    double u = 0, v = 0;
    glm::dvec3 point{0};
    double distance = 0;
};

// Many points projected onto one curve: the samples (a grid over each knot span, so no span
// is missed) are evaluated once. For each point the nearest sample starts Newton's iteration
// on (C(t) - P) . C'(t) = 0 (P&T eq. 6.3), clamped to the domain; the answer is never farther
// than the best sample. nullopt when no sample exists (the denominator vanishes everywhere
// sampled). The curve must outlive the projector. Precondition: a valid curve.
class CurveProjector {
public:
    explicit CurveProjector(const Curve& c);
    std::optional<CurveFoot> closest(const glm::dvec3& p) const;

private:
    const Curve& c_;
    std::vector<CurveFoot> samples_;
};

// The same on a surface: Newton on (S - P) . S_u = 0, (S - P) . S_v = 0 (P&T eqs. 6.5-6.7).
class SurfaceProjector {
public:
    explicit SurfaceProjector(const Surface& s);
    std::optional<SurfaceFoot> closest(const glm::dvec3& p) const;

private:
    const Surface& s_;
    std::vector<SurfaceFoot> samples_;
};

// One point, one shape.
std::optional<CurveFoot> closest_point(const Curve& c, const glm::dvec3& p);
std::optional<SurfaceFoot> closest_point(const Surface& s, const glm::dvec3& p);

} // namespace isoparm::geom
