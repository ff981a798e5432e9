// B-spline basis functions and their derivatives; rational basis R_i and R_ij.
#pragma once

#include <optional>
#include <vector>

#include "core/geom/types.hpp"

namespace isoparm::geom {

// Piegl & Tiller A2.2 BasisFuns: the p + 1 non-zero N_{s-p..s,p}(t) into N.
void basis_funs(int span, double t, int p, const Knots& U, double* N);

// Piegl & Tiller A2.3 DersBasisFuns: ders[k * (p + 1) + r] = N^(k)_{s-p+r,p}(t), k = 0..d.
// Derivatives above p are zero.
void ders_basis_funs(int span, double t, int p, int d, const Knots& U, double* ders);

// What a panel needs to see at t: the span and the p + 1 non-zero values (and derivatives).
struct BasisAt {
    int span = 0;
    int first_index = 0;                     // span - p
    std::vector<std::vector<double>> values; // values[k][r] = N^(k)_{first_index + r}(t)
};
BasisAt basis_at(const Knots& U, int p, int n, double t, int derivatives = 0);

// All n functions (zeros outside their support): result[k][i] = N^(k)_i(t).
std::vector<std::vector<double>> all_basis(const Knots& U, int p, int n, double t,
                                           int derivatives = 0);

// Rational basis R_i = N_i w_i / sum_j N_j w_j and its derivatives (quotient rule, Leibniz).
// nullopt where the denominator is exactly zero (the point does not exist there).
std::optional<std::vector<std::vector<double>>>
rational_basis(const Knots& U, int p, const std::vector<double>& w, double t, int derivatives = 0);

// R_ij(u, v) of one control point of a surface; nullopt where the denominator vanishes.
std::optional<double> rational_basis_ij(const Surface& s, int i, int j, double u, double v);

} // namespace isoparm::geom
