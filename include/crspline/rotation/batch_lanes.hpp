// crspline: the lanes of the rotation curves' batch kernels (batch.hpp):
// two doubles in a 16-byte vector (SSE2, NEON, or one at a time elsewhere),
// the AVX2 clone's four-double registers grouped N at a time (multi), the
// run-time choice between them (best_isa), and where a batch writes its
// rows (batch_rows).
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

}  // namespace crspline::rotation::detail_batch

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop  // -Wpsabi stays ignored (set before the push): see above
#endif
