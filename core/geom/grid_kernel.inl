// The vertex kernel source (see grid_kernel.hpp for the scheme), included by
// grid_kernel_baseline.cpp, grid_kernel_avx2.cpp and grid_kernel_avx512.cpp, each of which
// defines ISOPARM_KERNEL_LANES (doubles per vector) first. Everything here is in an anonymous
// namespace and calls no inline library code, so the builds cannot lend each other code.
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace {

using isoparm::geom::kernel::GridArgs;

constexpr int W = ISOPARM_KERNEL_LANES;
// W sample columns as one vector (GCC/Clang vector extensions: one zmm / ymm register in the
// AVX-512 / AVX2 builds, one xmm (SSE2, or NEON elsewhere) register in the baseline build: a
// wider generic vector would live on the stack there) and the masks comparisons give.
typedef double vd __attribute__((vector_size(8 * W)));
typedef long long vm __attribute__((vector_size(8 * W)));
typedef double v4 __attribute__((vector_size(32)));

inline void load(vd& v, const double* p) {
    __builtin_memcpy(&v, p, sizeof v);
}
inline void store(double* p, const vd& v) {
    __builtin_memcpy(p, &v, sizeof v);
}

// acc + a * b. The kernel files are compiled with -ffp-contract=off, so that the multiply-adds
// fused are exactly these (the same in every instantiation, every degree and every build with
// FMA), not whichever ones the compiler chooses per inlining context.
// (By reference: returning a vector type from a non-AVX function would change the ABI.)
inline void madd(vd& acc, const vd& a, const vd& b) {
#if defined(__AVX512F__) && ISOPARM_KERNEL_LANES == 8
    acc = (vd)_mm512_fmadd_pd((__m512d)a, (__m512d)b, (__m512d)acc);
#elif defined(__FMA__) && ISOPARM_KERNEL_LANES == 4
    acc = (vd)_mm256_fmadd_pd((__m256d)a, (__m256d)b, (__m256d)acc);
#else
    acc += a * b;
#endif
}
// a in every lane (vd{} + a would add +0.0 first: an addition before each broadcast).
inline vd splat(double a) {
#if defined(__AVX512F__) && ISOPARM_KERNEL_LANES == 8
    return (vd)_mm512_set1_pd(a);
#elif defined(__AVX__) && ISOPARM_KERNEL_LANES == 4
    return (vd)_mm256_set1_pd(a);
#elif defined(__SSE2__) && ISOPARM_KERNEL_LANES == 2
    return (vd)_mm_set1_pd(a);
#else
    vd v;
    for (int l = 0; l < W; ++l) v[l] = a;
    return v;
#endif
}
inline void madd(vd& acc, double a, const vd& b) {
    madd(acc, splat(a), b);
}
inline void madd(vd& acc, const vd& a, double b) {
    madd(acc, a, splat(b));
}

// One bit per lane where the mask is set.
inline int bits(const vm& m) {
#if defined(__AVX512F__) && ISOPARM_KERNEL_LANES == 8
    return _mm512_test_epi64_mask((__m512i)m, (__m512i)m);
#elif defined(__AVX__) && ISOPARM_KERNEL_LANES == 4
    return _mm256_movemask_pd((__m256d)m);
#elif defined(__SSE2__) && ISOPARM_KERNEL_LANES == 2
    return _mm_movemask_pd((__m128d)m);
#else
    int b = 0;
    for (int l = 0; l < W; ++l) b |= (m[l] != 0) << l;
    return b;
#endif
}

// 1 / w, and the lanes where w is zero (one bit each: the points that do not exist).
inline int reciprocal(vd& r, const vd& w) {
    r = 1.0 / w;
#if defined(__AVX512F__) && ISOPARM_KERNEL_LANES == 8
    // Straight into a mask register (a vector comparison would be widened to a vector and
    // tested back: two more operations on the busy ports).
    return _mm512_cmp_pd_mask((__m512d)w, _mm512_setzero_pd(), _CMP_EQ_OQ);
#else
    return bits(w == 0.0);
#endif
}

// The lanes of a normal that is good: len2 > 1e-20 big2^2, and finite (len2 - len2 == 0 is
// false for infinities and NaN: isfinite without a library call).
inline int good_lanes(const vd& len2, const vd& big2) {
    const vd least = 1e-20 * big2 * big2, zero = len2 - len2;
#if defined(__AVX512F__) && ISOPARM_KERNEL_LANES == 8
    return _mm512_cmp_pd_mask((__m512d)len2, (__m512d)least, _CMP_GT_OQ) &
           _mm512_cmp_pd_mask((__m512d)zero, _mm512_setzero_pd(), _CMP_EQ_OQ);
#else
    return bits((len2 > least) & (zero == 0.0));
#endif
}

// 1 / sqrt(x), the normals' length. (AVX-512F's vrsqrt14pd with two Newton steps was measured
// no faster here, within noise, and would make this path's normals differ from AVX2's in the
// last bits: the two FMA paths give the same bits, which the protocol recordings rely on.)
inline void reciprocal_sqrt(vd& r, const vd& x) {
#if defined(__AVX512F__) && ISOPARM_KERNEL_LANES == 8
    // The masked form: GCC 12 warns about _mm512_sqrt_pd's undefined pass-through operand.
    r = 1.0 / (vd)_mm512_mask_sqrt_pd((__m512d)x, (__mmask8)0xFF, (__m512d)x);
#elif defined(__AVX__) && ISOPARM_KERNEL_LANES == 4
    r = 1.0 / (vd)_mm256_sqrt_pd((__m256d)x);
#elif defined(__SSE2__) && ISOPARM_KERNEL_LANES == 2
    r = 1.0 / (vd)_mm_sqrt_pd((__m128d)x);
#else
    vd root;
    for (int l = 0; l < W; ++l) root[l] = __builtin_sqrt(x[l]);
    r = 1.0 / root;
#endif
}

// Four lanes of x, y, z as 12 consecutive doubles (x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3).
inline void store_xyz4(double* out, const v4& x, const v4& y, const v4& z) {
    const v4 t0 = __builtin_shufflevector(x, y, 0, 4, 1, 5);
    const v4 o0 = __builtin_shufflevector(t0, z, 0, 1, 4, 2);
    const v4 t1 = __builtin_shufflevector(y, z, 1, 5, 2, 6);
    const v4 o1 = __builtin_shufflevector(t1, x, 0, 1, 6, 2);
    const v4 t2 = __builtin_shufflevector(x, y, 3, 7, 3, 7);
    const v4 o2 = __builtin_shufflevector(z, t2, 2, 4, 5, 3);
    __builtin_memcpy(out, &o0, 32);
    __builtin_memcpy(out + 4, &o1, 32);
    __builtin_memcpy(out + 8, &o2, 32);
}

#if defined(__AVX512F__) && ISOPARM_KERNEL_LANES == 8
// How 8 lanes of x, y, z (24 consecutive doubles, starting `offset` doubles into a 64-byte
// line) fall into the 4 lines they touch: per line, the indices of a permute of x and y (0-7
// x, 8-15 y), then of one of that and z (0-7 kept, 8-15 z), and the lanes that are the
// chunk's (lines 1 and 2 always all 8; line 0 the last 8 - offset, line 3 the first offset).
struct StorePlan {
    alignas(64) long long xy[4][8];
    alignas(64) long long z[4][8];
    __mmask16 first, last; // the lanes of lines 0 and 3 (16 bits: what _load_mask16 reads)
};
struct StorePlans {
    StorePlan p[8];
};
constexpr StorePlans make_store_plans() {
    StorePlans plans{};
    for (int offset = 0; offset < 8; ++offset)
        for (int k = 0; k < 4; ++k)
            for (int l = 0; l < 8; ++l) {
                StorePlan& p = plans.p[offset];
                const int q = 8 * k + l - offset; // the double's place among the 24
                p.z[k][l] = l;
                if (q < 0 || q >= 24) continue;
                if (k == 0) p.first = static_cast<__mmask16>(p.first | 1 << l);
                if (k == 3) p.last = static_cast<__mmask16>(p.last | 1 << l);
                if (q % 3 == 2)
                    p.z[k][l] = 8 + q / 3;
                else
                    p.xy[k][l] = q / 3 + 8 * (q % 3);
            }
    return plans;
}
constexpr StorePlans store_plans = make_store_plans();

// The plan of a row's chunks, chosen once per row: every chunk of a row starts at the same
// offset in its line (24 doubles = 3 lines apart). Choosing it per chunk, from the address, had
// cost two mask moves to port 5 per line (8 per chunk, as many as the permutes) on the port
// that runs every 512-bit operation but the other half of the FMAs, and kept positions at
// 1.15-1.25x AVX2. RowStore reloads indices and masks per chunk (loads are cheap: index
// registers held across the normals' loop made it spill its accumulators); RowRegs holds them
// in registers (positions: few live vectors, no mask move at all per chunk).
struct RowStore {
    const StorePlan* plan;
};
inline void row_store(RowStore& r, const double* at) {
    r.plan = &store_plans.p[(reinterpret_cast<std::uintptr_t>(at) >> 3) & 7];
}
struct RowRegs {
    __m512i xy[4], z[4];
    __mmask8 first, last;
};
inline void row_store(RowRegs& r, const double* at) {
    RowStore s;
    row_store(s, at);
    for (int k = 0; k < 4; ++k) {
        r.xy[k] = _mm512_load_si512(s.plan->xy[k]);
        r.z[k] = _mm512_load_si512(s.plan->z[k]);
    }
    r.first = static_cast<__mmask8>(s.plan->first);
    r.last = static_cast<__mmask8>(s.plan->last);
}
// Lines 0 .. 3 of the 24 doubles (see store_xyz).
inline __m512d store_line(const RowStore& r, int k, __m512d x, __m512d y, __m512d z) {
    const __m512d t = _mm512_permutex2var_pd(x, _mm512_load_si512(r.plan->xy[k]), y);
    return _mm512_permutex2var_pd(t, _mm512_load_si512(r.plan->z[k]), z);
}
inline __m512d store_line(const RowRegs& r, int k, __m512d x, __m512d y, __m512d z) {
    return _mm512_permutex2var_pd(_mm512_permutex2var_pd(x, r.xy[k], y), r.z[k], z);
}
inline __mmask8 first_lanes(const RowStore& r) {
    return static_cast<__mmask8>(_load_mask16(const_cast<__mmask16*>(&r.plan->first)));
}
inline __mmask8 last_lanes(const RowStore& r) {
    return static_cast<__mmask8>(_load_mask16(const_cast<__mmask16*>(&r.plan->last)));
}
inline __mmask8 first_lanes(const RowRegs& r) {
    return r.first;
}
inline __mmask8 last_lanes(const RowRegs& r) {
    return r.last;
}
#else
struct RowStore {};
struct RowRegs {};
inline void row_store(RowStore&, const double*) {}
inline void row_store(RowRegs&, const double*) {}
#endif

// out: where a chunk of the row that `r` (a RowStore or RowRegs) was made for starts.
template <class R>
inline void store_xyz(double* out, [[maybe_unused]] const R& r, const vd& x, const vd& y,
                      const vd& z) {
#if ISOPARM_KERNEL_LANES == 2
    typedef double v2 __attribute__((vector_size(16)));
    const v2 o0 = __builtin_shufflevector(x, y, 0, 2), o1 = __builtin_shufflevector(z, x, 0, 3),
             o2 = __builtin_shufflevector(y, z, 1, 3);
    __builtin_memcpy(out, &o0, 16);
    __builtin_memcpy(out + 2, &o1, 16);
    __builtin_memcpy(out + 4, &o2, 16);
#elif ISOPARM_KERNEL_LANES == 4
    store_xyz4(out, x, y, z);
#elif defined(__AVX512F__) && ISOPARM_KERNEL_LANES == 8
    // Straight into the cache lines the 24 doubles cover: four aligned stores (masked where a
    // line is shared with the neighbours) of two permutes each (x and y together, then z into
    // its lanes). Unaligned 64-byte stores would each touch two lines: the output vectors (16
    // bytes past a line from malloc) made such split stores the largest cost of this path.
    double* line =
        reinterpret_cast<double*>(reinterpret_cast<std::uintptr_t>(out) & ~std::uintptr_t{63});
    const __m512d X = (__m512d)x, Y = (__m512d)y, Z = (__m512d)z;
    _mm512_mask_store_pd(line, first_lanes(r), store_line(r, 0, X, Y, Z));
    _mm512_store_pd(line + 8, store_line(r, 1, X, Y, Z));
    _mm512_store_pd(line + 16, store_line(r, 2, X, Y, Z));
    _mm512_mask_store_pd(line + 24, last_lanes(r), store_line(r, 3, X, Y, Z));
#else
    for (int h = 0; h < W; h += 4) {
        v4 a, b, c;
        __builtin_memcpy(&a, reinterpret_cast<const double*>(&x) + h, 32);
        __builtin_memcpy(&b, reinterpret_cast<const double*>(&y) + h, 32);
        __builtin_memcpy(&c, reinterpret_cast<const double*>(&z) + h, 32);
        store_xyz4(out + 3 * h, a, b, c);
    }
#endif
}

// Where the chunk's lanes land: whole chunks inside j0..j1 are written in place, the others
// through `tmp` (then only their lanes inside j0..j1 are copied).
struct Lanes {
    int j;      // the chunk's first sample column
    int lo, hi; // lanes inside j0..j1
    bool whole() const { return lo == 0 && hi == W - 1; }
};

// r: the row's (row_store of a chunk's start in row).
template <class R>
inline void put_xyz(double* row, const R& r, const Lanes& L, const vd& x, const vd& y,
                    const vd& z) {
    if (L.whole()) return store_xyz(row + 3L * L.j, r, x, y, z);
    double tmp[3 * W];
    RowStore t;
    row_store(t, tmp);
    store_xyz(tmp, t, x, y, z);
    for (int l = L.lo; l <= L.hi; ++l)
        for (int c = 0; c < 3; ++c) row[3L * (L.j + l) + c] = tmp[3 * l + c];
}

// row: the block's status row, whose first byte is column j0.
inline int put_status(std::uint8_t* row, int j0, const Lanes& L, int missing, int degenerate) {
    using namespace isoparm::geom::kernel;
    int bad = 0;
    for (int l = L.lo; l <= L.hi; ++l) {
        const std::uint8_t s = (missing >> l) & 1        ? vertex_missing
                               : ((degenerate >> l) & 1) ? vertex_degenerate
                                                         : vertex_ok;
        row[L.j + l - j0] = s;
        bad += s != vertex_ok;
    }
    return bad;
}

// Four components B doubles apart.
inline void store4(double* to, long B, const vd& x, const vd& y, const vd& z, const vd& w) {
    store(to, x);
    store(to + B, y);
    store(to + 2 * B, z);
    store(to + 3 * B, w);
}

// Step 1 for control row a: R (and Rv with v-derivatives) for chunks ch0 .. ch0 + nch - 1;
// each of the 4 components is a row of B = nch * W doubles, stored at R and again at R +
// mirror (see block). H receives the homogeneous control points (wx, wy, wz, w) of columns c0
// .. c0 + width - 1 of the row first (the products homogeneous coordinates always are: x * w
// rounded once, in every build).
template <int NC>
void contract_v(const GridArgs& g, int a, int ch0, int nch, double* H, int c0, int width, double* R,
                double* Rv, long mirror) {
    const int nc = NC > 0 ? NC : g.nc;
    const long B = static_cast<long>(nch) * W;
    {
        const long first = static_cast<long>(a) * g.n_v + c0;
        const double* xyz = g.points + 3 * first;
        const double* wt = g.weights + first;
        for (int c = 0; c < width; ++c) {
            const double w = wt[c];
            H[4 * c + 0] = xyz[3 * c + 0] * w;
            H[4 * c + 1] = xyz[3 * c + 1] * w;
            H[4 * c + 2] = xyz[3 * c + 2] * w;
            H[4 * c + 3] = w;
        }
    }
    for (int k = 0; k < nch; ++k) {
        const int ch = ch0 + k;
        const double* m = g.M + static_cast<long>(ch) * nc * W;
        const double* P = H + 4L * (g.f0[ch] - c0);
        vd x = {}, y = {}, z = {}, w = {};
        if (!Rv) {
#pragma GCC unroll 10
            for (int c = 0; c < nc; ++c) {
                vd mc;
                load(mc, m + c * W);
                madd(x, mc, P[4 * c + 0]);
                madd(y, mc, P[4 * c + 1]);
                madd(z, mc, P[4 * c + 2]);
                madd(w, mc, P[4 * c + 3]);
            }
        } else {
            const double* dm = g.dM + static_cast<long>(ch) * nc * W;
            vd xv = {}, yv = {}, zv = {}, wv = {};
#pragma GCC unroll 10
            for (int c = 0; c < nc; ++c) {
                vd mc, dc;
                load(mc, m + c * W);
                load(dc, dm + c * W);
                madd(x, mc, P[4 * c + 0]);
                madd(y, mc, P[4 * c + 1]);
                madd(z, mc, P[4 * c + 2]);
                madd(w, mc, P[4 * c + 3]);
                madd(xv, dc, P[4 * c + 0]);
                madd(yv, dc, P[4 * c + 1]);
                madd(zv, dc, P[4 * c + 2]);
                madd(wv, dc, P[4 * c + 3]);
            }
            store4(Rv + k * W, B, xv, yv, zv, wv);
            store4(Rv + mirror + k * W, B, xv, yv, zv, wv);
        }
        store4(R + k * W, B, x, y, z, w);
        store4(R + mirror + k * W, B, x, y, z, w);
    }
}

// Step 2, positions only, for sample row i; R points at control row first_u[i] of the block.
template <int P1> long row_positions(const GridArgs& g, int i, int ch0, int nch, const double* R) {
    const int p1 = P1 > 0 ? P1 : g.p + 1;
    const long B = static_cast<long>(nch) * W;
    const double* nu = g.Nu + static_cast<long>(i) * p1;
    double* out = g.positions + 3L * i * g.samples_v;
    std::uint8_t* st = g.status + static_cast<long>(i - g.i0) * (g.j1 - g.j0 + 1);
    long bad = 0;
    // The row's u basis in registers (the output stores could alias nu: loads in the loop
    // would be repeated for every chunk).
    vd N[P1 > 0 ? P1 : 1];
    if constexpr (P1 > 0)
        for (int r = 0; r < P1; ++r) N[r] = splat(nu[r]);
    RowRegs rs;
    row_store(rs, out + 3L * ch0 * W);
    const auto finish = [&](int k, const vd& x, const vd& y, const vd& z, const vd& w) {
        vd inv;
        const int missing = reciprocal(inv, w);
        const int j = (ch0 + k) * W;
        const Lanes L{j, g.j0 > j ? g.j0 - j : 0, g.j1 < j + W - 1 ? g.j1 - j : W - 1};
        put_xyz(out, rs, L, x * inv, y * inv, z * inv);
        if (missing == 0 && L.whole()) {
            __builtin_memset(st + (j - g.j0), 0, W);
        } else {
            bad += put_status(st, g.j0, L, missing, 0);
        }
    };
    int k = 0;
    for (; k < nch; ++k) {
        vd x = {}, y = {}, z = {}, w = {};
#pragma GCC unroll 8
        for (int r = 0; r < p1; ++r) {
            const double* Rr = R + 4 * r * B + k * W;
            vd a0, a1, a2, a3;
            load(a0, Rr);
            load(a1, Rr + B);
            load(a2, Rr + 2 * B);
            load(a3, Rr + 3 * B);
            const vd n = P1 > 0 ? N[r] : splat(nu[r]);
            madd(x, n, a0);
            madd(y, n, a1);
            madd(z, n, a2);
            madd(w, n, a3);
        }
        finish(k, x, y, z, w);
    }
    return bad;
}

// Step 2 with first derivatives and unit normals: S = A / w, S_u = (A_u - w_u S) / w, S_v
// likewise (A4.4 to first order); the normal is degenerate where
// |S_u x S_v| < 1e-10 max(|S_u|, |S_v|)^2 (as normal_from_derivatives).
template <int P1>
long row_normals(const GridArgs& g, int i, int ch0, int nch, const double* R, const double* Rv) {
    const int p1 = P1 > 0 ? P1 : g.p + 1;
    const long B = static_cast<long>(nch) * W;
    const double* nu = g.Nu + static_cast<long>(i) * p1;
    const double* dnu = g.dNu + static_cast<long>(i) * p1;
    double* out = g.positions + 3L * i * g.samples_v;
    double* nout = g.normals + 3L * i * g.samples_v;
    std::uint8_t* st = g.status + static_cast<long>(i - g.i0) * (g.j1 - g.j0 + 1);
    long bad = 0;
    vd N[P1 > 0 ? P1 : 1], dN[P1 > 0 ? P1 : 1];
    if constexpr (P1 > 0)
        for (int r = 0; r < P1; ++r) {
            N[r] = splat(nu[r]);
            dN[r] = splat(dnu[r]);
        }
    RowStore rs, nrs;
    row_store(rs, out + 3L * ch0 * W);
    row_store(nrs, nout + 3L * ch0 * W);
    for (int k = 0; k < nch; ++k) {
        vd x = {}, y = {}, z = {}, w = {};
        vd xu = {}, yu = {}, zu = {}, wu = {};
        vd xv = {}, yv = {}, zv = {}, wv = {};
#pragma GCC unroll 8
        for (int r = 0; r < p1; ++r) {
            const double* Rr = R + 4 * r * B + k * W;
            const double* Vr = Rv + 4 * r * B + k * W;
            vd a0, a1, a2, a3, b0, b1, b2, b3;
            load(a0, Rr);
            load(a1, Rr + B);
            load(a2, Rr + 2 * B);
            load(a3, Rr + 3 * B);
            load(b0, Vr);
            load(b1, Vr + B);
            load(b2, Vr + 2 * B);
            load(b3, Vr + 3 * B);
            const vd n = P1 > 0 ? N[r] : splat(nu[r]), dn = P1 > 0 ? dN[r] : splat(dnu[r]);
            madd(x, n, a0);
            madd(y, n, a1);
            madd(z, n, a2);
            madd(w, n, a3);
            madd(xu, dn, a0);
            madd(yu, dn, a1);
            madd(zu, dn, a2);
            madd(wu, dn, a3);
            madd(xv, n, b0);
            madd(yv, n, b1);
            madd(zv, n, b2);
            madd(wv, n, b3);
        }
        vd inv;
        const int missing = reciprocal(inv, w);
        const vd sx = x * inv, sy = y * inv, sz = z * inv;
        const vd ux = (xu - wu * sx) * inv, uy = (yu - wu * sy) * inv, uz = (zu - wu * sz) * inv;
        const vd vx = (xv - wv * sx) * inv, vy = (yv - wv * sy) * inv, vz = (zv - wv * sz) * inv;
        const vd nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        const vd len2 = nx * nx + ny * ny + nz * nz;
        const vd su2 = ux * ux + uy * uy + uz * uz, sv2 = vx * vx + vy * vy + vz * vz;
        const vd big2 = su2 > sv2 ? su2 : sv2;
        const int good = good_lanes(len2, big2);
        vd rn;
        reciprocal_sqrt(rn, len2);
        const int j = (ch0 + k) * W;
        const Lanes L{j, g.j0 > j ? g.j0 - j : 0, g.j1 < j + W - 1 ? g.j1 - j : W - 1};
        put_xyz(out, rs, L, sx, sy, sz);
        put_xyz(nout, nrs, L, nx * rn, ny * rn, nz * rn);
        const int degenerate = ~good & ((1 << W) - 1);
        if ((missing | degenerate) == 0 && L.whole()) {
            __builtin_memset(st + (j - g.j0), 0, W);
        } else {
            bad += put_status(st, g.j0, L, missing, degenerate);
        }
    }
    return bad;
}

template <int NC, int P1> long block(const GridArgs& g) {
    const int nc = NC > 0 ? NC : g.nc, p1 = P1 > 0 ? P1 : g.p + 1;
    const int ch0 = g.j0 / W, nch = g.j1 / W - ch0 + 1;
    const long plane = 4L * nch * W; // one control row's R
    // Control rows are contracted in v just before the first sample row that needs them, into
    // a ring of the last p + 1 (row a in slot a % (p + 1)) kept twice over, slot s also at
    // s + p + 1: the rows first .. first + p of a sample row are then consecutive (from slot
    // first % (p + 1)), and the ring stays in L1 however many control rows the block spans.
    const long mirror = p1 * plane;
    double* R = g.scratch;
    double* Rv = g.normals ? R + 2 * mirror : nullptr;
    double* H = R + (g.normals ? 4 : 2) * mirror;
    const int c0 = g.f0[ch0], width = g.f0[ch0 + nch - 1] + nc - c0;
    int done = g.first_u[g.i0] - 1;
    long bad = 0;
    for (int i = g.i0; i <= g.i1; ++i) {
        const int first = g.first_u[i];
        // Rows below first are never read again (first only grows): skipped, not contracted.
        for (int a = done >= first ? done + 1 : first; a <= first + g.p; ++a) {
            const long at = (a % p1) * plane;
            contract_v<NC>(g, a, ch0, nch, H, c0, width, R + at, Rv ? Rv + at : nullptr, mirror);
        }
        if (first + g.p > done) done = first + g.p;
        const long off = (first % p1) * plane;
        bad += g.normals ? row_normals<P1>(g, i, ch0, nch, R + off, Rv + off)
                         : row_positions<P1>(g, i, ch0, nch, R + off);
    }
    return bad;
}

// Compile-time band widths and u degrees for the common cases (degrees 1..5), run-time ones
// otherwise (and when the tests ask for the generic code).
template <int NC> long with_nc(const GridArgs& g) {
    if (g.generic) return block<0, 0>(g);
    switch (g.p) {
    case 1:
        return block<NC, 2>(g);
    case 2:
        return block<NC, 3>(g);
    case 3:
        return block<NC, 4>(g);
    case 4:
        return block<NC, 5>(g);
    case 5:
        return block<NC, 6>(g);
    default:
        return block<NC, 0>(g);
    }
}

long dispatch(const GridArgs& g) {
    if (g.generic) return block<0, 0>(g);
    switch (g.nc) {
    case 2:
        return with_nc<2>(g);
    case 3:
        return with_nc<3>(g);
    case 4:
        return with_nc<4>(g);
    case 5:
        return with_nc<5>(g);
    case 6:
        return with_nc<6>(g);
    case 7:
        return with_nc<7>(g);
    case 8:
        return with_nc<8>(g);
    case 9:
        return with_nc<9>(g);
    default:
        return with_nc<0>(g);
    }
}

} // namespace
