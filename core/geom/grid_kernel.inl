// The vertex kernel source, included by grid_kernel_avx2.cpp and grid_kernel_baseline.cpp.
// Fixed column counts let the compiler unroll and keep (x, y, z, w) in one vector register.
namespace {

// (wx, wy, wz, w) as one vector: one AVX register in the AVX2 build, two SSE2 registers in
// the baseline build (GCC/Clang vector extensions).
typedef double v4d __attribute__((vector_size(32)));

// By reference: returning a vector type from a non-AVX function would change the ABI.
inline void load4(v4d& v, const double* p) {
    __builtin_memcpy(&v, p, sizeof v);
}

template <int Cols>
inline void contract_point(const isoparm::geom::kernel::RowArgs& a, int j, v4d& A) {
    const int cols = Cols > 0 ? Cols : a.q + 1;
    const double* N = a.N + static_cast<long>(j) * cols;
    const double* Q = a.Q + 4L * a.first[j];
    v4d s = {0, 0, 0, 0};
    for (int r = 0; r < cols; ++r) {
        v4d q;
        load4(q, Q + 4 * r);
        s += N[r] * q;
    }
    A = s;
}

template <int Cols>
inline void contract(const isoparm::geom::kernel::RowArgs& a, int j, v4d& A, v4d& Au, v4d& Av) {
    const int cols = Cols > 0 ? Cols : a.q + 1;
    const double* N = a.N + static_cast<long>(j) * cols;
    const double* dN = a.dN + static_cast<long>(j) * cols;
    const double* Q = a.Q + 4L * a.first[j];
    const double* dQ = a.dQ + 4L * a.first[j];
    v4d s = {0, 0, 0, 0}, su = {0, 0, 0, 0}, sv = {0, 0, 0, 0};
    for (int r = 0; r < cols; ++r) {
        v4d q, dq;
        load4(q, Q + 4 * r);
        load4(dq, dQ + 4 * r);
        s += N[r] * q;
        su += N[r] * dq;
        sv += dN[r] * q;
    }
    A = s;
    Au = su;
    Av = sv;
}

// S = A / w, S_u = (A_u - w_u S) / w, S_v likewise (A4.4 to first order); the normal is
// degenerate where |S_u x S_v| < 1e-10 max(|S_u|, |S_v|)^2 (as normal_from_derivatives).
template <int Cols> void positions_impl(const isoparm::geom::kernel::RowArgs& a) {
    using namespace isoparm::geom::kernel;
    for (int j = a.j0; j <= a.j1; ++j) {
        v4d A;
        contract_point<Cols>(a, j, A);
        if (A[3] == 0.0) {
            a.status[j] = vertex_missing;
            continue;
        }
        const double inv = 1.0 / A[3];
        double* P = a.positions + 3L * j;
        P[0] = A[0] * inv;
        P[1] = A[1] * inv;
        P[2] = A[2] * inv;
        a.status[j] = vertex_ok;
    }
}

template <int Cols> void row_impl(const isoparm::geom::kernel::RowArgs& a) {
    using namespace isoparm::geom::kernel;
    if (!a.normals) return positions_impl<Cols>(a);
    for (int j = a.j0; j <= a.j1; ++j) {
        v4d A, Au, Av;
        contract<Cols>(a, j, A, Au, Av);
        const double w = A[3];
        if (w == 0.0) {
            a.status[j] = vertex_missing;
            continue;
        }
        const double inv = 1.0 / w;
        const double sx = A[0] * inv, sy = A[1] * inv, sz = A[2] * inv;
        const double ux = (Au[0] - Au[3] * sx) * inv, uy = (Au[1] - Au[3] * sy) * inv,
                     uz = (Au[2] - Au[3] * sz) * inv;
        const double vx = (Av[0] - Av[3] * sx) * inv, vy = (Av[1] - Av[3] * sy) * inv,
                     vz = (Av[2] - Av[3] * sz) * inv;
        const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        const double len2 = nx * nx + ny * ny + nz * nz;
        const double su2 = ux * ux + uy * uy + uz * uz, sv2 = vx * vx + vy * vy + vz * vz;
        const double big2 = su2 > sv2 ? su2 : sv2;
        double* P = a.positions + 3L * j;
        P[0] = sx;
        P[1] = sy;
        P[2] = sz;
        if (len2 > 1e-20 * big2 * big2 && __builtin_isfinite(len2)) {
            const double r = 1.0 / __builtin_sqrt(len2);
            double* n = a.normals + 3L * j;
            n[0] = nx * r;
            n[1] = ny * r;
            n[2] = nz * r;
            a.status[j] = vertex_ok;
        } else {
            a.status[j] = vertex_degenerate;
        }
    }
}

void dispatch(const isoparm::geom::kernel::RowArgs& a) {
    switch (a.q) {
    case 1:
        row_impl<2>(a);
        break;
    case 2:
        row_impl<3>(a);
        break;
    case 3:
        row_impl<4>(a);
        break;
    case 4:
        row_impl<5>(a);
        break;
    case 5:
        row_impl<6>(a);
        break;
    default:
        row_impl<0>(a);
        break;
    }
}

} // namespace
