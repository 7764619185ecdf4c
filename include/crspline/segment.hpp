// crspline: one cubic segment, its canonical form and its conversions.
//
// A segment is the cubic C(u), u in [0, 1], between two consecutive control
// points, stored relative to its first control point (the "origin") so that
// curves far from the origin of coordinates keep full precision:
//
//   C(u) = origin + c1 u + c2 u^2 + c3 u^3
//
// The global parameter is t = t0 + u h. Bézier and Hermite forms are derived
// from it; the Barry-Goldman pyramid (reference evaluator) lives here too.
#pragma once

#include <array>
#include <cstddef>

#include "vec.hpp"

namespace crspline {

template <std::size_t D, class T = double>
struct cubic_segment {
    using point = vec<D, T>;
    point origin{};          ///< C(0), the control point the segment starts at
    point c1{}, c2{}, c3{};  ///< power-basis coefficients in u, relative to origin
    T t0 = 0;                ///< global parameter at u = 0
    T h = 0;                 ///< knot interval; 0 for a constant segment
    T inv_h = 0;             ///< 1 / h, or 0 when h == 0 (all derivatives are then 0)

    /// The cubic Hermite segment from p0 to p1 with end tangents m0, m1 in
    /// u-units (dC/du), on the knot interval [t0, t0 + h].
    static cubic_segment hermite(const point& p0, const point& p1, const point& m0, const point& m1,
                                 T t0, T h) noexcept {
        return hermite(p0, p1, m0, m1, t0, h, h > 0 ? T(1) / h : T(0));
    }
    /// The same with 1 / h given (0 when h == 0), as a curve that stores it passes.
    static cubic_segment hermite(const point& p0, const point& p1, const point& m0, const point& m1,
                                 T t0, T h, T inv_h) noexcept {
        cubic_segment s;
        const point delta = p1 - p0;
        s.origin = p0;
        s.c1 = m0;
        s.c2 = T(3) * delta - T(2) * m0 - m1;
        s.c3 = m0 + m1 - T(2) * delta;
        s.t0 = t0;
        s.h = h;
        s.inv_h = inv_h;
        return s;
    }

    /// Position at local u (Horner, relative to the origin).
    point at(T u) const noexcept { return origin + u * (c1 + u * (c2 + u * c3)); }

    /// Derivative of the given order (0-3) with respect to u.
    point du(T u, int order) const noexcept {
        switch (order) {
            case 0: return at(u);
            case 1: return c1 + u * (T(2) * c2 + T(3) * u * c3);
            case 2: return T(2) * c2 + T(6) * u * c3;
            case 3: return T(6) * c3;
            default: return point{};
        }
    }

    /// Derivative of the given order (0-3) with respect to the global t.
    point dt(T u, int order) const noexcept {
        switch (order) {
            case 0: return at(u);
            case 1: return du(u, 1) * inv_h;
            case 2: return du(u, 2) * (inv_h * inv_h);
            case 3: return du(u, 3) * (inv_h * inv_h * inv_h);
            default: return point{};
        }
    }

    /// Local parameter of a global t (not clamped).
    T local(T t) const noexcept { return (t - t0) * inv_h; }

    /// Hermite end tangents in u-units: {C'(0), C'(1)}.
    std::array<point, 2> tangents() const noexcept { return {c1, c1 + T(2) * c2 + T(3) * c3}; }
};

/// Bézier control points B0..B3 of a cubic segment on u in [0, 1]. B0 is the
/// origin exactly; B3 = origin + (c1 + c2 + c3) up to rounding.
template <std::size_t D, class T>
std::array<vec<D, T>, 4> to_bezier(const cubic_segment<D, T>& s) {
    using point = vec<D, T>;
    const point d1 = s.c1 / T(3);                          // B1 - B0
    const point d2 = (T(2) * s.c1 + s.c2) / T(3);          // B2 - B0
    const point d3 = s.c1 + s.c2 + s.c3;                   // B3 - B0
    return {s.origin, s.origin + d1, s.origin + d2, s.origin + d3};
}

/// Evaluate a cubic Bézier curve by de Casteljau's algorithm (nested lerps).
template <std::size_t D, class T>
vec<D, T> bezier_at(const std::array<vec<D, T>, 4>& b, T u) noexcept {
    const auto a0 = lerp(b[0], b[1], u), a1 = lerp(b[1], b[2], u), a2 = lerp(b[2], b[3], u);
    const auto q0 = lerp(a0, a1, u), q1 = lerp(a1, a2, u);
    return lerp(q0, q1, u);
}

/// The paper's Eq. 2 in general form: the Bézier control points of the
/// Catmull-Rom segment from p[1] to p[2] with knots t[0] < t[1] < t[2] < t[3]
/// (any parameterization, not only |P(i+1) - P(i)|^alpha). With h0 = t1 - t0,
/// h1 = t2 - t1, h2 = t3 - t2:
///
///   B1 = P1 + [h1^2 (P1 - P0) + h0^2 (P2 - P1)] / [3 h0 (h0 + h1)]
///   B2 = P2 - [h1^2 (P3 - P2) + h2^2 (P2 - P1)] / [3 h2 (h1 + h2)]
///
/// which for t(i+1) - t(i) = d(i+1)^alpha is exactly the printed Eq. 2.
template <std::size_t D, class T>
std::array<vec<D, T>, 4> catmull_rom_bezier(const std::array<vec<D, T>, 4>& p, const std::array<T, 4>& t) {
    const T h0 = t[1] - t[0], h1 = t[2] - t[1], h2 = t[3] - t[2];
    const vec<D, T> b1 = p[1] + ((h1 * h1) * (p[1] - p[0]) + (h0 * h0) * (p[2] - p[1])) / (T(3) * h0 * (h0 + h1));
    const vec<D, T> b2 = p[2] - ((h1 * h1) * (p[3] - p[2]) + (h2 * h2) * (p[2] - p[1])) / (T(3) * h2 * (h1 + h2));
    return {p[1], b1, b2, p[2]};
}

/// Barry-Goldman pyramid: the reference evaluator of the segment from p[1] to
/// p[2], written in the paper's three stages, at global t in [t1, t2]. Needs
/// strictly increasing knots. Points are taken relative to p[1] so that large
/// offsets keep their precision. Slow and exact in form: the fast path
/// (cubic_segment) is tested against it.
template <std::size_t D, class T>
vec<D, T> barry_goldman(const std::array<vec<D, T>, 4>& p, const std::array<T, 4>& t, T x) noexcept {
    const vec<D, T> o = p[1];
    const vec<D, T> P0 = p[0] - o, P1{}, P2 = p[2] - o, P3 = p[3] - o;
    const T t0 = t[0], t1 = t[1], t2 = t[2], t3 = t[3];
    // Stage 1: linear interpolation along each polygon edge (Lagrange, degree 1).
    const vec<D, T> A1 = (t1 - x) / (t1 - t0) * P0 + (x - t0) / (t1 - t0) * P1;
    const vec<D, T> A2 = (t2 - x) / (t2 - t1) * P1 + (x - t1) / (t2 - t1) * P2;
    const vec<D, T> A3 = (t3 - x) / (t3 - t2) * P2 + (x - t2) / (t3 - t2) * P3;
    // Stage 2: blend neighbouring edges (Lagrange, degree 2).
    const vec<D, T> B1 = (t2 - x) / (t2 - t0) * A1 + (x - t0) / (t2 - t0) * A2;
    const vec<D, T> B2 = (t3 - x) / (t3 - t1) * A2 + (x - t1) / (t3 - t1) * A3;
    // Stage 3: B-spline-like blend over the segment's own interval.
    const vec<D, T> C = (t2 - x) / (t2 - t1) * B1 + (x - t1) / (t2 - t1) * B2;
    return C + o;
}

}  // namespace crspline
