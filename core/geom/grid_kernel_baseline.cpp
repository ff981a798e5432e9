// The vertex kernel for any x86-64 (SSE2: 2 sample columns per xmm register) or other CPU, and the
// run-time choice between the builds: the widest one the CPU runs, unless ISOPARM_SIMD names
// another supported one.
#include "core/geom/grid_kernel.hpp"

#include <cstdlib>
#include <initializer_list>
#include <optional>

#include "core/geom/enum_names.hpp"

#define ISOPARM_KERNEL_LANES 2
#include "core/geom/grid_kernel.inl"

namespace isoparm::geom::kernel {

long run_baseline(const GridArgs& a) {
    return dispatch(a);
}

#if !(defined(__x86_64__) && defined(ISOPARM_HAVE_AVX2_KERNEL))
long run_avx2(const GridArgs& a) {
    return dispatch(a); // never chosen: supported(avx2) is false
}
#endif
#if !(defined(__x86_64__) && defined(ISOPARM_HAVE_AVX512_KERNEL))
long run_avx512(const GridArgs& a) {
    return dispatch(a); // never chosen: supported(avx512) is false (and the lanes differ)
}
#endif

int lanes(Path path) {
    return path == Path::avx512 ? 8 : path == Path::avx2 ? 4 : 2;
}

bool supported(Path path) {
    switch (path) {
    case Path::baseline:
        return true;
    case Path::avx2:
#if defined(__x86_64__) && defined(ISOPARM_HAVE_AVX2_KERNEL)
        return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
        return false;
#endif
    case Path::avx512:
#if defined(__x86_64__) && defined(ISOPARM_HAVE_AVX512_KERNEL)
        // libgcc's check includes the operating system's support (XCR0's zmm state).
        return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("fma");
#else
        return false;
#endif
    }
    return false;
}

// The paths' names (ISOPARM_SIMD, benchmarks, tests). Here, not in the header: the ISA builds
// include grid_kernel.hpp and must not see library templates.
inline constexpr EnumName<Path> path_names[] = {
    {Path::baseline, "baseline"}, {Path::avx2, "avx2"}, {Path::avx512, "avx512"}};
static_assert(in_declaration_order(path_names));
constexpr std::span<const EnumName<Path>> enum_names(Path) {
    return path_names;
}

const char* name(Path path) {
    return name_of(path);
}

namespace {
// The widest path first: on the AVX-512 Xeon measured (KVM, 2 vCPUs; tests/bench/compare,
// BM_GridPathsInterleaved: AVX2 and AVX-512 pass after pass in one process, one thread, 256 x
// 256 samples of bicubic rational nets) AVX-512 took 1.26x (128 x 128) and 1.32x (32 x 32)
// less time than AVX2 for positions, 1.61x and 1.70x for normals, once its output interleave
// kept its permute indices and masks out of general registers (grid_kernel.inl, RowStore);
// before that, positions had been 1.15-1.25x and on another Xeon slower than AVX2. The two
// give the same bits, so the choice is one of speed only: ISOPARM_SIMD=avx2 takes AVX2 where a
// CPU runs AVX-512 slowly (a frequency licence, or 512-bit operations split in two halves).
Path choose() {
    if (const char* forced = std::getenv("ISOPARM_SIMD"); forced && *forced)
        if (const std::optional<Path> p = parse_name<Path>(forced); p && supported(*p)) return *p;
    for (Path p : {Path::avx512, Path::avx2})
        if (supported(p)) return p;
    return Path::baseline;
}
} // namespace

Path active_path() {
    static const Path path = choose();
    return path;
}

std::size_t scratch_doubles(const GridArgs& a, int lanes) {
    // The ring of contracted rows (2 (p + 1) rows of 4 components; twice with the
    // derivatives) and one homogeneous control row of the columns the block reads.
    const int ch0 = a.j0 / lanes, ch1 = a.j1 / lanes;
    const long columns = static_cast<long>(ch1 - ch0 + 1) * lanes;
    const long ring = 2L * (a.p + 1) * 4 * columns * (a.normals ? 2 : 1);
    return static_cast<std::size_t>(ring + 4L * (a.f0[ch1] + a.nc - a.f0[ch0]));
}

long run(Path path, const GridArgs& a) {
    switch (path) {
    case Path::avx512:
        return run_avx512(a);
    case Path::avx2:
        return run_avx2(a);
    case Path::baseline:
        break;
    }
    return run_baseline(a);
}

} // namespace isoparm::geom::kernel
