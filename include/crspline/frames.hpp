// crspline: curvature, torsion and moving frames along a curve.
//
// Where the speed vanishes (a cusp of a uniform or chordal curve, a segment
// between coincident points) the formulas divide by zero. Each function
// returns the limit there when it exists and a documented value otherwise,
// never NaN. A cubic makes the limits simple: if x'(t0) = 0 the segment near
// t0 is x0 + a s^2 / 2 + b s^3 / 6 (s = t - t0, a = x'', b = x'''), which is
// a straight line when a and b are parallel and a cusp otherwise.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "catmull_rom.hpp"
#include "detail/format.hpp"
#include "error.hpp"
#include "vec.hpp"

namespace crspline {

namespace detail {

/// a * b - c * d with one rounding error (Kahan's fma trick).
template <class T>
T difference_of_products(T a, T b, T c, T d) noexcept {
    const T w = c * d;
    const T e = std::fma(-c, d, w);
    const T f = std::fma(a, b, -w);
    return f + e;
}

/// |a ^ b| = sqrt(|a|^2 |b|^2 - (a . b)^2), computed stably by the Lagrange
/// identity as the root of the sum of squared 2x2 minors (no cancellation
/// of the two big terms), with a and b scaled to avoid overflow.
template <std::size_t D, class T>
T wedge_norm(const vec<D, T>& a, const vec<D, T>& b) noexcept {
    const T ma = max_abs(a), mb = max_abs(b);
    if (ma == 0 || mb == 0) return 0;
    const vec<D, T> x = a / ma, y = b / mb;
    T s = 0;
    for (std::size_t i = 0; i < D; ++i)
        for (std::size_t j = i + 1; j < D; ++j) {
            const T m = difference_of_products(x[i], y[j], x[j], y[i]);
            s += m * m;
        }
    return std::sqrt(s) * ma * mb;
}

template <class T>
vec<3, T> cross(const vec<3, T>& a, const vec<3, T>& b) noexcept {
    return {{difference_of_products(a[1], b[2], a[2], b[1]), difference_of_products(a[2], b[0], a[0], b[2]),
             difference_of_products(a[0], b[1], a[1], b[0])}};
}

/// The derivatives x', x'', x''' at t (checked: throws out_of_domain).
template <std::size_t D, class T>
std::array<vec<D, T>, 3> derivatives(const catmull_rom<D, T>& curve, T t) {
    return {curve.evaluate(t, 1), curve.evaluate(t, 2), curve.evaluate(t, 3)};
}

/// Unit vector along v, or nothing when v is zero.
template <std::size_t D, class T>
std::optional<vec<D, T>> direction(const vec<D, T>& v) noexcept {
    const T n = norm(v);
    if (!(n > 0) || !std::isfinite(n)) return std::nullopt;
    return v / n;
}

/// The unit tangent: x' / |x'|, or where the speed is zero the direction of
/// the first non-vanishing derivative (the limit of x' / |x'| from the right).
template <std::size_t D, class T>
std::optional<vec<D, T>> unit_tangent(const std::array<vec<D, T>, 3>& d) noexcept {
    for (const auto& v : d)
        if (auto e = direction(v)) return e;
    return std::nullopt;
}

/// v made perpendicular to the unit vector e and normalized (Gram-Schmidt,
/// twice for full precision), or nothing when v is (nearly) along e.
template <std::size_t D, class T>
std::optional<vec<D, T>> perpendicular(const vec<D, T>& v, const vec<D, T>& e) noexcept {
    const T n = norm(v);
    vec<D, T> w = v - dot(v, e) * e;
    if (!(norm(w) > T(1e-3) * n)) return std::nullopt;
    w -= dot(w, e) * e;
    return direction(w);
}

/// Some unit vector perpendicular to the unit vector e: the coordinate axis
/// least aligned with e, made perpendicular.
template <std::size_t D, class T>
vec<D, T> any_perpendicular(const vec<D, T>& e) noexcept {
    std::size_t j = 0;
    for (std::size_t k = 1; k < D; ++k)
        if (std::abs(e[k]) < std::abs(e[j])) j = k;
    vec<D, T> axis{};
    axis[j] = 1;
    return *perpendicular(axis, e);  // |e_j| <= 1/sqrt(D): far from parallel
}

}  // namespace detail

/// Curvature |x' ^ x''| / |x'|^3 at t, in any dimension (0 in 1-D).
///
/// Where the speed is zero: 0 when x'' and x''' are parallel (or zero),
/// because the cubic is then locally a straight line and the curvature is 0
/// on both sides; +infinity otherwise, because that is a cusp and the
/// curvature grows like 1 / |t - t0| as it is approached. Never NaN.
/// Throws out_of_domain for t outside [t_min, t_max].
template <std::size_t D, class T>
T curvature(const catmull_rom<D, T>& curve, T t) {
    const auto d = detail::derivatives(curve, t);
    const T speed = norm(d[0]);
    // 1. Zero speed: the limit, by the cubic's local form.
    if (!(speed * speed > 0))
        return detail::wedge_norm(d[1], d[2]) > 0 ? std::numeric_limits<T>::infinity() : T(0);
    // 2. |e ^ x''| / |x'|^2 with e the unit tangent.
    return detail::wedge_norm(d[0] / speed, d[1]) / (speed * speed);
}

/// Signed curvature of a plane curve, (x'_x x''_y - x'_y x''_x) / |x'|^3:
/// positive where the curve turns left. Where the speed is zero: 0 on a
/// locally straight piece, and +-infinity at a cusp with the sign of
/// x'' x x''' (the limit, the same from both sides).
template <class T>
T signed_curvature(const catmull_rom<2, T>& curve, T t) {
    const auto d = detail::derivatives(curve, t);
    const T speed = norm(d[0]);
    auto turn = [](const vec<2, T>& a, const vec<2, T>& b) {
        return detail::difference_of_products(a[0], b[1], a[1], b[0]);
    };
    if (!(speed * speed > 0)) {
        const T s = turn(d[1], d[2]);
        return s == 0 ? T(0) : std::copysign(std::numeric_limits<T>::infinity(), s);
    }
    return turn(d[0] / speed, d[1]) / (speed * speed);
}

/// Torsion det(x', x'', x''') / |x' x x''|^2 of a space curve at t.
///
/// On a cubic, det(x', x'', x''') is constant (its derivative is a sum of
/// determinants with a repeated column or x'''' = 0), a multiple of
/// det(c1, c2, c3). So either the segment is planar and its torsion is 0
/// everywhere, or x' x x'' never vanishes on it. A segment whose
/// det(c1, c2, c3) is within rounding of zero (64 eps (|c1| + |c2| + |c3|)^3,
/// the noise that rounding of the coefficients alone creates) is planar: 0. So is any point where x' x x'' is zero (zero speed, straight
/// pieces): 0, which is the limit there. Never NaN. Example: the end
/// segments of an open curve with natural ends (x'' = 0 at the end) are
/// planar, so their torsion is 0.
template <class T>
T torsion(const catmull_rom<3, T>& curve, T t) {
    const auto d = detail::derivatives(curve, t);
    // 1. A planar segment, by its constant determinant.
    const auto& s = curve.segment(curve.locate(t));
    const T det = dot(detail::cross(s.c1, s.c2), s.c3), size = norm(s.c1) + norm(s.c2) + norm(s.c3);
    if (!(std::abs(det) > T(64) * std::numeric_limits<T>::epsilon() * size * size * size)) return 0;
    // 2. With e = x' / |x'|: c = e x x'' = (x' x x'') / |x'|, so the torsion
    //    is (c . x''') / (|c|^2 |x'|).
    const T speed = norm(d[0]);
    if (!(speed * speed > 0)) return 0;
    const vec<3, T> c = detail::cross(d[0] / speed, d[1]);
    const T c2 = dot(c, c);
    if (!(c2 > 0)) return 0;
    const T tau = dot(c, d[2]) / (c2 * speed);
    return std::isfinite(tau) ? tau : T(0);
}

/// A moving frame: position, unit tangent, unit normal and, in 3-D, the
/// binormal tangent x normal (zero in 2-D).
template <std::size_t D, class T = double>
struct frame {
    vec<D, T> position, tangent, normal, binormal;
};

namespace detail {

/// Positions and unit tangents at the samples. Where every derivative
/// vanishes (a segment between coincident points) the tangent is carried
/// from the previous sample, or taken from the first sample that has one;
/// the x axis if none has.
template <std::size_t D, class T>
std::vector<frame<D, T>> positions_and_tangents(const catmull_rom<D, T>& curve, std::span<const T> t,
                                                std::vector<std::array<vec<D, T>, 3>>& derivs) {
    const std::size_t n = t.size();
    std::vector<frame<D, T>> f(n);
    std::vector<std::optional<vec<D, T>>> e(n);
    derivs.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        if (!(t[k] >= curve.t_min() && t[k] <= curve.t_max()))
            throw out_of_domain("t[" + std::to_string(k) + "] = " + num(double(t[k])) + " is outside the domain [" +
                                num(double(curve.t_min())) + ", " + num(double(curve.t_max())) + "]");
        f[k].position = curve.evaluate(t[k]);
        derivs[k] = derivatives(curve, t[k]);
        e[k] = unit_tangent(derivs[k]);
    }
    const auto first = std::find_if(e.begin(), e.end(), [](const auto& x) { return x.has_value(); });
    vec<D, T> carried{};
    carried[0] = 1;
    if (first != e.end()) carried = **first;
    for (std::size_t k = 0; k < n; ++k) {
        if (e[k]) carried = *e[k];
        f[k].tangent = carried;
    }
    return f;
}

/// Rotate v (perpendicular to the unit vector e) by angle a about e.
template <class T>
vec<3, T> rotate_about(const vec<3, T>& v, const vec<3, T>& e, T a) noexcept {
    return std::cos(a) * v + std::sin(a) * cross(e, v);
}

/// One double-reflection step (Wang, Jüttler, Zheng, Liu 2008, Algorithm 1):
/// the normal r at (x0, e0) carried to (x1, e1). Coincident positions
/// reflect in the plane normal to e0 instead of the chord's, which makes the
/// step the smallest rotation taking e0 to e1.
template <class T>
vec<3, T> double_reflection(const vec<3, T>& x0, const vec<3, T>& e0, const vec<3, T>& r, const vec<3, T>& x1,
                            const vec<3, T>& e1) noexcept {
    const T tiny = T(1024) * std::numeric_limits<T>::epsilon();
    // 1. Reflect in the bisector plane of x0 and x1.
    vec<3, T> v1 = x1 - x0;
    if (!(norm(v1) > tiny * (max_abs(x0) + max_abs(x1)))) v1 = e0;
    const T c1 = dot(v1, v1);
    const vec<3, T> rl = r - (T(2) / c1) * dot(v1, r) * v1;
    const vec<3, T> el = e0 - (T(2) / c1) * dot(v1, e0) * v1;
    // 2. Reflect el onto e1; the same reflection carries rl.
    const vec<3, T> v2 = e1 - el;
    const T c2 = dot(v2, v2);
    const vec<3, T> r1 = c2 > tiny * tiny ? rl - (T(2) / c2) * dot(v2, rl) * v2 : rl;
    // 3. Back onto the plane normal to e1 (rounding only).
    if (auto p = perpendicular(r1, e1)) return *p;
    return any_perpendicular(e1);
}

template <std::size_t D, class T>
void check_normal(const std::optional<vec<D, T>>& n) {
    if (!n) return;
    for (std::size_t k = 0; k < D; ++k)
        if (!std::isfinite((*n)[k]))
            throw invalid_input("initial normal coordinate " + std::to_string(k) + " is not finite (" +
                                num(double((*n)[k])) + ")");
}

}  // namespace detail

/// Frenet frames (tangent, principal normal, binormal) of a space curve at
/// the parameters t. Where the curvature vanishes (|e x x''| below 1e3 eps
/// |x''|) the normal is undefined: the previous sample's normal is carried
/// (made perpendicular to the new tangent), or before the first defined one,
/// that one; a fixed perpendicular if the whole sample is straight. At a
/// zero-speed point the binormal is the limit x'' x x''' (see curvature).
/// Throws out_of_domain naming the first t outside the domain.
template <class T>
std::vector<frame<3, T>> frenet_frames(const catmull_rom<3, T>& curve, std::span<const T> t) {
    using point = vec<3, T>;
    std::vector<std::array<point, 3>> d;
    auto f = detail::positions_and_tangents(curve, t, d);
    const std::size_t n = t.size();
    const T tiny = T(1e3) * std::numeric_limits<T>::epsilon();
    // 1. The normal where the curvature defines it: binormal x tangent.
    std::vector<std::optional<point>> normal(n);
    for (std::size_t k = 0; k < n; ++k) {
        const bool moving = norm(d[k][0]) > 0;
        const point& a = moving ? d[k][0] : d[k][1];  // the tangent's derivative and the next one
        const point& b = moving ? d[k][1] : d[k][2];
        const auto e = detail::direction(a);
        if (!e) continue;
        const point w = detail::cross(*e, b);
        if (!(norm(w) > tiny * norm(b))) continue;
        normal[k] = detail::perpendicular(detail::cross(w, f[k].tangent), f[k].tangent);
    }
    // 2. Elsewhere carry the previous one (the first defined one at the start).
    const auto first = std::find_if(normal.begin(), normal.end(), [](const auto& x) { return x.has_value(); });
    std::optional<point> carried;
    if (first != normal.end()) carried = *first;
    for (std::size_t k = 0; k < n; ++k) {
        point nk;
        if (normal[k]) nk = *normal[k];
        else if (auto p = carried ? detail::perpendicular(*carried, f[k].tangent) : std::nullopt) nk = *p;
        else nk = detail::any_perpendicular(f[k].tangent);
        carried = nk;
        f[k].normal = nk;
        f[k].binormal = detail::cross(f[k].tangent, nk);
    }
    return f;
}

/// Rotation-minimizing frames at the parameters t (any order; sorted gives
/// the usual sweep), by the double-reflection method of Wang, Jüttler, Zheng
/// and Liu (2008), each sample's frame carried from the previous one.
///
/// 3-D: the first normal is initial_normal made perpendicular to the first
/// tangent (invalid_input if it is not finite or is along the tangent), by
/// default the Frenet normal there (a fixed perpendicular on a straight
/// start). On a closed curve with nondecreasing samples spanning at most one
/// period, the frame carried once around (from the last sample to the first
/// point again) must turn by an angle phi about the tangent to meet the first
/// frame; sample k is turned by phi (t[k] - t[0]) / period, the correction
/// spread evenly in the parameter, so the frames close up: a sample at t_max
/// gets the same frame as one at t_min.
///
/// 2-D: the tangent and its left normal (which minimize rotation trivially);
/// an initial normal pointing to the right picks the right normal instead.
/// The binormal is zero.
template <std::size_t D, class T>
    requires(D == 2 || D == 3)
std::vector<frame<D, T>> rotation_minimizing_frames(const catmull_rom<D, T>& curve, std::span<const T> t,
                                                    std::optional<std::type_identity_t<vec<D, T>>> initial_normal = std::nullopt) {
    using point = vec<D, T>;
    detail::check_normal(initial_normal);
    std::vector<std::array<point, 3>> d;
    auto f = detail::positions_and_tangents(curve, t, d);
    const std::size_t n = t.size();
    if constexpr (D == 2) {
        // The left normal, or the right one if the initial normal says so.
        const T side = initial_normal && n > 0 && dot(*initial_normal, point{{-f[0].tangent[1], f[0].tangent[0]}}) < 0
                           ? T(-1)
                           : T(1);
        for (auto& fk : f) fk.normal = side * point{{-fk.tangent[1], fk.tangent[0]}};
        return f;
    } else {
        if (n == 0) return f;
        // 1. The first normal.
        if (initial_normal) {
            const auto p = detail::perpendicular(*initial_normal, f[0].tangent);
            if (!p) throw invalid_input("initial normal is zero or along the tangent at t[0]");
            f[0].normal = *p;
        } else {
            const auto frenet = frenet_frames(curve, t.first(1));
            f[0].normal = frenet[0].normal;
        }
        // 2. Carry it along by double reflection.
        for (std::size_t k = 1; k < n; ++k)
            f[k].normal = detail::double_reflection(f[k - 1].position, f[k - 1].tangent, f[k - 1].normal,
                                                    f[k].position, f[k].tangent);
        // 3. A closed curve swept once around: spread the closing rotation.
        const T period = curve.t_max() - curve.t_min();
        const bool sorted = std::is_sorted(t.begin(), t.end());
        if (curve.closed() && n >= 2 && sorted && t.back() - t.front() <= period && period > 0) {
            const point start = curve.evaluate(t.front());
            const point back = detail::double_reflection(f[n - 1].position, f[n - 1].tangent, f[n - 1].normal,
                                                         start, f[0].tangent);
            // The angle turning the carried normal onto the first one, about the tangent.
            const T phi = std::atan2(dot(detail::cross(back, f[0].normal), f[0].tangent), dot(back, f[0].normal));
            for (std::size_t k = 0; k < n; ++k) {
                const T a = phi * ((t[k] - t.front()) / period);
                if (auto p = detail::perpendicular(detail::rotate_about(f[k].normal, f[k].tangent, a), f[k].tangent))
                    f[k].normal = *p;
            }
        }
        for (auto& fk : f) fk.binormal = detail::cross(fk.tangent, fk.normal);
        return f;
    }
}

}  // namespace crspline
