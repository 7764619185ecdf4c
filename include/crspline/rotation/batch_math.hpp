// crspline: the arithmetic of the rotation curves' batch kernels
// (batch.hpp) on lanes (batch_lanes.hpp): polynomials by Estrin's scheme,
// sine and cosine (poly_sincos, within 1 ulp), the angle of a point in the
// upper half plane, the series of so3.hpp's Jacobian coefficients, and
// 3-vectors and quaternions of lanes.
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

#include "batch_lanes.hpp"

namespace crspline::rotation::detail_batch {

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

}  // namespace crspline::rotation::detail_batch
