// crspline internal: lanes of doubles, four side by side with the GCC/Clang
// vector extension or one without it, and the few operations on them that
// the branch points and the rule choice of arc length's fast path are
// written in (speed_branch_points.hpp, quadrature_rule.hpp), so that one
// text serves one segment and four.
#pragma once

#include <cmath>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "x86_kernels.hpp"

namespace crspline::detail {

/// Lanes of doubles for the branch points and the first rule choices: four side by side with
/// the GCC/Clang vector extension (two SSE2 instructions each on the x86-64
/// baseline, one in the AVX2 clone), else one. Every operation is the
/// scalar one lane by lane (no FMA contraction: the library is built
/// without it), so a segment gets the same bits in any lane width.
#if defined(__GNUC__) || defined(__clang__)
#define CRSPLINE_LANES4 1
inline constexpr int lanes_width = 4;
using lanes = double __attribute__((vector_size(8 * lanes_width)));
using lanes_mask = long long __attribute__((vector_size(8 * lanes_width)));
// (Operands by reference: a 32-byte vector by value changes the calling
// convention without AVX, which GCC warns about.)
[[gnu::always_inline]] inline void lanes_set(lanes& x, const lanes_mask& m, const lanes& a) noexcept {
    x = lanes((lanes_mask(a) & m) | (lanes_mask(x) & ~m));
}
[[gnu::always_inline]] inline bool lanes_any(const lanes_mask& m) noexcept {
    long long any = 0;
    for (int l = 0; l < lanes_width; ++l) any |= m[l];
    return any != 0;
}
[[gnu::always_inline]] inline void lanes_clear(lanes_mask& m, const lanes_mask& off) noexcept { m = m & ~off; }
[[gnu::always_inline]] inline bool lanes_any_not(const lanes_mask& m) noexcept {
    long long all = -1;
    for (int l = 0; l < lanes_width; ++l) all &= m[l];
    return all == 0;
}
template <class F>
[[gnu::always_inline]] inline void lanes_make(lanes& x, F f) noexcept {
    x = lanes{f(0), f(1), f(2), f(3)};
}
[[gnu::always_inline]] inline void lanes_add_abs(lanes& acc, const lanes& x) noexcept {
    acc += lanes(lanes_mask(x) & (lanes_mask{} + 0x7fffffffffffffffLL));
}
template <class V>
[[gnu::always_inline]] inline auto lanes_get(const V& x, int l) noexcept -> std::remove_cvref_t<decltype(x[0])> {
    return x[l];
}
[[gnu::always_inline]] inline void lanes_sqrt(lanes& x) noexcept {
#if defined(__SSE2__)
    // Two halves in registers (through memory they would stall the AVX2
    // clone on store forwarding), each one SSE2 square root.
    static_assert(lanes_width == 4);
    const __m128d lo = _mm_sqrt_pd(__m128d(__builtin_shufflevector(x, x, 0, 1)));
    const __m128d hi = _mm_sqrt_pd(__m128d(__builtin_shufflevector(x, x, 2, 3)));
    x = __builtin_shufflevector(lo, hi, 0, 1, 2, 3);
#else
    for (int l = 0; l < lanes_width; ++l) x[l] = std::sqrt(x[l]);
#endif
}
#else
#define CRSPLINE_LANES4 0
#endif
/// x = a in the lanes where m holds.
[[gnu::always_inline]] inline void lanes_set(double& x, bool m, double a) noexcept {
    if (m) x = a;
}
[[gnu::always_inline]] inline bool lanes_any(bool m) noexcept { return m; }
/// m = m and not off.
[[gnu::always_inline]] inline void lanes_clear(bool& m, bool off) noexcept { m = m && !off; }
/// Whether m fails in any lane.
[[gnu::always_inline]] inline bool lanes_any_not(bool m) noexcept { return !m; }
/// x = the lanes f(0), f(1), ... (built in registers).
template <class F>
[[gnu::always_inline]] inline void lanes_make(double& x, F f) noexcept {
    x = f(0);
}
/// x = sqrt(x) (x >= 0), lane by lane.
[[gnu::always_inline]] inline void lanes_sqrt(double& x) noexcept { x = std::sqrt(x); }
/// acc += |x|, lane by lane.
[[gnu::always_inline]] inline void lanes_add_abs(double& acc, double x) noexcept { acc += std::abs(x); }
/// Lane l of x (x itself for one lane).
[[gnu::always_inline]] inline double lanes_get(double x, int) noexcept { return x; }
[[gnu::always_inline]] inline bool lanes_get(bool x, int) noexcept { return x; }

/// Square roots lane by lane for the lanes code below, a template argument
/// of it: sqrt_baseline is lanes_sqrt (four lanes in two SSE2 instructions
/// on the x86-64 baseline); sqrt_avx, for the AVX2 clones only, takes four
/// in one instruction, as fast as one SSE2 one. Both round correctly: the
/// same bits.
struct sqrt_baseline {
    template <class V>
    [[gnu::always_inline]] static void apply(V& x) noexcept {
        lanes_sqrt(x);
    }
};
#if CRSPLINE_X86_DISPATCH && CRSPLINE_LANES4
struct sqrt_avx {
    // Not always_inline: the generic code that calls it is inlined into
    // an AVX2 function first, and this then into that.
    CRSPLINE_TARGET_AVX2 static void apply(lanes& x) noexcept { x = lanes(_mm256_sqrt_pd(__m256d(x))); }
    [[gnu::always_inline]] static void apply(double& x) noexcept { x = std::sqrt(x); }
};
#endif

}  // namespace crspline::detail
