// crspline internal: tessellate()'s greedy cut of the segments, several
// segments side by side in vector lanes, for double on CPUs with AVX2
// (AVX-512F where the CPU has it).
//
// Why lanes. One vertex of the greedy cut is a chain of about twenty
// dependent square roots and divisions (|C''| at the piece's start, the
// closed-form width, the bound at a first end, the predicted growth, the
// bound again): the processor waits on their latency, about 100 ns a vertex
// on the benchmark's walk, while it could start others. The segments are
// independent, so each lane cuts its own segment (two groups of four lanes
// with AVX2, of eight with AVX-512: two independent chains); a lane that
// finishes takes the next segment that
// nobody has taken, and tessellate() puts the vertices of each segment back
// in order. Each lane does exactly the operations of the scalar cut
// (tessellate_scalar_cut below, the text tessellate() had), in the same
// order, with no FMA: the same vertices, bit for bit
// (Kernels.TessellationLanesAgreeBitForBit). Issue 30: the benchmark's
// sorted evaluation got three times faster, and tessellation per vertex
// stood at 138 of its points where the goal is 50. On a Zen 5 EPYC a
// square root costs the same per instruction for 4 or 8 doubles, and the
// AVX-512 lanes took the benchmark's walk at 1e-5 from 35 to 22 ns a
// vertex (BENCHMARKS.md).//
// The parts: tessellate_scalar_cut.hpp (the reference cut),
// tessellate_lane_bounds.hpp (one vertex's arithmetic in lanes); here the
// lanes' walk over the segments and the choice of instruction set.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

#include "../segment.hpp"
#include "../vec.hpp"
#include "simd_lanes.hpp"
#include "tessellate_lane_bounds.hpp"
#include "tessellate_scalar_cut.hpp"

namespace crspline::detail {

/// Where one segment's vertices are in its lane's buffer.
struct cut_record {
    int lane = -1;
    std::size_t start = 0, count = 0;
};

/// The greedy cut of segments 0 .. n-1 (segment_at(i) gives segment i,
/// grid[i + 1] its end knot; a constant segment gets no vertex and an
/// empty record) in G groups of lanes of V, each lane its own segment:
/// buf[lane] (lane = W g + l) gets the parameters of the vertices strictly
/// inside each segment it cut, in order, and rec[i] where segment i's are.
/// Each lane does what tessellate_scalar_cut does, operation for
/// operation; the G groups are independent chains of work side by side.
template <std::size_t D, int G, class V, class M, class S, class SegmentAt>
[[gnu::always_inline]] inline void cut_segments_lanes(std::size_t n, const SegmentAt& segment_at, const double* grid,
                                                      double tol, std::vector<double>* buf, cut_record* rec) {
#if defined(__clang__)
#pragma clang fp contract(off)  // the same roundings as the scalar cut (cut_avx512)
#endif
    constexpr int W = vx_width<V>;
    cut_lanes<D, V> c[G];
    const V zero = V{} - V{}, one = zero + 1.0, four = zero + 4.0, tol_v = zero + tol, least_grow = zero + 1.02;
    M none;
    S::gt(none, zero, zero);
    M live[G];
    std::size_t seg[G][W] = {}, next = 0;
    for (int g = 0; g < G; ++g) {
        for (std::size_t k = 0; k < D; ++k) c[g].c1[k] = c[g].c2[k] = c[g].c3[k] = c[g].c2x2[k] = zero;
        c[g].t0 = c[g].inv_h = c[g].h = c[g].t_end = c[g].n_uniform = c[g].a = zero;
        live[g] = none;
    }
    // Segment next (or the first non-constant one after it) into lane l of
    // group g.
    auto refill = [&](int g, int l) __attribute__((always_inline)) {
        while (next < n) {
            const std::size_t i = next++;
            const cubic_segment<D, double> s = segment_at(i);
            if (s.c1 == vec<D, double>{} && s.c2 == vec<D, double>{} && s.c3 == vec<D, double>{}) {
                rec[i] = cut_record{};
                continue;
            }
            cut_lanes<D, V>& cg = c[g];
            for (std::size_t k = 0; k < D; ++k)
                cg.c1[k][l] = s.c1[k], cg.c2[k][l] = s.c2[k], cg.c3[k][l] = s.c3[k], cg.c2x2[k][l] = 2.0 * s.c2[k];
            cg.t0[l] = s.t0, cg.inv_h[l] = s.inv_h, cg.h[l] = s.h;
            cg.t_end[l] = grid[i + 1], cg.a[l] = grid[i];
            cg.n_uniform[l] = double(uniform_piece_count(s, tol));
            rec[i] = {W * g + l, buf[W * g + l].size(), 0};
            seg[g][l] = i;
            S::put_mask(live[g], l, true);
            return;
        }
        S::put_mask(live[g], l, false);
    };
    for (int g = 0; g < G; ++g)
        for (int l = 0; l < W; ++l) refill(g, l);
    // Whether m holds in some lane of some group.
    auto any_of = [&](const M (&m)[G]) __attribute__((always_inline)) {
        bool any = false;
        for (int g = 0; g < G; ++g) any = any || S::any(m[g]);
        return any;
    };
    // Local u of vertex parameters, as evaluate() computes it. (Results
    // through references here too.)
    auto u_of = [&](int g, V& u, const V& t) __attribute__((always_inline)) {
        u = (t - c[g].t0) * c[g].inv_h;
        M at_end;
        S::eq(at_end, t, c[g].t_end);
        S::set(u, at_end, one);
    };
    auto c2_norm = [&](int g, V& r, const V& u) __attribute__((always_inline)) {
        V d2[D];
        const V six_u = 6.0 * u;
        for (std::size_t k = 0; k < D; ++k) d2[k] = c[g].c2x2[k] + six_u * c[g].c3[k];
        lanes_norm<D, V, M, S>(r, d2);
    };
    // k > 0 ? sqrt(8 tol / k) : 1 - u0.
    auto closed_width = [&](V& w, const V& k, const V& u0) __attribute__((always_inline)) {
        w = 8.0 * tol / k;
        S::apply(w);
        M positive;
        S::gt(positive, k, zero);
        S::set_not(w, positive, one - u0);
    };
    while (any_of(live)) {
        V a[G], u0[G], k0[G], d0[G][D], lo[G], hi[G], f[G], f_hi[G], pt[G];
        M end_failed[G], pass[G], o[G];
        // The test of the pieces [a, t] in the lanes act of group g: their
        // bounds; where one holds, lo = t, else hi = t. pass: where it held.
        auto test = [&](int g, const V& t, const M& act) __attribute__((always_inline)) {
            V ut, ft;
            u_of(g, ut, t);
            lanes_flatness<D, V, M, S>(ft, c[g], u0[g], ut, k0[g], d0[g]);
            M ok, at_end;
            S::le(ok, ft, tol_v);
            pass[g] = act & ok;
            M fail = act;
            vx_clear(fail, ok);
            S::set(lo[g], pass[g], t), S::set(f[g], pass[g], ft);
            S::set(hi[g], fail, t), S::set(f_hi[g], fail, ft);
            S::eq(at_end, t, c[g].t_end);
            end_failed[g] = end_failed[g] | (fail & at_end);
        };
        auto open = [&](int g, const V& t) __attribute__((always_inline)) {
            M at_end, below;
            S::eq(at_end, t, c[g].t_end);
            vx_clear(at_end, end_failed[g]);
            S::lt(below, t, hi[g]);
            o[g] = below | at_end;
            S::and_gt(o[g], t, lo[g]);
        };
        // The closed-form start, and the first end tested.
        for (int g = 0; g < G; ++g) {
            V w0, k1, w1, x;
            a[g] = c[g].a;
            u_of(g, u0[g], a[g]);
            const V three_u0 = 3.0 * u0[g];
            for (std::size_t k = 0; k < D; ++k)
                d0[g][k] = c[g].c1[k] + u0[g] * (c[g].c2x2[k] + three_u0 * c[g].c3[k]);
            c2_norm(g, k0[g], u0[g]);
            closed_width(w0, k0[g], u0[g]);
            S::min(x, one, u0[g] + w0);
            c2_norm(g, k1, x);
            S::max(k1, k0[g], k1);
            closed_width(w1, k1, u0[g]);
            lo[g] = a[g], hi[g] = c[g].t_end, f[g] = zero, f_hi[g] = zero, end_failed[g] = none;
            S::min(pt[g], c[g].t_end, a[g] + w1 * c[g].h);
            open(g, pt[g]);
            test(g, pt[g], live[g] & o[g]);
        }
        // No closed-form start proved (rounding): bisect from a until a
        // piece is.
        M bisect[G];
        for (int g = 0; g < G; ++g) bisect[g] = live[g];
        for (int halve = 0; halve < 64; ++halve) {
            V mid[G];
            for (int g = 0; g < G; ++g) {
                M proved;
                S::gt(proved, lo[g], a[g]);
                vx_clear(bisect[g], proved);
                mid[g] = lo[g] + (hi[g] - lo[g]) / 2.0;
                S::and_gt(bisect[g], mid[g], lo[g]);
                S::and_lt(bisect[g], mid[g], hi[g]);
            }
            if (!any_of(bisect)) break;
            for (int g = 0; g < G; ++g)
                if (S::any(bisect[g])) test(g, mid[g], bisect[g]);
        }
        // The grow steps (at most 4), and after a failed one the step back,
        // as the scalar loop takes them lane by lane; a lane's step back is
        // tested together with the other lanes' next grow step (one bound
        // a round, not two).
        M grow_on[G], back_on[G], act[G];
        V steps[G];
        for (int g = 0; g < G; ++g) grow_on[g] = live[g], back_on[g] = none, steps[g] = zero;
        for (;;) {
            for (int g = 0; g < G; ++g) {
                S::and_lt(grow_on[g], steps[g], four);
                S::and_gt(grow_on[g], lo[g], a[g]);
                S::and_lt(grow_on[g], lo[g], c[g].t_end);
                V root = tol / f[g], grow, nx;
                S::apply(root);
                S::min(grow, four, 0.99 * root);
                M positive;
                S::gt(positive, f[g], zero);
                S::set_not(grow, positive, four);
                S::and_gt(grow_on[g], grow, least_grow);
                S::min(nx, c[g].t_end, a[g] + grow * (lo[g] - a[g]));
                open(g, nx);
                S::set_not(nx, o[g], lo[g] + (hi[g] - lo[g]) / 2.0);
                open(g, nx);
                grow_on[g] = grow_on[g] & o[g];
                act[g] = grow_on[g] | back_on[g];
                S::set(pt[g], grow_on[g], nx);
            }
            if (!any_of(act)) break;
            for (int g = 0; g < G; ++g) {
                if (!S::any(act[g])) continue;
                test(g, pt[g], act[g]);
                S::set(steps[g], grow_on[g], steps[g] + 1.0);
                M failed = grow_on[g];
                vx_clear(failed, pass[g]);
                back_on[g] = none;
                if (S::any(failed)) {
                    V back_root = tol / f_hi[g];
                    S::apply(back_root);
                    const V back = a[g] + (pt[g] - a[g]) * 0.99 * back_root;
                    back_on[g] = failed;
                    S::and_gt(back_on[g], back, lo[g] + (hi[g] - lo[g]) / 8.0);
                    S::and_lt(back_on[g], back, hi[g]);
                    S::set(pt[g], back_on[g], back);
                }
                grow_on[g] = grow_on[g] & pass[g];
            }
        }
        for (int g = 0; g < G; ++g) {
            V x;
            M fin, stuck, fin_now;
            S::eq(fin, lo[g], c[g].t_end);
            S::min(x, c[g].t_end, a[g] + c[g].h / c[g].n_uniform);
            S::max(lo[g], lo[g], x);
            S::eq(stuck, lo[g], a[g]);
            S::set(lo[g], stuck, hi[g]);
            S::eq(fin_now, lo[g], c[g].t_end);
            fin = fin | fin_now;
            c[g].a = lo[g];
            // The lanes' outcomes as bits and the new vertices as scalars,
            // each in one instruction, not lane by lane.
            const unsigned live_bits = S::bits(live[g]), fin_bits = S::bits(fin);
            double vertex[W];
            std::memcpy(vertex, &lo[g], sizeof vertex);
            for (int l = 0; l < W; ++l) {
                if (!((live_bits >> l) & 1u)) continue;
                if ((fin_bits >> l) & 1u) {
                    cut_record& r = rec[seg[g][l]];
                    r.count = buf[W * g + l].size() - r.start;
                    refill(g, l);
                } else {
                    buf[W * g + l].push_back(vertex[l]);
                }
            }
        }
    }
}

#if CRSPLINE_X86_DISPATCH && CRSPLINE_LANES4
/// The operations of the cut's lanes in the AVX2 clone (four lanes, masks
/// as vectors): one instruction each.
struct cut_avx2 {
    using V = lanes;
    using M = lanes_mask;
    [[gnu::always_inline]] static void apply(V& x) noexcept { sqrt_avx::apply(x); }
    // r = std::max(a, b) = (a < b ? b : a) and r = std::min(a, b) = (b < a ?
    // b : a) exactly, NaN and signed zeros included: vmaxpd(x, y) is (x > y
    // ? x : y) and vminpd(x, y) is (x < y ? x : y), so with x = b, y = a.
    CRSPLINE_TARGET_AVX2 static void max(V& r, const V& a, const V& b) noexcept {
        r = V(_mm256_max_pd(__m256d(b), __m256d(a)));
    }
    CRSPLINE_TARGET_AVX2 static void min(V& r, const V& a, const V& b) noexcept {
        r = V(_mm256_min_pd(__m256d(b), __m256d(a)));
    }
    // r = (a < b), ... lane by lane; and_lt, and_gt: r = r and (a < b), ...
    [[gnu::always_inline]] static void lt(M& r, const V& a, const V& b) noexcept { r = a < b; }
    [[gnu::always_inline]] static void le(M& r, const V& a, const V& b) noexcept { r = a <= b; }
    [[gnu::always_inline]] static void gt(M& r, const V& a, const V& b) noexcept { r = a > b; }
    [[gnu::always_inline]] static void eq(M& r, const V& a, const V& b) noexcept { r = a == b; }
    [[gnu::always_inline]] static void and_lt(M& r, const V& a, const V& b) noexcept { r &= a < b; }
    [[gnu::always_inline]] static void and_gt(M& r, const V& a, const V& b) noexcept { r &= a > b; }
    /// x = a in the lanes where m holds; where it fails.
    [[gnu::always_inline]] static void set(V& x, const M& m, const V& a) noexcept {
        x = V((M(a) & m) | (M(x) & ~m));
    }
    [[gnu::always_inline]] static void set_not(V& x, const M& m, const V& a) noexcept {
        x = V((M(x) & m) | (M(a) & ~m));
    }
    [[gnu::always_inline]] static void put_mask(M& m, int l, bool v) noexcept { m[l] = v ? -1 : 0; }
    /// acc += |x| (the sign bit cleared).
    [[gnu::always_inline]] static void add_abs(V& acc, const V& x) noexcept {
        acc += V(M(x) & (M{} + 0x7fffffffffffffffLL));
    }
    CRSPLINE_TARGET_AVX2 static unsigned bits(const M& m) noexcept { return unsigned(_mm256_movemask_pd(__m256d(m))); }
    CRSPLINE_TARGET_AVX2 static bool any(const M& m) noexcept { return bits(m) != 0; }
    CRSPLINE_TARGET_AVX2 static bool any_not(const M& m) noexcept { return bits(m) != 0xFu; }
};

/// The operations of the cut's lanes in the AVX-512 clone: eight lanes in
/// one register, masks in k-registers (GCC 12 makes the vector extension's
/// 512-bit comparisons lane by lane, so intrinsics here: the ordered, quiet
/// comparisons of C++'s <, <=, >, ==, false where a NaN is; blends are
/// masked moves). AVX-512F brings FMA with it: GCC's contraction of a
/// product and a sum is off in CRSPLINE_TARGET_AVX512 functions, Clang's
/// (made in the front end, expression by expression) by the pragma in the
/// generic functions above, so that each lane rounds as the scalar cut.
using lanes8 = double __attribute__((vector_size(64)));
using lanes8_bits = long long __attribute__((vector_size(64)));
struct cut_avx512 {
    using V = lanes8;
    using M = __mmask8;
    // (The masked forms with every lane on: the plain intrinsics' undefined
    // source draws GCC 12's -Wmaybe-uninitialized; the same instructions.)
    CRSPLINE_TARGET_AVX512 static void apply(V& x) noexcept {
        x = V(_mm512_mask_sqrt_pd(__m512d(x), __mmask8(0xFF), __m512d(x)));
    }
    CRSPLINE_TARGET_AVX512 static void max(V& r, const V& a, const V& b) noexcept {
        r = V(_mm512_mask_max_pd(__m512d(a), __mmask8(0xFF), __m512d(b), __m512d(a)));
    }
    CRSPLINE_TARGET_AVX512 static void min(V& r, const V& a, const V& b) noexcept {
        r = V(_mm512_mask_min_pd(__m512d(a), __mmask8(0xFF), __m512d(b), __m512d(a)));
    }
    CRSPLINE_TARGET_AVX512 static void lt(M& r, const V& a, const V& b) noexcept {
        r = _mm512_cmp_pd_mask(__m512d(a), __m512d(b), _CMP_LT_OQ);
    }
    CRSPLINE_TARGET_AVX512 static void le(M& r, const V& a, const V& b) noexcept {
        r = _mm512_cmp_pd_mask(__m512d(a), __m512d(b), _CMP_LE_OQ);
    }
    CRSPLINE_TARGET_AVX512 static void gt(M& r, const V& a, const V& b) noexcept {
        r = _mm512_cmp_pd_mask(__m512d(a), __m512d(b), _CMP_GT_OQ);
    }
    CRSPLINE_TARGET_AVX512 static void eq(M& r, const V& a, const V& b) noexcept {
        r = _mm512_cmp_pd_mask(__m512d(a), __m512d(b), _CMP_EQ_OQ);
    }
    CRSPLINE_TARGET_AVX512 static void and_lt(M& r, const V& a, const V& b) noexcept {
        r = _mm512_mask_cmp_pd_mask(r, __m512d(a), __m512d(b), _CMP_LT_OQ);
    }
    CRSPLINE_TARGET_AVX512 static void and_gt(M& r, const V& a, const V& b) noexcept {
        r = _mm512_mask_cmp_pd_mask(r, __m512d(a), __m512d(b), _CMP_GT_OQ);
    }
    CRSPLINE_TARGET_AVX512 static void set(V& x, M m, const V& a) noexcept {
        x = V(_mm512_mask_mov_pd(__m512d(x), m, __m512d(a)));
    }
    CRSPLINE_TARGET_AVX512 static void set_not(V& x, M m, const V& a) noexcept {
        x = V(_mm512_mask_mov_pd(__m512d(a), m, __m512d(x)));
    }
    [[gnu::always_inline]] static void put_mask(M& m, int l, bool v) noexcept {
        m = M(v ? m | (1u << l) : m & ~(1u << l));
    }
    [[gnu::always_inline]] static void add_abs(V& acc, const V& x) noexcept {
        acc += V(lanes8_bits(x) & (lanes8_bits{} + 0x7fffffffffffffffLL));
    }
    [[gnu::always_inline]] static unsigned bits(M m) noexcept { return m; }
    [[gnu::always_inline]] static bool any(M m) noexcept { return m != 0; }
    [[gnu::always_inline]] static bool any_not(M m) noexcept { return m != 0xFFu; }
};

/// The groups of lanes side by side (two: three or four measured no
/// faster with AVX2), and the lanes' buffers (the most lanes of a path).
inline constexpr int cut_groups = 2;
inline constexpr int cut_width = cut_groups * 8;

template <std::size_t D, class SegmentAt>
CRSPLINE_TARGET_AVX2 void cut_segments_avx2(std::size_t n, const SegmentAt& segment_at, const double* grid,
                                            double tol, std::vector<double>* buf, cut_record* rec) {
    cut_segments_lanes<D, cut_groups, lanes, lanes_mask, cut_avx2>(n, segment_at, grid, tol, buf, rec);
}
template <std::size_t D, class SegmentAt>
CRSPLINE_TARGET_AVX512 void cut_segments_avx512(std::size_t n, const SegmentAt& segment_at, const double* grid,
                                                double tol, std::vector<double>* buf, cut_record* rec) {
    cut_segments_lanes<D, cut_groups, lanes8, __mmask8, cut_avx512>(n, segment_at, grid, tol, buf, rec);
}
#else
inline constexpr int cut_width = 1;
#endif

/// The fewest segments tessellate() cuts in lanes.
inline constexpr std::size_t cut_lanes_from = 64;

/// Whether tessellate() cuts in lanes: with AVX2 (avx2_enabled()). On the
/// x86-64 baseline, four lanes in SSE2 pairs measured slower than one
/// segment at a time (143 against 101 ns a vertex on the benchmark's walk
/// at 1e-5), so the portable code cuts one by one.
inline bool cut_in_lanes() noexcept {
#if CRSPLINE_X86_DISPATCH && CRSPLINE_LANES4
    return avx2_enabled();
#else
    return false;
#endif
}

/// cut_segments_lanes in the AVX-512 clone where the CPU has AVX-512F, else
/// in the AVX2 clone (only where cut_in_lanes()).
template <std::size_t D, class SegmentAt>
void cut_segments(std::size_t n, const SegmentAt& segment_at, const double* grid, double tol,
                  std::vector<double>* buf, cut_record* rec) {
#if CRSPLINE_X86_DISPATCH && CRSPLINE_LANES4
    if (avx512_enabled()) return cut_segments_avx512<D>(n, segment_at, grid, tol, buf, rec);
    cut_segments_avx2<D>(n, segment_at, grid, tol, buf, rec);
#else
    (void)n, (void)segment_at, (void)grid, (void)tol, (void)buf, (void)rec;
#endif
}

}  // namespace crspline::detail
