// crspline: batch evaluation kernels of the rotation curves: the C2 spline
// (c2.hpp), piecewise slerp (catmull_rom.hpp) and, through them, the pose
// curve (pose.hpp).
//
// The classes' batch calls check their arguments and hand the samples here.
// Each segment's data is packed once, at construction, so that a sample does
// the least: for the C2 spline the rotation-vector cubic and the key (one
// exp of a small vector, one quaternion product), for slerp the step's axis
// and half angle (one sine and cosine, one product). Samples go two at a
// time through 16-byte vectors (GCC/Clang vector extensions: two doubles in
// one SSE2 register on the x86-64 baseline, NEON on AArch64; elsewhere one
// at a time), with sine and cosine from a polynomial (poly_sincos) instead
// of libm, which no compiler vectorises.
//
// Every path computes what the scalar evaluate_on() computes, in the same
// order of operations, except sine and cosine (poly_sincos: within 1 ulp of
// the correctly rounded value, std:: within 1 ulp too) and the series for
// the Jacobian coefficients (the first 10 or 16 terms, by Estrin's scheme): the
// results agree with the scalar ones to a few ulps of their size
// (tests/rotation/test_rotation_batch.cpp).
#pragma once
// The parts (one job each): batch_lanes.hpp (the vectors and the run-time
// choice of instruction set), batch_math.hpp (sine, cosine, angles, series,
// quaternions of lanes), batch_io.hpp (rows written, samples located); here
// the kernels of each curve and the driver.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
#include <utility>

#include "batch_io.hpp"
#include "batch_lanes.hpp"
#include "batch_math.hpp"
#include "quaternion.hpp"
#include "so3.hpp"

namespace crspline::rotation::detail_batch {

// ----- the C2 spline -------------------------------------------------------------------

/// One segment of c2_rotation_spline, packed: R(t) = q Exp(theta(t - t0)),
/// theta(tau) = ((c3 tau + c2) tau + c1) tau.
template <class T>
struct c2_packed {
    T t0;
    T c3[3], c2[3], c1[3];
    T q[4];
    T pad[2];
};

/// The C2 spline's rotation (and with order >= 1 its angular velocity,
/// order 2 its acceleration, in frame f) on lanes: tau = t - t0 per lane,
/// seg(l) the packed segment of lane l. Each step is
/// c2_rotation_spline::evaluate_on's, on lanes. With rotation false and the
/// body frame the rotation is not formed (the rates do not need it).
template <class T, class V, class Seg>
[[gnu::always_inline]] inline void c2_lanes(Seg seg, const V& tau, int order, frame f, ql<V>& q, v3l<V>& w, v3l<V>& acc,
                                            bool rotation = true) noexcept {
    // (Gathered value by value: rows loaded whole and transposed measured
    // slower here, on both paths.)
    auto g = [&](auto member) CRSPLINE_ROTATION_BLOCK { return make_lanes<V>([&](int l) { return member(seg(l)); }); };
    v3l<V> c3, c2, c1;
    c3.x = g([](const c2_packed<T>& s) { return s.c3[0]; }), c3.y = g([](const c2_packed<T>& s) { return s.c3[1]; }),
    c3.z = g([](const c2_packed<T>& s) { return s.c3[2]; });
    c2.x = g([](const c2_packed<T>& s) { return s.c2[0]; }), c2.y = g([](const c2_packed<T>& s) { return s.c2[1]; }),
    c2.z = g([](const c2_packed<T>& s) { return s.c2[2]; });
    c1.x = g([](const c2_packed<T>& s) { return s.c1[0]; }), c1.y = g([](const c2_packed<T>& s) { return s.c1[1]; }),
    c1.z = g([](const c2_packed<T>& s) { return s.c1[2]; });
    const v3l<V> th{((c3.x * tau + c2.x) * tau + c1.x) * tau, ((c3.y * tau + c2.y) * tau + c1.y) * tau,
                    ((c3.z * tau + c2.z) * tau + c1.z) * tau};
    const bool form_q = rotation || f == frame::world;
    // The half angle a, its sine and cosine, and sin(a)/a: for the rotation,
    // and for the rates' closed forms where a lane turns 2 rad or more.
    // (h = th/2 and |h|^2 only there: the rates alone need z = |th|^2.)
    v3l<V> h{};
    V a{}, sinc{};
    sin_cos<V> sc{};
    auto trig = [&]() CRSPLINE_ROTATION_BLOCK {
        h = {th.x * T(0.5), th.y * T(0.5), th.z * T(0.5)};
        a = vsqrt(dot(h, h));
        sc = sincos(a);
        sinc = sel(a > T(0), sc.s / a, V{} + T(1));  // sin(a)/a
    };
    if (form_q || order == 0) {
        trig();
        // The key is gathered here only: the body-frame rates alone never
        // read it.
        const ql<V> key{g([](const c2_packed<T>& s) { return s.q[0]; }), g([](const c2_packed<T>& s) { return s.q[1]; }),
                        g([](const c2_packed<T>& s) { return s.q[2]; }), g([](const c2_packed<T>& s) { return s.q[3]; })};
        q = mul(key, ql<V>{sc.c, h.x * sinc, h.y * sinc, h.z * sinc});
    }
    if (order == 0) return;
    // Body frame: omega = J_r(theta) theta', alpha = J_r(theta) theta'' + N_r(theta, theta').
    const v3l<V> d1{(T(3) * c3.x * tau + T(2) * c2.x) * tau + c1.x, (T(3) * c3.y * tau + T(2) * c2.y) * tau + c1.y,
                    (T(3) * c3.z * tau + T(2) * c2.z) * tau + c1.z};
    // z = theta^2 (|th|^2: the same bits as 4 |th/2|^2, a power of two
    // apart). Three tiers, chosen lane by lane (so every path gives a lane
    // the same bits whatever its neighbours): theta < sqrt(2) (z < 2), k1
    // and k2 from the first 10 terms of their series; sqrt(2) <= theta < 2,
    // the first 16; theta >= 2, the closed forms. The rates alone need no
    // square root, sine or cosine below theta = 2, and the common small
    // turns the shorter series only (a lane group pays for a longer tier
    // only when one of its lanes needs it; sel keeps each lane's own bits).
    // The 10 terms' truncation: both series alternate with decreasing
    // terms for z < 2, so the error is below the first term left out,
    // z^10/22! < 2^10/22! = 9.1e-19 for k1 (>= (1 - cos sqrt 2)/2 = 0.42:
    // 2.2e-18 relative, 1% of an ulp) and 2^10/23! = 4.0e-20 for k2 (>=
    // 0.15: 2.6e-19 relative); tested against the 16 terms
    // (tests/rotation/test_rotation_batch.cpp, JacobianSeriesTiers).
    const V z = dot(th, th);
    const auto small = z < T(2), mid = z < T(4);
    V k1 = estrin<T, jacobian_short_terms>(series.k1, z), k2 = estrin<T, jacobian_short_terms>(series.k2, z);
    bool all_mid = true;
    V theta{}, sin_t{}, cos_t{}, big{}, zb{};
    if (!all_of(small)) {
        k1 = sel(small, k1, horner16<T>(series.k1, z)), k2 = sel(small, k2, horner16<T>(series.k2, z));
        all_mid = all_of(mid);
    }
    if (!all_mid) {
        if (!(form_q || order == 0)) trig();
        theta = T(2) * a;
        // sin theta = 2 s c, cos theta = c^2 - s^2.
        sin_t = T(2) * sc.s * sc.c, cos_t = sc.c * sc.c - sc.s * sc.s;
        big = sel(mid, V{} + T(1), theta);  // keeps the unused closed forms finite at theta = 0
        zb = big * big;
        k1 = sel(mid, k1, sinc * sinc / T(2));
        k2 = sel(mid, k2, (big - sin_t) / (zb * big));
    }
    auto jr = [&](const v3l<V>& v) CRSPLINE_ROTATION_BLOCK {
        const v3l<V> pv = cross(th, v), ppv = cross(th, pv);
        return v3l<V>{v.x - k1 * pv.x + k2 * ppv.x, v.y - k1 * pv.y + k2 * ppv.y, v.z - k1 * pv.z + k2 * ppv.z};
    };
    w = jr(d1);
    if (order >= 2) {
        const v3l<V> d2{T(6) * c3.x * tau + T(2) * c2.x, T(6) * c3.y * tau + T(2) * c2.y, T(6) * c3.z * tau + T(2) * c2.z};
        V K1 = horner16<T>(series.K1, z), K2 = horner16<T>(series.K2, z);
        if (!all_mid) {
            K1 = sel(mid, K1, (T(2) * (T(1) - cos_t) - big * sin_t) / (zb * zb));
            K2 = sel(mid, K2, (T(3) * sin_t - T(2) * big - big * cos_t) / (zb * zb * big));
        }
        const V dp = dot(th, d1);
        const v3l<V> cp = cross(th, d1), ccp = cross(th, cp), dccp = cross(d1, cp);
        const v3l<V> j2 = jr(d2);
        acc = {j2.x + (dp * (K1 * cp.x + K2 * ccp.x) + k2 * dccp.x), j2.y + (dp * (K1 * cp.y + K2 * ccp.y) + k2 * dccp.y),
               j2.z + (dp * (K1 * cp.z + K2 * ccp.z) + k2 * dccp.z)};
    }
    if (f == frame::world) {
        w = rotate(q, w);
        if (order >= 2) acc = rotate(q, acc);
    }
}

/// Samples k .. k + width - 1 of the C2 spline (segments seg[0..width-1]),
/// the first `valid` of them written.
template <class T, class V = typename pack<T>::V>
[[gnu::always_inline]] inline void c2_block(const c2_packed<T>* segs, const std::size_t* seg, const T* t, std::size_t k,
                                            int valid, int order, frame f, const rows<T>& out) noexcept {
    const V tau = make_lanes<V>([&](int l) { return t[l] - segs[seg[l]].t0; });
    ql<V> q;
    v3l<V> w, acc;
    const bool rotation = out.q != nullptr || out.quats != nullptr;
    c2_lanes<T>([&](int l) -> const c2_packed<T>& { return segs[seg[l]]; }, tau, order, f, q, w, acc, rotation);
#if CRSPLINE_ROTATION_AVX2
    // The rates alone (SciPy's spline(t, 1)) from a full block of the AVX2
    // clone: whole rows.
    if constexpr (std::is_same_v<V, vx>)
        if (!rotation && order == 1 && valid == V::width) {
            for (int i = 0; i < V::width / V::half_width; ++i)
                store_rows3(w.x.h[i], w.y.h[i], w.z.h[i], out.omega + 3 * (k + std::size_t(i * V::half_width)));
            return;
        }
#endif
    store<T, V>(out, k, valid, q, order >= 1 ? &w : nullptr, order >= 2 ? &acc : nullptr);
}

/// One segment of a pose curve with a C2 rotation, packed: the position's
/// cubic in local u = (t - t0) inv_h (origin + u (c1 + u (c2 + u c3)), as
/// cubic_segment) and the rotation's segment.
template <class T>
struct pose_packed {
    c2_packed<T> rot;
    T origin[3], c1[3], c2[3], c3[3];
    T inv_h;
};

/// Samples k .. k + width - 1 of a pose curve: position, velocity (dx/dt),
/// rotation and angular velocity, velocities in frame f; the position and
/// velocity by cubic_segment's arithmetic (at(u), dt(u, 1); at t_end the
/// last point exactly, as catmull_rom gives it), the rotation by c2_lanes.
/// out[k + l] for the first `valid` lanes.
template <class T, class V, class Sample>
[[gnu::always_inline]] inline void pose_block(const pose_packed<T>* segs, const std::size_t* seg, const T* t, std::size_t k,
                                              int valid, frame f, T t_end, const T* end_point, Sample* out) noexcept {
    auto g = [&](auto member) CRSPLINE_ROTATION_BLOCK { return make_lanes<V>([&](int l) { return member(segs[seg[l]]); }); };
    const V u = make_lanes<V>([&](int l) { return (t[l] - segs[seg[l]].rot.t0) * segs[seg[l]].inv_h; });
    const V tau = make_lanes<V>([&](int l) { return t[l] - segs[seg[l]].rot.t0; });
    const V inv_h = g([](const pose_packed<T>& s) { return s.inv_h; });
    V pos[3], vel[3];
    for (int d = 0; d < 3; ++d) {
        const V o = g([d](const pose_packed<T>& s) { return s.origin[d]; }), c1 = g([d](const pose_packed<T>& s) { return s.c1[d]; }),
                c2 = g([d](const pose_packed<T>& s) { return s.c2[d]; }), c3 = g([d](const pose_packed<T>& s) { return s.c3[d]; });
        pos[d] = o + u * (c1 + u * (c2 + u * c3));
        vel[d] = (c1 + u * (T(2) * c2 + T(3) * u * c3)) * inv_h;
    }
    ql<V> q;
    v3l<V> w, acc;
    c2_lanes<T>([&](int l) -> const c2_packed<T>& { return segs[seg[l]].rot; }, tau, 1, f, q, w, acc);
    v3l<V> v{vel[0], vel[1], vel[2]};
    if (f == frame::body) v = rotate(ql<V>{q.w, -q.x, -q.y, -q.z}, v);
    for (int l = 0; l < valid; ++l) {
        Sample& s = out[k + std::size_t(l)];
        s.position[0] = lane(pos[0], l), s.position[1] = lane(pos[1], l), s.position[2] = lane(pos[2], l);
        if (t[l] == t_end) s.position[0] = end_point[0], s.position[1] = end_point[1], s.position[2] = end_point[2];  // exactly
        s.orientation = {lane(q.w, l), lane(q.x, l), lane(q.y, l), lane(q.z, l)};
        s.velocity[0] = lane(v.x, l), s.velocity[1] = lane(v.y, l), s.velocity[2] = lane(v.z, l);
        s.omega[0] = lane(w.x, l), s.omega[1] = lane(w.y, l), s.omega[2] = lane(w.z, l);
    }
}


// ----- piecewise slerp --------------------------------------------------------------------

/// One segment of a piecewise slerp, packed: q(t) = exp(u L) a with u = (t -
/// t0) inv_h, L = log(b a*) = half_angle * axis; omega = 2 L inv_h (world).
/// A zero-length segment has inv_h = 0: the curve rests at a.
template <class T>
struct slerp_packed {
    T t0, inv_h, half_angle;
    T axis[3];
    T a[4];
};

template <class T, class V = typename pack<T>::V>
[[gnu::always_inline]] inline void slerp_block(const slerp_packed<T>* segs, const std::size_t* seg, const T* t,
                                               std::size_t k, int valid, int order, frame f, const rows<T>& out) noexcept {
    auto g = [&](auto member) CRSPLINE_ROTATION_BLOCK { return make_lanes<V>([&](int l) { return member(segs[seg[l]]); }); };
    const V u = make_lanes<V>([&](int l) { return (t[l] - segs[seg[l]].t0) * segs[seg[l]].inv_h; });
    const V ang = u * g([](const slerp_packed<T>& s) { return s.half_angle; });
    const v3l<V> n{g([](const slerp_packed<T>& s) { return s.axis[0]; }), g([](const slerp_packed<T>& s) { return s.axis[1]; }),
                   g([](const slerp_packed<T>& s) { return s.axis[2]; })};
    const ql<V> a{g([](const slerp_packed<T>& s) { return s.a[0]; }), g([](const slerp_packed<T>& s) { return s.a[1]; }),
                  g([](const slerp_packed<T>& s) { return s.a[2]; }), g([](const slerp_packed<T>& s) { return s.a[3]; })};
    const sin_cos<V> sc = sincos(ang);
    const ql<V> q = mul(ql<V>{sc.c, n.x * sc.s, n.y * sc.s, n.z * sc.s}, a);
    if (order == 0) return store<T, V>(out, k, valid, q, nullptr, nullptr);
    // omega = 2 L / h, constant on the segment (world frame); alpha = 0.
    const V r = T(2) * g([](const slerp_packed<T>& s) { return s.half_angle * s.inv_h; });
    v3l<V> w{r * n.x, r * n.y, r * n.z};
    const V zero{};
    const v3l<V> acc{zero, zero, zero};
    if (f == frame::body) w = rotate(ql<V>{q.w, -q.x, -q.y, -q.z}, w);
    store<T, V>(out, k, valid, q, &w, order >= 2 ? &acc : nullptr);
}

// ----- the De Casteljau family and Squad ---------------------------------------------------

/// A slerp whose two ends do not depend on the sample, packed: slerp(a, b,
/// s) = exp(s L) a with L = log(b a*) = angle * n (half-angle units, as
/// quaternion.hpp's exp and log), which is cos(s angle) a + sin(s angle) o
/// with o = [0, n] a (a unit quaternion orthogonal to a).
template <class T>
struct fixed_slerp {
    T angle;
    T a[4];
    T o[4];
};

/// One segment of a De Casteljau pyramid of 4 controls (Catmull-Rom,
/// Kochanek-Bartels, De Casteljau) or of Barry-Goldman's, packed: the three
/// slerps of the first level between fixed pairs (f), and the parameter of
/// each of the six slerps, s_j = (t - ta[j]) inv[j] (j < 3: the first level;
/// 3, 4 the second; 5 the last). The De Casteljau curves have one parameter
/// u for all six; Barry-Goldman's run over their own knot intervals. A
/// zero-length segment has every angle and inv 0 and every a its key: the
/// curve rests there, exactly.
template <class T>
struct pyramid_packed {
    T ta[6], inv[6];
    fixed_slerp<T> f[3];
};

/// One segment of Squad, packed: slerp(slerp(q_i, q_(i+1), u), slerp(s_i+,
/// s_(i+1)-, u), 2u(1-u)), u = (t - t0) inv_h; f the two inner slerps.
template <class T>
struct squad_packed {
    T t0, inv_h;
    fixed_slerp<T> f[2];
};

/// exp(s L) a = cos(s angle) a + sin(s angle) o on lanes, from each lane's
/// fixed_slerp.
template <class T, class V, class Get>
[[gnu::always_inline]] inline ql<V> fixed_lanes(Get get, const V& s) noexcept {
    auto g = [&](auto member) CRSPLINE_ROTATION_BLOCK { return make_lanes<V>([&](int l) { return member(get(l)); }); };
    const sin_cos<V> sc = sincos(s * g([](const fixed_slerp<T>& f) { return f.angle; }));
    const ql<V> a = gather_quat<V>([&](int l) CRSPLINE_ROTATION_BLOCK { return get(l).a; });
    const ql<V> o = gather_quat<V>([&](int l) CRSPLINE_ROTATION_BLOCK { return get(l).o; });
    return {a.w * sc.c + o.w * sc.s, a.x * sc.c + o.x * sc.s, a.y * sc.c + o.y * sc.s, a.z * sc.c + o.z * sc.s};
}

/// slerp(a, b, s) = exp(s log(b a*)) a on lanes whose ends depend on the
/// sample. b a* = [w, v] with w = a . b, and v a = b - w a = o, so |v| =
/// |o| and exp(s log(b a*)) a = cos(s h) a + sin(s h) o/|o|, h = atan2(|o|,
/// w) in [0, pi] the half angle (atan2_upper, then sincos). Where o = 0 and
/// w < 0 (b = -a exactly) log() takes the axis [1, 0, 0]: then o/|o| is
/// [0, 1, 0, 0] a. No sign change: a negative a . b takes the long way, as
/// slerp() does.
template <class T, class V>
[[gnu::always_inline]] inline ql<V> slerp_lanes(const ql<V>& a, const ql<V>& b, const V& s) noexcept {
    const V w = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
    const ql<V> o{b.w - w * a.w, b.x - w * a.x, b.y - w * a.y, b.z - w * a.z};
    const V no = vsqrt(o.w * o.w + o.x * o.x + o.y * o.y + o.z * o.z);
    const sin_cos<V> sc = sincos(s * atan2_upper(no, w));
    const auto axis = no > T(0);
    const V zero{};
    const ql<V> u{sel(axis, o.w, zero - a.x), sel(axis, o.x, a.w), sel(axis, o.y, zero - a.z), sel(axis, o.z, a.y)};
    const V f = sc.s / sel(axis, no, zero + T(1));
    return {a.w * sc.c + u.w * f, a.x * sc.c + u.x * f, a.y * sc.c + u.y * f, a.z * sc.c + u.z * f};
}

/// Samples k .. k + width - 1 of a pyramid curve (rotations only).
/// uniform: one parameter for all six slerps (the De Casteljau curves).
template <class T, class V, bool uniform>
[[gnu::always_inline]] inline void pyramid_block(const pyramid_packed<T>* segs, const std::size_t* seg, const T* t,
                                                 std::size_t k, int valid, const rows<T>& out) noexcept {
    V s[6];
    for (int j = 0; j < 6; ++j) {
        if (uniform && j > 0) {
            s[j] = s[0];
            continue;
        }
        s[j] = make_lanes<V>([&](int l) { return (t[l] - segs[seg[l]].ta[j]) * segs[seg[l]].inv[j]; });
    }
    auto fixed = [&](int j) CRSPLINE_ROTATION_BLOCK {
        return fixed_lanes<T>([&](int l) -> const fixed_slerp<T>& { return segs[seg[l]].f[j]; }, s[j]);
    };
    // In the order that keeps the fewest quaternions alive (registers).
    const ql<V> F1 = fixed(1);
    const ql<V> D0 = slerp_lanes<T>(fixed(0), F1, s[3]);
    const ql<V> D1 = slerp_lanes<T>(F1, fixed(2), s[4]);
    store<T, V>(out, k, valid, slerp_lanes<T>(D0, D1, s[5]), nullptr, nullptr);
}

/// Samples k .. k + width - 1 of a Squad curve (rotations only).
template <class T, class V>
[[gnu::always_inline]] inline void squad_block(const squad_packed<T>* segs, const std::size_t* seg, const T* t, std::size_t k,
                                               int valid, const rows<T>& out) noexcept {
    const V u = make_lanes<V>([&](int l) { return (t[l] - segs[seg[l]].t0) * segs[seg[l]].inv_h; });
    const ql<V> a = fixed_lanes<T>([&](int l) -> const fixed_slerp<T>& { return segs[seg[l]].f[0]; }, u);
    const ql<V> b = fixed_lanes<T>([&](int l) -> const fixed_slerp<T>& { return segs[seg[l]].f[1]; }, u);
    store<T, V>(out, k, valid, slerp_lanes<T>(a, b, T(2) * u * (T(1) - u)), nullptr, nullptr);
}

// ----- the driver -------------------------------------------------------------------------

/// Runs block(lanes_of<V>{}, seg, t, k, valid) over samples t[0..n) a lane
/// type's width (4 portable, 8 AVX2) at a time; the segment of each from locate(k, t[k]). The
/// last, partial block repeats its last sample in the unused lanes and
/// writes only the valid ones. The block must be always_inline (the AVX2
/// clone compiles it inside its own body).
template <class T, class V, class Locate, class Block>
[[gnu::always_inline]] inline void run_lanes(std::span<const T> t, Locate& locate, Block& block) {
    constexpr int W = width_of<V>;
    const std::size_t n = t.size();
    std::size_t seg[W];
    T tl[W];
    for (std::size_t k = 0; k < n; k += W) {
        const int valid = int(std::min<std::size_t>(W, n - k));
        for (int l = 0; l < W; ++l) {
            const std::size_t s = k + std::size_t(l < valid ? l : valid - 1);
            tl[l] = t[s];
            seg[l] = locate(s, t[s]);
        }
        block(lanes_of<V>{}, seg, tl, k, valid);
    }
}

#if CRSPLINE_ROTATION_AVX2
template <class Locate, class Block>
__attribute__((target("avx2"))) void run_avx2(std::span<const double> t, Locate& locate, Block& block) {
    run_lanes<double, vx>(t, locate, block);
}
#endif

/// run_lanes on the given path: the AVX2 clone for double where asked and
/// the CPU has it, else the portable lanes.
template <class T, class Locate, class Block>
void run(std::span<const T> t, Locate&& locate, Block&& block, isa path = best_isa()) {
#if CRSPLINE_ROTATION_AVX2
    if constexpr (std::is_same_v<T, double>)
        if (path == isa::avx2 && best_isa() == isa::avx2) return run_avx2(t, locate, block);
#endif
    (void)path;
    run_lanes<T, typename pack<T>::V>(t, locate, block);
}

}  // namespace crspline::rotation::detail_batch
