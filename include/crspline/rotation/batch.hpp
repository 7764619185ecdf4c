// crspline: batch evaluation kernels of the rotation curves: the C2 spline
// (c2.hpp), piecewise slerp (catmull_rom.hpp) and, through them, the pose
// curve (pose.hpp).
//
// The classes' batch calls check their arguments and hand the samples here.
// Each segment's data is packed once, at construction, so that a sample does
// the least: for the C2 spline the rotation-vector cubic and the key (one
// exp of a small vector, one quaternion product), for slerp the step's axis
// and half angle (one sine and cosine, one product). Samples go two at a
// time through 16-byte vectors (GCC/Clang vector extensions: two doubles in
// one SSE2 register on the x86-64 baseline, NEON on AArch64; elsewhere one
// at a time), with sine and cosine from a polynomial (poly_sincos) instead
// of libm, which no compiler vectorises.
//
// Every path computes what the scalar evaluate_on() computes, in the same
// order of operations, except sine and cosine (poly_sincos: within 1 ulp of
// the correctly rounded value, std:: within 1 ulp too) and the series for
// the Jacobian coefficients (the first 10 or 16 terms, by Estrin's scheme): the
// results agree with the scalar ones to a few ulps of their size
// (tests/rotation/test_rotation_batch.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(CRSPLINE_NO_X86_DISPATCH)
#include <immintrin.h>  // declares the AVX builtins the clone uses
#endif

#include "../detail/knot_index.hpp"
#include "quaternion.hpp"
#include "so3.hpp"

namespace crspline::rotation {

/// Where a batch evaluation writes, per sample: the rotation as 4 values
/// [w, x, y, z] (or [x, y, z, w], SciPy's order, with xyzw) at q, or as a
/// quaternion at quats (both null: the rotations are not written, for a
/// call that wants the rates alone); the angular velocity and acceleration
/// as 3 values at omega and alpha (null when the order does not ask for
/// them).
template <class T>
struct batch_rows {
    T* q = nullptr;
    quaternion<T>* quats = nullptr;
    T* omega = nullptr;
    T* alpha = nullptr;
    bool xyzw = false;
};

}  // namespace crspline::rotation

#if defined(__GNUC__) && !defined(__clang__)
// GCC warns (-Wpsabi) that a function returning a 32-byte vector is called
// differently with AVX than without. The AVX2 clone's helpers do, and are
// only ever inlined inside the clone (they take their vectors by
// reference, which keeps GCC's note on argument passing away), so the
// warning says nothing here; but GCC gives it for templates instantiated at
// the end of the translation unit, outside any push/pop of this header. So
// it is off from here to the end of the including file (it concerns
// calling conventions between AVX settings only).
#pragma GCC diagnostic ignored "-Wpsabi"
#pragma GCC diagnostic push
#endif

namespace crspline::rotation::detail_batch {

template <class T>
using rows = batch_rows<T>;

// ----- lanes ----------------------------------------------------------------------

#if defined(__GNUC__) || defined(__clang__)
#define CRSPLINE_ROTATION_LANES 1
/// Two doubles in one 16-byte vector (one SSE2 register on the x86-64
/// baseline, NEON on AArch64; plain code elsewhere) and its mask.
typedef double v2 __attribute__((vector_size(16)));
typedef decltype(v2{} < v2{}) m2;  // what a comparison gives

[[gnu::always_inline]] inline v2 sel(m2 m, v2 a, v2 b) noexcept { return (v2)((m & (m2)a) | (~m & (m2)b)); }
/// -x in the lanes where m holds (a sign flip: exact).
[[gnu::always_inline]] inline v2 negate_if(m2 m, v2 x) noexcept {
    return (v2)((m2)x ^ (m & static_cast<std::int64_t>(0x8000000000000000ULL)));
}
[[gnu::always_inline]] inline v2 vsqrt(v2 x) noexcept {
#if defined(__SSE2__)
    return (v2)_mm_sqrt_pd((__m128d)x);  // correctly rounded: the bits of std::sqrt
#else
    return v2{std::sqrt(x[0]), std::sqrt(x[1])};
#endif
}
/// Whether every lane of m holds.
[[gnu::always_inline]] inline bool all_of(m2 m) noexcept { return (m[0] & m[1]) != 0; }
#else
#define CRSPLINE_ROTATION_LANES 0
#endif

// The AVX2 clone (x86-64 with GCC): the same kernels on four doubles per
// 32-byte register (v4), compiled inside functions with target("avx2") and
// chosen at run time by a CPUID test (run() below), as detail/x86_kernels.hpp
// does for the point curves: nothing needs -mavx2 or -march. The target has
// no FMA, so every operation rounds as the portable code's does: the two
// paths give the same bits (tests/rotation/test_rotation_batch.cpp; a build
// with -mfma or -march=native lets GCC fuse products and sums, possibly
// differently on the two paths: the results stay within their tolerances,
// the bits may differ). Clang
// takes the portable path (it refuses 32-byte vectors in functions without
// AVX even when they are inlined into one that has it).
#if CRSPLINE_ROTATION_LANES && defined(__x86_64__) && !defined(__clang__) && !defined(CRSPLINE_NO_X86_DISPATCH)
#define CRSPLINE_ROTATION_AVX2 1
typedef double v4 __attribute__((vector_size(32)));
typedef decltype(v4{} < v4{}) m4;  // what a comparison gives
// Templates, not functions: only ever instantiated inside the clone.
#define CRSPLINE_V4 template <class V> requires std::is_same_v<V, v4> [[gnu::always_inline]] inline
CRSPLINE_V4 V sel(const m4& m, const V& a, const V& b) noexcept { return (V)((m & (m4)a) | (~m & (m4)b)); }
CRSPLINE_V4 V negate_if(const m4& m, const V& x) noexcept { return (V)((m4)x ^ (m & static_cast<std::int64_t>(0x8000000000000000ULL))); }
CRSPLINE_V4 V vsqrt(const V& x) noexcept { return __builtin_ia32_sqrtpd256(x); }  // correctly rounded
template <class M> requires std::is_same_v<M, m4>
[[gnu::always_inline]] inline bool all_of(const M& m) noexcept { return __builtin_ia32_movmskpd256((v4)m) == 0xF; }
#else
#define CRSPLINE_ROTATION_AVX2 0
#endif

#if CRSPLINE_ROTATION_LANES
/// The lanes of a batch: N vectors H side by side (H = v2, N = 2: four
/// lanes, the portable code; H = v4: the AVX2 clone). Each operation is N
/// independent instructions, so N chains of the long sine, cosine, atan2
/// and product computations are in flight at once for the out-of-order core
/// to overlap (one chain alone waits on each step's latency; more than the
/// registers hold spill). A struct of vectors, not one vector N times as
/// wide: passing that by value without AVX changes the ABI, which GCC warns
/// about at every use.
template <class MH, int N>
struct multi_mask {
    MH h[N];
#define CRSPLINE_VM_OP(op)                                                                                       \
    friend multi_mask operator op(const multi_mask& a, const multi_mask& b) noexcept {                                         \
        multi_mask r;                                                                                            \
        for (int i = 0; i < N; ++i) r.h[i] = a.h[i] op b.h[i];                                                   \
        return r;                                                                                                \
    }
    CRSPLINE_VM_OP(|)
    CRSPLINE_VM_OP(&)
    CRSPLINE_VM_OP(^)
#undef CRSPLINE_VM_OP
};
template <class H, int N>
struct multi {
    using half = H;
    using mask = multi_mask<decltype(H{} < H{}), N>;
    static constexpr int half_width = int(sizeof(H) / sizeof(double));
    static constexpr int width = N * half_width;
    H h[N];
    multi() = default;
    constexpr multi(double a, double b, double c, double d) noexcept requires(width == 4 && half_width == 2) : h{{a, b}, {c, d}} {}
    template <class... Hs>
    requires(sizeof...(Hs) == N && (std::is_same_v<Hs, H> && ...))
    constexpr explicit multi(const Hs&... hs) noexcept : h{hs...} {}
    double operator[](int l) const noexcept { return h[l / half_width][l % half_width]; }
    void set(int l, double x) noexcept { h[l / half_width][l % half_width] = x; }
#define CRSPLINE_VD_OP(op)                                                                                       \
    friend multi operator op(const multi& a, const multi& b) noexcept {                                                        \
        multi r;                                                                                                 \
        for (int i = 0; i < N; ++i) r.h[i] = a.h[i] op b.h[i];                                                   \
        return r;                                                                                                \
    }                                                                                                            \
    friend multi operator op(const multi& a, double b) noexcept {                                                       \
        multi r;                                                                                                 \
        for (int i = 0; i < N; ++i) r.h[i] = a.h[i] op b;                                                        \
        return r;                                                                                                \
    }                                                                                                            \
    friend multi operator op(double a, const multi& b) noexcept {                                                       \
        multi r;                                                                                                 \
        for (int i = 0; i < N; ++i) r.h[i] = a op b.h[i];                                                        \
        return r;                                                                                                \
    }
    CRSPLINE_VD_OP(+)
    CRSPLINE_VD_OP(-)
    CRSPLINE_VD_OP(*)
    CRSPLINE_VD_OP(/)
#undef CRSPLINE_VD_OP
#define CRSPLINE_VD_CMP(op)                                                                                      \
    friend mask operator op(const multi& a, const multi& b) noexcept {                                                         \
        mask r;                                                                                                  \
        for (int i = 0; i < N; ++i) r.h[i] = a.h[i] op b.h[i];                                                   \
        return r;                                                                                                \
    }                                                                                                            \
    friend mask operator op(const multi& a, double b) noexcept {                                                        \
        mask r;                                                                                                  \
        for (int i = 0; i < N; ++i) r.h[i] = a.h[i] op b;                                                        \
        return r;                                                                                                \
    }
    CRSPLINE_VD_CMP(<)
    CRSPLINE_VD_CMP(>)
    CRSPLINE_VD_CMP(<=)
    CRSPLINE_VD_CMP(>=)
    CRSPLINE_VD_CMP(==)
#undef CRSPLINE_VD_CMP
    friend multi operator-(const multi& a) noexcept {
        multi r;
        for (int i = 0; i < N; ++i) r.h[i] = -a.h[i];
        return r;
    }
};

template <class H, class MH, int N>
[[gnu::always_inline]] inline multi<H, N> sel(const multi_mask<MH, N>& m, const multi<H, N>& a, const multi<H, N>& b) noexcept {
    multi<H, N> r;
    for (int i = 0; i < N; ++i) r.h[i] = sel(m.h[i], a.h[i], b.h[i]);
    return r;
}
template <class H, class MH, int N>
[[gnu::always_inline]] inline multi<H, N> negate_if(const multi_mask<MH, N>& m, const multi<H, N>& x) noexcept {
    multi<H, N> r;
    for (int i = 0; i < N; ++i) r.h[i] = negate_if(m.h[i], x.h[i]);
    return r;
}
template <class H, int N>
[[gnu::always_inline]] inline multi<H, N> vsqrt(const multi<H, N>& x) noexcept {
    multi<H, N> r;
    for (int i = 0; i < N; ++i) r.h[i] = vsqrt(x.h[i]);
    return r;
}
template <class MH, int N>
[[gnu::always_inline]] inline bool all_of(const multi_mask<MH, N>& m) noexcept {
    bool all = true;
    for (int i = 0; i < N; ++i) all &= all_of(m.h[i]);
    return all;
}
template <class H, int N>
[[gnu::always_inline]] inline void set_lane(multi<H, N>& v, int l, double x) noexcept { v.set(l, x); }
/// |x|, lane by lane (the sign bit cleared: exact).
template <class H, int N>
[[gnu::always_inline]] inline multi<H, N> vabs(const multi<H, N>& x) noexcept {
    using MH = decltype(H{} < H{});
    constexpr std::int64_t m = 0x7FFFFFFFFFFFFFFFLL;
    multi<H, N> r;
    for (int i = 0; i < N; ++i) r.h[i] = (H)((MH)x.h[i] & m);
    return r;
}

/// The portable lanes: four doubles in two 16-byte vectors.
using vd = multi<v2, 2>;
using vm = vd::mask;
inline constexpr int vd_width = vd::width;
#if CRSPLINE_ROTATION_AVX2
/// The AVX2 clone's lanes: CRSPLINE_ROTATION_AVX2_N 32-byte vectors
/// (default 3: twelve doubles, three chains in flight; measured faster
/// than two or four on the pyramids, whose chains are long).
#ifndef CRSPLINE_ROTATION_AVX2_N
#define CRSPLINE_ROTATION_AVX2_N 3
#endif
using vx = multi<v4, CRSPLINE_ROTATION_AVX2_N>;
#endif
#endif

/// Which code runs a batch: the portable lanes, or the AVX2 clone.
enum class isa { portable, avx2 };

/// The CPU's answer, once (constant after).
inline isa best_isa() noexcept {
#if CRSPLINE_ROTATION_AVX2
    static const bool avx2 = __builtin_cpu_supports("avx2");
    return avx2 ? isa::avx2 : isa::portable;
#else
    return isa::portable;
#endif
}

/// The batch blocks are lambdas that the AVX2 clone must compile inside its
/// own body: always_inline.
#if defined(__GNUC__) || defined(__clang__)
#define CRSPLINE_ROTATION_BLOCK __attribute__((always_inline))
#else
#define CRSPLINE_ROTATION_BLOCK
#endif

/// A lane type as a value: the batch blocks take one to know their V.
template <class V>
struct lanes_of {
    using type = V;
};

// Scalar lanes (one sample; float and long double, or no vector extension).
template <class S>
[[gnu::always_inline]] inline S sel(bool m, S a, S b) noexcept { return m ? a : b; }
template <class S>
[[gnu::always_inline]] inline S negate_if(bool m, S x) noexcept { return m ? -x : x; }
template <class S>
[[gnu::always_inline]] inline S vsqrt(S x) noexcept { return std::sqrt(x); }
[[gnu::always_inline]] inline bool all_of(bool m) noexcept { return m; }

/// How many samples a lane type holds.
template <class V>
inline constexpr int width_of = 1;
#if CRSPLINE_ROTATION_LANES
template <class H, int N>
inline constexpr int width_of<multi<H, N>> = multi<H, N>::width;
#endif

/// The lanes a sample type T is computed in by the portable code: four
/// doubles, or one T.
template <class T>
struct pack {
    using V = T;
};
#if CRSPLINE_ROTATION_LANES
template <>
struct pack<double> {
    using V = vd;
};
#endif

// ----- polynomials ---------------------------------------------------------------

/// sum_{i < K} c[i] z^i by Estrin's scheme: pairs c[2i] + c[2i+1] z, then
/// pairs of those with z^2, z^4, ...: about log2(K) multiply-adds deep
/// instead of Horner's K, so that the lanes do not wait on each step's
/// latency. Its roundings differ from Horner's in the high-order terms only.
template <int H, class V>
[[gnu::always_inline]] inline V power_of_two(const V& z) noexcept {  // z^H, H a power of two
    if constexpr (H == 1) return z;
    else {
        const V h = power_of_two<H / 2>(z);
        return h * h;
    }
}
template <class T, int K, class V>
[[gnu::always_inline]] inline V estrin(const double* c, const V& z) noexcept {
    if constexpr (K == 1) return V{} + T(c[0]);
    else if constexpr (K == 2) return T(c[0]) + z * T(c[1]);
    else {
        constexpr int H = K > 8 ? 8 : K > 4 ? 4 : 2;  // the largest power of two below K (K <= 16)
        static_assert(K <= 16);
        return estrin<T, H>(c, z) + estrin<T, K - H>(c + H, z) * power_of_two<H>(z);
    }
}

// ----- sine and cosine ------------------------------------------------------------

template <class V>
struct sin_cos {
    V s, c;
};

#if CRSPLINE_ROTATION_LANES
/// Arguments up to this size take the polynomial (the reduction below is
/// exact there); larger ones, and NaN, go to std::sin and std::cos.
inline constexpr double poly_sincos_limit = 1 << 19;

/// sin x and cos x, lane by lane. Cody-Waite reduction x = n pi/2 + r with
/// |r| <= pi/4 (n by the 1.5 * 2^52 rounding trick, exact in the default
/// rounding mode for |x| < 2^51), pi/2 split in three parts of which the
/// first two have 33 significant bits, so n p1 and n p2 are exact for
/// n < 2^20 and r carries an error below 2^-70 |n| + half an ulp of r; then
/// fdlibm's kernels (k_sin.c, k_cos.c), whose polynomials are within 2^-58
/// of sin and cos on [-pi/4, pi/4], so the result is within 1 ulp of the
/// true value (tested against std:: at random, tests/rotation/).
/// std::sin and std::cos lane by lane, for arguments beyond the reduction:
/// out of line, so that the kernels hold no call (every vector register is
/// lost across a call, and a call inside a kernel makes the compiler keep
/// its values in memory throughout).
template <class V>
[[gnu::noinline, gnu::cold]] void libm_sincos(const V& x, sin_cos<V>& r) noexcept {
    r = {x, x};
    for (int l = 0; l < V::width; ++l) set_lane(r.s, l, std::sin(x[l])), set_lane(r.c, l, std::cos(x[l]));
}

template <class V>
[[gnu::always_inline]] inline sin_cos<V> poly_sincos(const V& x) noexcept {
    if (!all_of(vabs(x) <= poly_sincos_limit)) [[unlikely]] {  // NaN fails the test too
        sin_cos<V> r;
        libm_sincos(x, r);
        return r;
    }
    const double magic = 6755399441055744.0;  // 1.5 * 2^52
    const V n = (x * 6.36619772367581382433e-01 + magic) - magic;  // round(x 2/pi)
    const double p1 = 1.57079632673412561417e+00, p2 = 6.07710050630396597660e-11,
                 p3 = 2.02226624879595063154e-21;  // pi/2 = p1 + p2 + p3 + O(1e-32)
    const V r = ((x - n * p1) - n * p2) - n * p3;
    const V z = r * r;
    // fdlibm __kernel_sin(r, 0, 0): r + r^3 (S1 + z S2 + ... + z^5 S6).
    static constexpr double sin_poly[5] = {8.33333333332248946124e-03, -1.98412698298579493134e-04, 2.75573137070700676789e-06,
                                           -2.50507602534068634195e-08, 1.58969099521155010221e-10};
    const V ps = estrin<double, 5>(sin_poly, z);
    const V s = r + (z * r) * (-1.66666666666666324348e-01 + z * ps);
    // fdlibm __kernel_cos(r, 0): 1 - z/2 + z^2 (C1 + ... + z^5 C6), the
    // rounding of 1 - z/2 recovered as (1 - w) - z/2.
    static constexpr double cos_poly[6] = {4.16666666666666019037e-02,  -1.38888888888741095749e-03, 2.48015872894767294178e-05,
                                           -2.75573143513906633035e-07, 2.08757232129817482790e-09,  -1.13596475577881948265e-11};
    const V pc = z * estrin<double, 6>(cos_poly, z);
    const V hz = 0.5 * z, w = 1.0 - hz;
    const V c = w + (((1.0 - w) - hz) + z * pc);
    // The quadrant j = n mod 4 (floor(n/4) = round(n/4 - 3/8) for integer n).
    const V f = ((n * 0.25 - 0.375) + magic) - magic;
    const V j = n - 4.0 * f;
    const auto odd = (j == 1.0) | (j == 3.0);
    return {negate_if(j >= 2.0, sel(odd, c, s)), negate_if((j == 1.0) | (j == 2.0), sel(odd, s, c))};
}

template <class H, int N>
[[gnu::always_inline]] inline sin_cos<multi<H, N>> sincos(const multi<H, N>& x) noexcept { return poly_sincos(x); }
#endif

template <class S>
[[gnu::always_inline]] inline sin_cos<S> sincos(S x) noexcept {
    return {std::sin(x), std::cos(x)};
}

// ----- the angle of a point in the upper half plane ---------------------------------

/// atan2(y, x) for y >= 0 (the length of a quaternion's vector part and its
/// w), in [0, pi], lane by lane, for the logs of the slerps between
/// quaternions that depend on the sample. With lo = min(y, |x|) and hi =
/// max(y, |x|), atan(lo/hi) in [0, pi/4] is c_k + atan(r), r = (lo - t_k
/// hi)/(hi + t_k lo), t_k = 0, 1/2 or 1 and c_k = atan(t_k) as a sum of two
/// doubles. t_k is exact, so t_k hi, t_k lo and (Sterbenz) the numerator
/// are exact nearly everywhere: r carries two roundings. The breaks (lo/hi
/// = tan(1/4), 0.7208) leave |r| <= 0.2554, and an angle of at least 1/4
/// wherever c_k is added, so r's error is below half an ulp of the result
/// there. atan(r) is its Taylor series to r^27: the first term left out is
/// below r^29/29 < 2^-59 r. c_k + atan(r) rounds once more, and the
/// quadrant (pi/2 - a for y > |x|, pi - a for x < 0, pi/2 + a for both,
/// with pi/2 and pi as sums of two doubles) once more: within 2 ulps of
/// atan2 (tested against std::atan2 at random,
/// tests/rotation/test_rotation_batch.cpp). NaN in either argument gives
/// NaN; x = -0 counts as +0 (atan2(0, -0) is 0 here, pi in std::; a unit
/// quaternion never has both parts zero).
template <class V>
[[gnu::always_inline]] inline V poly_atan2(const V& y, const V& x) noexcept {
    const auto neg = x < 0.0;
    const V ax = negate_if(neg, x);
    const auto swap = y > ax;
    const V lo = sel(swap, ax, y), hi = sel(swap, y, ax);
    const auto k1 = lo > hi * 0.25534192122103627, k2 = lo > hi * 0.7207592200561265;
    const V zero{};
    const V tk = sel(k2, zero + 1.0, sel(k1, zero + 0.5, zero));
    const V ch = sel(k2, zero + 0.7853981633974483, sel(k1, zero + 0.4636476090008061, zero));
    const V cl = sel(k2, zero + 3.061616997868383e-17, sel(k1, zero + 2.2698777452961687e-17, zero));
    const V r = sel(hi == 0.0, zero, (lo - tk * hi) / (hi + tk * lo));  // y = x = 0: angle 0
    const V z = r * r;
    // atan r = r + r z P(z), P(z) = sum_{k=1..13} (-1)^k z^(k-1)/(2k+1) (Estrin).
    static constexpr double atan_series[13] = {-0.3333333333333333,   0.2,  -0.14285714285714285, 0.1111111111111111,
                                               -0.09090909090909091,  0.07692307692307693,  -0.06666666666666667,
                                               0.058823529411764705,  -0.05263157894736842, 0.047619047619047616,
                                               -0.043478260869565216, 0.04, -0.037037037037037035};
    const V p = estrin<double, 13>(atan_series, z);
    const V a = ch + (cl + (r + (r * z) * p));
    // The quadrant: a, pi/2 - a (y > |x|), pi - a (x < 0), pi/2 + a (both),
    // as b_hi + (b_lo +- a): one rounding for the sum.
    const V bh = sel(swap, zero + 1.5707963267948966, sel(neg, zero + 3.141592653589793, zero));
    const V bl = sel(swap, zero + 6.123233995736766e-17, sel(neg, zero + 1.2246467991473532e-16, zero));
    return bh + (bl + negate_if(swap ^ neg, a));
}

#if CRSPLINE_ROTATION_LANES
template <class H, int N>
[[gnu::always_inline]] inline multi<H, N> atan2_upper(const multi<H, N>& y, const multi<H, N>& x) noexcept { return poly_atan2(y, x); }
#endif
template <class S>
[[gnu::always_inline]] inline S atan2_upper(S y, S x) noexcept {
    return std::atan2(y, x);
}

// ----- series of the Jacobian coefficients (so3.hpp) -------------------------------

/// Coefficients of z^m (z = theta^2), m = 0..15, of k1 = (1 - cos)/theta^2,
/// k2 = (theta - sin)/theta^3, K1 and K2 (so3::jacobian_coefficients: the
/// same terms as its loop; k1 there is 2 sin^2(theta/2)/theta^2). The last
/// term left out is below 4^16/34! ~ 1e-29 of the first at theta = 2.
struct jacobian_series {
    double k1[16], k2[16], K1[16], K2[16];
};

constexpr jacobian_series make_jacobian_series() {
    jacobian_series s{};
    double f[40]{};  // f[k] = k!
    f[0] = 1;
    for (int k = 1; k < 40; ++k) f[k] = f[k - 1] * k;
    for (int m = 0; m < 16; ++m) {
        const double sign = m % 2 == 0 ? 1 : -1;
        s.k1[m] = sign / f[2 * m + 2];
        s.k2[m] = sign / f[2 * m + 3];
        s.K1[m] = sign * 2 * (m + 1) / f[2 * m + 4];
        s.K2[m] = -sign * 2 * (m + 1) / f[2 * m + 5];
    }
    return s;
}
inline constexpr jacobian_series series = make_jacobian_series();

/// The terms of k1 and k2 taken for z < 2 (c2_lanes: the truncation bound).
inline constexpr int jacobian_short_terms = 10;

template <class T, class V>
[[gnu::always_inline]] inline V horner16(const double (&c)[16], const V& z) noexcept {
    return estrin<T, 16>(c, z);
}

// ----- 3-vectors and quaternions of lanes ---------------------------------------------

template <class V>
struct v3l {
    V x, y, z;
};
template <class V>
struct ql {
    V w, x, y, z;
};

template <class V>
[[gnu::always_inline]] inline v3l<V> cross(const v3l<V>& a, const v3l<V>& b) noexcept {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class V>
[[gnu::always_inline]] inline V dot(const v3l<V>& a, const v3l<V>& b) noexcept {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class V>
[[gnu::always_inline]] inline ql<V> mul(const ql<V>& a, const ql<V>& b) noexcept {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
/// rotate(q, v) of quaternion.hpp: v + w t + u x t, t = 2 u x v.
template <class V>
[[gnu::always_inline]] inline v3l<V> rotate(const ql<V>& q, const v3l<V>& v) noexcept {
    const v3l<V> u{q.x, q.y, q.z};
    const v3l<V> c = cross(u, v);
    const v3l<V> t{c.x + c.x, c.y + c.y, c.z + c.z};  // 2 u x v, exactly
    const v3l<V> d = cross(u, t);
    return {v.x + q.w * t.x + d.x, v.y + q.w * t.y + d.y, v.z + q.w * t.z + d.z};
}

// ----- output rows -------------------------------------------------------------------

template <class S>
[[gnu::always_inline]] inline S lane(S x, int) noexcept { return x; }
#if CRSPLINE_ROTATION_LANES
template <class H, int N>
[[gnu::always_inline]] inline double lane(const multi<H, N>& x, int l) noexcept { return x[l]; }
#endif

template <class T, class V>
[[gnu::always_inline]] inline void store(const rows<T>& out, std::size_t k, int valid, const ql<V>& q, const v3l<V>* w,
                                         const v3l<V>* a) noexcept {
    for (int l = 0; l < valid; ++l) {
        const T qw = lane(q.w, l), qx = lane(q.x, l), qy = lane(q.y, l), qz = lane(q.z, l);
        if (out.quats) {
            out.quats[k + std::size_t(l)] = {qw, qx, qy, qz};
        } else if (out.q) {
            T* p = out.q + 4 * (k + std::size_t(l));
            if (out.xyzw) p[0] = qx, p[1] = qy, p[2] = qz, p[3] = qw;
            else p[0] = qw, p[1] = qx, p[2] = qy, p[3] = qz;
        }
        if (w) {
            T* o = out.omega + 3 * (k + std::size_t(l));
            o[0] = lane(w->x, l), o[1] = lane(w->y, l), o[2] = lane(w->z, l);
        }
        if (a) {
            T* o = out.alpha + 3 * (k + std::size_t(l));
            o[0] = lane(a->x, l), o[1] = lane(a->y, l), o[2] = lane(a->z, l);
        }
    }
}

/// Lane values from a function of the lane index.
template <class V, class F>
[[gnu::always_inline]] inline V make_lanes(F f) noexcept {
    if constexpr (std::is_floating_point_v<V>) return f(0);
#if CRSPLINE_ROTATION_LANES
    else {
        using H = typename V::half;
        return [&]<int... I>(std::integer_sequence<int, I...>) CRSPLINE_ROTATION_BLOCK {
            if constexpr (V::half_width == 2) return V(H{f(2 * I), f(2 * I + 1)}...);
            else return V(H{f(4 * I), f(4 * I + 1), f(4 * I + 2), f(4 * I + 3)}...);
        }(std::make_integer_sequence<int, V::width / V::half_width>{});
    }
#endif
}

/// The quaternions at ptr(l) (4 consecutive values each) as lanes; on the
/// AVX2 clone as rows loaded whole and transposed four lanes at a time
/// (shorter than one value at a time).
#if CRSPLINE_ROTATION_AVX2
template <class P, class H>
requires std::is_same_v<H, v4>
[[gnu::always_inline]] inline void transpose_rows(P ptr, int l0, H& w, H& x, H& y, H& z) noexcept {
    H r0, r1, r2, r3;
    std::memcpy(&r0, ptr(l0), sizeof r0), std::memcpy(&r1, ptr(l0 + 1), sizeof r1);
    std::memcpy(&r2, ptr(l0 + 2), sizeof r2), std::memcpy(&r3, ptr(l0 + 3), sizeof r3);
    const H t0 = __builtin_shuffle(r0, r1, m4{0, 4, 2, 6}), t1 = __builtin_shuffle(r0, r1, m4{1, 5, 3, 7});
    const H t2 = __builtin_shuffle(r2, r3, m4{0, 4, 2, 6}), t3 = __builtin_shuffle(r2, r3, m4{1, 5, 3, 7});
    w = __builtin_shuffle(t0, t2, m4{0, 1, 4, 5}), x = __builtin_shuffle(t1, t3, m4{0, 1, 4, 5});
    y = __builtin_shuffle(t0, t2, m4{2, 3, 6, 7}), z = __builtin_shuffle(t1, t3, m4{2, 3, 6, 7});
}
#endif
#if CRSPLINE_ROTATION_AVX2
/// Four lanes' 3-vectors (x, y, z: one value per lane) written as four
/// consecutive rows [x, y, z] at o: six shuffles and three 32-byte stores
/// instead of twelve single ones (the values' bits unchanged).
template <class H>
requires std::is_same_v<H, v4>
[[gnu::always_inline]] inline void store_rows3(const H& x, const H& y, const H& z, double* o) noexcept {
    const H xy = __builtin_shuffle(x, y, m4{0, 4, 2, 6});  // x0 y0 x2 y2
    const H zx = __builtin_shuffle(z, x, m4{0, 5, 2, 7});  // z0 x1 z2 x3
    const H yz = __builtin_shuffle(y, z, m4{1, 5, 3, 7});  // y1 z1 y3 z3
    const H r0 = __builtin_shuffle(xy, zx, m4{0, 1, 4, 5}), r1 = __builtin_shuffle(yz, xy, m4{0, 1, 6, 7}),
            r2 = __builtin_shuffle(zx, yz, m4{2, 3, 6, 7});
    std::memcpy(o, &r0, sizeof r0), std::memcpy(o + 4, &r1, sizeof r1), std::memcpy(o + 8, &r2, sizeof r2);
}
#endif

template <class V, class P>
[[gnu::always_inline]] inline ql<V> gather_quat(P ptr) noexcept {
    if constexpr (std::is_floating_point_v<V>) {
        const auto* p = ptr(0);
        return {p[0], p[1], p[2], p[3]};
    }
#if CRSPLINE_ROTATION_LANES
    else if constexpr (V::half_width == 2) {
        // Two lanes per vector: value by value (a load and a load-high per
        // vector) is as short as a transpose.
        return {make_lanes<V>([&](int l) { return ptr(l)[0]; }), make_lanes<V>([&](int l) { return ptr(l)[1]; }),
                make_lanes<V>([&](int l) { return ptr(l)[2]; }), make_lanes<V>([&](int l) { return ptr(l)[3]; })};
    } else {
        ql<V> q{};  // every half assigned below
        constexpr int hw = V::half_width;
        for (int i = 0; i < V::width / hw; ++i) transpose_rows(ptr, i * hw, q.w.h[i], q.x.h[i], q.y.h[i], q.z.h[i]);
        return q;
    }
#endif
}

// ----- locating samples -----------------------------------------------------------------

/// Whether g[i] <= t < g[i + 1], as one branch for the caller: random t
/// passes the first test half the time, which a branch of its own would
/// mispredict, and GCC splits int(a) & int(b) into two branches; so for
/// double both compares are one vector compare (g[i] <= t and not g[i + 1]
/// <= t: lane mask 0b01; NaN fails it, as it fails the scalar tests). It
/// took about 7 ns per sample off every class's batch on random t (the C2
/// rates alone: 17 -> 10 ns per sample, AVX2).
template <class T>
[[gnu::always_inline]] inline bool in_segment(const T* g, std::size_t i, T t) noexcept {
#if defined(__SSE2__) && CRSPLINE_ROTATION_LANES
    if constexpr (std::is_same_v<T, double>) {
        v2 ends;
        std::memcpy(&ends, g + i, sizeof ends);
        return _mm_movemask_pd((__m128d)(ends <= (v2{} + t))) == 1;
    }
#endif
    return int(g[i] <= t) & int(t < g[i + 1]);
}

/// The segment of each sample: the one before (sorted input stays in a
/// segment for many samples, so one well-predicted test usually settles
/// it), else the knot index (O(1), knot_index.hpp), which random input
/// takes every time (a well-predicted test too).
template <class T>
struct locator {
    const T* g;
    std::size_t nseg;
    const detail::knot_index<T>* index;
    std::size_t last = 0;

    std::size_t operator()(T t) noexcept {
        if (!in_segment(g, last, t)) last = index->locate(t, g, nseg);
        return last;
    }
};

// ----- the C2 spline -------------------------------------------------------------------

/// One segment of c2_rotation_spline, packed: R(t) = q Exp(theta(t - t0)),
/// theta(tau) = ((c3 tau + c2) tau + c1) tau.
template <class T>
struct c2_packed {
    T t0;
    T c3[3], c2[3], c1[3];
    T q[4];
    T pad[2];
};

/// The C2 spline's rotation (and with order >= 1 its angular velocity,
/// order 2 its acceleration, in frame f) on lanes: tau = t - t0 per lane,
/// seg(l) the packed segment of lane l. Each step is
/// c2_rotation_spline::evaluate_on's, on lanes. With rotation false and the
/// body frame the rotation is not formed (the rates do not need it).
template <class T, class V, class Seg>
[[gnu::always_inline]] inline void c2_lanes(Seg seg, const V& tau, int order, frame f, ql<V>& q, v3l<V>& w, v3l<V>& acc,
                                            bool rotation = true) noexcept {
    // (Gathered value by value: rows loaded whole and transposed measured
    // slower here, on both paths.)
    auto g = [&](auto member) CRSPLINE_ROTATION_BLOCK { return make_lanes<V>([&](int l) { return member(seg(l)); }); };
    v3l<V> c3, c2, c1;
    c3.x = g([](const c2_packed<T>& s) { return s.c3[0]; }), c3.y = g([](const c2_packed<T>& s) { return s.c3[1]; }),
    c3.z = g([](const c2_packed<T>& s) { return s.c3[2]; });
    c2.x = g([](const c2_packed<T>& s) { return s.c2[0]; }), c2.y = g([](const c2_packed<T>& s) { return s.c2[1]; }),
    c2.z = g([](const c2_packed<T>& s) { return s.c2[2]; });
    c1.x = g([](const c2_packed<T>& s) { return s.c1[0]; }), c1.y = g([](const c2_packed<T>& s) { return s.c1[1]; }),
    c1.z = g([](const c2_packed<T>& s) { return s.c1[2]; });
    const v3l<V> th{((c3.x * tau + c2.x) * tau + c1.x) * tau, ((c3.y * tau + c2.y) * tau + c1.y) * tau,
                    ((c3.z * tau + c2.z) * tau + c1.z) * tau};
    const bool form_q = rotation || f == frame::world;
    // The half angle a, its sine and cosine, and sin(a)/a: for the rotation,
    // and for the rates' closed forms where a lane turns 2 rad or more.
    // (h = th/2 and |h|^2 only there: the rates alone need z = |th|^2.)
    v3l<V> h{};
    V a{}, sinc{};
    sin_cos<V> sc{};
    auto trig = [&]() CRSPLINE_ROTATION_BLOCK {
        h = {th.x * T(0.5), th.y * T(0.5), th.z * T(0.5)};
        a = vsqrt(dot(h, h));
        sc = sincos(a);
        sinc = sel(a > T(0), sc.s / a, V{} + T(1));  // sin(a)/a
    };
    if (form_q || order == 0) {
        trig();
        // The key is gathered here only: the body-frame rates alone never
        // read it.
        const ql<V> key{g([](const c2_packed<T>& s) { return s.q[0]; }), g([](const c2_packed<T>& s) { return s.q[1]; }),
                        g([](const c2_packed<T>& s) { return s.q[2]; }), g([](const c2_packed<T>& s) { return s.q[3]; })};
        q = mul(key, ql<V>{sc.c, h.x * sinc, h.y * sinc, h.z * sinc});
    }
    if (order == 0) return;
    // Body frame: omega = J_r(theta) theta', alpha = J_r(theta) theta'' + N_r(theta, theta').
    const v3l<V> d1{(T(3) * c3.x * tau + T(2) * c2.x) * tau + c1.x, (T(3) * c3.y * tau + T(2) * c2.y) * tau + c1.y,
                    (T(3) * c3.z * tau + T(2) * c2.z) * tau + c1.z};
    // z = theta^2 (|th|^2: the same bits as 4 |th/2|^2, a power of two
    // apart). Three tiers, chosen lane by lane (so every path gives a lane
    // the same bits whatever its neighbours): theta < sqrt(2) (z < 2), k1
    // and k2 from the first 10 terms of their series; sqrt(2) <= theta < 2,
    // the first 16; theta >= 2, the closed forms. The rates alone need no
    // square root, sine or cosine below theta = 2, and the common small
    // turns the shorter series only (a lane group pays for a longer tier
    // only when one of its lanes needs it; sel keeps each lane's own bits).
    // The 10 terms' truncation: both series alternate with decreasing
    // terms for z < 2, so the error is below the first term left out,
    // z^10/22! < 2^10/22! = 9.1e-19 for k1 (>= (1 - cos sqrt 2)/2 = 0.42:
    // 2.2e-18 relative, 1% of an ulp) and 2^10/23! = 4.0e-20 for k2 (>=
    // 0.15: 2.6e-19 relative); tested against the 16 terms
    // (tests/rotation/test_rotation_batch.cpp, JacobianSeriesTiers).
    const V z = dot(th, th);
    const auto small = z < T(2), mid = z < T(4);
    V k1 = estrin<T, jacobian_short_terms>(series.k1, z), k2 = estrin<T, jacobian_short_terms>(series.k2, z);
    bool all_mid = true;
    V theta{}, sin_t{}, cos_t{}, big{}, zb{};
    if (!all_of(small)) {
        k1 = sel(small, k1, horner16<T>(series.k1, z)), k2 = sel(small, k2, horner16<T>(series.k2, z));
        all_mid = all_of(mid);
    }
    if (!all_mid) {
        if (!(form_q || order == 0)) trig();
        theta = T(2) * a;
        // sin theta = 2 s c, cos theta = c^2 - s^2.
        sin_t = T(2) * sc.s * sc.c, cos_t = sc.c * sc.c - sc.s * sc.s;
        big = sel(mid, V{} + T(1), theta);  // keeps the unused closed forms finite at theta = 0
        zb = big * big;
        k1 = sel(mid, k1, sinc * sinc / T(2));
        k2 = sel(mid, k2, (big - sin_t) / (zb * big));
    }
    auto jr = [&](const v3l<V>& v) CRSPLINE_ROTATION_BLOCK {
        const v3l<V> pv = cross(th, v), ppv = cross(th, pv);
        return v3l<V>{v.x - k1 * pv.x + k2 * ppv.x, v.y - k1 * pv.y + k2 * ppv.y, v.z - k1 * pv.z + k2 * ppv.z};
    };
    w = jr(d1);
    if (order >= 2) {
        const v3l<V> d2{T(6) * c3.x * tau + T(2) * c2.x, T(6) * c3.y * tau + T(2) * c2.y, T(6) * c3.z * tau + T(2) * c2.z};
        V K1 = horner16<T>(series.K1, z), K2 = horner16<T>(series.K2, z);
        if (!all_mid) {
            K1 = sel(mid, K1, (T(2) * (T(1) - cos_t) - big * sin_t) / (zb * zb));
            K2 = sel(mid, K2, (T(3) * sin_t - T(2) * big - big * cos_t) / (zb * zb * big));
        }
        const V dp = dot(th, d1);
        const v3l<V> cp = cross(th, d1), ccp = cross(th, cp), dccp = cross(d1, cp);
        const v3l<V> j2 = jr(d2);
        acc = {j2.x + (dp * (K1 * cp.x + K2 * ccp.x) + k2 * dccp.x), j2.y + (dp * (K1 * cp.y + K2 * ccp.y) + k2 * dccp.y),
               j2.z + (dp * (K1 * cp.z + K2 * ccp.z) + k2 * dccp.z)};
    }
    if (f == frame::world) {
        w = rotate(q, w);
        if (order >= 2) acc = rotate(q, acc);
    }
}

/// Samples k .. k + width - 1 of the C2 spline (segments seg[0..width-1]),
/// the first `valid` of them written.
template <class T, class V = typename pack<T>::V>
[[gnu::always_inline]] inline void c2_block(const c2_packed<T>* segs, const std::size_t* seg, const T* t, std::size_t k,
                                            int valid, int order, frame f, const rows<T>& out) noexcept {
    const V tau = make_lanes<V>([&](int l) { return t[l] - segs[seg[l]].t0; });
    ql<V> q;
    v3l<V> w, acc;
    const bool rotation = out.q != nullptr || out.quats != nullptr;
    c2_lanes<T>([&](int l) -> const c2_packed<T>& { return segs[seg[l]]; }, tau, order, f, q, w, acc, rotation);
#if CRSPLINE_ROTATION_AVX2
    // The rates alone (SciPy's spline(t, 1)) from a full block of the AVX2
    // clone: whole rows.
    if constexpr (std::is_same_v<V, vx>)
        if (!rotation && order == 1 && valid == V::width) {
            for (int i = 0; i < V::width / V::half_width; ++i)
                store_rows3(w.x.h[i], w.y.h[i], w.z.h[i], out.omega + 3 * (k + std::size_t(i * V::half_width)));
            return;
        }
#endif
    store<T, V>(out, k, valid, q, order >= 1 ? &w : nullptr, order >= 2 ? &acc : nullptr);
}

/// One segment of a pose curve with a C2 rotation, packed: the position's
/// cubic in local u = (t - t0) inv_h (origin + u (c1 + u (c2 + u c3)), as
/// cubic_segment) and the rotation's segment.
template <class T>
struct pose_packed {
    c2_packed<T> rot;
    T origin[3], c1[3], c2[3], c3[3];
    T inv_h;
};

/// Samples k .. k + width - 1 of a pose curve: position, velocity (dx/dt),
/// rotation and angular velocity, velocities in frame f; the position and
/// velocity by cubic_segment's arithmetic (at(u), dt(u, 1); at t_end the
/// last point exactly, as catmull_rom gives it), the rotation by c2_lanes.
/// out[k + l] for the first `valid` lanes.
template <class T, class V, class Sample>
[[gnu::always_inline]] inline void pose_block(const pose_packed<T>* segs, const std::size_t* seg, const T* t, std::size_t k,
                                              int valid, frame f, T t_end, const T* end_point, Sample* out) noexcept {
    auto g = [&](auto member) CRSPLINE_ROTATION_BLOCK { return make_lanes<V>([&](int l) { return member(segs[seg[l]]); }); };
    const V u = make_lanes<V>([&](int l) { return (t[l] - segs[seg[l]].rot.t0) * segs[seg[l]].inv_h; });
    const V tau = make_lanes<V>([&](int l) { return t[l] - segs[seg[l]].rot.t0; });
    const V inv_h = g([](const pose_packed<T>& s) { return s.inv_h; });
    V pos[3], vel[3];
    for (int d = 0; d < 3; ++d) {
        const V o = g([d](const pose_packed<T>& s) { return s.origin[d]; }), c1 = g([d](const pose_packed<T>& s) { return s.c1[d]; }),
                c2 = g([d](const pose_packed<T>& s) { return s.c2[d]; }), c3 = g([d](const pose_packed<T>& s) { return s.c3[d]; });
        pos[d] = o + u * (c1 + u * (c2 + u * c3));
        vel[d] = (c1 + u * (T(2) * c2 + T(3) * u * c3)) * inv_h;
    }
    ql<V> q;
    v3l<V> w, acc;
    c2_lanes<T>([&](int l) -> const c2_packed<T>& { return segs[seg[l]].rot; }, tau, 1, f, q, w, acc);
    v3l<V> v{vel[0], vel[1], vel[2]};
    if (f == frame::body) v = rotate(ql<V>{q.w, -q.x, -q.y, -q.z}, v);
    for (int l = 0; l < valid; ++l) {
        Sample& s = out[k + std::size_t(l)];
        s.position[0] = lane(pos[0], l), s.position[1] = lane(pos[1], l), s.position[2] = lane(pos[2], l);
        if (t[l] == t_end) s.position[0] = end_point[0], s.position[1] = end_point[1], s.position[2] = end_point[2];  // exactly
        s.orientation = {lane(q.w, l), lane(q.x, l), lane(q.y, l), lane(q.z, l)};
        s.velocity[0] = lane(v.x, l), s.velocity[1] = lane(v.y, l), s.velocity[2] = lane(v.z, l);
        s.omega[0] = lane(w.x, l), s.omega[1] = lane(w.y, l), s.omega[2] = lane(w.z, l);
    }
}


// ----- piecewise slerp --------------------------------------------------------------------

/// One segment of a piecewise slerp, packed: q(t) = exp(u L) a with u = (t -
/// t0) inv_h, L = log(b a*) = half_angle * axis; omega = 2 L inv_h (world).
/// A zero-length segment has inv_h = 0: the curve rests at a.
template <class T>
struct slerp_packed {
    T t0, inv_h, half_angle;
    T axis[3];
    T a[4];
};

template <class T, class V = typename pack<T>::V>
[[gnu::always_inline]] inline void slerp_block(const slerp_packed<T>* segs, const std::size_t* seg, const T* t,
                                               std::size_t k, int valid, int order, frame f, const rows<T>& out) noexcept {
    auto g = [&](auto member) CRSPLINE_ROTATION_BLOCK { return make_lanes<V>([&](int l) { return member(segs[seg[l]]); }); };
    const V u = make_lanes<V>([&](int l) { return (t[l] - segs[seg[l]].t0) * segs[seg[l]].inv_h; });
    const V ang = u * g([](const slerp_packed<T>& s) { return s.half_angle; });
    const v3l<V> n{g([](const slerp_packed<T>& s) { return s.axis[0]; }), g([](const slerp_packed<T>& s) { return s.axis[1]; }),
                   g([](const slerp_packed<T>& s) { return s.axis[2]; })};
    const ql<V> a{g([](const slerp_packed<T>& s) { return s.a[0]; }), g([](const slerp_packed<T>& s) { return s.a[1]; }),
                  g([](const slerp_packed<T>& s) { return s.a[2]; }), g([](const slerp_packed<T>& s) { return s.a[3]; })};
    const sin_cos<V> sc = sincos(ang);
    const ql<V> q = mul(ql<V>{sc.c, n.x * sc.s, n.y * sc.s, n.z * sc.s}, a);
    if (order == 0) return store<T, V>(out, k, valid, q, nullptr, nullptr);
    // omega = 2 L / h, constant on the segment (world frame); alpha = 0.
    const V r = T(2) * g([](const slerp_packed<T>& s) { return s.half_angle * s.inv_h; });
    v3l<V> w{r * n.x, r * n.y, r * n.z};
    const V zero{};
    const v3l<V> acc{zero, zero, zero};
    if (f == frame::body) w = rotate(ql<V>{q.w, -q.x, -q.y, -q.z}, w);
    store<T, V>(out, k, valid, q, &w, order >= 2 ? &acc : nullptr);
}

// ----- the De Casteljau family and Squad ---------------------------------------------------

/// A slerp whose two ends do not depend on the sample, packed: slerp(a, b,
/// s) = exp(s L) a with L = log(b a*) = angle * n (half-angle units, as
/// quaternion.hpp's exp and log), which is cos(s angle) a + sin(s angle) o
/// with o = [0, n] a (a unit quaternion orthogonal to a).
template <class T>
struct fixed_slerp {
    T angle;
    T a[4];
    T o[4];
};

/// One segment of a De Casteljau pyramid of 4 controls (Catmull-Rom,
/// Kochanek-Bartels, De Casteljau) or of Barry-Goldman's, packed: the three
/// slerps of the first level between fixed pairs (f), and the parameter of
/// each of the six slerps, s_j = (t - ta[j]) inv[j] (j < 3: the first level;
/// 3, 4 the second; 5 the last). The De Casteljau curves have one parameter
/// u for all six; Barry-Goldman's run over their own knot intervals. A
/// zero-length segment has every angle and inv 0 and every a its key: the
/// curve rests there, exactly.
template <class T>
struct pyramid_packed {
    T ta[6], inv[6];
    fixed_slerp<T> f[3];
};

/// One segment of Squad, packed: slerp(slerp(q_i, q_(i+1), u), slerp(s_i+,
/// s_(i+1)-, u), 2u(1-u)), u = (t - t0) inv_h; f the two inner slerps.
template <class T>
struct squad_packed {
    T t0, inv_h;
    fixed_slerp<T> f[2];
};

/// exp(s L) a = cos(s angle) a + sin(s angle) o on lanes, from each lane's
/// fixed_slerp.
template <class T, class V, class Get>
[[gnu::always_inline]] inline ql<V> fixed_lanes(Get get, const V& s) noexcept {
    auto g = [&](auto member) CRSPLINE_ROTATION_BLOCK { return make_lanes<V>([&](int l) { return member(get(l)); }); };
    const sin_cos<V> sc = sincos(s * g([](const fixed_slerp<T>& f) { return f.angle; }));
    const ql<V> a = gather_quat<V>([&](int l) CRSPLINE_ROTATION_BLOCK { return get(l).a; });
    const ql<V> o = gather_quat<V>([&](int l) CRSPLINE_ROTATION_BLOCK { return get(l).o; });
    return {a.w * sc.c + o.w * sc.s, a.x * sc.c + o.x * sc.s, a.y * sc.c + o.y * sc.s, a.z * sc.c + o.z * sc.s};
}

/// slerp(a, b, s) = exp(s log(b a*)) a on lanes whose ends depend on the
/// sample. b a* = [w, v] with w = a . b, and v a = b - w a = o, so |v| =
/// |o| and exp(s log(b a*)) a = cos(s h) a + sin(s h) o/|o|, h = atan2(|o|,
/// w) in [0, pi] the half angle (atan2_upper, then sincos). Where o = 0 and
/// w < 0 (b = -a exactly) log() takes the axis [1, 0, 0]: then o/|o| is
/// [0, 1, 0, 0] a. No sign change: a negative a . b takes the long way, as
/// slerp() does.
template <class T, class V>
[[gnu::always_inline]] inline ql<V> slerp_lanes(const ql<V>& a, const ql<V>& b, const V& s) noexcept {
    const V w = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
    const ql<V> o{b.w - w * a.w, b.x - w * a.x, b.y - w * a.y, b.z - w * a.z};
    const V no = vsqrt(o.w * o.w + o.x * o.x + o.y * o.y + o.z * o.z);
    const sin_cos<V> sc = sincos(s * atan2_upper(no, w));
    const auto axis = no > T(0);
    const V zero{};
    const ql<V> u{sel(axis, o.w, zero - a.x), sel(axis, o.x, a.w), sel(axis, o.y, zero - a.z), sel(axis, o.z, a.y)};
    const V f = sc.s / sel(axis, no, zero + T(1));
    return {a.w * sc.c + u.w * f, a.x * sc.c + u.x * f, a.y * sc.c + u.y * f, a.z * sc.c + u.z * f};
}

/// Samples k .. k + width - 1 of a pyramid curve (rotations only).
/// uniform: one parameter for all six slerps (the De Casteljau curves).
template <class T, class V, bool uniform>
[[gnu::always_inline]] inline void pyramid_block(const pyramid_packed<T>* segs, const std::size_t* seg, const T* t,
                                                 std::size_t k, int valid, const rows<T>& out) noexcept {
    V s[6];
    for (int j = 0; j < 6; ++j) {
        if (uniform && j > 0) {
            s[j] = s[0];
            continue;
        }
        s[j] = make_lanes<V>([&](int l) { return (t[l] - segs[seg[l]].ta[j]) * segs[seg[l]].inv[j]; });
    }
    auto fixed = [&](int j) CRSPLINE_ROTATION_BLOCK {
        return fixed_lanes<T>([&](int l) -> const fixed_slerp<T>& { return segs[seg[l]].f[j]; }, s[j]);
    };
    // In the order that keeps the fewest quaternions alive (registers).
    const ql<V> F1 = fixed(1);
    const ql<V> D0 = slerp_lanes<T>(fixed(0), F1, s[3]);
    const ql<V> D1 = slerp_lanes<T>(F1, fixed(2), s[4]);
    store<T, V>(out, k, valid, slerp_lanes<T>(D0, D1, s[5]), nullptr, nullptr);
}

/// Samples k .. k + width - 1 of a Squad curve (rotations only).
template <class T, class V>
[[gnu::always_inline]] inline void squad_block(const squad_packed<T>* segs, const std::size_t* seg, const T* t, std::size_t k,
                                               int valid, const rows<T>& out) noexcept {
    const V u = make_lanes<V>([&](int l) { return (t[l] - segs[seg[l]].t0) * segs[seg[l]].inv_h; });
    const ql<V> a = fixed_lanes<T>([&](int l) -> const fixed_slerp<T>& { return segs[seg[l]].f[0]; }, u);
    const ql<V> b = fixed_lanes<T>([&](int l) -> const fixed_slerp<T>& { return segs[seg[l]].f[1]; }, u);
    store<T, V>(out, k, valid, slerp_lanes<T>(a, b, T(2) * u * (T(1) - u)), nullptr, nullptr);
}

// ----- the driver -------------------------------------------------------------------------

/// Runs block(lanes_of<V>{}, seg, t, k, valid) over samples t[0..n) a lane
/// type's width (4 portable, 8 AVX2) at a time; the segment of each from locate(k, t[k]). The
/// last, partial block repeats its last sample in the unused lanes and
/// writes only the valid ones. The block must be always_inline (the AVX2
/// clone compiles it inside its own body).
template <class T, class V, class Locate, class Block>
[[gnu::always_inline]] inline void run_lanes(std::span<const T> t, Locate& locate, Block& block) {
    constexpr int W = width_of<V>;
    const std::size_t n = t.size();
    std::size_t seg[W];
    T tl[W];
    for (std::size_t k = 0; k < n; k += W) {
        const int valid = int(std::min<std::size_t>(W, n - k));
        for (int l = 0; l < W; ++l) {
            const std::size_t s = k + std::size_t(l < valid ? l : valid - 1);
            tl[l] = t[s];
            seg[l] = locate(s, t[s]);
        }
        block(lanes_of<V>{}, seg, tl, k, valid);
    }
}

#if CRSPLINE_ROTATION_AVX2
template <class Locate, class Block>
__attribute__((target("avx2"))) void run_avx2(std::span<const double> t, Locate& locate, Block& block) {
    run_lanes<double, vx>(t, locate, block);
}
#endif

/// run_lanes on the given path: the AVX2 clone for double where asked and
/// the CPU has it, else the portable lanes.
template <class T, class Locate, class Block>
void run(std::span<const T> t, Locate&& locate, Block&& block, isa path = best_isa()) {
#if CRSPLINE_ROTATION_AVX2
    if constexpr (std::is_same_v<T, double>)
        if (path == isa::avx2 && best_isa() == isa::avx2) return run_avx2(t, locate, block);
#endif
    (void)path;
    run_lanes<T, typename pack<T>::V>(t, locate, block);
}

}  // namespace crspline::rotation::detail_batch

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
