// crspline internal: the Bezier pieces of the self-intersection search
// (intersections.hpp) and the tests on a pair of them: boxes, monotone
// along a direction, the Gauss-Newton polish of C_i(u) = C_j(v) relative
// to a pair origin, the chords' angle and closest points, transversality,
// separation across a chord, monotone near a joint.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "../segment.hpp"
#include "../vec.hpp"

namespace crspline {

namespace detail {

template <std::size_t D, class T>
struct sub_bezier {
    std::array<vec<D, T>, 4> b;
    T u0, u1;
};

template <std::size_t D, class T>
std::array<sub_bezier<D, T>, 2> split_half(const sub_bezier<D, T>& s) {
    const auto& b = s.b;
    const T h = T(0.5);
    const auto a0 = lerp(b[0], b[1], h), a1 = lerp(b[1], b[2], h), a2 = lerp(b[2], b[3], h);
    const auto q0 = lerp(a0, a1, h), q1 = lerp(a1, a2, h);
    const auto m = lerp(q0, q1, h);
    const T um = s.u0 + (s.u1 - s.u0) / 2;
    return {sub_bezier<D, T>{{b[0], a0, q0, m}, s.u0, um}, sub_bezier<D, T>{{m, q1, a2, b[3]}, um, s.u1}};
}

template <std::size_t D, class T>
std::array<vec<D, T>, 2> box_of(const std::array<vec<D, T>, 4>& b) {
    vec<D, T> lo = b[0], hi = b[0];
    for (const auto& p : b)
        for (std::size_t k = 0; k < D; ++k) { lo[k] = std::min(lo[k], p[k]); hi[k] = std::max(hi[k], p[k]); }
    return {lo, hi};
}

template <std::size_t D, class T>
bool boxes_meet(const std::array<vec<D, T>, 2>& a, const std::array<vec<D, T>, 2>& b, T pad) {
    for (std::size_t k = 0; k < D; ++k)
        if (a[0][k] > b[1][k] + pad || b[0][k] > a[1][k] + pad) return false;
    return true;
}

// Every hodograph control point of b has a positive component along d.
template <std::size_t D, class T>
bool monotone_along(const std::array<vec<D, T>, 4>& b, const vec<D, T>& d) {
    for (std::size_t k = 0; k < 3; ++k)
        if (!(dot(b[k + 1] - b[k], d) > 0)) return false;
    return true;
}

// Position of s at u relative to its origin: c1 u + c2 u^2 + c3 u^3, without
// adding the origin (whose ulp may exceed the tolerance far from the origin
// of coordinates).
template <std::size_t D, class T>
vec<D, T> relative_at(const cubic_segment<D, T>& s, T u) noexcept {
    return u * (s.c1 + u * (s.c2 + u * s.c3));
}

// Bézier points of s relative to a pair origin, given offset = s.origin -
// that origin: B0 = offset exactly, then offset + (Bk - B0).
template <std::size_t D, class T>
std::array<vec<D, T>, 4> relative_bezier(const cubic_segment<D, T>& s, const vec<D, T>& offset) {
    return {offset, offset + s.c1 / T(3), offset + (T(2) * s.c1 + s.c2) / T(3), offset + (s.c1 + s.c2 + s.c3)};
}

// Gauss-Newton on |C_i(u) - C_j(v)|^2 from (u, v), clamped to [0, 1]^2, with
// C_i - C_j = (origin_i - origin_j) + relative parts: no absolute position is
// ever formed, so the residual keeps the precision of the curve's size.
template <std::size_t D, class T>
std::array<T, 3> polish(const cubic_segment<D, T>& A, const cubic_segment<D, T>& B, T u, T v) {
    const vec<D, T> offset = A.origin - B.origin;
    auto F = [&](T x, T y) { return offset + relative_at(A, x) - relative_at(B, y); };
    T best = norm(F(u, v));
    for (int it = 0; it < 30 && best > 0; ++it) {
        const vec<D, T> f = F(u, v), ja = A.du(u, 1), jb = -B.du(v, 1);
        const T a11 = dot(ja, ja), a12 = dot(ja, jb), a22 = dot(jb, jb);
        const T r1 = -dot(ja, f), r2 = -dot(jb, f);
        const T det = a11 * a22 - a12 * a12;
        if (!(det > 0)) break;
        const T du = (r1 * a22 - a12 * r2) / det, dv = (a11 * r2 - a12 * r1) / det;
        T lam = 1;
        T nu = std::clamp(u + du, T(0), T(1)), nv = std::clamp(v + dv, T(0), T(1));
        T n = norm(F(nu, nv));
        for (int h = 0; h < 20 && !(n < best); ++h) {
            lam /= 2;
            nu = std::clamp(u + lam * du, T(0), T(1));
            nv = std::clamp(v + lam * dv, T(0), T(1));
            n = norm(F(nu, nv));
        }
        if (!(n < best)) break;
        u = nu;
        v = nv;
        best = n;
    }
    return {u, v, best};
}

/// How two segments of a curve touch by construction.
enum class pair_joint {
    none,   ///< not adjacent
    next,   ///< A(1) = B(0): consecutive segments
    wrap,   ///< A(0) = B(1): the first and last segments of a closed curve
};

// The largest angle between the chord b[3] - b[0] of a Bézier piece and its
// hodograph's control points (so every tangent of the piece), as {cos, sin};
// {-1, 0} when some hodograph point is not strictly ahead along the chord
// (the piece is not a graph over its chord, or has no chord).
template <std::size_t D, class T>
std::array<T, 2> tangent_cone(const std::array<vec<D, T>, 4>& b) {
    const vec<D, T> d = b[3] - b[0];
    const T nd = norm(d);
    T c = 1;
    for (std::size_t k = 0; k < 3; ++k) {
        const vec<D, T> h = b[k + 1] - b[k];
        const T dh = dot(h, d), nh = norm(h);
        if (!(dh > 0) || !(nd > 0)) return {T(-1), T(0)};
        c = std::min(c, dh / (nh * nd));
    }
    return {c, std::sqrt(std::max(T(0), 1 - c * c))};
}

// Whether every tangent of piece a meets every tangent of piece b (either
// way round) at an angle of at least half that between their chords' lines,
// and of at least about half a degree, each piece's tangents being within
// 30 degrees of its chord. Then A(u) - B(v) is a well-conditioned, nearly
// affine map of the pair's cell, and the pieces meet at most once there
// (two meetings P != Q would make Q - P a positive combination of a's
// tangents and, up to sign, of b's, which share no direction). A shallow
// crossing passes once the pieces are short enough to be nearly straight;
// parallel pieces (an overlap) never do.
template <std::size_t D, class T>
bool transversal(const std::array<vec<D, T>, 4>& a, const std::array<vec<D, T>, 4>& b) {
    constexpr T cos_narrow = T(0.86602540378443865);  // cos 30 degrees: a piece's tangents about its chord
    constexpr T cos_least = T(0.99984769515639124);   // cos 1 degree: the chords' lines at least this far apart
    const auto ca = tangent_cone(a);
    if (!(ca[0] >= cos_narrow)) return false;
    const auto cb = tangent_cone(b);
    if (!(cb[0] >= cos_narrow)) return false;
    const vec<D, T> da = a[3] - a[0], db = b[3] - b[0];
    // cos of the angle theta between the chords' lines, in [0, 1].
    const T c = std::abs(dot(da, db)) / (norm(da) * norm(db));
    if (!(c <= cos_least)) return false;
    // cos(2 (alpha_a + alpha_b)) >= cos theta: the cones together take at
    // most half of theta.
    const T cs = ca[0] * cb[0] - ca[1] * cb[1], sn = ca[1] * cb[0] + ca[0] * cb[1];
    return cs * cs - sn * sn >= c;
}

// Whether pieces a and b are more than tol apart across a's chord: the
// direction n across a's chord towards b (in 2-D the chord's normal; in
// more dimensions the part of the step between the pieces' centres that is
// across the chord), and the control points of each piece, which hold it
// in their convex hull, projected on n with a gap above tol between them.
// Tighter than the boxes for pieces at an angle to the axes.
template <std::size_t D, class T>
bool apart_across(const std::array<vec<D, T>, 4>& a, const std::array<vec<D, T>, 4>& b, T tol) {
    const vec<D, T> d = a[3] - a[0];
    const T dd = dot(d, d);
    if (!(dd > 0)) return false;
    vec<D, T> n;
    if constexpr (D == 2) {
        n = vec<D, T>{{-d[1], d[0]}};
    } else {
        const vec<D, T> step = (b[0] + b[1] + b[2] + b[3]) - (a[0] + a[1] + a[2] + a[3]);
        n = step - (dot(step, d) / dd) * d;
    }
    // Projections on n unnormalised: the gap is |n| times the distance.
    const T gap = tol * norm(n);
    if (!(gap > 0)) return false;
    T alo = 0, ahi = 0, blo = dot(b[0] - a[0], n), bhi = blo;
    for (std::size_t k = 1; k < 4; ++k) {
        const T x = dot(a[k] - a[0], n), y = dot(b[k] - a[0], n);
        alo = std::min(alo, x), ahi = std::max(ahi, x);
        blo = std::min(blo, y), bhi = std::max(bhi, y);
    }
    return blo - ahi > gap || alo - bhi > gap;
}

// Where the chords of pieces a and b come closest, as parameters of A and B:
// the start of the polish in a transversal cell.
template <std::size_t D, class T>
std::array<T, 2> chord_meeting(const sub_bezier<D, T>& a, const sub_bezier<D, T>& b) {
    const vec<D, T> da = a.b[3] - a.b[0], db = b.b[3] - b.b[0], r = b.b[0] - a.b[0];
    // Least squares for s da - t db = r.
    const T a11 = dot(da, da), a12 = -dot(da, db), a22 = dot(db, db), r1 = dot(da, r), r2 = -dot(db, r);
    const T det = a11 * a22 - a12 * a12;
    T s = T(0.5), t = T(0.5);
    if (det > 0) {
        s = std::clamp((r1 * a22 - a12 * r2) / det, T(0), T(1));
        t = std::clamp((a11 * r2 - a12 * r1) / det, T(0), T(1));
    }
    return {a.u0 + s * (a.u1 - a.u0), b.u0 + t * (b.u1 - b.u0)};
}

// Whether every hodograph control point of s (B1 - B0, B2 - B1, B3 - B2) is
// within 75 degrees of one direction d (the chord, or the bisector of the
// end tangents) and ahead along it by more than 1e-6 of their total
// length. Then C'(u) . d > 0 on [0, 1], so C is one to one: no loop and no
// fold. The margins keep analyze_segment's rounding-level decisions from
// seeing one either: its fold test needs the speed along the segment's line
// below zero by more than its threshold (here C' . d >= |C'| / 4 along d),
// and its loop test a divided difference (C(t) - C(s)) / (t - s) below 1e-8
// of |c1| + |c2| + |c3| (here at least 3e-6 / 7 of it).
template <std::size_t D, class T>
bool monotone_segment(const cubic_segment<D, T>& s) {
    const std::array<vec<D, T>, 3> h{s.c1 / T(3), (s.c1 + s.c2) / T(3), (s.c1 + T(2) * s.c2 + T(3) * s.c3) / T(3)};
    const std::array<T, 3> nh{norm(h[0]), norm(h[1]), norm(h[2])};
    const T total = nh[0] + nh[1] + nh[2];
    const auto ahead = [&](const vec<D, T>& d) {
        const T nd = norm(d);
        if (!(nd > 0)) return false;
        for (std::size_t k = 0; k < 3; ++k) {
            const T along = dot(h[k], d) / nd;
            if (!(along >= nh[k] / 4) || !(along > T(1e-6) * total)) return false;
        }
        return true;
    };
    return ahead(s.c1 + s.c2 + s.c3) || (nh[0] > 0 && nh[2] > 0 && ahead(h[0] / nh[0] + h[2] / nh[2]));
}

}  // namespace detail
}  // namespace crspline
