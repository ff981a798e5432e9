// Binomial coefficients as doubles (exact while they fit in 53 bits), for the derivative
// formulas of Piegl & Tiller A4.2 / A4.4 and the degree-elevation coefficients of A5.9.
#pragma once

namespace isoparm::geom {

inline double binomial(int n, int k) {
    double r = 1.0;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return r;
}

} // namespace isoparm::geom
