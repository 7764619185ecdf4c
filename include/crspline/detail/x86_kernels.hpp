// crspline: AVX2 batch kernels for 3-D points, chosen at run time.
//
// The library is built for the x86-64 baseline (SSE2: 2 doubles per
// instruction). On a CPU with AVX2 the batch evaluation of 3-D points
// (sorted t: double and float; unsorted t: double) runs these kernels
// instead, 4 doubles or 8 floats per instruction (sorted batches: 8
// doubles or 16 floats where the CPU has AVX-512F), selected once by a
// CPUID test (GCC/Clang function targets: nothing needs -mavx2 or -march). They use no FMA, so each
// result goes through the same roundings, in the same order, as the
// portable code: the same bits on every CPU.
//
// detail::avx2_enabled() can be set to false (tests compare both paths).
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

/// The 512-bit steps of a sorted batch of 3-D floats or doubles: W = 16
/// float or 8 double points a step, 3 W scalars in 3 registers laid out as
/// in memory (lanes512's layout: lane j of register r holds coordinate
/// (W r + j) % 3 of point (W r + j) / 3), the same operations as the
/// portable run_kernel (batch_kernels.hpp), so the same bits. A segment's
/// coefficients are loaded by one masked load and 3 permutes each. (Issue
/// 30: built through a 16-float array on the stack, as the 8-lane patterns
/// were, each cost a failed store forward.) Doubles (issue 30): on the AMD
/// EPYC the 4-lane AVX2 runs took 6.3 ms of instructions per 10^7 points in
/// cache, about the whole time memset takes to write the output: this walk
/// halves the arithmetic and drops the runs (BENCHMARKS.md, issue 30).
template <class T, int Order>
struct steps512 {
    using L = lanes512<T>;
    using V = typename L::V;
    using M = typename L::M;
    static constexpr unsigned W = L::W;
    V A0, A1, A2, B0, B1, B2, C0, C1, C2, O0, O1, O2, vt0, vih, vend;

    /// Takes segment seg's coefficients: segments.load(seg, o, a, b, c, t0,
    /// ih, t_end) fills them: origin and Horner coefficients per coordinate
    /// (run_coefficients), t0, 1/h and the end knot.
    template <class Segments>
    CRSPLINE_TARGET_AVX512 __attribute__((always_inline)) void load(const Segments& segments, std::size_t seg) noexcept {
        T o[3], a[3], b[3], c[3], t0, ih, t_end;
        segments.load(seg, o, a, b, c, t0, ih, t_end);
        const V va = L::maskload(0x7, a), vb = L::maskload(0x7, b), vc = L::maskload(0x7, c);
        // (Order 1: no origin term.)
        const V vo = Order == 0 ? L::maskload(0x7, o) : L::zero();
        A0 = L::template pattern<0>(va), A1 = L::template pattern<1>(va), A2 = L::template pattern<2>(va);
        B0 = L::template pattern<0>(vb), B1 = L::template pattern<1>(vb), B2 = L::template pattern<2>(vb);
        C0 = L::template pattern<0>(vc), C1 = L::template pattern<1>(vc), C2 = L::template pattern<2>(vc);
        O0 = L::template pattern<0>(vo), O1 = L::template pattern<1>(vo), O2 = L::template pattern<2>(vo);
        vt0 = L::set1(t0), vih = L::set1(ih), vend = L::set1(t_end);
    }

    /// The W points at parameters x on this segment, as 3 W scalars in r0 r1 r2.
    CRSPLINE_TARGET_AVX512 void points(V x, V& r0, V& r1, V& r2) const noexcept {
        const V u = L::mul(L::sub(x, vt0), vih);
        const V U0 = L::template spread<0>(u), U1 = L::template spread<1>(u), U2 = L::template spread<2>(u);
        r0 = L::add(A0, L::mul(U0, L::add(B0, L::mul(U0, C0))));
        r1 = L::add(A1, L::mul(U1, L::add(B1, L::mul(U1, C1))));
        r2 = L::add(A2, L::mul(U2, L::add(B2, L::mul(U2, C2))));
        if constexpr (Order == 0) {
            r0 = L::add(O0, L::mul(U0, r0));
            r1 = L::add(O1, L::mul(U1, r1));
            r2 = L::add(O2, L::mul(U2, r2));
        }
    }

    /// Any step of up to W points at t[0..m) (1 <= m <= W): the batch's
    /// first (first: t[-1] is not read, lane 0 is compared with t[0]), its
    /// last, or one that crosses into later segments, with masked loads and
    /// stores (nothing outside the m points is read or written) unless nt
    /// (m = W, out 64-byte aligned: non-temporal stores). Each lane gets
    /// the segment the sorted walk gives it: the step is computed on seg,
    /// then for the lanes at or past its end knot on the segment of the
    /// first of them (segments.next), and so on; seg is left at the last.
    /// Returns false, writing nothing, when the step is not sorted (or
    /// holds NaN).
    template <class Segments>
    CRSPLINE_TARGET_AVX512 __attribute__((always_inline)) bool step(const Segments& segments, std::size_t& seg,
                                                                    const T* t, T* out, unsigned m, bool first,
                                                                    bool nt) noexcept {
        const M in = L::first_lanes(m);
        const V x = L::maskload(in, t);
        // Lane j's predecessor: t[j - 1], for the batch's first step t[0]
        // in lane 0 (x's lanes shifted up one, t[-1] is not read).
        const V before = first ? L::shift_in(x, t[0]) : L::maskload(in, t - 1);
        if ((L::le(before, x) & in) != in) return false;  // not sorted, or NaN
        V r0, r1, r2;
        points(x, r0, r1, r2);
        const V X0 = L::template spread<0>(x), X1 = L::template spread<1>(x), X2 = L::template spread<2>(x);
        for (M past = L::nlt(in, x, vend); past != 0; past = L::nlt(in, x, vend)) {
            const std::size_t next = segments.next(seg, t[__builtin_ctz(unsigned(past))]);
            if (next == seg) break;  // (no later segment: cannot happen in the domain)
            const V end = vend;
            seg = next;
            load(segments, seg);
            V q0, q1, q2;
            points(x, q0, q1, q2);
            r0 = L::blend(r0, L::nlt(X0, end), q0);
            r1 = L::blend(r1, L::nlt(X1, end), q1);
            r2 = L::blend(r2, L::nlt(X2, end), q2);
        }
        if (nt) {
            L::stream(out, r0), L::stream(out + W, r1), L::stream(out + 2 * W, r2);
        } else {
            const unsigned f = 3 * m;  // scalars to store
            L::maskstore(out, L::first_lanes(f), r0);
            L::maskstore(out + W, L::first_lanes(f > W ? f - W : 0), r1);
            L::maskstore(out + 2 * W, L::first_lanes(f > 2 * W ? f - 2 * W : 0), r2);
        }
        return true;
    }
};

/// Prefetches t 4 KiB ahead of the sorted walks' loads. Reading t beside
/// the stream of non-temporal stores, the hardware prefetcher alone left
/// the double walks at 0.65 ns a point on 10^7 points (AMD EPYC Zen 5,
/// AVX-512), 0.615 with this prefetch (floats 0.30 -> 0.295; 1 to 8 KiB
/// ahead measured alike; BENCHMARKS.md, issue 30). The address is formed
/// as an integer (it may lie past the array; a prefetch never faults).
CRSPLINE_TARGET_AVX2 inline void prefetch_ahead(const void* p) noexcept {
    _mm_prefetch(reinterpret_cast<const char*>(reinterpret_cast<std::uintptr_t>(p) + 4096), _MM_HINT_T0);
}

/// The W-point steps of sorted_walk3_512 from point k (out + 3 k 64-byte
/// aligned when Stream: non-temporal stores of whole cache lines) while
/// W points remain, are sorted and are below the segment's end knot;
/// returns the new k. (It takes the coefficients by value: as members of
/// an object whose address a call takes, GCC read them from memory each
/// step.)
template <int Order, bool Stream, class T>
CRSPLINE_TARGET_AVX512 std::size_t bulk512(const steps512<T, Order> s, const T* t, T* out, std::size_t k,
                                           std::size_t n) noexcept {
    using L = lanes512<T>;
    constexpr unsigned W = L::W;
    for (; k + W <= n; k += W) {
        prefetch_ahead(t + k);
        const typename L::V x = L::load(t + k);
        const unsigned go = unsigned(L::lt(x, s.vend)) & unsigned(L::le(L::load(t + k - 1), x));
        if (go != L::all) break;  // unsorted, NaN, or past the end knot: a step for sorted_walk3_512
        typename L::V r0, r1, r2;
        s.points(x, r0, r1, r2);
        T* dst = out + 3 * k;
        if constexpr (Stream) {
            L::stream(dst, r0), L::stream(dst + W, r1), L::stream(dst + 2 * W, r2);
        } else {
            L::store(dst, r0), L::store(dst + W, r1), L::store(dst + 2 * W, r2);
        }
    }
    return k;
}

/// The x with 3 x = 1 (mod w), w a power of two: the walks' first step
/// solves 3 h = -(out mod bytes) / sizeof(T) (mod w) with it.
constexpr unsigned inverse_of_3_mod(unsigned w) noexcept {
    unsigned x = 1;
    while (3 * x % w != 1) ++x;
    return x;
}
static_assert(inverse_of_3_mod(16) == 11 && inverse_of_3_mod(8) == 3 && inverse_of_3_mod(4) == 3);

/// A whole sorted batch of 3-D floats or doubles on a CPU with AVX-512F,
/// the segments walked inside the vector loop (issue 30): the positions
/// (Order 0) or velocities (Order 1) at t[0..n) into out (3 n scalars), the
/// same bits as the portable kernel's runs (and as the AVX2 walk). seg:
/// t[0]'s segment.
/// Segments gives the curve's segments: next(seg, x), the segment of x
/// from seg on (the sorted walk's rule: while x >= the next knot, the next
/// segment), and load(seg, o, a, b, c, t0, ih, t_end), the coefficients
/// as steps512::load takes them. One step of up to W points (16 floats, 8
/// doubles) brings out + 3 k to 64-byte alignment (12 h = -out mod 64
/// bytes, h in 1..16 for floats; 24 h, h in 1..8 for doubles); then every
/// step is W points (192 bytes), its stores three whole cache lines
/// (non-temporal when stream); a step that crosses a knot is computed on
/// both segments and blended, so there are no short runs at the knots: a
/// knot costs its segment's coefficients and one step computed twice
/// (about 35-45 ns on the AMD EPYC for floats, from the step's chain of
/// dependent work; the runs per segment this replaces, capped at 4096
/// points, cost about 140 ns each in set-up, scalar ends and partially
/// written lines: BENCHMARKS.md, issue 30). Returns false as soon as a
/// step is not sorted (or holds NaN): the caller starts over; out is then
/// partly written.
template <int Order, class Segments, class T>
CRSPLINE_TARGET_AVX512 bool sorted_walk3_512(const Segments& segments, std::size_t seg, const T* t, T* out,
                                             std::size_t n, bool stream) noexcept {
    constexpr unsigned W = lanes512<T>::W;
    if (n == 0) return true;
    steps512<T, Order> s;
    s.load(segments, seg);
    // 3 h = -(out mod 64) / sizeof(T) (mod W), and 1 / 3 (mod W) is 11 for
    // W = 16, 3 for W = 8.
    constexpr unsigned third = inverse_of_3_mod(W);
    const unsigned lane = unsigned(reinterpret_cast<std::uintptr_t>(out) % 64) / unsigned(sizeof(T));
    const unsigned h0 = (third * ((W - lane) % W)) % W, h = h0 == 0 ? W : h0;
    const unsigned m = unsigned(n < h ? n : h);
    if (!s.step(segments, seg, t, out, m, true, stream && m == W)) return false;
    std::size_t k = m;
    // out + 3 k is 64-byte aligned from here on.
    while (k + W <= n) {
        k = stream ? bulk512<Order, true>(s, t, out, k, n) : bulk512<Order, false>(s, t, out, k, n);
        if (k + W <= n) {
            if (!s.step(segments, seg, t + k, out + 3 * k, W, false, stream)) return false;
            k += W;
        }
    }
    return k == n || s.step(segments, seg, t + k, out + 3 * k, unsigned(n - k), false, false);
}

/// steps512 in 256-bit AVX2 lanes for CPUs without AVX-512F: W = 8 float
/// or 4 double points a step, 3 W scalars in 3 registers laid out as in
/// memory (lanes256's layout), masks as vectors (all ones or zero per
/// lane), masked loads and stores by maskload / maskstore; the same
/// operations as the portable run_kernel, so the same bits. Doubles (issue
/// 30): it replaced the 4-lane runs, one per segment capped at 4096 points,
/// about 140 ns of set-up, scalar ends and shared lines each (on the AMD
/// EPYC without AVX-512: 7.3 ms per 10^7 points with the runs, 6.85-6.88 ms
/// walked; BENCHMARKS.md, issue 30).
template <class T, int Order>
struct steps256 {
    using L = lanes256<T>;
    using V = typename L::V;
    static constexpr unsigned W = L::W;
    V A0, A1, A2, B0, B1, B2, C0, C1, C2, O0, O1, O2, vt0, vih, vend;

    /// As steps512::load.
    template <class Segments>
    CRSPLINE_TARGET_AVX2 __attribute__((always_inline)) void load(const Segments& segments, std::size_t seg) noexcept {
        T o[3], a[3], b[3], c[3], t0, ih, t_end;
        segments.load(seg, o, a, b, c, t0, ih, t_end);
        A0 = L::pattern(a, 0), A1 = L::pattern(a, 1), A2 = L::pattern(a, 2);
        B0 = L::pattern(b, 0), B1 = L::pattern(b, 1), B2 = L::pattern(b, 2);
        C0 = L::pattern(c, 0), C1 = L::pattern(c, 1), C2 = L::pattern(c, 2);
        if constexpr (Order == 0) O0 = L::pattern(o, 0), O1 = L::pattern(o, 1), O2 = L::pattern(o, 2);
        else O0 = O1 = O2 = L::zero();
        vt0 = L::set1(t0), vih = L::set1(ih), vend = L::set1(t_end);
    }

    /// The W points at parameters x on this segment, as 3 W scalars in r0 r1 r2.
    CRSPLINE_TARGET_AVX2 void points(V x, V& r0, V& r1, V& r2) const noexcept {
        const V u = L::mul(L::sub(x, vt0), vih);
        const V U0 = L::template spread<0>(u), U1 = L::template spread<1>(u), U2 = L::template spread<2>(u);
        r0 = L::add(A0, L::mul(U0, L::add(B0, L::mul(U0, C0))));
        r1 = L::add(A1, L::mul(U1, L::add(B1, L::mul(U1, C1))));
        r2 = L::add(A2, L::mul(U2, L::add(B2, L::mul(U2, C2))));
        if constexpr (Order == 0) {
            r0 = L::add(O0, L::mul(U0, r0));
            r1 = L::add(O1, L::mul(U1, r1));
            r2 = L::add(O2, L::mul(U2, r2));
        }
    }

    /// steps512::step with W = 8 or 4 lanes (1 <= m <= W; nt: m = W, out
    /// 32-byte aligned).
    template <class Segments>
    CRSPLINE_TARGET_AVX2 __attribute__((always_inline)) bool step(const Segments& segments, std::size_t& seg,
                                                                  const T* t, T* out, unsigned m, bool first,
                                                                  bool nt) noexcept {
        const __m256i in = L::first_lanes(m);
        const int in_bits = int((1u << m) - 1);
        const V x = L::maskload(t, in);
        // Lane j's predecessor: t[j - 1]; for the batch's first step t[0]
        // in lane 0 (x's lanes moved up one, lane 0 kept: t[-1] is not read).
        const V before = first ? L::shift_up(x) : L::maskload(t - 1, in);
        if ((L::mask(L::le(before, x)) & in_bits) != in_bits) return false;  // not sorted, or NaN
        V r0, r1, r2;
        points(x, r0, r1, r2);
        const V X0 = L::template spread<0>(x), X1 = L::template spread<1>(x), X2 = L::template spread<2>(x);
        for (int past = L::mask(L::nlt(x, vend)) & in_bits; past != 0; past = L::mask(L::nlt(x, vend)) & in_bits) {
            const std::size_t next = segments.next(seg, t[__builtin_ctz(unsigned(past))]);
            if (next == seg) break;  // (no later segment: cannot happen in the domain)
            const V end = vend;
            seg = next;
            load(segments, seg);
            V q0, q1, q2;
            points(x, q0, q1, q2);
            r0 = L::blend(r0, q0, L::nlt(X0, end));
            r1 = L::blend(r1, q1, L::nlt(X1, end));
            r2 = L::blend(r2, q2, L::nlt(X2, end));
        }
        if (nt) {
            L::stream(out, r0), L::stream(out + W, r1), L::stream(out + 2 * W, r2);
        } else {
            const unsigned f = 3 * m;  // scalars to store
            L::maskstore(out, L::first_lanes(f), r0);
            L::maskstore(out + W, L::first_lanes(f > W ? f - W : 0), r1);
            L::maskstore(out + 2 * W, L::first_lanes(f > 2 * W ? f - 2 * W : 0), r2);
        }
        return true;
    }
};

/// bulk512 in W = 8 float or 4 double lanes (out + 3 k 32-byte aligned when
/// Stream).
template <int Order, bool Stream, class T>
CRSPLINE_TARGET_AVX2 std::size_t bulk256(const steps256<T, Order> s, const T* t, T* out, std::size_t k,
                                         std::size_t n) noexcept {
    using L = lanes256<T>;
    constexpr unsigned W = L::W;
    for (; k + W <= n; k += W) {
        prefetch_ahead(t + k);
        const typename L::V x = L::load(t + k);
        if (L::mask(L::both(L::lt(x, s.vend), L::le(L::load(t + k - 1), x))) != L::all) break;
        typename L::V r0, r1, r2;
        s.points(x, r0, r1, r2);
        T* dst = out + 3 * k;
        if constexpr (Stream) {
            L::stream(dst, r0), L::stream(dst + W, r1), L::stream(dst + 2 * W, r2);
        } else {
            L::store(dst, r0), L::store(dst + W, r1), L::store(dst + 2 * W, r2);
        }
    }
    return k;
}

/// sorted_walk3_512 for CPUs with AVX2 and not AVX-512F: steps of W = 8
/// float or 4 double points (96 bytes; two steps fill 3 cache lines, by
/// non-temporal 32-byte stores when stream), after one step of up to W
/// that brings out + 3 k to 32-byte alignment (12 h = -out mod 32 bytes,
/// h in 1..8 for floats; 24 h, h in 1..4 for doubles). The same bits.
template <int Order, class Segments, class T>
CRSPLINE_TARGET_AVX2 bool sorted_walk3_256(const Segments& segments, std::size_t seg, const T* t, T* out,
                                           std::size_t n, bool stream) noexcept {
    constexpr unsigned W = lanes256<T>::W;
    if (n == 0) return true;
    steps256<T, Order> s;
    s.load(segments, seg);
    // 3 h = -(out mod 32) / sizeof(T) (mod W), and 3 = 1 / 3 (mod 8) and
    // (mod 4).
    constexpr unsigned third = inverse_of_3_mod(W);
    const unsigned lane = unsigned(reinterpret_cast<std::uintptr_t>(out) % 32) / unsigned(sizeof(T));
    const unsigned h0 = (third * ((W - lane) % W)) % W, h = h0 == 0 ? W : h0;
    const unsigned m = unsigned(n < h ? n : h);
    if (!s.step(segments, seg, t, out, m, true, stream && m == W)) return false;
    std::size_t k = m;
    // out + 3 k is 32-byte aligned from here on.
    while (k + W <= n) {
        k = stream ? bulk256<Order, true>(s, t, out, k, n) : bulk256<Order, false>(s, t, out, k, n);
        if (k + W <= n) {
            if (!s.step(segments, seg, t + k, out + 3 * k, W, false, stream)) return false;
            k += W;
        }
    }
    return k == n || s.step(segments, seg, t + k, out + 3 * k, unsigned(n - k), false, false);
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
