// A B-spline that follows a function of one parameter within a tolerance, keeping that
// parameter: how curves on surfaces and mapped trim curves become NURBS.
#pragma once

#include <functional>
#include <glm/vec3.hpp>

#include "core/geom/types.hpp"

namespace isoparm::geom {

// A cubic least-squares fit (Piegl & Tiller 9.4.1, ends interpolated) of f at uniform samples
// of [d.lo, d.hi], its knots on that interval (uniform samples with uniform parameters: the
// fit runs with t), with more control points and then more samples until it is within
// `tolerance` of f at every sample and halfway between them (or 16384 samples are reached).
// `pieces` (at least 1) says how many smooth pieces f has, for the first sample count. A
// function that stays at one point gives a degree-1 curve there.
Curve fit_samples(const std::function<glm::dvec3(double)>& f, Interval d, int pieces,
                  double tolerance);

// The same with at most `max_samples` samples (so at most max_samples + 1 control points):
// the closest fit found and whether it is within the tolerance. Callers split an interval
// where a fit is not (a kink inside is what keeps a cubic fit from converging).
struct SampleFit {
    Curve curve;
    bool within = false;
};
SampleFit fit_samples_limited(const std::function<glm::dvec3(double)>& f, Interval d, int pieces,
                              double tolerance, int max_samples);

} // namespace isoparm::geom
