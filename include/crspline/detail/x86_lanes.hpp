// crspline: the x86 lanes of the batch kernels (x86_kernels.hpp): the
// run-time choice (avx2_enabled, avx512_enabled, each the CPU's answer
// once, writable for the tests), the function targets, and the lanes types
// lanes256 (AVX2: 4 doubles or 8 floats) and lanes512 (AVX-512F: 8
// doubles or 16 floats), each with the loads, masked loads and stores,
// arithmetic, comparisons, blends and permutes the walks use.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__)) && \
    !defined(CRSPLINE_NO_X86_DISPATCH)
#define CRSPLINE_X86_DISPATCH 1
#include <immintrin.h>
#define CRSPLINE_TARGET_AVX2 __attribute__((target("avx2")))
// AVX-512F brings FMA with it, and GCC contracts a product and a sum into
// one FMA by default (-ffp-contract=fast): a different rounding. Off for
// these functions, so that they keep the portable code's bits.
#if defined(__clang__)
#define CRSPLINE_TARGET_AVX512 __attribute__((target("avx512f")))
#else
#define CRSPLINE_TARGET_AVX512 __attribute__((target("avx512f"), optimize("fp-contract=off")))
#endif
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

/// Whether the AVX-512 kernels run (sorted 3-D float and double evaluation): the
/// CPU's answer (AVX-512F with the OS saving its registers), once; writable
/// so that tests can compare it with the AVX2 and portable kernels.
inline bool& avx512_enabled() noexcept {
    static bool on = __builtin_cpu_supports("avx512f");
    return on;
}

/// 256-bit lanes of doubles (4) or floats (8) for the sorted kernels: the
/// operations they use, and the two layouts that let them compute 3-D points
/// in the order they are stored. A step covers W points, 3 W scalars, held
/// in 3 registers exactly as laid out in memory (double: x0 y0 z0 x1 | y1 z1
/// x2 y2 | z2 x3 y3 z3): lane j of register r holds scalar e = W r + j of
/// the step, that is coordinate e % 3 of point e / 3. So the coefficients
/// are arranged once per segment (pattern) and u once per step (spread, one
/// permute per register), and no result needs a shuffle. Masks are vectors
/// (all ones or zero per lane), masked loads and stores maskload /
/// maskstore.
template <class T>
struct lanes256;

template <>
struct lanes256<double> {
    using V = __m256d;
    static constexpr unsigned W = 4;
    static constexpr int all = 0xF;
    CRSPLINE_TARGET_AVX2 static V set1(double x) noexcept { return _mm256_set1_pd(x); }
    CRSPLINE_TARGET_AVX2 static V zero() noexcept { return _mm256_setzero_pd(); }
    CRSPLINE_TARGET_AVX2 static V load(const double* p) noexcept { return _mm256_loadu_pd(p); }
    CRSPLINE_TARGET_AVX2 static V maskload(const double* p, __m256i in) noexcept { return _mm256_maskload_pd(p, in); }
    CRSPLINE_TARGET_AVX2 static V add(V a, V b) noexcept { return _mm256_add_pd(a, b); }
    CRSPLINE_TARGET_AVX2 static V sub(V a, V b) noexcept { return _mm256_sub_pd(a, b); }
    CRSPLINE_TARGET_AVX2 static V mul(V a, V b) noexcept { return _mm256_mul_pd(a, b); }
    CRSPLINE_TARGET_AVX2 static V both(V a, V b) noexcept { return _mm256_and_pd(a, b); }
    CRSPLINE_TARGET_AVX2 static V ones() noexcept { return _mm256_castsi256_pd(_mm256_set1_epi64x(-1)); }
    CRSPLINE_TARGET_AVX2 static V lt(V a, V b) noexcept { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
    CRSPLINE_TARGET_AVX2 static V le(V a, V b) noexcept { return _mm256_cmp_pd(a, b, _CMP_LE_OQ); }
    CRSPLINE_TARGET_AVX2 static V nlt(V a, V b) noexcept { return _mm256_cmp_pd(a, b, _CMP_NLT_UQ); }
    CRSPLINE_TARGET_AVX2 static int mask(V a) noexcept { return _mm256_movemask_pd(a); }
    /// a where m is zero, b where it is all ones.
    CRSPLINE_TARGET_AVX2 static V blend(V a, V b, V m) noexcept { return _mm256_blendv_pd(a, b, m); }
    CRSPLINE_TARGET_AVX2 static void store(double* p, V a) noexcept { _mm256_storeu_pd(p, a); }
    CRSPLINE_TARGET_AVX2 static void maskstore(double* p, __m256i in, V a) noexcept { _mm256_maskstore_pd(p, in, a); }
    CRSPLINE_TARGET_AVX2 static void stream(double* p, V a) noexcept { _mm256_stream_pd(p, a); }
    /// Lanes 0 .. min(q, 4) - 1 all ones, the others zero.
    CRSPLINE_TARGET_AVX2 static __m256i first_lanes(unsigned q) noexcept {
        return _mm256_cmpgt_epi64(_mm256_set1_epi64x(q < 4 ? q : 4), _mm256_setr_epi64x(0, 1, 2, 3));
    }
    /// Lane j: x[j - 1], lane 0 kept (x's lanes moved up one).
    CRSPLINE_TARGET_AVX2 static V shift_up(V x) noexcept { return _mm256_permute4x64_pd(x, 0x90); }
    CRSPLINE_TARGET_AVX2 static V pattern(const double* v, int r) noexcept {
        return _mm256_setr_pd(v[(4 * r) % 3], v[(4 * r + 1) % 3], v[(4 * r + 2) % 3], v[(4 * r + 3) % 3]);
    }
    template <int r>
    CRSPLINE_TARGET_AVX2 static V spread(V u) noexcept {
        // lanes take u[e / 3] for e = 4 r .. 4 r + 3: 0 0 0 1 | 1 1 2 2 | 2 3 3 3
        if constexpr (r == 0) return _mm256_permute4x64_pd(u, 0x40);
        else if constexpr (r == 1) return _mm256_permute4x64_pd(u, 0xA5);
        else return _mm256_permute4x64_pd(u, 0xFE);
    }
};

template <>
struct lanes256<float> {
    using V = __m256;
    static constexpr unsigned W = 8;
    static constexpr int all = 0xFF;
    CRSPLINE_TARGET_AVX2 static V set1(float x) noexcept { return _mm256_set1_ps(x); }
    CRSPLINE_TARGET_AVX2 static V zero() noexcept { return _mm256_setzero_ps(); }
    CRSPLINE_TARGET_AVX2 static V load(const float* p) noexcept { return _mm256_loadu_ps(p); }
    CRSPLINE_TARGET_AVX2 static V maskload(const float* p, __m256i in) noexcept { return _mm256_maskload_ps(p, in); }
    CRSPLINE_TARGET_AVX2 static V add(V a, V b) noexcept { return _mm256_add_ps(a, b); }
    CRSPLINE_TARGET_AVX2 static V sub(V a, V b) noexcept { return _mm256_sub_ps(a, b); }
    CRSPLINE_TARGET_AVX2 static V mul(V a, V b) noexcept { return _mm256_mul_ps(a, b); }
    CRSPLINE_TARGET_AVX2 static V both(V a, V b) noexcept { return _mm256_and_ps(a, b); }
    CRSPLINE_TARGET_AVX2 static V ones() noexcept { return _mm256_castsi256_ps(_mm256_set1_epi32(-1)); }
    CRSPLINE_TARGET_AVX2 static V lt(V a, V b) noexcept { return _mm256_cmp_ps(a, b, _CMP_LT_OQ); }
    CRSPLINE_TARGET_AVX2 static V le(V a, V b) noexcept { return _mm256_cmp_ps(a, b, _CMP_LE_OQ); }
    CRSPLINE_TARGET_AVX2 static V nlt(V a, V b) noexcept { return _mm256_cmp_ps(a, b, _CMP_NLT_UQ); }
    CRSPLINE_TARGET_AVX2 static int mask(V a) noexcept { return _mm256_movemask_ps(a); }
    /// a where m is zero, b where it is all ones.
    CRSPLINE_TARGET_AVX2 static V blend(V a, V b, V m) noexcept { return _mm256_blendv_ps(a, b, m); }
    CRSPLINE_TARGET_AVX2 static void store(float* p, V a) noexcept { _mm256_storeu_ps(p, a); }
    CRSPLINE_TARGET_AVX2 static void maskstore(float* p, __m256i in, V a) noexcept { _mm256_maskstore_ps(p, in, a); }
    CRSPLINE_TARGET_AVX2 static void stream(float* p, V a) noexcept { _mm256_stream_ps(p, a); }
    /// Lanes 0 .. min(q, 8) - 1 all ones, the others zero.
    CRSPLINE_TARGET_AVX2 static __m256i first_lanes(unsigned q) noexcept {
        return _mm256_cmpgt_epi32(_mm256_set1_epi32(int(q < 8 ? q : 8)), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
    }
    /// Lane j: x[j - 1], lane 0 kept (x's lanes moved up one).
    CRSPLINE_TARGET_AVX2 static V shift_up(V x) noexcept {
        return _mm256_permutevar8x32_ps(x, _mm256_setr_epi32(0, 0, 1, 2, 3, 4, 5, 6));
    }
    // (One masked load and a permute: built through a stack array, as
    // before issue 30, each pattern cost a failed store forward.)
    CRSPLINE_TARGET_AVX2 static V pattern(const float* v, int r) noexcept {
        const V xyz = _mm256_maskload_ps(v, _mm256_setr_epi32(-1, -1, -1, 0, 0, 0, 0, 0));
        const int f = 8 * r;
        return _mm256_permutevar8x32_ps(xyz, _mm256_setr_epi32(f % 3, (f + 1) % 3, (f + 2) % 3, (f + 3) % 3,
                                                               (f + 4) % 3, (f + 5) % 3, (f + 6) % 3, (f + 7) % 3));
    }
    template <int r>
    CRSPLINE_TARGET_AVX2 static V spread(V u) noexcept {
        // lanes take u[e / 3] for e = 8 r .. 8 r + 7
        const __m256i idx = _mm256_setr_epi32((8 * r) / 3, (8 * r + 1) / 3, (8 * r + 2) / 3, (8 * r + 3) / 3,
                                              (8 * r + 4) / 3, (8 * r + 5) / 3, (8 * r + 6) / 3, (8 * r + 7) / 3);
        return _mm256_permutevar8x32_ps(u, idx);
    }
};

/// 512-bit lanes of floats (16) or doubles (8) for the AVX-512F steps, in
/// lanes256's layout (lane j of register r holds coordinate (W r + j) % 3 of
/// point (W r + j) / 3 of the step); masks are bits (__mmask16, __mmask8),
/// and masked loads and stores read and write nothing outside their lanes.
template <class T>
struct lanes512;

template <>
struct lanes512<float> {
    using V = __m512;
    using M = __mmask16;
    static constexpr unsigned W = 16;
    static constexpr unsigned all = 0xFFFF;
    CRSPLINE_TARGET_AVX512 static V set1(float x) noexcept { return _mm512_set1_ps(x); }
    CRSPLINE_TARGET_AVX512 static V zero() noexcept { return _mm512_setzero_ps(); }
    CRSPLINE_TARGET_AVX512 static V load(const float* p) noexcept { return _mm512_loadu_ps(p); }
    CRSPLINE_TARGET_AVX512 static V maskload(M in, const float* p) noexcept { return _mm512_maskz_loadu_ps(in, p); }
    CRSPLINE_TARGET_AVX512 static V add(V a, V b) noexcept { return _mm512_add_ps(a, b); }
    CRSPLINE_TARGET_AVX512 static V sub(V a, V b) noexcept { return _mm512_sub_ps(a, b); }
    CRSPLINE_TARGET_AVX512 static V mul(V a, V b) noexcept { return _mm512_mul_ps(a, b); }
    CRSPLINE_TARGET_AVX512 static M lt(V a, V b) noexcept { return _mm512_cmp_ps_mask(a, b, _CMP_LT_OQ); }
    CRSPLINE_TARGET_AVX512 static M le(V a, V b) noexcept { return _mm512_cmp_ps_mask(a, b, _CMP_LE_OQ); }
    CRSPLINE_TARGET_AVX512 static M nlt(V a, V b) noexcept { return _mm512_cmp_ps_mask(a, b, _CMP_NLT_UQ); }
    /// nlt in the lanes of in, zero in the others.
    CRSPLINE_TARGET_AVX512 static M nlt(M in, V a, V b) noexcept {
        return _mm512_mask_cmp_ps_mask(in, a, b, _CMP_NLT_UQ);
    }
    /// a where m is zero, b where it is one.
    CRSPLINE_TARGET_AVX512 static V blend(V a, M m, V b) noexcept { return _mm512_mask_mov_ps(a, m, b); }
    CRSPLINE_TARGET_AVX512 static void store(float* p, V a) noexcept { _mm512_storeu_ps(p, a); }
    CRSPLINE_TARGET_AVX512 static void maskstore(float* p, M in, V a) noexcept { _mm512_mask_storeu_ps(p, in, a); }
    CRSPLINE_TARGET_AVX512 static void stream(float* p, V a) noexcept { _mm512_stream_ps(p, a); }
    /// Lanes 0 .. min(q, 16) - 1.
    static M first_lanes(unsigned q) noexcept { return M((1u << (q < 16 ? q : 16)) - 1); }
    /// Lane 0: first; lane j > 0: x[j - 1] (x's lanes 0-14 moved up one).
    CRSPLINE_TARGET_AVX512 static V shift_in(V x, float first) noexcept {
        return _mm512_castsi512_ps(
            _mm512_maskz_alignr_epi32(0xFFFF, _mm512_castps_si512(x), _mm512_castps_si512(_mm512_set1_ps(first)), 15));
    }
    /// Lane j of the result: v's lane idx[j]. (_mm512_permutexvar_ps is the
    /// same instruction, but GCC 12 warns about its own undefined source
    /// operand, a known false positive.)
    CRSPLINE_TARGET_AVX512 static V permute(__m512i idx, V v) noexcept {
        return _mm512_maskz_permutexvar_ps(0xFFFF, idx, v);
    }
    /// Lane j: v[(16 r + j) % 3], v one coordinate triple in lanes 0-2.
    template <int r>
    CRSPLINE_TARGET_AVX512 static V pattern(V v) noexcept {
        constexpr int f = 16 * r;
        return permute(_mm512_setr_epi32(f % 3, (f + 1) % 3, (f + 2) % 3, (f + 3) % 3, (f + 4) % 3, (f + 5) % 3,
                                         (f + 6) % 3, (f + 7) % 3, (f + 8) % 3, (f + 9) % 3, (f + 10) % 3,
                                         (f + 11) % 3, (f + 12) % 3, (f + 13) % 3, (f + 14) % 3, (f + 15) % 3),
                       v);
    }
    /// Lane j: u[(16 r + j) / 3], the value of the point lane j is part of.
    template <int r>
    CRSPLINE_TARGET_AVX512 static V spread(V u) noexcept {
        constexpr int f = 16 * r;
        return permute(_mm512_setr_epi32(f / 3, (f + 1) / 3, (f + 2) / 3, (f + 3) / 3, (f + 4) / 3, (f + 5) / 3,
                                         (f + 6) / 3, (f + 7) / 3, (f + 8) / 3, (f + 9) / 3, (f + 10) / 3,
                                         (f + 11) / 3, (f + 12) / 3, (f + 13) / 3, (f + 14) / 3, (f + 15) / 3),
                       u);
    }
};

template <>
struct lanes512<double> {
    using V = __m512d;
    using M = __mmask8;
    static constexpr unsigned W = 8;
    static constexpr unsigned all = 0xFF;
    CRSPLINE_TARGET_AVX512 static V set1(double x) noexcept { return _mm512_set1_pd(x); }
    CRSPLINE_TARGET_AVX512 static V zero() noexcept { return _mm512_setzero_pd(); }
    CRSPLINE_TARGET_AVX512 static V load(const double* p) noexcept { return _mm512_loadu_pd(p); }
    CRSPLINE_TARGET_AVX512 static V maskload(M in, const double* p) noexcept { return _mm512_maskz_loadu_pd(in, p); }
    CRSPLINE_TARGET_AVX512 static V add(V a, V b) noexcept { return _mm512_add_pd(a, b); }
    CRSPLINE_TARGET_AVX512 static V sub(V a, V b) noexcept { return _mm512_sub_pd(a, b); }
    CRSPLINE_TARGET_AVX512 static V mul(V a, V b) noexcept { return _mm512_mul_pd(a, b); }
    CRSPLINE_TARGET_AVX512 static M lt(V a, V b) noexcept { return _mm512_cmp_pd_mask(a, b, _CMP_LT_OQ); }
    CRSPLINE_TARGET_AVX512 static M le(V a, V b) noexcept { return _mm512_cmp_pd_mask(a, b, _CMP_LE_OQ); }
    CRSPLINE_TARGET_AVX512 static M nlt(V a, V b) noexcept { return _mm512_cmp_pd_mask(a, b, _CMP_NLT_UQ); }
    /// nlt in the lanes of in, zero in the others.
    CRSPLINE_TARGET_AVX512 static M nlt(M in, V a, V b) noexcept {
        return _mm512_mask_cmp_pd_mask(in, a, b, _CMP_NLT_UQ);
    }
    /// a where m is zero, b where it is one.
    CRSPLINE_TARGET_AVX512 static V blend(V a, M m, V b) noexcept { return _mm512_mask_mov_pd(a, m, b); }
    CRSPLINE_TARGET_AVX512 static void store(double* p, V a) noexcept { _mm512_storeu_pd(p, a); }
    CRSPLINE_TARGET_AVX512 static void maskstore(double* p, M in, V a) noexcept { _mm512_mask_storeu_pd(p, in, a); }
    CRSPLINE_TARGET_AVX512 static void stream(double* p, V a) noexcept { _mm512_stream_pd(p, a); }
    /// Lanes 0 .. min(q, 8) - 1.
    static M first_lanes(unsigned q) noexcept { return M((1u << (q < 8 ? q : 8)) - 1); }
    /// Lane 0: first; lane j > 0: x[j - 1] (x's lanes 0-6 moved up one).
    CRSPLINE_TARGET_AVX512 static V shift_in(V x, double first) noexcept {
        return _mm512_castsi512_pd(
            _mm512_maskz_alignr_epi64(0xFF, _mm512_castpd_si512(x), _mm512_castpd_si512(_mm512_set1_pd(first)), 7));
    }
    /// As lanes512<float>::permute.
    CRSPLINE_TARGET_AVX512 static V permute(__m512i idx, V v) noexcept {
        return _mm512_maskz_permutexvar_pd(0xFF, idx, v);
    }
    /// Lane j: v[(8 r + j) % 3], v one coordinate triple in lanes 0-2.
    template <int r>
    CRSPLINE_TARGET_AVX512 static V pattern(V v) noexcept {
        constexpr long long f = 8 * r;
        return permute(_mm512_setr_epi64(f % 3, (f + 1) % 3, (f + 2) % 3, (f + 3) % 3, (f + 4) % 3, (f + 5) % 3,
                                         (f + 6) % 3, (f + 7) % 3),
                       v);
    }
    /// Lane j: u[(8 r + j) / 3], the value of the point lane j is part of.
    template <int r>
    CRSPLINE_TARGET_AVX512 static V spread(V u) noexcept {
        constexpr long long f = 8 * r;
        return permute(_mm512_setr_epi64(f / 3, (f + 1) / 3, (f + 2) / 3, (f + 3) / 3, (f + 4) / 3, (f + 5) / 3,
                                         (f + 6) / 3, (f + 7) / 3),
                       u);
    }
};

#else

inline bool& avx2_enabled() noexcept {
    static bool on = false;
    return on;
}

#endif

}  // namespace crspline::detail
