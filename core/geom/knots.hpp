// Knot vectors: validation with precise messages, multiplicities, spans and domains.
#pragma once

#include <string>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// Validates a knot vector for n control points of degree p (p >= 1, n >= p + 1 checked by
// the caller). Error paths are relative to the knot vector: "" (count, empty domain) or
// "/k" (the first knot smaller than its predecessor, the first knot past p + 1 copies).
Status validate_knots(const Knots& U, int p, int n);

// The parameter domain [U[p], U[n]].
inline Interval domain(const Knots& U, int p, int n) {
    return {U[p], U[n]};
}
// The same for a curve, a surface along one direction and a surface in both: the one place
// every caller (panels, commands, the protocol) asks for a domain.
inline Interval domain(const Curve& c) {
    return domain(c.knots, c.degree, c.count());
}
inline Interval domain(const Surface& s, Dir dir) {
    return domain(s.knots(dir), s.degree(dir), s.count(dir));
}
inline ParamRect domain(const Surface& s) {
    return {domain(s, Dir::u), domain(s, Dir::v)};
}

// Piegl & Tiller A2.1 FindSpan, with the protocol's convention: the span s with
// U[s] <= t < U[s+1] (right limit at interior knots, whatever their multiplicity), except
// at the end of the domain, which takes the left limit (the last s with U[s] < U[n]).
// Precondition: t inside the domain, valid knots.
int find_span(const Knots& U, int p, int n, double t);

// How many knots equal t exactly (multiplicities need exact comparison, never epsilons).
int multiplicity(const Knots& U, double t);

// Clamped at both ends: U[0] = ... = U[p] and U[n] = ... = U[n+p].
bool is_clamped(const Knots& U, int p, int n);

// The distinct knots inside the domain with their multiplicities (for knot curves, ticks).
struct KnotRun {
    double value;
    int multiplicity;
    int first_index;
};
std::vector<KnotRun> knot_runs(const Knots& U);

// The Greville abscissa of control point i, (U[i+1] + ... + U[i+p]) / p: the parameter a
// control point "belongs to" (Piegl & Tiller sec. 9.3, Farin). A running mean, so equal knots
// give their value exactly.
double greville_abscissa(const Knots& U, int p, int i);

// Clamped uniform knots for n points of degree p on [a, b].
Knots clamped_uniform_knots(int n, int p, double a = 0.0, double b = 1.0);
// Bezier knots a^(p+1) b^(p+1).
Knots bezier_knots(int p, double a = 0.0, double b = 1.0);

// The parametric continuity a B-spline of degree p has at an interior knot of multiplicity m:
// C^(p - m) (Piegl & Tiller sec. 2.3, P2.5); -1 means not even continuous (m = p + 1). A
// coincidence of control points can make the shape smoother than this; never less smooth.
inline int continuity_at_knot(int degree, int multiplicity) {
    return degree - multiplicity;
}

// "C1 here", "C0 here: a corner may appear", "not continuous here (C-1)" for tooltips.
std::string continuity_text(int degree, int multiplicity);

} // namespace isoparm::geom
