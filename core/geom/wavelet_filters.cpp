// The cubic B-spline wavelet filters, derived numerically once per level:
//   P_j  by knot insertion (Piegl & Tiller A5.4) of every span's midpoint into level j - 1's
//        knots, one unit control point at a time;
//   G_j  the Gram matrix <N_a, N_b> of level j's B-splines (4-point Gauss-Legendre per span,
//        exact for the degree-6 products);
//   Q_j  a basis of the null space of P_j^T G_j: the wavelets are L2-orthogonal to every
//        coarse B-spline, Finkelstein & Salesin's semiorthogonal choice (Stollnitz et al.
//        sec. 7.3). We take the basis that is the identity on the free columns of a full-pivot
//        Gauss-Jordan elimination, not their minimal-support one: the detail *function* (and so
//        every edit) depends only on the span of Q_j, not on its basis;
//   A_j  the least-squares analysis (P^T G P)^(-1) P^T G, the L2 projection onto level j - 1
//        (Stollnitz et al. eq. 7.10): A_j P_j = I and A_j Q_j = 0;
//   B_j  the rows of I - P_j A_j at Q_j's identity rows, so that B_j P_j = 0 and B_j Q_j = I.
#include "core/geom/wavelet_filters.hpp"

#include <array>
#include <cassert>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <utility>

#include "core/geom/basis.hpp"
#include "core/geom/refine.hpp"

namespace isoparm::geom {

namespace {

DenseMatrix multiply(const DenseMatrix& a, const DenseMatrix& b) {
    assert(a.cols == b.rows);
    DenseMatrix out(a.rows, b.cols);
    for (int r = 0; r < a.rows; ++r)
        for (int k = 0; k < a.cols; ++k) {
            const double x = a(r, k);
            if (x == 0.0) continue;
            for (int c = 0; c < b.cols; ++c) out(r, c) += x * b(k, c);
        }
    return out;
}

DenseMatrix transpose(const DenseMatrix& a) {
    DenseMatrix out(a.cols, a.rows);
    for (int r = 0; r < a.rows; ++r)
        for (int c = 0; c < a.cols; ++c) out(c, r) = a(r, c);
    return out;
}

// Level j's knots on the canonical domain [0, 2^j] (the filters do not depend on the domain's
// position or length: only the knots' ratios enter P, and G scales as a whole).
Knots canonical_knots(int spans, int step) {
    Knots U(3, 0.0);
    for (int k = 0; k <= spans; ++k) U.push_back(static_cast<double>(k * step));
    U.insert(U.end(), 3, static_cast<double>(spans * step));
    return U;
}

DenseMatrix refinement_matrix(int level) {
    const int coarse_spans = 1 << (level - 1);
    const int n_coarse = coarse_spans + 3, n_fine = 2 * coarse_spans + 3;
    std::vector<double> midpoints;
    for (int k = 0; k < coarse_spans; ++k) midpoints.push_back(2.0 * k + 1.0);
    DenseMatrix P(n_fine, n_coarse);
    for (int c = 0; c < n_coarse; ++c) {
        Knots U = canonical_knots(coarse_spans, 2);
        std::vector<HPoint> unit(n_coarse, HPoint(0, 0, 0, 1));
        unit[c].x = 1.0;
        refine_knot_vector(3, U, unit, midpoints);
        assert(static_cast<int>(unit.size()) == n_fine);
        for (int r = 0; r < n_fine; ++r) P(r, c) = unit[r].x;
    }
    return P;
}

DenseMatrix gram_matrix(int level) {
    const int spans = 1 << level, n = spans + 3;
    const Knots U = canonical_knots(spans, 1);
    constexpr std::array<std::pair<double, double>, 4> gauss = {{
        {-0.8611363115940526, 0.3478548451374538},
        {-0.3399810435848563, 0.6521451548625461},
        {0.3399810435848563, 0.6521451548625461},
        {0.8611363115940526, 0.3478548451374538},
    }};
    DenseMatrix G(n, n);
    for (int k = 0; k < spans; ++k)
        for (const auto& [x, w] : gauss) {
            double N[4];
            basis_funs(k + 3, k + 0.5 + 0.5 * x, 3, U, N);
            for (int a = 0; a < 4; ++a)
                for (int b = 0; b < 4; ++b) G(k + a, k + b) += 0.5 * w * N[a] * N[b];
        }
    return G;
}

// Q: the null space of M (full row rank) with the identity on the free columns, and those
// columns in increasing order.
std::pair<DenseMatrix, std::vector<int>> null_space(DenseMatrix M) {
    const int rows = M.rows, cols = M.cols;
    std::vector<int> pivot_col(rows, -1);
    std::vector<bool> is_pivot(cols, false);
    for (int r = 0; r < rows; ++r) {
        // Full pivoting over the remaining rows and non-pivot columns.
        int best_row = r, best_col = -1;
        double best = 0.0;
        for (int i = r; i < rows; ++i)
            for (int c = 0; c < cols; ++c)
                if (!is_pivot[c] && std::abs(M(i, c)) > best) {
                    best = std::abs(M(i, c));
                    best_row = i;
                    best_col = c;
                }
        assert(best_col >= 0 && best > 0.0);
        for (int c = 0; c < cols; ++c) std::swap(M(r, c), M(best_row, c));
        const double inv = 1.0 / M(r, best_col);
        for (int c = 0; c < cols; ++c) M(r, c) *= inv;
        for (int i = 0; i < rows; ++i) {
            if (i == r || M(i, best_col) == 0.0) continue;
            const double f = M(i, best_col);
            for (int c = 0; c < cols; ++c) M(i, c) -= f * M(r, c);
        }
        pivot_col[r] = best_col;
        is_pivot[best_col] = true;
    }
    std::vector<int> free_cols;
    for (int c = 0; c < cols; ++c)
        if (!is_pivot[c]) free_cols.push_back(c);
    DenseMatrix Q(cols, static_cast<int>(free_cols.size()));
    for (int k = 0; k < Q.cols; ++k) {
        const int f = free_cols[k];
        Q(f, k) = 1.0;
        for (int r = 0; r < rows; ++r) Q(pivot_col[r], k) = -M(r, f);
    }
    return {std::move(Q), std::move(free_cols)};
}

// X with S X = R (S square and invertible), Gaussian elimination with partial pivoting.
DenseMatrix solve(DenseMatrix S, DenseMatrix R) {
    const int n = S.rows;
    for (int k = 0; k < n; ++k) {
        int p = k;
        for (int i = k + 1; i < n; ++i)
            if (std::abs(S(i, k)) > std::abs(S(p, k))) p = i;
        for (int c = 0; c < n; ++c) std::swap(S(k, c), S(p, c));
        for (int c = 0; c < R.cols; ++c) std::swap(R(k, c), R(p, c));
        for (int i = k + 1; i < n; ++i) {
            const double f = S(i, k) / S(k, k);
            if (f == 0.0) continue;
            for (int c = k; c < n; ++c) S(i, c) -= f * S(k, c);
            for (int c = 0; c < R.cols; ++c) R(i, c) -= f * R(k, c);
        }
    }
    for (int k = n - 1; k >= 0; --k)
        for (int c = 0; c < R.cols; ++c) {
            double x = R(k, c);
            for (int i = k + 1; i < n; ++i) x -= S(k, i) * R(i, c);
            R(k, c) = x / S(k, k);
        }
    return R;
}

WaveletFilters build_filters(int level) {
    WaveletFilters f;
    f.level = level;
    f.P = refinement_matrix(level);
    const DenseMatrix M = multiply(transpose(f.P), gram_matrix(level)); // P^T G
    auto [Q, rows] = null_space(M);
    f.Q = std::move(Q);
    f.detail_rows = std::move(rows);
    f.A = solve(multiply(M, f.P), M);
    const DenseMatrix PA = multiply(f.P, f.A);
    f.B = DenseMatrix(static_cast<int>(f.detail_rows.size()), f.P.rows);
    for (int k = 0; k < f.B.rows; ++k) {
        const int r = f.detail_rows[k];
        for (int c = 0; c < f.B.cols; ++c) f.B(k, c) = (r == c ? 1.0 : 0.0) - PA(r, c);
    }
    return f;
}

} // namespace

const WaveletFilters& cubic_wavelet_filters(int level) {
    assert(level >= 1 && level <= max_wavelet_level);
    static std::mutex mutex;
    static std::map<int, std::unique_ptr<const WaveletFilters>> built;
    std::lock_guard lock(mutex);
    auto& slot = built[level];
    if (!slot) slot = std::make_unique<const WaveletFilters>(build_filters(level));
    return *slot;
}

} // namespace isoparm::geom
