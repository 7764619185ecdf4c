// crspline: the proof behind fit(): one cubic segment against the part of
// the input polyline it covers, both ways.
//
// Curve to polyline. A cubic piece lies in the convex hull of its Bézier
// points, so within e of its chord (e: the inner Bézier points' distance to
// the chord). The distance to the polyline is 1-Lipschitz, so the chord
// [X, Y] of length L is within (d(X) + d(Y) + L) / 2 of it; and the distance
// to one polyline segment S is convex, so the chord is within max(|X S|,
// |Y S|) of S. A piece proved by neither bound is split in two (de
// Casteljau at 1/2) and each half tried again, up to a fixed depth; a
// piece end farther than the limit (a point of the curve) ends the search
// at once. Any subset of the polyline's segments gives an upper bound, so
// the search looks at the segments near the piece first.
//
// Polyline to curve. Each input point q is within dist(q, chord) + e of the
// curve, for any piece of it with chord [C(u0), C(u1)] and flatness bound e
// (tessellate.hpp's flatness_bound: the piece is within e of its chord, and
// every chord point within e of the piece); where no piece proves it, the
// exact nearest point (nearest.hpp) decides.
//
// Rounding: every bound is compared with the limit minus a slack of many
// ulps of the coordinates' magnitude (fit.hpp's rounding floor), which
// covers the rounding of the Bézier points, of the splits and of the
// distances themselves.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

#include "../nearest.hpp"
#include "../segment.hpp"
#include "../tessellate.hpp"
#include "../vec.hpp"

namespace crspline::detail {

template <std::size_t D, class T>
T fit_point_segment_distance(const vec<D, T>& p, const vec<D, T>& a, const vec<D, T>& b) noexcept {
    const vec<D, T> d = b - a, w = p - a;
    const T l2 = dot(d, d);
    const T f = l2 > 0 ? std::clamp(dot(w, d) / l2, T(0), T(1)) : T(0);
    return norm(w - f * d);
}

/// What the proof of one segment found: whether both directions are within
/// the limit, and the largest bound established (the curve-to-polyline and
/// the polyline-to-curve one), meaningful when proved.
template <class T>
struct segment_proof {
    bool proved = false;
    T curve_to_input = 0;
    T input_to_curve = 0;
    T worst() const noexcept { return std::max(curve_to_input, input_to_curve); }
};

/// The polyline part [first, last] (inclusive, indices into `poly`, possibly
/// wrapping around a closed polyline of poly.size() points) as a view that
/// yields its points in order.
template <std::size_t D, class T>
struct poly_range {
    std::span<const vec<D, T>> poly;
    std::size_t first = 0;
    std::size_t count = 0;  // points in the range (at least 2)
    const vec<D, T>& operator[](std::size_t k) const noexcept {
        std::size_t i = first + k;
        if (i >= poly.size()) i -= poly.size();
        return poly[i];
    }
};

/// How far the curve-to-polyline search may split a piece: 2^-depth of the
/// segment, far below any tolerance the rounding floor allows.
inline constexpr int fit_max_depth = 16;

// De Casteljau halves of a Bézier cubic.
template <std::size_t D, class T>
void split_half(const std::array<vec<D, T>, 4>& b, std::array<vec<D, T>, 4>& l, std::array<vec<D, T>, 4>& r) noexcept {
    const T h = T(0.5);
    const auto a0 = h * (b[0] + b[1]), a1 = h * (b[1] + b[2]), a2 = h * (b[2] + b[3]);
    const auto q0 = h * (a0 + a1), q1 = h * (a1 + a2);
    const auto m = h * (q0 + q1);
    l = {b[0], a0, q0, m};
    r = {m, q1, a2, b[3]};
}

/// The distance from x to the polyline range, over the segments near
/// `hint` (an upper bound on the distance to the whole range), or over all
/// of them; `hint` moves to the nearest segment found.
template <std::size_t D, class T>
T range_distance(const vec<D, T>& x, const poly_range<D, T>& pr, std::size_t& hint, bool all) {
    const std::size_t nseg = pr.count - 1;
    const std::size_t lo = all ? 0 : (hint > 2 ? hint - 2 : 0), hi = all ? nseg : std::min(nseg, hint + 3);
    T best = std::numeric_limits<T>::infinity();
    for (std::size_t s = lo; s < hi; ++s) {
        const T d = fit_point_segment_distance(x, pr[s], pr[s + 1]);
        if (d < best) {
            best = d;
            hint = s;
        }
    }
    return best;
}

/// Curve to polyline for one Bézier piece q whose end points are at
/// distances a and b (upper bounds) from the polyline range: true when
/// every point of the piece is proved within `limit`; `worst` grows to the
/// largest bound used. The piece is within e of its chord (e: the farther
/// inner Bézier point's distance to the chord); the chord, of length L,
/// is within (a + b + L) / 2 of the polyline (the distance to a set is
/// 1-Lipschitz), and within max(|X - S|, |Y - S|) of a segment S that both
/// its ends are near (convexity).
template <std::size_t D, class T>
bool piece_within(const std::array<vec<D, T>, 4>& q, T a, T b, const poly_range<D, T>& pr, T limit, int depth,
                  T& worst, std::size_t& hint) {
    using point = vec<D, T>;
    const T e = std::max(fit_point_segment_distance(q[1], q[0], q[3]), fit_point_segment_distance(q[2], q[0], q[3]));
    const T len = norm(q[3] - q[0]);
    T chord = (a + b + len) / T(2);
    if (e + std::max(a, b) <= limit && e + chord > limit) {
        const std::size_t nseg = pr.count - 1;
        const std::size_t lo = hint > 2 ? hint - 2 : 0, hi = std::min(nseg, hint + 3);
        for (std::size_t s = lo; s < hi; ++s)
            chord = std::min(chord, std::max(fit_point_segment_distance(q[0], pr[s], pr[s + 1]),
                                             fit_point_segment_distance(q[3], pr[s], pr[s + 1])));
    }
    if (e + chord <= limit) {
        worst = std::max(worst, e + chord);
        return true;
    }
    if (depth >= fit_max_depth) return false;
    std::array<point, 4> left, right;
    split_half(q, left, right);
    // The middle is a point of the curve: farther than the limit from every
    // segment of the range, nothing can prove the piece.
    std::size_t h = hint;
    T m = range_distance(left[3], pr, h, false);
    if (m > limit) m = range_distance(left[3], pr, h, true);
    if (m > limit) return false;
    hint = h;
    return piece_within(left, a, m, pr, limit, depth + 1, worst, hint) &&
           piece_within(right, m, b, pr, limit, depth + 1, worst, hint);
}

/// Polyline to curve: whether every point pr[first .. end) is proved within
/// `limit` of the segment; `worst` grows to the largest bound used. Pieces
/// of equal u, as many as make each piece flat within `flat_target` (at
/// most 32), then each point against the pieces near the last one that
/// proved a point, then against all of them, then the exact nearest point.
template <std::size_t D, class T>
bool input_within(const cubic_segment<D, T>& seg, const poly_range<D, T>& pr, T limit, T flat_target,
                  std::size_t first, std::size_t end, T& worst) {
    using point = vec<D, T>;
    const std::size_t pieces = std::min<std::size_t>(32, uniform_piece_count(seg, flat_target));
    std::array<point, 33> at;
    std::array<T, 32> flat;
    for (std::size_t l = 0; l <= pieces; ++l) at[l] = seg.at(T(l) / T(pieces));
    for (std::size_t l = 0; l < pieces; ++l) flat[l] = flatness_bound(seg, T(l) / T(pieces), T(l + 1) / T(pieces));
    std::size_t hint = 0;
    const std::size_t stop = std::min(end, pr.count);
    for (std::size_t k = first; k < stop; ++k) {
        const point& p = pr[k];
        T best = std::numeric_limits<T>::infinity(), lower = best;
        auto try_piece = [&](std::size_t l) {
            const T c = fit_point_segment_distance(p, at[l], at[l + 1]);
            lower = std::min(lower, c - flat[l]);
            if (c + flat[l] < best) {
                best = c + flat[l];
                hint = l;
            }
        };
        const std::size_t h0 = hint;
        for (std::size_t l = h0; l < std::min(pieces, h0 + 3); ++l) try_piece(l);
        if (best > limit)
            for (std::size_t l = 0; l < pieces; ++l) try_piece(l);
        if (best > limit) {
            // Every piece farther than the limit: the point is (the pieces
            // are within their flatness of the curve both ways).
            if (lower > limit) return false;
            // The exact nearest point.
            best = std::sqrt(nearest(seg, p).distance_sq);
            if (!(best <= limit)) return false;
        }
        worst = std::max(worst, best);
    }
    return true;
}

/// Proves the segment `seg` (u in [0, 1]) within `tolerance` of the polyline
/// range `pr` both ways (the range's two end points are the segment's ends
/// in subset mode, and are checked like the others unless first_point and
/// end_point leave them out), with `slack` for rounding. The bounds found
/// include the slack.
template <std::size_t D, class T>
segment_proof<T> prove_segment(const cubic_segment<D, T>& seg, const poly_range<D, T>& pr, T tolerance, T slack,
                               std::size_t first_point = 0, std::size_t end_point = std::size_t(-1)) {
    segment_proof<T> res;
    const T limit = tolerance - slack;
    // 1. Polyline to curve (first: on a segment too long it fails soonest).
    T worst = 0;
    if (!input_within(seg, pr, limit, tolerance / T(4), first_point, end_point, worst)) return res;
    res.input_to_curve = worst + slack;
    // 2. Curve to polyline.
    {
        const auto b = to_bezier(seg);
        T far = 0;
        std::size_t hint = 0, h1 = pr.count - 2;
        const T a0 = range_distance(b[0], pr, hint, false), a1 = range_distance(b[3], pr, h1, false);
        if (!(a0 <= limit) || !(a1 <= limit)) return res;
        if (!piece_within(b, a0, a1, pr, limit, 0, far, hint)) return res;
        res.curve_to_input = far + slack;
    }
    res.proved = true;
    return res;
}

/// The search's quick test of a segment (not a proof: fit() proves the
/// segments it keeps with prove_segment and repairs those that fail): the
/// input points by input_within, then the curve sampled at twice as many
/// points as the range has, each within the tolerance less a margin (3%)
/// of the polyline segments near it.
template <std::size_t D, class T>
bool quick_segment_test(const cubic_segment<D, T>& seg, const poly_range<D, T>& pr, T tolerance, T slack,
                        std::size_t first_point, std::size_t end_point) {
    const T limit = tolerance - slack;
    T worst = 0;
    if (!input_within(seg, pr, limit, tolerance / T(4), first_point, end_point, worst)) return false;
    const T sampled_limit = limit * T(0.97);
    const std::size_t m = 2 * pr.count;
    std::size_t hint = 0;
    for (std::size_t k = 1; k < m; ++k) {
        const vec<D, T> x = seg.at(T(k) / T(m));
        T d = range_distance(x, pr, hint, false);
        if (d > sampled_limit) d = range_distance(x, pr, hint, true);
        if (d > sampled_limit) return false;
    }
    return true;
}

}  // namespace crspline::detail
