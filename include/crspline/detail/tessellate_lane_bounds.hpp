// crspline internal: the per-vertex arithmetic of tessellate()'s cut in
// vector lanes (tessellate_lanes.hpp): the segments' state per lane, the
// norms (the plain formula where it is proved safe, as norm() does), and
// the flatness bound and the piece widths, each the scalar cut's
// operations in the same order.
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

namespace crspline::detail {

/// Lanes of doubles for the cut: V, a GCC/Clang vector of doubles (its
/// arithmetic written with the usual operators), M its mask, and S the
/// policy of the instruction set (cut_avx2, cut_avx512 in tessellate_lanes.hpp): square
/// roots, max and min, comparisons (M: a vector of all-ones or zero lanes
/// with AVX2, a k-register's bits with AVX-512, where GCC 12 would lower
/// the vector extension's comparisons lane by lane), blends and mask
/// tests. Masks combine with & and |.
template <class V>
inline constexpr int vx_width = int(sizeof(V) / sizeof(double));
/// m = m and not off.
template <class M>
[[gnu::always_inline]] inline void vx_clear(M& m, const std::type_identity_t<M>& off) noexcept {
    m = M(m & ~off);
}

/// The segments' cut in lanes of V: segment i's coefficients (and 2 c2,
/// which the bounds take: doubling is exact), knots and uniform piece count
/// per lane, and the state of its cut.
template <std::size_t D, class V>
struct cut_lanes {
    V c1[D], c2[D], c3[D], c2x2[D], t0, inv_h, h, t_end, n_uniform, a;
};

/// detail::plain_norm_range's limits for double: sqrt(min) / eps =
/// 2^-511 / 2^-52 exactly, and sqrt(max / D) (folded by the compiler).
inline constexpr double plain_norm_lo = 0x1p-459;
static_assert(plain_norm_lo == 0x1p-511 / std::numeric_limits<double>::epsilon() &&
              0x1p-511 * 0x1p-511 == std::numeric_limits<double>::min());
template <std::size_t D>
inline double plain_norm_hi() noexcept {
    return std::sqrt(std::numeric_limits<double>::max() / double(D));
}

/// The bounds on a sum of squares s of D numbers (computed as the plain
/// formula does) that prove plain_norm_range for their largest magnitude m:
/// s > D lo^2 proves m > lo, s < fl(hi^2) proves m < hi. Each term fl(x^2)
/// is at most fl(lo^2) = lo^2 where every |x| <= lo, and their rounded sum
/// at most D lo^2 (exact in double); and s >= fl(m^2) >= fl(hi^2) where
/// m >= hi (rounding is monotone). A NaN fails both. Where they fail (tiny,
/// huge, zero or NaN vectors: rare), the callers test m itself, as norm()
/// does (plain_by_magnitude); so the same lanes take the plain formula, at
/// the cost of two compares, not D magnitudes and maxima.
template <std::size_t D>
inline double squares_lo() noexcept {
    return double(D) * (plain_norm_lo * plain_norm_lo);
}
template <std::size_t D>
inline double squares_hi() noexcept {
    return plain_norm_hi<D>() * plain_norm_hi<D>();
}

/// m = the largest magnitude of x, lane by lane, as max_abs() finds it.
template <std::size_t D, class V, class S>
[[gnu::always_inline]] inline void lanes_max_abs(V& m, const V (&x)[D], const V& zero) noexcept {
    m = zero;
    for (std::size_t k = 0; k < D; ++k) {
        V ax = zero;
        S::add_abs(ax, x[k]);
        S::max(m, m, ax);
    }
}

/// Where plain_norm_range holds for the magnitude m, lane by lane (the test
/// norm() makes).
template <std::size_t D, class V, class M, class S>
[[gnu::always_inline]] inline void plain_by_magnitude(M& r, const V& m, const V& zero) noexcept {
    S::gt(r, m, zero + plain_norm_lo);
    S::and_lt(r, m, zero + plain_norm_hi<D>());
}

/// r = norm(x) lane by lane: the plain formula where plain_norm_range
/// holds, as norm() takes it; the lanes where it does not are done one by
/// one by norm() itself (a zero, huge or tiny vector: rare).
template <std::size_t D, class V, class M, class S>
[[gnu::always_inline]] inline void lanes_norm(V& r, const V (&x)[D]) noexcept {
#if defined(__clang__)
#pragma clang fp contract(off)  // the same roundings as the scalar cut (cut_avx512)
#endif
    const V zero = x[0] - x[0];
    if constexpr (D == 1) {
        r = zero;
        S::add_abs(r, x[0]);  // std::abs: 0 + |x|, the sign bit cleared
    } else {
        V s = zero;
        for (std::size_t k = 0; k < D; ++k) s += x[k] * x[k];
        M plain;  // proved by the sum of squares, else tested on the magnitude
        S::gt(plain, s, zero + squares_lo<D>());
        S::and_lt(plain, s, zero + squares_hi<D>());
        S::apply(s);
        if (S::any_not(plain)) [[unlikely]] {
            V m;
            lanes_max_abs<D, V, S>(m, x, zero);
            plain_by_magnitude<D, V, M, S>(plain, m, zero);
            constexpr int W = vx_width<V>;
            for (int l = 0; l < W; ++l) {
                if ((S::bits(plain) >> l) & 1u) continue;
                vec<D, double> v;
                for (std::size_t k = 0; k < D; ++k) v[k] = x[k][l];
                s[l] = norm(v);
            }
        }
        r = s;
    }
}

/// r = flatness_bound (tessellate.hpp) lane by lane, the same operations:
/// the piece [u0, u1] of each lane's segment, k0 = |C''(u0)|, d0 = C'(u0)
/// as flatness_bound computes it (c1 + u0 (2 c2 + 3 u0 c3): the same for
/// every piece from u0).
template <std::size_t D, class V, class M, class S>
[[gnu::always_inline]] inline void lanes_flatness(V& r, const cut_lanes<D, V>& c, const V& u0, const V& u1,
                                                  const V& k0, const V (&d0)[D]) noexcept {
#if defined(__clang__)
#pragma clang fp contract(off)  // the same roundings as the scalar cut (cut_avx512)
#endif
    const V w = u1 - u0, zero = w - w, one = zero + 1.0;
    V d2[D], q1[D], q2[D], chord[D];
    const V six_u1 = 6.0 * u1, three_u1 = 3.0 * u1;
    for (std::size_t k = 0; k < D; ++k) d2[k] = c.c2x2[k] + six_u1 * c.c3[k];
    V curvature;
    lanes_norm<D, V, M, S>(curvature, d2);
    S::max(curvature, k0, curvature);
    const V by_second_difference = w * w / 8.0 * curvature;
    const V sum = u0 + u1, sq = u0 * u0 + u0 * u1 + u1 * u1, w3 = w / 3.0;
    V len2 = zero;
    for (std::size_t k = 0; k < D; ++k) {
        chord[k] = w * (c.c1[k] + sum * c.c2[k] + sq * c.c3[k]);
        q1[k] = w3 * d0[k];
        q2[k] = chord[k] - w3 * (c.c1[k] + u1 * (c.c2x2[k] + three_u1 * c.c3[k]));
        len2 += chord[k] * chord[k];
    }
    M has_len;
    S::gt(has_len, len2, zero);
    V e1[D], e2[D];
    // e = q - f chord, f = std::clamp(q.chord / len2, 0, 1) where len2 > 0,
    // else 0.
    for (int j = 0; j < 2; ++j) {
        const V(&q)[D] = j == 0 ? q1 : q2;
        V(&e)[D] = j == 0 ? e1 : e2;
        V qc = zero;
        for (std::size_t k = 0; k < D; ++k) qc += q[k] * chord[k];
        const V f = qc / len2;
        // std::clamp(f, 0, 1) = std::max(std::min(f, 1), 0) (where f < 0,
        // min(f, 1) is f), NaN included.
        V g, ff = zero;
        S::min(g, f, one);
        S::max(g, g, zero);
        S::set(ff, has_len, g);
        for (std::size_t k = 0; k < D; ++k) e[k] = q[k] - ff * chord[k];
    }
    V by_hull, n1, n2;
    if constexpr (D == 1) {
        lanes_norm<D, V, M, S>(n1, e1);
        lanes_norm<D, V, M, S>(n2, e2);
        S::max(by_hull, n1, n2);
    } else {
        V s1 = zero, s2 = zero;
        for (std::size_t k = 0; k < D; ++k) s1 += e1[k] * e1[k], s2 += e2[k] * e2[k];
        // flatness_bound's test, plain_norm_range of m = max(max_abs(e1),
        // max_abs(e2)), proved from the sums of squares where it can be
        // (squares_lo, squares_hi: both below fl(hi^2) bound both magnitudes
        // above; either above D lo^2 bounds m below), else made as it makes it.
        const V s_lo = zero + squares_lo<D>(), s_hi = zero + squares_hi<D>();
        M plain, lower2;
        S::gt(plain, s1, s_lo);
        S::gt(lower2, s2, s_lo);
        plain = plain | lower2;
        S::and_lt(plain, s1, s_hi);
        S::and_lt(plain, s2, s_hi);
        S::max(by_hull, s1, s2);
        S::apply(by_hull);
        // Where plain fails in a lane: the larger norm, as norm() gives it.
        if (S::any_not(plain)) [[unlikely]] {
            V m1, m2;
            lanes_max_abs<D, V, S>(m1, e1, zero);
            lanes_max_abs<D, V, S>(m2, e2, zero);
            S::max(m1, m1, m2);
            plain_by_magnitude<D, V, M, S>(plain, m1, zero);
            lanes_norm<D, V, M, S>(n1, e1);
            lanes_norm<D, V, M, S>(n2, e2);
            S::max(n1, n1, n2);
            S::set_not(by_hull, plain, n1);
        }
    }
    S::min(r, by_second_difference, by_hull);
}

}  // namespace crspline::detail
