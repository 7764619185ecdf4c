// crspline::geo internals: the proof's tests on Bézier points: a segment's
// deviation from its input segment in closed form, its own loops and cusps,
// hulls apart at a shared end, a point outside a hull, winding numbers, the
// boxes of fitted arcs, polyline pieces with their flatness margins.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <span>
#include <utility>

#include "../bounds.hpp"
#include "arcs.hpp"

namespace crspline::geo {

namespace detail {

// ---- The proof, segment by segment (see the file comment) ----------------

// Max and min of the cubic with Bernstein coefficients c0..c3 on [0, 1]:
// the ends and the roots of its derivative (a quadratic) inside.
inline std::pair<double, double> bernstein_range(double c0, double c1, double c2, double c3) noexcept {
    double lo = std::min(c0, c3), hi = std::max(c0, c3);
    auto at = [&](double u) {
        const double v = 1 - u;
        return v * v * v * c0 + 3 * u * v * (v * c1 + u * c2) + u * u * u * c3;
    };
    auto consider = [&](double u) {
        if (!(u > 0 && u < 1)) return;
        const double x = at(u);
        lo = std::min(lo, x);
        hi = std::max(hi, x);
    };
    // Derivative / 3 in Bernstein form: d0 (1-u)^2 + 2 d1 u (1-u) + d2 u^2.
    const double d0 = c1 - c0, d1 = c2 - c1, d2 = c3 - c2;
    const double qa = d0 - 2 * d1 + d2, qb = 2 * (d1 - d0), qc = d0;
    const double big = std::max({std::abs(qa), std::abs(qb), std::abs(qc)});
    if (big == 0) return {lo, hi};
    if (std::abs(qa) <= 1e-12 * big) {
        if (qb != 0) consider(-qc / qb);
        return {lo, hi};
    }
    const double disc = qb * qb - 4 * qa * qc;
    if (disc < 0) return {lo, hi};
    const double r = std::sqrt(disc);
    const double q = -0.5 * (qb + (qb >= 0 ? r : -r));  // no cancellation
    consider(q / qa);
    if (q != 0) consider(qc / q);
    return {lo, hi};
}

// A bound on the distance of the cubic with Bézier points b from the
// segment [b0, b3] (its own input segment): with a the coordinate along the
// segment and h across it (both cubics in u), every point is at distance
// sqrt(h^2 + overshoot^2) where overshoot is how far a runs past [0, L];
// the maximum of each, found in closed form, bounds it.
inline double segment_deviation(const std::array<p2, 4>& b) noexcept {
    const p2 d = b[3] - b[0];
    const double len = norm(d);
    if (!(len > 0)) return std::max(norm(b[1] - b[0]), norm(b[2] - b[0]));
    const p2 t = d / len, n{{-t[1], t[0]}};
    double a[4], h[4];
    for (int i = 0; i < 4; ++i) {
        const p2 r = b[i] - b[0];
        a[i] = dot(r, t);
        h[i] = dot(r, n);
    }
    const auto [hlo, hhi] = bernstein_range(h[0], h[1], h[2], h[3]);
    const auto [alo, ahi] = bernstein_range(a[0], a[1], a[2], a[3]);
    const double across = std::max(-hlo, hhi), over = std::max({0.0, -alo, ahi - len});
    return std::sqrt(across * across + over * over);
}

// Whether the segment with Bézier points b is free of loops and cusps
// cheaply: its Bézier points advance strictly along its chord (each step
// by more than `slack`), so the curve's coordinate along the chord grows
// strictly and the curve is a graph over the chord. An end step that is
// exactly zero (b1 == b0 or b2 == b3: that end at tension 1) is allowed:
// the derivative 3 [(1-u)^2 h0 + 2 u (1-u) h1 + u^2 h2] of the coordinate
// is still positive on (0, 1) and at the other end, so the coordinate still
// grows strictly (decision.hpp's joint argument allows such points too).
inline bool advances_along_chord(const std::array<p2, 4>& b, double slack) noexcept {
    const p2 d = b[3] - b[0];
    const double len = norm(d);
    if (!(len > 0)) return false;
    const p2 t = d / len;
    const bool first_zero = b[1] == b[0], last_zero = b[2] == b[3];
    if (first_zero && last_zero) return dot(b[2] - b[1], t) > slack;  // the chord itself
    return (first_zero || dot(b[1] - b[0], t) > slack) && dot(b[2] - b[1], t) > slack &&
           (last_zero || dot(b[3] - b[2], t) > slack);
}

// Two point sets, each with v, whose hulls meet only at v: their wedges at
// v are disjoint (with a margin against rounding).
inline bool hulls_apart_at(const std::array<p2, 4>& p, const std::array<p2, 4>& q, const p2& v, double slack) {
    double a0, a1, b0, b1;
    if (!wedge_of(p, v, slack, a0, a1) || !wedge_of(q, v, slack, b0, b1)) return false;
    constexpr double margin = 1e-9, two_pi = 2 * std::numbers::pi;
    double s = std::fmod(b0 - a0, two_pi);
    if (s < 0) s += two_pi;
    return s > (a1 - a0) + margin && s + (b1 - b0) < two_pi - margin;
}

// hulls_apart_at's cheaper sufficient test: a line through v with every
// point of p (other than v) strictly on one side and every point of q on
// the other. The line tried is the one across the direction from p's
// points to q's (their sums, seen from v): the usual case of two
// consecutive segments of a curve turning less than a right angle.
inline bool apart_by_line(const std::array<p2, 4>& p, const std::array<p2, 4>& q, const p2& v, double slack) {
    auto near_v = [&](const p2& d) { return std::abs(d[0]) <= slack && std::abs(d[1]) <= slack; };
    p2 dir{};
    for (const p2& x : q) dir = dir + (x - v);
    for (const p2& x : p) dir = dir - (x - v);
    const double margin = slack * (std::abs(dir[0]) + std::abs(dir[1]));
    for (const p2& x : p)
        if (!near_v(x - v) && !(dot(x - v, dir) < -margin)) return false;
    for (const p2& x : q)
        if (!near_v(x - v) && !(dot(x - v, dir) > margin)) return false;
    return true;
}

// Whether w is outside the convex hull of q by more than `slack`: some
// direction n has every point of q more than slack |n| before w, or every
// one more than that beyond it. Tried: from q's centroid towards w, and
// across each pair of q's points (the hull's edge directions are among
// them). Relative to w, so rounding stays within a few ulps of the
// coordinates, far below the slack; |n|_1 >= |n|_2 keeps the margin true.
inline bool outside_hull(const std::array<p2, 4>& q, const p2& w, double slack) noexcept {
    auto apart = [&](const p2& n) {
        const double len = std::abs(n[0]) + std::abs(n[1]);
        if (!(len > 0)) return false;
        double lo = INFINITY, hi = -INFINITY;
        for (const p2& x : q) {
            const double v = dot(x - w, n);
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        return hi < -slack * len || lo > slack * len;
    };
    if (apart((q[0] + q[1] + q[2] + q[3]) / 4.0 - w)) return true;
    for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b) {
            const p2 d = q[b] - q[a];
            if (apart(p2{{-d[1], d[0]}})) return true;
        }
    return false;
}

// The winding number around w of the closed polygon v[0], ..., v[n - 1]
// (and back to v[0]), every edge of which is farther than a few ulps of
// the coordinates from w: then each orientation sign below is exact (an
// edge crossing the ray y = y_w does so at least that far from w, and the
// cross product's rounding is below that distance times the edge's rise).
inline int winding_around(std::span<const p2> v, const p2& w) noexcept {
    int wn = 0;
    const std::size_t n = v.size();
    for (std::size_t k = 0; k < n; ++k) {
        const p2 a = v[k] - w, b = v[k + 1 == n ? 0 : k + 1] - w;
        if (a[1] <= 0) {
            if (b[1] > 0 && cross2(a, b) > 0) ++wn;
        } else if (b[1] <= 0 && cross2(a, b) < 0) {
            --wn;
        }
    }
    return wn;
}

// The end point two point sets share (their first or last), if any.
inline const p2* shared_end(const std::array<p2, 4>& p, const std::array<p2, 4>& q) noexcept {
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            if (p[3 * i] == q[3 * j]) return &p[3 * i];
    return nullptr;
}

inline bool boxes_meet(const box<2>& a, const box<2>& b, double pad) noexcept {
    return !(a.lo[0] > b.hi[0] + pad || b.lo[0] > a.hi[0] + pad || a.lo[1] > b.hi[1] + pad ||
             b.lo[1] > a.hi[1] + pad);
}

// A box holding every Bézier hull a fitted arc's curve can have, whatever
// vertices it keeps and whatever tension: each hull's end points are input
// vertices, and its inner points are within a third of the end tangent of
// them; a Catmull-Rom tangent (any alpha, natural ends, tension lowering
// it) is at most 3 times the longer chord beside it (the two terms of the
// tangent are each at most the longer chord, the natural end's at most
// 5/2 of it), and every chord between input vertices is at most the
// diagonal of their box. So: their box grown by its diagonal.
inline box<2> fitted_bounds(std::span<const p2> full) noexcept {
    box<2> b = box<2>::of(full[0]);
    for (const p2& q : full) b.expand(q);
    const double d = norm(b.hi - b.lo);
    b.lo = b.lo - p2{{d, d}};
    b.hi = b.hi + p2{{d, d}};
    return b;
}

// Polyline piece k of the arc (from vertex k to k + 1), with its curve
// piece's Bézier points and flatness margin.
inline piece piece_of(const arc_work& a, std::uint32_t arc_index, std::size_t k, double slack) {
    piece pc;
    const std::size_t s = a.vseg[k];
    pc.arc = arc_index;
    pc.seg = std::uint32_t(s);
    pc.linear = a.linear(s);
    const p2 pa = a.line.points[k], pb = a.line.points[k + 1];
    pc.q[0] = pa;
    pc.q[3] = pb;
    if (pc.linear) {
        pc.q[1] = pa;
        pc.q[2] = pb;
    } else {
        const auto seg = a.curve->segment(s);
        // The next vertex is in this segment, or is its end knot.
        const double u0 = a.vu[k], u1 = a.vseg[k + 1] == s ? a.vu[k + 1] : 1.0;
        const double w = u1 - u0;
        pc.q[1] = pa + (w / 3) * seg.du(u0, 1);
        pc.q[2] = pb - (w / 3) * seg.du(u1, 1);
        pc.e = flatness_bound(seg, u0, u1) + slack;
    }
    pc.bounds = box<2>::of(pa);
    pc.bounds.expand(pb);
    return pc;
}

}  // namespace detail

}  // namespace crspline::geo
