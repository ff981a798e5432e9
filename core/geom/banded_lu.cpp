// Banded Gaussian elimination with partial pivoting (the dgbtf2 / dgbtrs scheme).
#include "core/geom/banded_lu.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

namespace isoparm::geom {

BandedLU::BandedLU(int n, int kl, int ku)
    : n_(n), kl_(kl), ku_(ku), width_(2 * kl + ku + 1),
      band_(static_cast<size_t>(n) * (2 * kl + ku + 1), 0.0), pivot_(n, 0) {
    assert(n >= 1 && kl >= 0 && ku >= 0);
}

void BandedLU::set(int i, int j, double value) {
    assert(i >= 0 && i < n_ && j >= 0 && j < n_);
    assert(j - i <= ku_ && i - j <= kl_);
    at(i, j) = value;
}

bool BandedLU::factor() {
    for (int k = 0; k < n_; ++k) {
        const int last_row = std::min(n_ - 1, k + kl_);
        const int last_col = std::min(n_ - 1, k + ku_ + kl_);
        int p = k;
        for (int i = k + 1; i <= last_row; ++i)
            if (std::abs(at(i, k)) > std::abs(at(p, k))) p = i;
        pivot_[k] = p;
        if (at(p, k) == 0.0) return false;
        // Only columns k.. are exchanged: the multipliers already stored left of k belong to
        // the rows as they were at their own step, and solve() replays the swaps in order.
        if (p != k)
            for (int j = k; j <= last_col; ++j) std::swap(at(k, j), at(p, j));
        const double pivot = at(k, k);
        for (int i = k + 1; i <= last_row; ++i) {
            const double l = at(i, k) / pivot;
            at(i, k) = l;
            if (l == 0.0) continue;
            for (int j = k + 1; j <= last_col; ++j) at(i, j) -= l * at(k, j);
        }
    }
    return true;
}

void BandedLU::solve(double* b) const {
    for (int k = 0; k < n_; ++k) { // L y = P b, swaps interleaved as in factor()
        if (pivot_[k] != k) std::swap(b[k], b[pivot_[k]]);
        const int last_row = std::min(n_ - 1, k + kl_);
        for (int i = k + 1; i <= last_row; ++i) b[i] -= at(i, k) * b[k];
    }
    for (int k = n_ - 1; k >= 0; --k) { // U x = y
        const int last_col = std::min(n_ - 1, k + ku_ + kl_);
        double s = b[k];
        for (int j = k + 1; j <= last_col; ++j) s -= at(k, j) * b[j];
        b[k] = s / at(k, k);
    }
}

} // namespace isoparm::geom
