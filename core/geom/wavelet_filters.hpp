// Cubic B-spline wavelet filters for endpoint-interpolating (clamped) uniform knots: the
// matrices that split level j's control points into level j - 1's plus detail and join them
// back (Finkelstein & Salesin, "Multiresolution curves", SIGGRAPH 1994; Stollnitz, DeRose &
// Salesin, "Wavelets for computer graphics", 1996, ch. 7 "B-spline wavelets").
//
// Level j has 2^j uniform spans and 2^j + 3 control points. With C_j its control points,
//     C_(j-1) = A_j C_j,   D_(j-1) = B_j C_j      (analysis)
//     C_j = P_j C_(j-1) + Q_j D_(j-1)             (synthesis)
// and [A_j; B_j] is the inverse of [P_j | Q_j].
#pragma once

#include <vector>

namespace isoparm::geom {

// A dense row-major matrix (the filters are small: level 10 has 1027 columns).
struct DenseMatrix {
    int rows = 0, cols = 0;
    std::vector<double> values;

    DenseMatrix() = default;
    DenseMatrix(int r, int c) : rows(r), cols(c), values(static_cast<std::size_t>(r) * c, 0.0) {}
    double& operator()(int r, int c) { return values[static_cast<std::size_t>(r) * cols + c]; }
    double operator()(int r, int c) const { return values[static_cast<std::size_t>(r) * cols + c]; }
};

struct WaveletFilters {
    int level = 1; // j: these filters join level j - 1 and level j
    DenseMatrix P; // (2^j + 3) x (2^(j-1) + 3): knot insertion at every span's midpoint
    DenseMatrix Q; // (2^j + 3) x 2^(j-1): wavelets, L2-orthogonal to level j - 1's B-splines
    DenseMatrix A; // (2^(j-1) + 3) x (2^j + 3): the least-squares (L2) coarse curve
    DenseMatrix B; // 2^(j-1) x (2^j + 3): the detail coefficients
    // detail_rows[k]: the fine control point that wavelet k is the unit vector at (Q's
    // identity rows); D_(j-1)[k] is the fine residual C_j - P_j C_(j-1) there.
    std::vector<int> detail_rows;
};

// The finest level the filters are built for (2^10 + 3 = 1027 control points): above it the
// dense matrices would cost more than an interactive edit can wait for.
inline constexpr int max_wavelet_level = 10;

// The filters between level j - 1 and level j, 1 <= j <= max_wavelet_level (checked by the
// caller), built once per level and kept (thread-safe).
const WaveletFilters& cubic_wavelet_filters(int level);

} // namespace isoparm::geom
