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
// detail::avx2_enabled() can be set to false (tests compare both paths).//
// The lanes and the run-time choice are in x86_lanes.hpp; here the walks
// of sorted batches and the Hermite point of the unsorted kernel.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "x86_lanes.hpp"

namespace crspline::detail {

#if CRSPLINE_X86_DISPATCH

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

#endif

}  // namespace crspline::detail
