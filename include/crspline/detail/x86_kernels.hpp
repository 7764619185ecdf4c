// crspline: AVX2 batch kernels for 3-D double points, chosen at run time.
//
// The library is built for the x86-64 baseline (SSE2: 2 doubles per
// instruction). On a CPU with AVX2 the batch evaluation of 3-D double
// points runs these kernels instead, 4 lanes per instruction, selected once
// by a CPUID test (GCC/Clang function targets: nothing needs -mavx2 or
// -march). They use no FMA, so each result goes through the same roundings,
// in the same order, as the portable code: the same bits on every CPU.
//
// detail::avx2_enabled() can be set to false (tests compare both paths).
#pragma once

#include <cstddef>
#include <cstdint>

#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__)) && \
    !defined(CRSPLINE_NO_X86_DISPATCH)
#define CRSPLINE_X86_DISPATCH 1
#include <immintrin.h>
#define CRSPLINE_TARGET_AVX2 __attribute__((target("avx2")))
#else
#define CRSPLINE_X86_DISPATCH 0
#endif

namespace crspline::detail {

#if CRSPLINE_X86_DISPATCH

/// Whether the AVX2 kernels run: the CPU's answer, once; writable so that
/// tests can compare against the portable kernels.
inline bool& avx2_enabled() noexcept {
    static bool on = __builtin_cpu_supports("avx2");
    return on;
}

/// v rotated by r into lanes v[r] v[r+1] v[r+2] v[r] (indices mod 3).
CRSPLINE_TARGET_AVX2 inline __m256d rot(const double* v, int r) noexcept {
    return _mm256_setr_pd(v[r % 3], v[(r + 1) % 3], v[(r + 2) % 3], v[r % 3]);
}

/// The vector loop of sorted_run3 from point k while 4 points remain;
/// returns the new k. Stream: non-temporal stores (out + 3 k 32-byte aligned).
///
/// The lanes hold the output as it is laid out (x0 y0 z0 x1 | y1 z1 x2 y2 |
/// z2 x3 y3 z3): u is spread to match with one permute per register and
/// the coefficients are rotated once per run, so no shuffle of results is
/// needed (3 permutes per 4 points instead of 6).
template <int Order, bool Stream>
CRSPLINE_TARGET_AVX2 std::size_t sorted_loop3(const double* o, const double* a, const double* b, const double* c,
                                              double t0, double ih, double t_end, const double* t, double* out,
                                              std::size_t k, std::size_t n, __m256d& good) noexcept {
    const __m256d vt0 = _mm256_set1_pd(t0), vih = _mm256_set1_pd(ih), vend = _mm256_set1_pd(t_end);
    // Coefficients in the three lane patterns xyzx, yzxy, zxyz (_mm256_setr_pd: lane 0 first).
    const __m256d A0 = rot(a, 0), A1 = rot(a, 1), A2 = rot(a, 2);
    const __m256d B0 = rot(b, 0), B1 = rot(b, 1), B2 = rot(b, 2);
    const __m256d C0 = rot(c, 0), C1 = rot(c, 1), C2 = rot(c, 2);
    const double zero[3] = {0.0, 0.0, 0.0};
    const double* oo = Order == 0 ? o : zero;
    const __m256d O0 = rot(oo, 0), O1 = rot(oo, 1), O2 = rot(oo, 2);
    for (; k + 4 <= n; k += 4) {
        const __m256d x = _mm256_loadu_pd(t + k);
        // Stop before a step with a point at or past the end knot (or NaN).
        if (_mm256_movemask_pd(_mm256_cmp_pd(x, vend, _CMP_LT_OQ)) != 0xF) break;
        const __m256d p = _mm256_loadu_pd(t + k - 1);
        good = _mm256_and_pd(good, _mm256_cmp_pd(p, x, _CMP_LE_OQ));  // false for NaN too
        const __m256d u = _mm256_mul_pd(_mm256_sub_pd(x, vt0), vih);
        const __m256d U0 = _mm256_permute4x64_pd(u, 0x40);  // u0 u0 u0 u1
        const __m256d U1 = _mm256_permute4x64_pd(u, 0xA5);  // u1 u1 u2 u2
        const __m256d U2 = _mm256_permute4x64_pd(u, 0xFE);  // u2 u3 u3 u3
        __m256d r0 = _mm256_add_pd(A0, _mm256_mul_pd(U0, _mm256_add_pd(B0, _mm256_mul_pd(U0, C0))));
        __m256d r1 = _mm256_add_pd(A1, _mm256_mul_pd(U1, _mm256_add_pd(B1, _mm256_mul_pd(U1, C1))));
        __m256d r2 = _mm256_add_pd(A2, _mm256_mul_pd(U2, _mm256_add_pd(B2, _mm256_mul_pd(U2, C2))));
        if constexpr (Order == 0) {
            r0 = _mm256_add_pd(O0, _mm256_mul_pd(U0, r0));
            r1 = _mm256_add_pd(O1, _mm256_mul_pd(U1, r1));
            r2 = _mm256_add_pd(O2, _mm256_mul_pd(U2, r2));
        }
        double* dst = out + 3 * k;
        if constexpr (Stream) {
            _mm256_stream_pd(dst, r0), _mm256_stream_pd(dst + 4, r1), _mm256_stream_pd(dst + 8, r2);
        } else {
            _mm256_storeu_pd(dst, r0), _mm256_storeu_pd(dst + 4, r1), _mm256_storeu_pd(dst + 8, r2);
        }
    }
    return k;
}

/// One sorted run of a 3-D double segment, as catmull_rom's portable
/// run_kernel: out[k] = o + u (a + u (b + u c)) (Order 0) or a + u (b + u c)
/// (Order 1, o unused) with u = (t[k] - t0) ih, for t[0] and the points
/// after it while they are below t_end (at most n); returns how many. Sets
/// unsorted when t is not sorted there (or holds a NaN). out holds 3 n
/// doubles. Large outputs (stream) use non-temporal stores once out is
/// 32-byte aligned.
template <int Order>
CRSPLINE_TARGET_AVX2 std::size_t sorted_run3(const double* o, const double* a, const double* b, const double* c,
                                             double t0, double ih, const double* t, double* out, std::size_t n,
                                             double& previous, bool stream, double t_end, bool& unsorted) noexcept {
    unsigned bad = 0;
    double prev = previous;
    std::size_t k = 0;
    // One point, scalar: the same expression as the portable kernel.
    auto one = [&](std::size_t q) {
        const double x = t[q];
        bad |= unsigned(!(prev <= x));
        prev = x;
        const double u = (x - t0) * ih;
        for (int d = 0; d < 3; ++d) {
            if constexpr (Order == 0) out[3 * q + d] = o[d] + u * (a[d] + u * (b[d] + u * c[d]));
            else out[3 * q + d] = a[d] + u * (b[d] + u * c[d]);
        }
    };
    // Head: at least one point (t[k - 1] is read below), then up to 3 more
    // until the output is 32-byte aligned (3 doubles per point: 24 bytes,
    // so 4 steps visit every 8-byte offset).
    if (n > 0) one(k++);
    while (k < n && k < 4 && t[k] < t_end && reinterpret_cast<std::uintptr_t>(out + 3 * k) % 32 != 0) one(k++);
    if (k + 4 <= n) {
        __m256d good = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
        if (stream && reinterpret_cast<std::uintptr_t>(out + 3 * k) % 32 == 0)
            k = sorted_loop3<Order, true>(o, a, b, c, t0, ih, t_end, t, out, k, n, good);
        else
            k = sorted_loop3<Order, false>(o, a, b, c, t0, ih, t_end, t, out, k, n, good);
        prev = t[k - 1];
        bad |= unsigned(_mm256_movemask_pd(good) != 0xF);
    }
    while (k < n && t[k] < t_end) one(k++);
    previous = prev;
    unsorted = unsorted || bad != 0;
    return k;
}

/// Loads a 3-D double point into lanes 0-2 (lane 3 zero) without reading
/// past it.
CRSPLINE_TARGET_AVX2 inline __m256d load3(const double* p) noexcept {
    return _mm256_maskload_pd(p, _mm256_set_epi64x(0, -1, -1, -1));
}

/// Position on the Hermite segment from p0 to p1 with tangents dx/dt v0, v1,
/// knot interval h, at local u: the arithmetic of catmull_rom's segment
/// (m = h v, c2 = 3 delta - 2 m0 - m1, c3 = m0 + m1 - 2 delta, Horner),
/// per coordinate in lanes 0-2 of the result (lane 3 is junk).
///
/// Wide (p0 and v0 followed by at least one more double in memory, as when
/// they are not the last entries of their arrays): those two are read with
/// plain 4-lane loads, lane 3 ignored.
template <bool Wide>
CRSPLINE_TARGET_AVX2 inline __m256d hermite_point3(const double* p0, const double* p1, const double* v0,
                                                   const double* v1, double h, double u) noexcept {
    const __m256d P0 = Wide ? _mm256_loadu_pd(p0) : load3(p0), P1 = load3(p1);
    const __m256d vh = _mm256_set1_pd(h), vu = _mm256_set1_pd(u);
    const __m256d m0 = _mm256_mul_pd(Wide ? _mm256_loadu_pd(v0) : load3(v0), vh), m1 = _mm256_mul_pd(load3(v1), vh);
    const __m256d delta = _mm256_sub_pd(P1, P0);
    const __m256d two = _mm256_set1_pd(2.0), three = _mm256_set1_pd(3.0);
    const __m256d c2 = _mm256_sub_pd(_mm256_sub_pd(_mm256_mul_pd(three, delta), _mm256_mul_pd(two, m0)), m1);
    const __m256d c3 = _mm256_sub_pd(_mm256_add_pd(m0, m1), _mm256_mul_pd(two, delta));
    return _mm256_add_pd(
        P0, _mm256_mul_pd(vu, _mm256_add_pd(m0, _mm256_mul_pd(vu, _mm256_add_pd(c2, _mm256_mul_pd(vu, c3))))));
}

/// Stores lanes 0-2 of r at out.
CRSPLINE_TARGET_AVX2 inline void store3(double* out, __m256d r) noexcept {
    _mm_storeu_pd(out, _mm256_castpd256_pd128(r));
    _mm_store_sd(out + 2, _mm256_extractf128_pd(r, 1));
}

#else

inline bool& avx2_enabled() noexcept {
    static bool on = false;
    return on;
}

#endif

}  // namespace crspline::detail
