// crspline: where the rotation curves' batch kernels (batch.hpp) read and
// write: the output rows (quaternions in either order, rates) written a
// lane at a time, and the segment of each sample (locator).
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

#include "../detail/knot_index.hpp"
#include "batch_math.hpp"

namespace crspline::rotation::detail_batch {

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

}  // namespace crspline::rotation::detail_batch
