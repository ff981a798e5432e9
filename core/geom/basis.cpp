// B-spline basis functions (Piegl & Tiller A2.2, A2.3) and the rational basis.
#include "core/geom/basis.hpp"

#include <algorithm>
#include <cassert>
#include <limits>

#include "core/geom/binomial.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/small_buffer.hpp"

namespace isoparm::geom {

namespace {
constexpr int max_degree_stack = 32; // larger degrees use the heap
}

void basis_funs(int span, double t, int p, const Knots& U, double* N) {
    // Piegl & Tiller A2.2 BasisFuns: the triangular Cox-de Boor scheme without zero terms.
    double left_stack[max_degree_stack + 1], right_stack[max_degree_stack + 1];
    std::vector<double> heap;
    double *left = left_stack, *right = right_stack;
    if (p > max_degree_stack) {
        heap.resize(2 * (static_cast<size_t>(p) + 1));
        left = heap.data();
        right = heap.data() + p + 1;
    }
    N[0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = t - U[span + 1 - j];
        right[j] = U[span + j] - t;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            const double denom = right[r + 1] + left[j - r];
            if (denom < std::numeric_limits<double>::min()) {
                // Knots a subnormal apart (a domain [0, 5e-324]): 1 / denom overflows, so the
                // ratios are formed first (each in [0, 1]).
                const double temp = N[r];
                N[r] = saved + right[r + 1] / denom * temp;
                saved = left[j - r] / denom * temp;
                continue;
            }
            const double temp = N[r] / denom;
            N[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        N[j] = saved;
    }
}

void ders_basis_funs(int span, double t, int p, int d, const Knots& U, double* ders) {
    // Piegl & Tiller A2.3 DersBasisFuns.
    const int w = p + 1;
    SmallBuffer<double, 256> ndu(static_cast<size_t>(w) * w);
    SmallBuffer<double, 16> left(w), right(w);
    SmallBuffer<double, 32> arow(2 * static_cast<size_t>(w)); // two rows of a_{k,j}, alternating
    auto NDU = [&](int r, int c) -> double& { return ndu[static_cast<size_t>(r) * w + c]; };
    NDU(0, 0) = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = t - U[span + 1 - j];
        right[j] = U[span + j] - t;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            NDU(j, r) = right[r + 1] + left[j - r]; // lower triangle: knot differences
            if (NDU(j, r) < std::numeric_limits<double>::min()) { // as in basis_funs
                const double temp = NDU(r, j - 1);
                NDU(r, j) = saved + right[r + 1] / NDU(j, r) * temp;
                saved = left[j - r] / NDU(j, r) * temp;
                continue;
            }
            const double temp = NDU(r, j - 1) / NDU(j, r);
            NDU(r, j) = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        NDU(j, j) = saved;
    }
    for (int k = 0; k <= d; ++k)
        for (int r = 0; r <= p; ++r) ders[k * w + r] = 0.0;
    for (int j = 0; j <= p; ++j) ders[j] = NDU(j, p);
    const int dmax = std::min(d, p);
    for (int r = 0; r <= p; ++r) {
        int s1 = 0, s2 = 1;
        std::fill(arow.data(), arow.data() + 2 * w, 0.0);
        auto AR = [&](int row, int col) -> double& {
            return arow[static_cast<size_t>(row) * w + col];
        };
        AR(0, 0) = 1.0;
        for (int k = 1; k <= dmax; ++k) {
            double dv = 0.0;
            const int rk = r - k, pk = p - k;
            if (r >= k) {
                AR(s2, 0) = AR(s1, 0) / NDU(pk + 1, rk);
                dv = AR(s2, 0) * NDU(rk, pk);
            }
            const int j1 = rk >= -1 ? 1 : -rk;
            const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
            for (int j = j1; j <= j2; ++j) {
                AR(s2, j) = (AR(s1, j) - AR(s1, j - 1)) / NDU(pk + 1, rk + j);
                dv += AR(s2, j) * NDU(rk + j, pk);
            }
            if (r <= pk) {
                AR(s2, k) = -AR(s1, k - 1) / NDU(pk + 1, r);
                dv += AR(s2, k) * NDU(r, pk);
            }
            ders[k * w + r] = dv;
            std::swap(s1, s2);
        }
    }
    double factor = p;
    for (int k = 1; k <= dmax; ++k) {
        for (int j = 0; j <= p; ++j) ders[k * w + j] *= factor;
        factor *= (p - k);
    }
}

BasisAt basis_at(const Knots& U, int p, int n, double t, int derivatives) {
    BasisAt b;
    b.span = find_span(U, p, n, t);
    b.first_index = b.span - p;
    std::vector<double> ders(static_cast<size_t>(derivatives + 1) * (p + 1));
    ders_basis_funs(b.span, t, p, derivatives, U, ders.data());
    b.values.resize(derivatives + 1);
    for (int k = 0; k <= derivatives; ++k)
        b.values[k].assign(ders.begin() + k * (p + 1), ders.begin() + (k + 1) * (p + 1));
    return b;
}

std::vector<std::vector<double>> all_basis(const Knots& U, int p, int n, double t,
                                           int derivatives) {
    const BasisAt b = basis_at(U, p, n, t, derivatives);
    std::vector<std::vector<double>> out(derivatives + 1, std::vector<double>(n, 0.0));
    for (int k = 0; k <= derivatives; ++k)
        for (int r = 0; r <= p; ++r) out[k][b.first_index + r] = b.values[k][r];
    return out;
}

std::optional<std::vector<std::vector<double>>>
rational_basis(const Knots& U, int p, const std::vector<double>& w, double t, int derivatives) {
    const int n = static_cast<int>(w.size());
    const auto N = all_basis(U, p, n, t, derivatives);
    // W^(k) = sum_i N_i^(k) w_i; R_i = N_i w_i / W, so N_i^(k) w_i = sum_j C(k,j) W^(j) R_i^(k-j)
    // (Leibniz), solved for R_i^(k) as in Piegl & Tiller A4.2.
    std::vector<double> W(derivatives + 1, 0.0);
    for (int k = 0; k <= derivatives; ++k)
        for (int i = 0; i < n; ++i) W[k] += N[k][i] * w[i];
    if (W[0] == 0.0) return std::nullopt;
    std::vector<std::vector<double>> R(derivatives + 1, std::vector<double>(n, 0.0));
    for (int i = 0; i < n; ++i) {
        for (int k = 0; k <= derivatives; ++k) {
            double v = N[k][i] * w[i];
            for (int j = 1; j <= k; ++j) v -= binomial(k, j) * W[j] * R[k - j][i];
            R[k][i] = v / W[0];
        }
    }
    return R;
}

std::optional<double> rational_basis_ij(const Surface& s, int i, int j, double u, double v) {
    const BasisAt bu = basis_at(s.knots_u, s.degree_u, s.n_u, u);
    const BasisAt bv = basis_at(s.knots_v, s.degree_v, s.n_v, v);
    double W = 0.0, Nij = 0.0;
    for (int a = 0; a <= s.degree_u; ++a) {
        for (int b = 0; b <= s.degree_v; ++b) {
            const int ii = bu.first_index + a, jj = bv.first_index + b;
            const double nb = bu.values[0][a] * bv.values[0][b];
            W += nb * s.weight(ii, jj);
            if (ii == i && jj == j) Nij = nb * s.weight(ii, jj);
        }
    }
    if (W == 0.0) return std::nullopt;
    return Nij / W;
}

} // namespace isoparm::geom
