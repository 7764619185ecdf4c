// crspline: batch evaluation of a catmull_rom curve, its kernels.
//
// catmull_rom::evaluate(span t, span out, order) checks its arguments and
// hands the batch to batch_kernels::evaluate: a sorted walk over the
// segments with each segment's coefficients held in registers (vector
// lanes where the compiler has them, AVX2 for 3-D points where the CPU
// has it: x86_kernels.hpp), else one located point at a time. Every path
// computes the same bits as the scalar evaluation (tests/unit/test_kernels.cpp).
// The kernels read the curve's arrays as they are stored: batch_kernels is
// catmull_rom's friend, so the segment arithmetic (make_segment) and the
// knot index (knot_index.hpp) stay defined once, in the curve.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <type_traits>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "../segment.hpp"
#include "../vec.hpp"
#include "knot_index.hpp"
#include "x86_kernels.hpp"

namespace crspline {

template <std::size_t D, class T>
class catmull_rom;

namespace detail {

// Vector kernels for batch evaluation: GCC/Clang vector extensions on
// 16-byte vectors (SSE2 is part of x86-64, NEON of AArch64). Elsewhere the
// scalar loops do all the work.
#if defined(__GNUC__) && (defined(__SSE2__) || defined(__ARM_NEON))
#define CRSPLINE_VECTOR_KERNELS 1
template <class T>
struct lanes16_of {};  // none: long double uses the scalar loops
template <>
struct lanes16_of<double> { typedef double type __attribute__((vector_size(16))); };
template <>
struct lanes16_of<float> { typedef float type __attribute__((vector_size(16))); };
template <class T>
using lanes16 = typename lanes16_of<T>::type;
template <class T>
inline constexpr bool has_lanes16 = std::is_same_v<T, double> || std::is_same_v<T, float>;
#else
#define CRSPLINE_VECTOR_KERNELS 0
#endif

/// Batch outputs of at least this many bytes are written with non-temporal
/// stores where available: they skip the read of each cache line that an
/// ordinary store must do first (and do not evict the caller's working set).
/// Below it the output is likely to be read again soon, from cache.
#ifndef CRSPLINE_STREAMING_THRESHOLD
#define CRSPLINE_STREAMING_THRESHOLD (std::size_t(8) << 20)
#endif
inline constexpr std::size_t streaming_threshold = CRSPLINE_STREAMING_THRESHOLD;

/// Writes D 16-byte vectors from buf to the 16-byte aligned p, bypassing the
/// caches (movntpd / movntps); a plain copy without SSE2.
template <std::size_t D, class T>
inline void stream_store(T* p, const T* buf) noexcept {
#if defined(__SSE2__)
    for (std::size_t i = 0; i < D; ++i) {
        if constexpr (std::is_same_v<T, double>) _mm_stream_pd(p + 2 * i, _mm_load_pd(buf + 2 * i));
        else _mm_stream_ps(p + 4 * i, _mm_load_ps(buf + 4 * i));
    }
#else
    std::memcpy(p, buf, 16 * D);
#endif
}

/// Orders non-temporal stores before whatever follows (they are weakly
/// ordered); nothing to do without them.
inline void store_fence() noexcept {
#if defined(__SSE2__)
    _mm_sfence();
#endif
}


/// The batch paths of catmull_rom<D, T>::evaluate(span, span, order).
template <std::size_t D, class T>
struct batch_kernels {
    using curve = catmull_rom<D, T>;
    using point = vec<D, T>;
    using segment_type = cubic_segment<D, T>;

    /// out[k] = d^order x / dt^order at t[k]; order in 0..3, t and out of
    /// the same, nonzero size (the curve checks both). Throws out_of_domain
    /// naming the first t outside the domain.
    static void evaluate(const curve& c, std::span<const T> t, std::span<point> out, int order) {
        // Try the sorted walk: it checks order as it goes, without a branch
        // per point, and sorted input is in the domain iff its two ends are.
        if (t.front() >= c.grid_.front() && t.back() <= c.grid_.back() && evaluate_sorted(c, t, out, order)) return;
        // Unsorted: one located point at a time, with the order chosen once
        // for the whole batch (not per point as in evaluate_unchecked), and
        // the domain check in the same pass (a branch that is never taken on
        // good input; on bad input check_t throws naming the first bad index,
        // as a separate checking pass would).
        const T lo = c.grid_.front(), hi = c.grid_.back();
        auto check = [&](std::size_t k) {
            if (!(t[k] >= lo && t[k] <= hi)) [[unlikely]] c.check_t(t[k], k);
        };
        switch (order) {
            case 0:
#if CRSPLINE_X86_DISPATCH
                if constexpr (D == 3 && std::is_same_v<T, double>)
                    if (detail::avx2_enabled()) {
                        positions3_avx2(c, t.data(), out.data(), t.size());
                        break;
                    }
#endif
                for (std::size_t k = 0; k < t.size(); ++k) check(k), out[k] = c.position_unchecked(t[k]);
                break;
            case 1:
                for (std::size_t k = 0; k < t.size(); ++k) {
                    check(k);
                    const segment_type s = c.make_segment(c.locate(t[k]));
                    out[k] = s.dt(s.local(t[k]), 1);
                }
                break;
            default:
                for (std::size_t k = 0; k < t.size(); ++k) check(k), out[k] = c.evaluate_unchecked(t[k], order);
        }
    }

    // Sorted batch: walk the segments, evaluating each run of parameters
    // inside one segment with that segment's coefficients held in
    // registers. No per-point search or branch. Returns false (and
    // the caller starts over) as soon as t turns out not to be sorted or
    // holds NaN: random input costs one short run here, not a whole pass.
    static bool evaluate_sorted(const curve& c, std::span<const T> t, std::span<point> out, int order) {
        const std::size_t n = t.size(), nseg = c.segment_count();
        // Large outputs bypass the caches (see detail::streaming_threshold).
        const bool stream = n * sizeof(point) >= detail::streaming_threshold;
        std::size_t seg = c.locate(t[0]);
#if CRSPLINE_X86_DISPATCH
        // 3-D floats and doubles on a CPU with AVX2: the segments are walked
        // inside the vector loop (no runs): 16 float or 8 double lanes with
        // AVX-512F, else 8 or 4 (detail::sorted_walk3_512, sorted_walk3_256,
        // templates over the scalar; issue 30).
        if constexpr (D == 3 && (std::is_same_v<T, float> || std::is_same_v<T, double>))
            if (order <= 1 && detail::avx2_enabled()) {
                T* o = reinterpret_cast<T*>(out.data());
                const bool wide = detail::avx512_enabled();
                const bool sorted =
                    order == 0
                        ? (wide ? detail::sorted_walk3_512<0>(walk_segments<0>{c}, seg, t.data(), o, n, stream)
                                : detail::sorted_walk3_256<0>(walk_segments<0>{c}, seg, t.data(), o, n, stream))
                        : (wide ? detail::sorted_walk3_512<1>(walk_segments<1>{c}, seg, t.data(), o, n, stream)
                                : detail::sorted_walk3_256<1>(walk_segments<1>{c}, seg, t.data(), o, n, stream));
                if (stream) detail::store_fence();
                if (!sorted) return false;
                if (order == 0) exact_last_points(c, t, out);
                return true;
            }
#endif
        std::size_t k = 0;
        bool unsorted = false;
        T previous = t[0];
        while (k < n && !unsorted) {
            seg = next_segment(c, seg, t[k]);
            // The kernel evaluates t[k] itself, then the points after it
            // while they are below the segment's end knot: every point is
            // evaluated and compared with the one before it, so unsorted
            // input is always detected. (The end is found by the kernel as
            // it goes: a binary search for it probed t far ahead of the
            // kernel, with cache misses.) Runs are capped at run_cap points:
            // unsorted input within one segment would otherwise be evaluated
            // in full before its sortedness flag is read.
            const std::size_t cap = std::min(n, k + run_cap);
            const T t_end = seg + 1 < nseg ? c.grid_[seg + 1] : std::numeric_limits<T>::infinity();
            k += run(c.make_segment(seg), t.data() + k, out.data() + k, cap - k, order, previous, stream, t_end,
                     unsorted);
        }
        if (stream) detail::store_fence();
        if (unsorted) return false;
        if (order == 0) exact_last_points(c, t, out);
        return true;
    }

    // As in evaluate_unchecked: the last knot gives the last point exactly.
    static void exact_last_points(const curve& c, std::span<const T> t, std::span<point> out) noexcept {
        for (std::size_t q = t.size(); q-- > 0 && t[q] == c.grid_.back();)
            out[q] = c.points_[c.closed_ ? 0 : c.points_.size() - 1];
    }

    // The curve's segments as detail::sorted_walk3_512 and _256 take them:
    // next is the sorted walk's rule (next_segment), load the run kernels'
    // coefficients.
    template <int Order>
    struct walk_segments {
        const curve& c;
        std::size_t next(std::size_t seg, T x) const noexcept { return batch_kernels::next_segment(c, seg, x); }
        void load(std::size_t seg, T* o, T* a, T* b, T* cc, T& t0, T& ih, T& t_end) const noexcept {
            batch_kernels::load_segment<Order>(c, seg, o, a, b, cc, t0, ih, t_end);
        }
    };
    static std::size_t next_segment(const curve& c, std::size_t seg, T x) noexcept {
        while (seg + 1 < c.segment_count() && x >= c.grid_[seg + 1]) ++seg;
        return seg;
    }
    template <int Order>
    static void load_segment(const curve& c, std::size_t seg, T* o, T* a, T* b, T* cc, T& t0, T& ih,
                             T& t_end) noexcept {
        const segment_type s = c.make_segment(seg);
        run_coefficients<Order>(s, o, a, b, cc);
        t0 = s.t0, ih = s.inv_h;
        t_end = seg + 1 < c.segment_count() ? c.grid_[seg + 1] : std::numeric_limits<T>::infinity();
    }

    static constexpr std::size_t run_cap = 4096;

    // The per-run kernel for position (Order 0) and velocity (Order 1). The
    // dimension loop is unrolled at compile time (index_sequence) so the
    // coefficients stay in registers:
    //   position  x = o + u (a + u (b + u c))            (Horner, as segment::at)
    //   velocity  x = a' + u (b' + u c')  with a' = c1/h, b' = 2 c2/h, c' = 3 c3/h
    // Each also folds "is t still sorted (and not NaN)?" into the loop:
    // !(previous <= t) costs a compare and an or, no branch.
    //
    // With GCC/Clang vector extensions (x86-64 SSE2, ARM NEON) W = 16 bytes /
    // sizeof(T) points go through each step (2 doubles, 4 floats): one packed
    // subtract and multiply for u, then per coordinate the Horner steps on W
    // lanes at once, then the W points are laid out as W * D consecutive
    // scalars (D 16-byte vectors; for D = 3 double GCC 12 -O2 makes that two
    // unpcklpd/unpckhpd-style shuffles and three 16-byte stores). That halves
    // the arithmetic instructions per point of the scalar loop, which was
    // compute bound (about 1.8 ns per 3-D point against 1.0 ns for a plain
    // store loop). Same operations in the same order as the scalar loop: the
    // results are bit for bit those of the scalar code. Streaming (large
    // outputs) uses non-temporal stores when the output is 16-byte aligned.
    // The kernels' coefficients. Position: o, a, b, c = origin, c1, c2, c3.
    // Velocity: 1/h folded in (o unused).
    template <int Order>
    static void run_coefficients(const segment_type& s, T* o, T* a, T* b, T* c) noexcept {
        const T ih = s.inv_h;
        for (std::size_t d = 0; d < D; ++d) {
            o[d] = s.origin[d];
            a[d] = Order == 0 ? s.c1[d] : s.c1[d] * ih;
            b[d] = Order == 0 ? s.c2[d] : T(2) * ih * s.c2[d];
            c[d] = Order == 0 ? s.c3[d] : T(3) * ih * s.c3[d];
        }
    }

    template <int Order, std::size_t... d>
    static std::size_t run_kernel(const segment_type& s, const T* t, point* out, std::size_t n, T& previous,
                                  bool stream, T t_end, bool& unsorted, std::index_sequence<d...>) noexcept {
        const T t0 = s.t0, ih = s.inv_h;
        T o[D], a[D], b[D], c[D];
        run_coefficients<Order>(s, o, a, b, c);
        auto horner = [&](auto u, std::size_t i) {
            if constexpr (Order == 0) return o[i] + u * (a[i] + u * (b[i] + u * c[i]));
            else return a[i] + u * (b[i] + u * c[i]);
        };
        unsigned bad = 0;
        T prev = previous;
        std::size_t k = 0;
        auto scalar_step = [&] {
            const T x = t[k];
            bad |= unsigned(!(prev <= x));
            prev = x;
            const T u = (x - t0) * ih;
            ((out[k][d] = horner(u, d)), ...);
            ++k;
        };
#if CRSPLINE_VECTOR_KERNELS
        if constexpr (detail::has_lanes16<T>) {
            using V = detail::lanes16<T>;
            constexpr std::size_t W = 16 / sizeof(T);
            // Head: at least one point (so t[k - 1] exists below), then points
            // until the output is 16-byte aligned (at most W more).
            if (n > 0) scalar_step();
            for (std::size_t q = 0; q < W && k < n && t[k] < t_end && reinterpret_cast<std::uintptr_t>(out + k) % 16 != 0; ++q)
                scalar_step();
            const bool aligned = reinterpret_cast<std::uintptr_t>(out + k) % 16 == 0;
            // Integer lanes, all ones while sorted: a compare and an and per
            // step (NaN compares false, so it clears the lane too).
            decltype(V{} < V{}) good = ~decltype(V{} < V{}){};
            // The loop, instantiated once per kind of store so that the choice
            // is not made per step (a test and a branch less, and the buffer
            // below stays in registers on the streaming path).
            auto steps = [&](auto store) {
                for (; k + W <= n; k += W) {
                    V x, p;
                    std::memcpy(&x, t + k, sizeof x);
                    // Stop before the first step with a point at or past the
                    // end knot (or NaN): the scalar steps finish the run.
                    const auto inside = x < t_end;
                    bool all_inside = true;
                    for (std::size_t j = 0; j < W; ++j) all_inside &= inside[j] != 0;
                    if (!all_inside) break;
                    std::memcpy(&p, t + k - 1, sizeof p);  // the previous values, one lane behind
                    good &= (p <= x);
                    const V u = (x - t0) * ih;
                    const V r[D] = {horner(u, d)...};
                    // W points, coordinates interleaved (AoS), as D 16-byte vectors.
                    alignas(16) T buf[W * D];
                    for (std::size_t j = 0; j < W; ++j) ((buf[j * D + d] = r[d][j]), ...);
                    store(reinterpret_cast<T*>(out + k), buf);
                }
            };
            if (stream && aligned) steps([](T* dst, const T* buf) { detail::stream_store<D>(dst, buf); });
            else steps([](T* dst, const T* buf) { std::memcpy(static_cast<void*>(dst), buf, W * D * sizeof(T)); });
            if (k > 0) prev = t[k - 1];
            for (std::size_t j = 0; j < W; ++j) bad |= unsigned(good[j] == 0);
        }
#endif
        (void)stream;
        if (k == 0 && n > 0) scalar_step();  // (without vector kernels: the run's first point)
        while (k < n && t[k] < t_end) scalar_step();
        previous = prev;
        unsorted = unsorted || bad != 0;
        return k;
    }
#if CRSPLINE_X86_DISPATCH
    // Unsorted positions: position_unchecked with the domain check of the
    // batch, in blocks of 32 points. First every point of the block is
    // located (a chain of dependent loads and arithmetic per point, but
    // independent between points, so they overlap), then each is evaluated
    // on its segment's Hermite form in 4-lane registers. One loop doing both
    // kept only 2-3 points in flight; the split doubles that.
    // (Non-temporal stores through a block buffer measured slower here: the
    // kernel is bound by instructions, not by the output's memory traffic.)
    static void positions3_avx2(const curve& c, const T* t, point* out, std::size_t n) {
        if (c.closed_) positions3_avx2<true>(c, t, out, n);
        else positions3_avx2<false>(c, t, out, n);
    }
    // (Closed: whether the segment after the last point wraps to the first.)
    template <bool Closed>
    CRSPLINE_TARGET_AVX2 static void positions3_avx2(const curve& c, const T* t, point* out, std::size_t n) {
        const T lo = c.grid_.front(), hi = c.grid_.back();
        const point last = c.points_[c.closed_ ? 0 : c.points_.size() - 1];
        const std::size_t np = c.points_.size();
        const point* P = c.points_.data();
        const point* V = c.tangent_.data();
        const point* W = c.in_.empty() ? c.tangent_.data() : c.in_.data();
        const T* g = c.grid_.data();
        const T* ih = c.inv_h_.data();
        const T* hs = c.h_.data();
        const std::size_t nseg = c.segment_count();
        const std::uint32_t* first = c.index_.first();
        const T scale = c.index_.scale(), bmax = c.index_.bucket_max();
        constexpr std::size_t block = 32;
        std::size_t idx[block];
        T u[block];
        for (std::size_t k0 = 0; k0 < n; k0 += block) {
            const std::size_t m = std::min(block, n - k0);
            std::uint32_t at_end = 0;  // bit q: t is the last knot
            for (std::size_t q = 0; q < m; ++q) {
                const T x = t[k0 + q];
                if (!(x >= lo && x < hi)) [[unlikely]] {
                    if (x != hi) c.check_t(x, k0 + q);  // throws
                    at_end |= std::uint32_t(1) << q;
                }
                const std::size_t b = knot_index<T>::bucket_of(x, g[0], scale, bmax);
                // locate_in's common case with one 4-lane compare of the
                // knots lo .. lo + 3 (in the array when lo + 3 <= nseg): they
                // increase, so the lanes with knot <= t are a prefix, and
                // its length less one is the count locate_in adds up.
                const std::size_t c0 = first[b], c1 = first[b + 1];
                std::size_t i;
                if (c1 - c0 <= 3 && c0 + 3 <= nseg) [[likely]] {
                    static constexpr unsigned char after_first[16] = {0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 3};
                    const int mask = _mm256_movemask_pd(_mm256_cmp_pd(_mm256_loadu_pd(g + c0), _mm256_set1_pd(x), _CMP_LE_OQ));
                    i = std::min(c0 + after_first[mask], nseg - 1);
                } else {
                    i = knot_index<T>::locate_in(x, g, nseg, first, scale, bmax);
                }
                idx[q] = i;
                u[q] = (x - g[i]) * ih[i];
            }
            // Each point is stored with one 4-lane store whose junk lane 3
            // lands on the next point's x, which is written next; the
            // batch's last point is stored in 3 lanes.
            const std::size_t wide = k0 + m < n ? m : m - 1;
            for (std::size_t q = 0; q < m; ++q) {
                const std::size_t i = idx[q], j = Closed && i + 1 == np ? 0 : i + 1;
                // Open: i + 1 < np, so P[i] and V[i] are not the last entries.
                const __m256d r = detail::hermite_point3<!Closed>(P[i].v.data(), P[j].v.data(), V[i].v.data(),
                                                                  W[j].v.data(), hs[i], u[q]);
                if (q < wide) [[likely]] _mm256_storeu_pd(out[k0 + q].v.data(), r);
                else detail::store3(out[k0 + q].v.data(), r);
            }
            for (; at_end != 0; at_end &= at_end - 1)  // the last knot gives the last point exactly
                out[k0 + std::size_t(__builtin_ctz(at_end))] = last;
        }
    }
#endif

    // One run on segment s: evaluates t[0], then the points after it while
    // they are below t_end (at most n); returns how many. Sets unsorted
    // when a point is not >= the one before it (or is NaN).
    static std::size_t run(const segment_type& s, const T* t, point* out, std::size_t n, int order, T& previous,
                           bool stream, T t_end, bool& unsorted) noexcept {
        switch (order) {
            case 0: return run_kernel<0>(s, t, out, n, previous, stream, t_end, unsorted, std::make_index_sequence<D>{});
            case 1: return run_kernel<1>(s, t, out, n, previous, stream, t_end, unsorted, std::make_index_sequence<D>{});
            default: {
                unsigned bad = 0;
                std::size_t k = 0;
                do {
                    bad |= unsigned(!(previous <= t[k]));
                    previous = t[k];
                    out[k] = s.dt(s.local(t[k]), order);
                    ++k;
                } while (k < n && t[k] < t_end);
                unsorted = unsorted || bad != 0;
                return k;
            }
        }
    }
};

}  // namespace detail
}  // namespace crspline
