// A banded LU factorization with partial pivoting, for the interpolation systems of A9.1.
#pragma once

#include <optional>
#include <vector>

namespace isoparm::geom {

// An n x n matrix with kl sub-diagonals and ku super-diagonals, factored in place as
// P A = L U (Gaussian elimination with partial pivoting, the scheme of LAPACK's dgbtf2: row
// swaps widen U's band to ku + kl, so the storage keeps kl extra super-diagonals).
// The B-spline collocation matrices of Piegl & Tiller A9.1 have kl, ku <= p and are totally
// positive, so pivoting is rarely needed; it keeps the solver honest for any caller.
class BandedLU {
public:
    BandedLU(int n, int kl, int ku);

    int size() const { return n_; }
    // A(i, j) before factor(); only |i - j| inside the band may be set.
    void set(int i, int j, double value);

    // False when the matrix is singular (a zero pivot column); the factors are then unusable.
    bool factor();

    // Solves A x = b in place for one right-hand side column of length n (after factor()).
    void solve(double* b) const;

private:
    double& at(int i, int j) { return band_[static_cast<size_t>(i) * width_ + (j - i + kl_)]; }
    double at(int i, int j) const { return band_[static_cast<size_t>(i) * width_ + (j - i + kl_)]; }

    int n_, kl_, ku_, width_;
    std::vector<double> band_; // row i holds columns i - kl .. i + ku + kl
    std::vector<int> pivot_;   // row exchanged with row k at step k
};

} // namespace isoparm::geom
