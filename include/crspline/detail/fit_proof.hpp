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
#include <cstdint>
#include <limits>
#include <memory>
#include <span>

#include "../nearest.hpp"
#include "../segment.hpp"
#include "../tessellate.hpp"
#include "../vec.hpp"

namespace crspline::detail {

/// The offset from p to its nearest point on the segment from a along d
/// (d = b - a, l2 = dot(d, d)), whose norm is p's distance to the segment.
/// A caller that tests one segment against many points computes d and l2
/// once: the same operations, so every offset has the same bits.
///
/// The foot's parameter is f = clamp(dot(w, d) / l2, 0, 1). Where l2 is
/// finite and positive (so is d), dot(w, d) <= 0 gives f = 0 and the
/// offset w, and dot(w, d) >= l2 a quotient >= 1 after rounding, so f = 1
/// and the offset w - d: the same numbers without the division (up to the
/// sign of a zero component, which norm() does not see).
template <std::size_t D, class T>
[[gnu::always_inline]] inline vec<D, T> fit_segment_offset(const vec<D, T>& p, const vec<D, T>& a, const vec<D, T>& d,
                                                           T l2) noexcept {
    const vec<D, T> w = p - a;
    const T t = dot(w, d);
    if (l2 > 0 && l2 < std::numeric_limits<T>::infinity()) {
        if (t <= 0) return w;
        if (t >= l2) return w - d;
    }
    const T f = l2 > 0 ? std::clamp(t / l2, T(0), T(1)) : T(0);
    return w - f * d;
}

/// The largest x with ok(x), for ok monotone (true up to some number,
/// false beyond it), stepping from a guess within a few ulps of it; `found`
/// false where 64 steps each way did not verify it.
template <class T, class Ok>
T largest_where(T guess, Ok ok, bool& found) {
    const T up = std::numeric_limits<T>::infinity();
    T x = guess;
    for (int k = 0; k < 64 && !ok(x); ++k) x = std::nextafter(x, -up);
    for (int k = 0; k < 64 && ok(std::nextafter(x, up)); ++k) x = std::nextafter(x, up);
    found = ok(x) && !ok(std::nextafter(x, up));
    return x;
}

/// A distance limit and the squares it splits: norm(v) <= limit tested on
/// dot(v, v), without the square root, where norm() takes sqrt(dot(v, v))
/// (its plain range). std::sqrt is correctly rounded, hence monotone: with
/// s the largest number whose root is <= limit, sqrt(q) <= limit exactly
/// when q <= s. `square` is that s, verified (`exact`); where it could not
/// be found (a limit whose square is not a normal number) every square
/// takes its root.
template <class T>
struct root_limit {
    T limit = 0;
    T square = 0;
    bool exact = false;
    explicit root_limit(T lim) noexcept : limit(lim) {
        const T guess = lim * lim;
        if (!(guess >= std::numeric_limits<T>::min() && guess < std::numeric_limits<T>::max())) return;
        square = largest_where(guess, [lim](T q) { return std::sqrt(q) <= lim; }, exact);
    }
};

/// Whether q = dot(v, v) shows that norm(v) takes its plain formula
/// sqrt(q) (D > 1), without max_abs(v): q > 2 D lo^2 rules out max|v_i| <=
/// lo (then q <= D lo^2 but for rounding) and q < max / (2 D) rules out
/// max|v_i| >= hi (then q >= hi^2 = max / D but for rounding), lo and hi
/// being plain_norm_range's bounds. Outside, the caller asks norm(v).
template <std::size_t D, class T>
[[gnu::always_inline]] inline bool plain_square(T q) noexcept {
    const T lo = std::sqrt(std::numeric_limits<T>::min()) / std::numeric_limits<T>::epsilon();
    return D > 1 && q > T(2 * D) * lo * lo && q < std::numeric_limits<T>::max() / T(2 * D);
}

/// norm(v), or +infinity in its stead where norm(v) > r.limit (for tests
/// that only ask whether norm(v) plus something >= 0 is within the limit).
template <std::size_t D, class T>
[[gnu::always_inline]] inline T norm_or_far(const vec<D, T>& v, const root_limit<T>& r) noexcept {
    const T q = dot(v, v);
    if (plain_square<D>(q)) return r.exact && q > r.square ? std::numeric_limits<T>::infinity() : std::sqrt(q);
    return norm(v);
}

/// Whether norm(v) <= r.limit.
template <std::size_t D, class T>
[[gnu::always_inline]] inline bool norm_within(const vec<D, T>& v, const root_limit<T>& r) noexcept {
    const T q = dot(v, v);
    if (plain_square<D>(q)) return r.exact ? q <= r.square : std::sqrt(q) <= r.limit;
    return norm(v) <= r.limit;
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
    /// The points at odd indices of `poly` are not input points but the
    /// middles of its segments (free mode's candidates): on the polyline,
    /// they need no proof of their distance to the curve.
    bool odd_middles = false;
    /// Whether range point k is an input point (poly has an even number of
    /// points when the range wraps: a closed polyline with its middles).
    bool is_input(std::size_t k) const noexcept { return !odd_middles || ((first + k) & 1) == 0; }
    const vec<D, T>& operator[](std::size_t k) const noexcept {
        std::size_t i = first + k;
        if (i >= poly.size()) i -= poly.size();
        return poly[i];
    }
    /// x's offset from the range's segment s (points s, s + 1).
    [[gnu::always_inline]] vec<D, T> offset(const vec<D, T>& x, std::size_t s) const noexcept {
        const vec<D, T>& a = (*this)[s];
        const vec<D, T> d = (*this)[s + 1] - a;
        return fit_segment_offset(x, a, d, dot(d, d));
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
/// of them; `hint` moves to the nearest segment found (the first of equal
/// ones). A segment whose offset's square is at least the best one's takes
/// no root: its distance, the root (monotone) of a larger square, would not
/// be smaller.
template <std::size_t D, class T>
T range_distance(const vec<D, T>& x, const poly_range<D, T>& pr, std::size_t& hint, bool all) {
    const std::size_t nseg = pr.count - 1;
    const std::size_t lo = all ? 0 : (hint > 2 ? hint - 2 : 0), hi = all ? nseg : std::min(nseg, hint + 3);
    T best = std::numeric_limits<T>::infinity();
    T best_square = best;  // dot(v, v) of the best where norm() took sqrt(dot(v, v)); else infinity
    for (std::size_t s = lo; s < hi; ++s) {
        const vec<D, T> v = pr.offset(x, s);
        T d, square = dot(v, v);
        if (plain_square<D>(square)) {
            if (square >= best_square) continue;
            d = std::sqrt(square);
        } else {
            d = norm(v);
            square = std::numeric_limits<T>::infinity();
        }
        if (d < best) {
            best = d;
            best_square = square;
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
    const point d = q[3] - q[0];
    const T l2 = dot(d, d);
    const T e = std::max(norm(fit_segment_offset(q[1], q[0], d, l2)), norm(fit_segment_offset(q[2], q[0], d, l2)));
    const T len = norm(d);
    T chord = (a + b + len) / T(2);
    if (e + std::max(a, b) <= limit && e + chord > limit) {
        const std::size_t nseg = pr.count - 1;
        const std::size_t lo = hint > 2 ? hint - 2 : 0, hi = std::min(nseg, hint + 3);
        for (std::size_t s = lo; s < hi; ++s) {
            // min(chord, max(d0, d3)): no change where d0 >= chord.
            const T d0 = norm(pr.offset(q[0], s));
            if (d0 < chord) chord = std::min(chord, std::max(d0, norm(pr.offset(q[3], s))));
        }
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

/// Room for an X built later: not zeroed on construction (vec<D, T> zeroes
/// itself), for tables of which a test builds few entries. An entry's
/// lifetime begins with std::construct_at (X's default constructor is not
/// trivial, so assigning to the member would not begin it); X is trivially
/// destructible.
template <class X>
union fit_slot {
    X x;
    fit_slot() noexcept {}
};

/// The pieces of equal u that input_within tests points against: piece l
/// runs from seg.at(l / n) to seg.at((l + 1) / n), and is within flat(l) of
/// the curve both ways (flatness_bound); n makes each piece flat within
/// `flat_target`, 32 at most. Each chord and each flatness bound is built
/// on first use (a quick test looks at few pieces, and needs no flatness
/// for most points): the same operations on the same numbers whenever it
/// is built, so the same bits.
template <std::size_t D, class T>
class fit_pieces {
public:
    using point = vec<D, T>;
    fit_pieces(const cubic_segment<D, T>& seg, T flat_target) : seg_(seg) {
        const std::size_t want = uniform_piece_count(seg, flat_target);
        n_ = std::min<std::size_t>(32, want);
        bounded_ = want <= 32 && flat_target * std::numeric_limits<T>::epsilon() >= std::numeric_limits<T>::min();
        const T big = std::numeric_limits<T>::max() / T(64);
        for (std::size_t i = 0; i < D; ++i) bounded_ = bounded_ && std::abs(seg.c2[i]) <= big && std::abs(seg.c3[i]) <= big;
    }
    std::size_t size() const noexcept { return n_; }
    /// Whether the count makes every piece flat within the target up to
    /// rounding (see quick_limits): not capped at 32, C'' computed without
    /// overflow (finite c2, c3 far below the largest number), and a target
    /// far above the subnormal numbers' absolute rounding.
    bool bounded() const noexcept { return bounded_; }
    /// p's offset from piece l's chord (fit_segment_offset).
    point offset(const point& p, std::size_t l) {
        if (!(have_chord_ >> l & 1)) {
            const point a = at(l), d = at(l + 1) - a;
            std::construct_at(&chords_[l].x, chord{a, d, dot(d, d)});
            have_chord_ |= std::uint64_t(1) << l;
        }
        const chord& c = chords_[l].x;
        return fit_segment_offset(p, c.a, c.d, c.l2);
    }
    /// p's distance to piece l's chord.
    T distance(const point& p, std::size_t l) { return norm(offset(p, l)); }
    /// Piece l's flatness bound.
    T flat(std::size_t l) {
        if (!(have_flat_ >> l & 1)) {
            flat_[l] = flatness_bound(seg_, T(l) / T(n_), T(l + 1) / T(n_));
            have_flat_ |= std::uint64_t(1) << l;
        }
        return flat_[l];
    }

private:
    struct chord {
        point a, d;  // start and direction (end - start)
        T l2;        // dot(d, d)
    };
    const point& at(std::size_t l) {
        if (!(have_at_ >> l & 1)) {
            std::construct_at(&at_[l].x, seg_.at(T(l) / T(n_)));
            have_at_ |= std::uint64_t(1) << l;
        }
        return at_[l].x;
    }
    const cubic_segment<D, T>& seg_;
    std::size_t n_;
    bool bounded_;
    std::uint64_t have_at_ = 0, have_chord_ = 0, have_flat_ = 0;
    std::array<fit_slot<point>, 33> at_;
    std::array<fit_slot<chord>, 32> chords_;
    std::array<T, 32> flat_;
};

/// Polyline to curve: whether every point pr[first .. end) is proved within
/// `limit` of the segment; `worst` grows to the largest bound used. Pieces
/// of equal u (fit_pieces), then each point against the pieces near the
/// last one that proved a point, then against all of them, then the exact
/// nearest point.
template <std::size_t D, class T>
bool input_within(const cubic_segment<D, T>& seg, const poly_range<D, T>& pr, T limit, T flat_target,
                  std::size_t first, std::size_t end, T& worst) {
    using point = vec<D, T>;
    fit_pieces<D, T> pieces(seg, flat_target);
    const std::size_t n = pieces.size();
    std::size_t hint = 0;
    const std::size_t stop = std::min(end, pr.count);
    for (std::size_t k = first; k < stop; ++k) {
        if (!pr.is_input(k)) continue;
        const point& p = pr[k];
        T best = std::numeric_limits<T>::infinity(), lower = best;
        auto try_piece = [&](std::size_t l) {
            const T c = pieces.distance(p, l), flat = pieces.flat(l);
            lower = std::min(lower, c - flat);
            if (c + flat < best) {
                best = c + flat;
                hint = l;
            }
        };
        const std::size_t h0 = hint;
        for (std::size_t l = h0; l < std::min(n, h0 + 3); ++l) try_piece(l);
        if (best > limit)
            for (std::size_t l = 0; l < n; ++l) try_piece(l);
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

/// The quick test's limits for a tolerance and slack, the same for every
/// segment a search tries: the input points' limit (tolerance - slack), the
/// probes' (97% of it) and the pieces' flatness target (tolerance / 4).
///
/// Where fit_pieces::bounded() holds, every piece's flatness bound is a
/// number in [0, flat_bound], flat_bound the target times 1 + 2^-10, more
/// than the rounding (a few hundred ulps): flatness_bound returns its
/// second-difference bound (u1 - u0)^2 / 8 max|C''| or less, and |C''| =
/// |2 c2 + 6 u c3|, convex in u, is at most its larger value at u = 0 or
/// 1, from which uniform_piece_count chose n >= sqrt(max|C''| / (8 target)).
/// Hence two limits on the distance c from a point to a piece's chord:
/// - `sure`: the largest c with c + flat_bound <= limit after rounding
///   (found by stepping; when not, nothing is sure): within it, c + flat
///   <= limit too (rounding is monotone), and the piece proves the point;
/// - `far`: limit + flat_bound, times 1 + 2^-20 for rounding: beyond it,
///   c - flat is beyond the limit after rounding, and the piece does not
///   keep the point near.
template <class T>
struct quick_limits {
    T flat_target, flat_bound;
    root_limit<T> input, probe, sure, far;
    quick_limits(T tolerance, T slack)
        : flat_target(tolerance / T(4)),
          flat_bound(flat_target * (T(1) + T(1) / T(1024))),
          input(tolerance - slack),
          probe(input.limit * T(0.97)),
          sure(sure_distance(input.limit, flat_bound)),
          far((input.limit + flat_bound) * (T(1) + T(1) / T(1 << 20))) {}

private:
    static T sure_distance(T limit, T flat_bound) {
        bool found = false;
        const T c = largest_where(limit - flat_bound, [&](T x) { return x + flat_bound <= limit; }, found);
        return found ? c : T(-1);
    }
};

/// input_within's answer alone, for the quick test: a point is proved when
/// some piece proves it (c + flat <= limit, c its distance to the piece's
/// chord), or when some piece keeps it near (c - flat <= limit) and the
/// nearest point proves it. So it may look at the pieces in any order (on
/// from where the point probably is) and stop at the first that proves it;
/// a piece with c within `sure` proves it without its flatness (see
/// quick_limits), and one with c beyond the limit (c + flat is then too:
/// flat >= 0) needs neither the root nor the flatness unless no piece
/// proves the point, nor then where c is beyond `far`. The same answer,
/// less work.
template <std::size_t D, class T>
bool input_points_pass(const cubic_segment<D, T>& seg, const poly_range<D, T>& pr, const quick_limits<T>& lim,
                       std::size_t first, std::size_t end) {
    using point = vec<D, T>;
    const T limit = lim.input.limit;
    fit_pieces<D, T> pieces(seg, lim.flat_target);
    const std::size_t n = pieces.size();
    const bool bounded = pieces.bounded();
    // Where to look first: the last piece that proved a point, or farther
    // on the piece k / (count - 1) of the way along (the range's points
    // spread about evenly in u): the first piece tried proves 7 points in 8.
    std::size_t hint = 0, guess = 0;
    const std::size_t stop = std::min(end, pr.count), span = pr.count - 1;
    for (std::size_t k = first; k < stop; ++k) {
        if (!pr.is_input(k)) continue;
        const point& p = pr[k];
        while (guess + 1 < n && (guess + 1) * span <= n * k) ++guess;
        const std::size_t start = std::max(hint, guess);
        std::array<std::uint8_t, 32> beyond;  // the pieces with c beyond the limit, short of `far`
        std::size_t nb = 0;
        bool proved = false, near = false;
        for (std::size_t q = 0; q < n && !proved; ++q) {
            const std::size_t l = start + q < n ? start + q : start + q - n;
            const point v = pieces.offset(p, l);
            if (bounded && norm_within(v, lim.sure)) {
                proved = true;
                hint = l;
                break;
            }
            const T c = norm_or_far(v, lim.input);
            if (!(c <= limit)) {
                if (!bounded || norm_within(v, lim.far)) beyond[nb++] = std::uint8_t(l);
                continue;
            }
            const T flat = pieces.flat(l);
            proved = c + flat <= limit;
            near = near || c - flat <= limit;
            if (proved) hint = l;
        }
        if (proved) continue;
        for (std::size_t b = 0; b < nb && !near; ++b)
            near = pieces.distance(p, beyond[b]) - pieces.flat(beyond[b]) <= limit;
        if (!near || !(std::sqrt(nearest(seg, p).distance_sq) <= limit)) return false;
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

/// Whether some segment of the range is within r.limit of x: all the
/// quick test asks of range_distance (the hint's window, then all the
/// segments: the answer is whether the minimum over all is within, whatever
/// the hint). So it may stop at the first segment within, looking at the
/// segments outward from the hint first; `hint` moves to the one found.
template <std::size_t D, class T>
bool range_within(const vec<D, T>& x, const poly_range<D, T>& pr, const root_limit<T>& r, std::size_t& hint) {
    const std::size_t nseg = pr.count - 1;
    auto within = [&](std::size_t s) {
        if (!norm_within(pr.offset(x, s), r)) return false;
        hint = s;
        return true;
    };
    // Outward from the hint, both ways at once: a curve point near some
    // segment is most often near one close to the hint (on a densely
    // sampled line a curve point is near many input segments, and a scan
    // from the range's start cost time in the square of its length).
    const std::size_t h = hint;
    if (within(h)) return true;
    for (std::size_t d = 1; d <= h || h + d < nseg; ++d)
        if ((h + d < nseg && within(h + d)) || (d <= h && within(h - d))) return true;
    return false;
}

/// The curve points the quick test looks at, as u along the segment: the
/// middle first, where a segment too long for the tolerance is most often
/// out. (It sampled its curve twice per input point besides, 64 points at
/// most: measured on the real corpus, BENCHMARKS.md, the samples cost a
/// quarter of the fit's time and changed the counts by under 0.2%, fewer
/// points without them; the proof checks the curve everywhere.)
inline constexpr double fit_probes[] = {0.5, 0.25, 0.75};

/// The search's quick test of a segment (not a proof: fit() proves the
/// segments it keeps with prove_segment and repairs those that fail): the
/// curve at the probes within the tolerance less a margin (3%) of the
/// polyline (range_within), then the input points by input_within's bound
/// (input_points_pass: its answer alone). A pure function of its
/// arguments, with limits built once per search.
template <std::size_t D, class T>
bool quick_segment_test(const cubic_segment<D, T>& seg, const poly_range<D, T>& pr, const quick_limits<T>& lim,
                        std::size_t first_point, std::size_t end_point) {
    const std::size_t nseg = pr.count - 1;
    for (const double u : fit_probes) {
        // Looked for from the segment u of the way along the range.
        std::size_t hint = std::min(nseg - 1, std::size_t(u * double(nseg)));
        if (!range_within(seg.at(T(u)), pr, lim.probe, hint)) return false;
    }
    return input_points_pass(seg, pr, lim, first_point, end_point);
}

}  // namespace crspline::detail
