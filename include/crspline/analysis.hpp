// crspline: analysis of cubic Catmull-Rom segments (Yuksel, Schaefer and
// Keyser 2011, "Parameterization and applications of Catmull-Rom curves").
//
// Per segment, in any dimension and for any alpha (or explicit knots):
//
//   * cusps (zero speed inside the segment) and self-intersections, with the
//     parameters where they occur; in 1-D (or for a collinear segment) a fold,
//     where the curve reverses;
//   * the paper's quantities: Bézier points (Eq. 2), the projected-derivative
//     test (Theorems 1-3), the projections of B1, B2 onto the chord, the
//     heights h1, h2 (Eq. 5), the distance bound to the chord line (Eq. 6 in
//     its corrected two-sided form), the endpoint bound (Eq. 8), and the
//     measured maximum distances to the chord line and the chord segment;
//   * curvature along the segment and where its maxima lie (Section 6.4).
//
// Everything is computed on the segment's cubic C(u) = B0 + c1 u + c2 u^2 +
// c3 u^3 relative to its first point, and in the chord frame (B0 at the
// origin, chord B3 - B0), so results keep full precision far from the origin.
//
// Exactness. "Zero" is decided with one relative threshold, the rounding
// level of the coefficients: zero_speed_tolerance * (|c1| + |c2| + |c3|)
// (see zero_speed_tolerance below for the justification). Everything else is
// exact algebra: self-intersections of a planar segment come from solving
// C(s) = C(t) in closed form, maxima from the roots of polynomial derivatives.//
// The parts: paper_bounds.hpp (the paper's closed forms), curvature.hpp
// (curvature and its maxima); here the per-segment analysis.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include "catmull_rom.hpp"
#include "curvature.hpp"
#include "detail/analysis_common.hpp"
#include "detail/polynomial.hpp"
#include "paper_bounds.hpp"
#include "parameterization.hpp"
#include "segment.hpp"
#include "vec.hpp"

namespace crspline {

/// Relative threshold for "the speed is zero" and for "this direction is
/// absent from the segment's span": k * epsilon * (|c1| + |c2| + |c3|).
///
/// Why 64: C'(u) = c1 + 2 c2 u + 3 c3 u^2 is evaluated with a few roundings
/// of terms no larger than 6 (|c1| + |c2| + |c3|), the root u* of the speed's
/// derivative is accurate to a few ulps (adding |C''| * ulp <= 8 eps * sum),
/// and the coefficients themselves carry the rounding of their construction
/// from the control points (c2 = 3 delta - 2 m0 - m1 etc.: about 10 eps *
/// sum). Together well under 32 eps * sum; 64 leaves a factor of two. A
/// genuine near-cusp whose minimum speed is above this (1.4e-14 relative in
/// double) is reported as no cusp; below it, the cusp is real to rounding.
inline constexpr double zero_speed_tolerance = 64;

/// Zero-speed points closer than this (in u) to a zero-speed end are that
/// end's zero, split by rounding (a double zero at the end moved by a
/// relative perturbation of size tau lands about sqrt(tau) away):
/// sqrt(64 eps) in double.
template <class T>
inline T end_merge_distance() noexcept {
    return std::sqrt(T(zero_speed_tolerance) * std::numeric_limits<T>::epsilon());
}

// ---------------------------------------------------------------------------
// Per-segment analysis
// ---------------------------------------------------------------------------

/// Quantities in the chord frame (B0 at the origin, chord B3 - B0), defined
/// when the chord is not zero.
template <class T = double>
struct chord_projection {
    /// (Bk - B0).(B3 - B0) / |B3 - B0|^2 for k = 1, 2. Theorem 2: both in the
    /// open interval (0, 1) implies no cusp and no self-intersection.
    std::array<T, 2> bezier{};
    bool theorem2 = false;                ///< both bezier projections in (0, 1)
    T derivative_min = 0;                 ///< min over u of C'(u).(B3-B0)/|B3-B0|^2 (Theorems 1-3)
    T derivative_min_u = 0;
    std::array<T, 2> range{};             ///< [min, max] over u of (C(u)-B0).(B3-B0)/|B3-B0|^2
};

/// Everything known about one segment. Parameters u are local, in [0, 1].
template <std::size_t D, class T = double>
struct segment_analysis {
    using point = vec<D, T>;
    std::size_t index = 0;                       ///< segment index in its curve (0 standalone)
    cubic_segment<D, T> segment{};               ///< the cubic analysed (relative to B0; u-units)
    std::array<point, 4> bezier{};               ///< B0..B3 (Eq. 2 in general form)
    std::size_t rank = 0;                        ///< dimension of the affine span (0: a point)

    // Classification (exact up to rounding; see zero_speed_tolerance).
    std::vector<T> zero_speed_u;                 ///< C'(u) = 0, ends included
    std::vector<T> cusp_u;                       ///< zero speed with 0 < u < 1
    std::vector<std::array<T, 2>> self_intersection;  ///< C(u) = C(v), u < v (planar segments)
    bool fold = false;                           ///< collinear segment that reverses (1-D fold)
    bool has_cusp() const noexcept { return !cusp_u.empty(); }
    /// A loop (C(u) = C(v)) or a fold (the collinear curve retraces itself).
    bool has_self_intersection() const noexcept { return fold || !self_intersection.empty(); }

    // Chord frame.
    std::optional<chord_projection<T>> projection;  ///< nullopt for a zero chord
    std::array<T, 2> bezier_height{};            ///< measured distances of B1, B2 to the chord line
    T bezier_bound = 0;                          ///< 3/4 max(bezier_height): bounds the chord-line distance
    T max_chord_line_distance = 0;               ///< max over u of the distance to the chord line
    T max_chord_line_distance_u = 0;
    T max_chord_distance = 0;                    ///< max over u of the distance to the closed chord segment
    T max_chord_distance_u = 0;
    /// Largest distance to B0 of a curve point projecting before B0 (and to
    /// B3 of one projecting beyond B3): the overshoot Eq. 8 bounds. 0 if none.
    std::array<T, 2> overshoot{};

    std::optional<paper_bounds<T>> bounds;       ///< the paper's formulas (need P0..P3 and knots)
};

namespace detail {

// Zero-speed points, cusps and folds of a segment with coefficients c[1..3]
// and span frame f (rank >= 1).
template <std::size_t D, class T>
void classify_speed(segment_analysis<D, T>& a, const std::array<vec<D, T>, 4>& c, const span_frame<D, T>& f,
                    T thr) {
    const T merge = end_merge_distance<T>();
    std::vector<T> interior;
    T speed0, speed1, zthr;
    if (f.rank == 1) {
        // Along the line: q(u) = e . C'(u), a quadratic; the parts of c1, c2,
        // c3 off the line are each below thr, so C'(u) has up to 6 thr of
        // noise off the line, and q's sign is only meaningful beyond that:
        // the rank-1 threshold is 8 thr.
        zthr = 8 * thr;
        const vec<D, T>& e = f.e[0];
        const std::array<T, 3> q{dot(e, c[1]), T(2) * dot(e, c[2]), T(3) * dot(e, c[3])};
        speed0 = std::abs(detail::horner(q, T(0)));
        speed1 = std::abs(detail::horner(q, T(1)));
        T qmin = std::min(detail::horner(q, T(0)), detail::horner(q, T(1)));
        T qmax = std::max(detail::horner(q, T(0)), detail::horner(q, T(1)));
        std::optional<T> vertex;
        if (q[2] != 0) {
            const T v = -q[1] / (2 * q[2]);
            if (v > 0 && v < 1) {
                vertex = v;
                const T qv = detail::horner(q, v);
                qmin = std::min(qmin, qv);
                qmax = std::max(qmax, qv);
            }
        }
        // Non-monotone by more than rounding: the curve retraces itself.
        a.fold = qmin < -zthr && qmax > zthr;
        if (vertex && std::abs(detail::horner(q, *vertex)) <= zthr) {
            interior.push_back(*vertex);  // touches zero: a double zero
        } else {
            for (T r : detail::real_roots(q, T(0), T(1))) interior.push_back(r);
        }
    } else {
        // Minima of |C'(u)|^2: roots of C'.C'' (a cubic), then is the speed
        // zero there? C' = A + B u + C u^2 with A = c1, B = 2 c2, C = 3 c3.
        zthr = thr;
        speed0 = norm(c[1]);
        speed1 = norm(c[1] + T(2) * c[2] + T(3) * c[3]);
        const std::array<vec<D, T>, 3> d1{c[1], T(2) * c[2], T(3) * c[3]};
        const std::array<vec<D, T>, 2> d2{T(2) * c[2], T(6) * c[3]};
        const auto g = dot_poly(d1, d2);
        for (T r : detail::real_roots(g, T(0), T(1))) {
            // The root of C'.C'' is ill-conditioned where that cubic is flat
            // (near-triple roots: a symmetric cusp); the speed itself is
            // not. Polish by Gauss-Newton on C'(u) = 0, u -= C'.C'' / |C''|^2,
            // which uses C' and C'' directly (rounding eps |c| / |C''| in u).
            T u = r, sp = norm(horner_vec(d1, u));
            for (int it = 0; it < 8 && sp > 0; ++it) {
                const vec<D, T> v = horner_vec(d1, u), w = horner_vec(d2, u);
                const T ww = dot(w, w);
                if (!(ww > 0)) break;
                const T nu = std::clamp(u - dot(v, w) / ww, T(0), T(1));
                const T ns = norm(horner_vec(d1, nu));
                if (!(ns < sp)) break;
                u = nu;
                sp = ns;
            }
            if (sp <= thr) interior.push_back(u);
        }
        std::sort(interior.begin(), interior.end());
    }
    bool zero0 = speed0 <= zthr, zero1 = speed1 <= zthr;
    // A zero found within merge distance of an end whose own speed is at
    // the rounding level (<= 2 zthr) is that end's zero: rounding of the
    // small end tangent's direction can move the computed minimum of the
    // speed a few ulps inside (a centripetal segment with theta ~ 1e-15).
    for (T u : interior) {
        if (u <= merge && speed0 <= 2 * zthr) zero0 = true;
        if (u >= 1 - merge && speed1 <= 2 * zthr) zero1 = true;
    }
    if (zero0) a.zero_speed_u.push_back(T(0));
    for (T u : interior) {
        if (zero0 && u <= merge) continue;
        if (zero1 && u >= 1 - merge) continue;
        if (!(u > 0 && u < 1)) continue;
        if (!a.zero_speed_u.empty() && u - a.zero_speed_u.back() <= merge && a.zero_speed_u.back() > 0) continue;
        a.zero_speed_u.push_back(u);
        a.cusp_u.push_back(u);
    }
    if (zero1) a.zero_speed_u.push_back(T(1));
}

// Self-intersection C(s) = C(t), s < t in [0, 1], of a segment whose span is
// a plane. With sigma = s + t and w = s^2 + s t + t^2 = sigma^2 - s t,
// (C(s) - C(t)) / (s - t) = c1 + c2 sigma + c3 w = 0: two linear equations
// in (sigma, w), solved by Cramer's rule in the plane's coordinates.
template <std::size_t D, class T>
void find_loop(segment_analysis<D, T>& a, const std::array<vec<D, T>, 4>& c, const span_frame<D, T>& f,
               T scale) {
    std::array<std::array<T, 2>, 4> q{};  // c_k in plane coordinates
    for (std::size_t k = 1; k < 4; ++k) {
        if constexpr (D == 2) {
            q[k] = {c[k][0], c[k][1]};
        } else {
            q[k] = {dot(c[k], f.e[0]), dot(c[k], f.e[1])};
        }
    }
    auto cross = [](const std::array<T, 2>& x, const std::array<T, 2>& y) { return x[0] * y[1] - x[1] * y[0]; };
    const T det = cross(q[2], q[3]);
    if (det == 0) return;  // c2 || c3 and c1 off their line: no solution
    T sigma = cross(q[3], q[1]) / det;
    T w = cross(q[1], q[2]) / det;
    // Cramer's rule loses accuracy when c2 and c3 are nearly parallel:
    // iterative refinement on the residual c1 + c2 sigma + c3 w (the
    // divided difference (C(s) - C(t)) / (s - t), which, unlike C(s) - C(t),
    // has no trivial solution s = t to slide into).
    for (int it = 0; it < 3; ++it) {
        const std::array<T, 2> r{q[1][0] + q[2][0] * sigma + q[3][0] * w, q[1][1] + q[2][1] * sigma + q[3][1] * w};
        const T ds = cross(q[3], r) / det, dw = cross(r, q[2]) / det;
        if (!(std::isfinite(ds) && std::isfinite(dw))) break;
        sigma += ds;
        w += dw;
    }
    const T disc = 4 * w - 3 * sigma * sigma;  // (t - s)^2
    if (!(disc > 0) || !std::isfinite(disc)) return;  // disc == 0 is a cusp, < 0 no real pair
    const T root = std::sqrt(disc);
    const T prod = sigma * sigma - w;  // s t
    T s, t;
    if (sigma >= 0) {
        t = (sigma + root) / 2;
        s = t != 0 ? prod / t : (sigma - root) / 2;
    } else {
        s = (sigma - root) / 2;
        t = s != 0 ? prod / s : (sigma + root) / 2;
    }
    if (s > t) std::swap(s, t);
    // Far outside [0, 1]: no loop in the segment, whatever the rounding.
    if (!(s > T(-0.5) && t < T(1.5))) return;
    // The residual of the divided difference at (s, t), relative to scale.
    const T sum = s + t, sq = s * s + s * t + t * t;
    const T gap = norm(c[1] + c[2] * sum + c[3] * sq);
    // Allow the ends to be missed by a few ulps of rounding.
    const T slack = 8 * std::numeric_limits<T>::epsilon();
    if (!(s >= -slack && t <= 1 + slack && s < t)) return;
    s = std::max(s, T(0));
    t = std::min(t, T(1));
    // Guard against a nearly singular system: the two points must coincide.
    if (!(gap <= T(1e-8) * scale)) return;
    // A loop of parameter width below end_merge_distance is at most about
    // |C''| (t - s)^2 <= zero_speed_tolerance * eps * scale across: a cusp
    // within rounding (and the speed there is within rounding of zero), not
    // a loop one can tell from rounding noise.
    if (t - s <= end_merge_distance<T>()) return;
    a.self_intersection.push_back({s, t});
}

// Largest value of the true function dist(u) over the candidate parameters.
template <class T, class F>
void keep_max(T& best, T& best_u, T u, F&& dist) {
    const T d = dist(u);
    if (d > best) { best = d; best_u = u; }
}

}  // namespace detail

namespace detail {

// The analysis proper. rel = {B1 - B0, B2 - B0, B3 - B0} as accurately as
// the caller knows them (from the Hermite tangents and the exact chord
// P2 - P1 when the control points are known: the power basis loses
// |c| / |chord| of relative accuracy on the chord when the tangents dwarf it).
template <std::size_t D, class T>
segment_analysis<D, T> analyze_core(const cubic_segment<D, T>& seg, const std::array<vec<D, T>, 3>& rel) {
    using point = vec<D, T>;
    segment_analysis<D, T> a;
    a.segment = seg;
    a.bezier = {seg.origin, seg.origin + rel[0], seg.origin + rel[1], seg.origin + rel[2]};
    const std::array<point, 4> c = detail::relative_coefficients(seg);
    const T scale = norm(c[1]) + norm(c[2]) + norm(c[3]);
    const T thr = T(zero_speed_tolerance) * std::numeric_limits<T>::epsilon() * scale;
    if (!(scale > 0)) return a;  // a constant segment: rank 0, nothing moves

    // 1. Span and classification.
    const auto f = detail::orthonormal_span<D, T>({c[1], c[2], c[3]}, thr);
    a.rank = f.rank;
    detail::classify_speed(a, c, f, thr);
    if (f.rank == 2 && a.cusp_u.empty()) detail::find_loop(a, c, f, scale);

    // 2. Chord frame: chord = B3 - B0 = c1 + c2 + c3 (relative to B0).
    const point chord = rel[2];
    const T L2 = dot(chord, chord);
    const point b1 = rel[0], b2 = rel[1];  // B1 - B0, B2 - B0
    const std::array<T, 7> dist0 = detail::dot_poly(c, c);           // |C(u) - B0|^2
    std::array<point, 4> cm = c;                                       // C(u) - B3
    cm[0] = -chord;
    const std::array<T, 7> dist3 = detail::dot_poly(cm, cm);
    std::vector<T> cand{T(0), T(1)};
    auto add_roots = [&](const auto& poly) {
        for (T r : detail::real_roots(detail::derivative(poly), T(0), T(1))) cand.push_back(r);
    };
    add_roots(dist0);
    add_roots(dist3);

    if (L2 > 0) {
        const T L = std::sqrt(L2);
        const point e = chord / L;
        chord_projection<T> pr;
        // lambda(u) = (C(u) - B0).chord / |chord|^2 = l1 u + l2 u^2 + l3 u^3.
        const std::array<T, 4> lam{T(0), dot(c[1], chord) / L2, dot(c[2], chord) / L2, dot(c[3], chord) / L2};
        const auto dlam = detail::derivative(lam);
        pr.bezier = {dot(b1, chord) / L2, dot(b2, chord) / L2};
        pr.theorem2 = pr.bezier[0] > 0 && pr.bezier[0] < 1 && pr.bezier[1] > 0 && pr.bezier[1] < 1;
        // Minimum of the quadratic lambda'(u): ends and vertex.
        pr.derivative_min = detail::horner(dlam, T(0));
        pr.derivative_min_u = 0;
        auto consider_min = [&](T u) {
            const T v = detail::horner(dlam, u);
            if (v < pr.derivative_min) { pr.derivative_min = v; pr.derivative_min_u = u; }
        };
        consider_min(T(1));
        if (dlam[2] != 0) {
            const T v = -dlam[1] / (2 * dlam[2]);
            if (v > 0 && v < 1) consider_min(v);
        }
        // Range of lambda: ends (0 and 1 by definition of the chord) and the
        // roots of lambda'.
        pr.range = {T(0), T(1)};
        for (T r : detail::real_roots(dlam, T(0), T(1))) {
            const T v = detail::horner(lam, r);
            pr.range[0] = std::min(pr.range[0], v);
            pr.range[1] = std::max(pr.range[1], v);
        }
        a.projection = pr;

        // Heights of B1, B2 and the Bézier bound on the chord-line distance.
        a.bezier_height = {norm(detail::perpendicular_part(b1, e)), norm(detail::perpendicular_part(b2, e))};
        a.bezier_bound = T(0.75) * std::max(a.bezier_height[0], a.bezier_height[1]);

        // Distance to the chord line: |perp(C(u))|; maxima at roots of the
        // derivative of its square (degree 5).
        const std::array<point, 4> p{point{}, detail::perpendicular_part(c[1], e), detail::perpendicular_part(c[2], e),
                                     detail::perpendicular_part(c[3], e)};
        const auto g = detail::dot_poly(p, p);
        std::vector<T> line_cand{T(0), T(1)};
        for (T r : detail::real_roots(detail::derivative(g), T(0), T(1))) line_cand.push_back(r);
        for (T u : line_cand)
            detail::keep_max(a.max_chord_line_distance, a.max_chord_line_distance_u, u,
                             [&](T x) { return norm(detail::horner_vec(p, x)); });
        // Distance to the closed segment: piecewise (before B0, along, beyond
        // B3); candidates are each piece's critical points and the switch
        // points lambda = 0, 1. Evaluating the true distance at every
        // candidate gives the exact maximum.
        cand.insert(cand.end(), line_cand.begin(), line_cand.end());
        for (T r : detail::real_roots(lam, T(0), T(1))) cand.push_back(r);
        std::array<T, 4> lam1 = lam;
        lam1[0] = -1;
        for (T r : detail::real_roots(lam1, T(0), T(1))) cand.push_back(r);
        for (T u : cand) {
            const point x = detail::horner_vec(c, u);
            const T d = detail::distance_to_segment(x, point{}, chord);
            if (d > a.max_chord_distance) { a.max_chord_distance = d; a.max_chord_distance_u = u; }
            const T l = dot(x, chord) / L2;
            if (l < 0) a.overshoot[0] = std::max(a.overshoot[0], norm(x));
            if (l > 1) a.overshoot[1] = std::max(a.overshoot[1], norm(x - chord));
        }
    } else {
        // Zero chord (the segment returns to its start): the chord "line"
        // and segment are the point B0.
        for (T u : cand) {
            detail::keep_max(a.max_chord_distance, a.max_chord_distance_u, u,
                             [&](T x) { return norm(detail::horner_vec(c, x)); });
        }
        a.max_chord_line_distance = a.max_chord_distance;
        a.max_chord_line_distance_u = a.max_chord_distance_u;
    }
    return a;
}

}  // namespace detail

/// Analysis of a cubic segment on its own: classification, chord frame,
/// measured distances. No paper bounds (those need the control points and
/// knots: see the other overloads).
template <std::size_t D, class T>
segment_analysis<D, T> analyze_segment(const cubic_segment<D, T>& seg) {
    const vec<D, T> b1 = seg.c1 / T(3), b2 = (T(2) * seg.c1 + seg.c2) / T(3), b3 = seg.c1 + seg.c2 + seg.c3;
    return detail::analyze_core(seg, {b1, b2, b3});
}

/// Analysis of the Catmull-Rom segment from p[1] to p[2] with knot intervals
/// h = {t1 - t0, t2 - t1, t3 - t2} (zero intervals follow the library's
/// convention: a zero chord velocity), with tangents scaled by 1 - tension.
/// Adds the paper bounds when every interval and edge is nonzero and
/// tension is 0.
template <std::size_t D, class T>
segment_analysis<D, T> analyze_segment(const std::array<vec<D, T>, 4>& p, const std::array<T, 3>& h,
                                       T tension = T(0)) {
    using point = vec<D, T>;
    // Chord velocities and the Catmull-Rom tangents, as catmull_rom builds them.
    const point v0 = h[0] > 0 ? (p[1] - p[0]) / h[0] : point{};
    const point v1 = h[1] > 0 ? (p[2] - p[1]) / h[1] : point{};
    const point v2 = h[2] > 0 ? (p[3] - p[2]) / h[2] : point{};
    const T s1 = h[0] + h[1], s2 = h[1] + h[2];
    point out1 = s1 > 0 ? ((h[1]) * v0 + (h[0]) * v1) / s1 : point{};
    point in2 = s2 > 0 ? ((h[2]) * v1 + (h[1]) * v2) / s2 : point{};
    const T keep = T(1) - tension;
    if (keep != T(1)) { out1 *= keep; in2 *= keep; }
    const point m0 = h[1] * out1, m1 = h[1] * in2, chord = p[2] - p[1];
    const auto seg = cubic_segment<D, T>::hermite(p[1], p[2], m0, m1, T(0), h[1]);
    segment_analysis<D, T> a = detail::analyze_core(seg, {m0 / T(3), chord - m1 / T(3), chord});
    a.bezier[3] = p[2];
    if (tension == T(0)) a.bounds = segment_paper_bounds(p, h);
    return a;
}

/// Analysis of the segment from p[1] to p[2] with knots from alpha
/// (t(i+1) - t(i) = |P(i+1) - P(i)|^alpha; coincident points get a zero
/// interval, as in catmull_rom).
template <std::size_t D, class T>
segment_analysis<D, T> analyze_segment(const std::array<vec<D, T>, 4>& p, double alpha, T tension = T(0)) {
    const auto iv = knot_intervals(std::span<const vec<D, T>>(p.data(), 4), alpha, false);
    return analyze_segment(p, std::array<T, 3>{iv[0], iv[1], iv[2]}, tension);
}

/// Convenience: four points in any order of arguments' natural reading.
template <std::size_t D, class T>
segment_analysis<D, T> analyze_segment(const vec<D, T>& p0, const vec<D, T>& p1, const vec<D, T>& p2,
                                       const vec<D, T>& p3, double alpha) {
    return analyze_segment(std::array<vec<D, T>, 4>{p0, p1, p2, p3}, alpha);
}

namespace detail {

// Is segment i of the curve the plain Catmull-Rom segment of its four
// control points (an interior segment of a curve built without tension or
// Kochanek-Bartels values)? Read from how the curve was built
// (catmull_rom::options()), never guessed from its Bézier points: a guess
// with a tolerance depends on where the curve lies. Returns the points and
// knot intervals when it is, and every interval is nonzero.
template <std::size_t D, class T>
std::optional<std::pair<std::array<vec<D, T>, 4>, std::array<T, 3>>> plain_neighbourhood(
    const catmull_rom<D, T>& c, std::size_t i) {
    const auto pts = c.points();
    const auto h_of = c.intervals();  // as computed, not differences of the rounded knots
    const std::size_t n = pts.size(), nseg = c.segment_count();
    if (!c.closed() && (i == 0 || i + 1 >= nseg)) return std::nullopt;  // an end segment: end conditions
    const auto& o = c.options();
    if (c.given_tangents() || o.tension != T(0) || !o.kb.empty()) return std::nullopt;
    auto interval = [&](std::size_t k) { return h_of[k]; };
    const std::size_t ib = (i + nseg - 1) % nseg, ia = (i + 1) % nseg;
    std::array<vec<D, T>, 4> p{pts[(i + n - 1) % n], pts[i], pts[(i + 1) % n], pts[(i + 2) % n]};
    std::array<T, 3> h{interval(ib), interval(i), interval(ia)};
    if (!(h[0] > 0 && h[1] > 0 && h[2] > 0)) return std::nullopt;
    return std::make_pair(p, h);
}

}  // namespace detail

/// Segment i's analysis, as analyze(c)[i], without the others (a report
/// written segment by segment: crspline::write_report).
template <std::size_t D, class T>
segment_analysis<D, T> analyze(const catmull_rom<D, T>& c, std::size_t i) {
    const auto& seg = c.segment(i);
    const auto pts = c.points();
    const auto [v0, v1] = c.tangents(i);
    const vec<D, T> chord = pts[(i + 1) % pts.size()] - pts[i];
    segment_analysis<D, T> a = detail::analyze_core(seg, {(seg.h / T(3)) * v0, chord - (seg.h / T(3)) * v1, chord});
    a.index = i;
    a.bezier = c.bezier(i);
    if (const auto nb = detail::plain_neighbourhood(c, i)) a.bounds = segment_paper_bounds(nb->first, nb->second);
    return a;
}

/// Analysis of every segment of a curve. Interior segments of a curve built
/// as plain Catmull-Rom (tension 0, no Kochanek-Bartels: catmull_rom::options())
/// also get the paper
/// bounds, computed from points[i-1..i+2] and the curve's knots. End segments
/// of an open curve have no P(i-1) or P(i+2): their end tangents come from the
/// end conditions, Eq. 5, 6 and 8 do not exist there, and `bounds` is nullopt;
/// bezier_height and bezier_bound (from the actual Bézier points) still hold.
template <std::size_t D, class T>
std::vector<segment_analysis<D, T>> analyze(const catmull_rom<D, T>& c) {
    std::vector<segment_analysis<D, T>> out;
    out.reserve(c.segment_count());
    for (std::size_t i = 0; i < c.segment_count(); ++i) out.push_back(analyze(c, i));
    return out;
}

}  // namespace crspline
