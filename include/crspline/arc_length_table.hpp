// crspline: the arc-length table of a curve (arc_length.hpp): every
// segment's quadrature pieces with cumulative lengths, for many length
// queries, t at arc length s, and batches of sorted s.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "catmull_rom.hpp"
#include "detail/length_quadrature.hpp"
#include "error.hpp"
#include "segment.hpp"

namespace crspline {

/// Default relative accuracy of arc-length computations.
inline constexpr double default_accuracy = 1e-12;
/// Arc-length table of a curve: the accepted quadrature pieces of every
/// segment with cumulative lengths. Answers length queries, t at arc
/// length s (safeguarded Newton inside one piece) and batches of sorted s
/// without integrating from the start again. Copies what it needs from the
/// curve: it stays valid when the curve is gone.
template <std::size_t D, class T = double>
class arc_length_table {
public:
    using point = vec<D, T>;

    explicit arc_length_table(const catmull_rom<D, T>& curve, T accuracy = T(default_accuracy))
        : accuracy_(accuracy), t_max_(curve.t_max()) {
        segments_.reserve(curve.segment_count());
        for (const auto& s : curve.segments()) segments_.push_back(s);
        detail::check_accuracy(accuracy);
        const double eff = detail::effective_accuracy(accuracy);
        const std::size_t nseg = segments_.size();
        first_piece_.assign(nseg + 1, 0);
        segment_start_.assign(nseg + 1, T(0));
        segment_length_.assign(nseg, T(0));
        // Summed per segment, then segment by segment: the same order as
        // arc_length(curve), so total() is that value bit for bit (and s =
        // arc_length(curve) is never past the table's end). Segments
        // without pieces (constant ones) keep length 0.
        std::size_t next = 0;  // the first segment not started yet
        T within = 0;
        auto finish_until = [&](std::size_t i) {  // close the open segment, start those up to i
            for (; next <= i && next <= nseg; ++next) {
                if (next > 0) segment_length_[next - 1] = within, total_ += within;
                within = 0;
                first_piece_[next] = pieces_.size();
                segment_start_[next] = total_;
            }
        };
        detail::for_each_segment_length_piece(
            nseg, [&](std::size_t i) { return segments_[i]; }, accuracy,
            [&](std::size_t i, T u0, T u1, T len, const detail::rule_choice& rc) {
                finish_until(i);
                pieces_.push_back({u0, u1, total_ + within, i, rc.n, T(rc.short_fraction(eff))});
                within += len;
            });
        finish_until(nseg);
        piece_start_.reserve(pieces_.size());
        for (const auto& p : pieces_) piece_start_.push_back(p.s0);
    }

    /// Total length.
    T total() const noexcept { return total_; }
    /// The relative accuracy the table was built for.
    T accuracy() const noexcept { return accuracy_; }
    /// Length of segment i (its own sum: not a difference of cumulative
    /// lengths, which would lose eps * total()).
    T segment_length(std::size_t i) const { return segment_length_.at(i); }
    /// Cumulative length at each knot (segment_count() + 1 values).
    std::span<const T> knot_lengths() const noexcept { return segment_start_; }

    /// Arc length from the start of the curve to parameter t (checked).
    T s_at(T t) const {
        check_t(t);
        const std::size_t i = locate_segment(t);
        const auto& seg = segments_[i];
        const T u = std::clamp(seg.local(t), T(0), T(1));
        // Find the piece of segment i holding u.
        std::size_t k = first_piece_[i], end = first_piece_[i + 1];
        if (k == end) return segment_start_[i];
        while (k + 1 < end && pieces_[k + 1].u0 <= u) ++k;
        return pieces_[k].s0 + detail::gauss_length_rule(seg, pieces_[k].u0, u, pieces_[k].rule);
    }

    /// How far outside [0, total()] an arc length may lie and still be
    /// taken as the nearer end: max(accuracy, 4 eps) * total(), the
    /// tolerance t_at promises. Why: total() is itself only known to that
    /// accuracy, so a length computed by another tool (or by this one at
    /// another accuracy) may end up to that much past it; s =
    /// total() (1 + 8e-15) is the curve's end to the promised 1e-12,
    /// while s = total() (1 + 1e-9) is not and stays an out_of_domain
    /// error. (4 eps: below that the sum of the pieces is not known
    /// either.) 0 for a curve of length 0.
    T end_slack() const noexcept {
        return std::max(accuracy_, T(4) * std::numeric_limits<T>::epsilon()) * total_;
    }
    /// Whether t_at accepts s: -end_slack() <= s <= total() + end_slack()
    /// (false for NaN). The one rule every front end checks arc lengths by.
    bool in_range(T s) const noexcept {
        const T slack = end_slack();
        return s >= -slack && s <= total_ + slack;
    }

    /// Parameter t at arc length s (checked: in_range(s), else
    /// out_of_domain). The result satisfies |s_at(t) - s| <= accuracy *
    /// total() up to rounding; s within end_slack() of an end (outside
    /// [0, total()] included) gives that end's knot exactly.
    T t_at(T s) const {
        s = checked_s(s, std::nullopt);
        // The ends are known exactly: no Newton landing within the tolerance.
        if (s == total_ && !pieces_.empty()) return t_end();
        if (s == 0) return segments_.front().t0;
        return t_in_piece(locate_piece(s), s, std::nullopt);
    }

    /// Batch: t[k] = t_at(s[k]), the same rule at the ends (an out_of_domain
    /// error names the first index outside). Sorted s walks the pieces
    /// forward (no search) and starts Newton from the previous answer.
    void t_at(std::span<const T> s_in, std::span<T> t) const {
        if (s_in.size() != t.size())
            throw invalid_input("output has " + std::to_string(t.size()) + " values for " +
                                std::to_string(s_in.size()) + " arc lengths");
        for (std::size_t k = 0; k < s_in.size(); ++k) checked_s(s_in[k], k);
        // Each s as t_at(s) takes it: within end_slack() of an end, that end.
        const auto s = [&](std::size_t k) { return std::clamp(s_in[k], T(0), total_); };
        std::size_t at = s_in.empty() ? 0 : locate_piece(s(0));
        // Warm start: the previous answer (u_a, with arc length s_a from the
        // curve's start) anchors the next query when it is in the same piece
        // and not before it; only the increment from u_a is integrated.
        bool anchored = false;
        T u_a = 0, s_a = 0;
        for (std::size_t k = 0; k < s_in.size(); ++k) {
            const T sk = s(k);
            if (k > 0 && sk >= s(k - 1)) {
                const std::size_t before = at;
                while (at + 1 < pieces_.size() && piece_start_[at + 1] <= sk) ++at;
                anchored = anchored && at == before;
            } else {
                at = locate_piece(sk);
                anchored = false;
            }
            if (pieces_.empty()) {
                t[k] = segments_.front().t0;
                continue;
            }
            if (sk == total_) {  // the end, exactly (as t_at(s) gives it)
                t[k] = t_end();
                anchored = false;
                continue;
            }
            if (sk == 0) {  // the start, exactly (as t_at(s) gives it)
                t[k] = segments_.front().t0;
                anchored = false;
                continue;
            }
            if (!anchored) u_a = pieces_[at].u0, s_a = pieces_[at].s0;
            t[k] = t_from_anchor(at, sk, u_a, s_a);
            anchored = true;
        }
    }
    std::vector<T> t_at(std::span<const T> s) const {
        std::vector<T> t(s.size());
        t_at(s, std::span<T>(t));
        return t;
    }

private:
    struct piece {
        T u0, u1;           // local range in the segment
        T s0;               // arc length from the curve's start to u0
        std::size_t seg;    // segment index
        int rule;           // Gauss-Legendre points that meet the accuracy on it
        T short_fraction;   // increments up to this fraction of it use the 4-point rule
    };
    std::vector<cubic_segment<D, T>> segments_;
    std::vector<piece> pieces_;
    std::vector<T> piece_start_;              // pieces_[k].s0, contiguous for searching
    std::vector<std::size_t> first_piece_;    // per segment, index of its first piece
    std::vector<T> segment_start_;            // cumulative length at each knot
    std::vector<T> segment_length_;           // length of each segment
    T total_ = 0;
    T accuracy_;
    T t_max_;  // the curve's t_max, exactly

    T t_end() const noexcept { return t_max_; }

    std::size_t locate_segment(T t) const noexcept {
        // Last segment whose t0 <= t (segments are few relative to queries
        // here; the curve's own bucket index is not copied).
        std::size_t lo = 0, len = segments_.size();
        while (len > 1) {
            const std::size_t half = len / 2;
            lo = segments_[lo + half].t0 <= t ? lo + half : lo;
            len -= half;
        }
        return lo;
    }
    std::size_t locate_piece(T s) const noexcept {
        if (pieces_.empty()) return 0;
        const auto it = std::upper_bound(piece_start_.begin(), piece_start_.end(), s);
        return it == piece_start_.begin() ? 0 : std::size_t(it - piece_start_.begin()) - 1;
    }
    void check_t(T t) const {
        const T lo = segments_.front().t0, hi = segments_.back().t0 + segments_.back().h;
        if (!(t >= lo && t <= hi))
            throw out_of_domain("t = " + detail::num(double(t)) + " is outside the domain [" +
                                detail::num(double(lo)) + ", " + detail::num(double(hi)) + "]");
    }
    // s if in_range(s), clamped to [0, total()]; else out_of_domain naming
    // s (and its index in a batch) and the range.
    T checked_s(T s, std::optional<std::size_t> index) const {
        if (!in_range(s))
            throw out_of_domain("s = " + detail::num(double(s)) +
                                (index ? " (index " + std::to_string(*index) + ")" : std::string()) +
                                " is outside the arc-length range [0, " + detail::num(double(total_)) + "]");
        return std::clamp(s, T(0), total_);
    }

    // Sorted batches: solve s_a + integral_{u_a}^{u} speed = s for u in piece
    // k, from an anchor (u_a, s_a) in it with s_a <= s (the previous answer,
    // or the piece's start), and move the anchor to the answer.
    //
    // Why integrating only the increment keeps the accuracy: the piece's
    // n-point Gauss rule's error on [a, b] is bounded by rho^-2n times the
    // integral scale, rho the Bernstein-ellipse parameter of the speed's
    // nearest singularity for [a, b]. The table cut every piece so that rho
    // is large enough over the whole piece; over a sub-interval the ellipse with the
    // same foci ratio shrinks around a shorter segment, so every singularity
    // is relatively farther and rho only grows: each increment is at least as
    // accurate, relative to its length, as the piece itself. The anchor's
    // errors add up along a piece to at most the relative accuracy times
    // the piece's length, the same bound as for one integral from the piece's
    // start, and the anchor is reset at each new piece from its exact s0.
    //
    // Short increments use the 4-point rule (degree 7). For fast-path pieces
    // the fraction comes from the piece's own proof (rule_choice::
    // short_fraction); for the slower path's pieces, with rho >= rho_min
    // for the piece (rho_min^-16 = acc / 100), every singularity is at least
    // (rho - 1/rho)/2 half-widths of the piece away from it, so for a
    // sub-interval of relative width w its parameter is rho_w >=
    // (rho - 1/rho) / (2 w), and the 4-point error ~ rho_w^-8 stays below
    // acc / 100 when w <= (100 / acc)^(-5/48) / 2.2 (1/64 at
    // acc = 1e-12: rho_w >= 236, rho_w^-8 = 1e-19; the fraction was derived
    // for a 3-point rule, whose rho_w^-6 = 6e-15 is met too).
    // In a batch of 10^6 sorted queries the increment is about 10^-3 of a
    // segment: Newton started from the anchor with the speed there lands
    // within the tolerance in one or two steps (about 10 speed evaluations
    // a query instead of 25 from the piece's start).
    T t_from_anchor(std::size_t k, T s, T& u_a, T& s_a) const {
        const piece& p = pieces_[k];
        const auto& seg = segments_[p.seg];
        const T target = s - s_a;  // >= 0
        const T tol = std::max(accuracy_, T(4) * std::numeric_limits<T>::epsilon()) * total_ / T(4);
        T lo = u_a, hi = p.u1;
        // Second-order guess from the anchor: with v = |C'| and v' = C'.C''/v,
        // du/ds = 1/v and d2u/ds2 = -v'/v^3, so u = u_a + ds/v - ds^2 v'/(2 v^3)
        // to O(ds^3): the first integral usually lands within the tolerance.
        const vec<D, T> d1 = seg.du(u_a, 1), d2 = seg.du(u_a, 2);
        const T v0 = norm(d1);
        T u = u_a + (hi - u_a) / 2;
        if (v0 > 0) {
            const T step = target / v0, dv = dot(d1, d2) / v0;
            u = std::clamp(u_a + step - step * step * dv / (T(2) * v0), u_a, hi);
        }
        const T short_step = p.short_fraction * (p.u1 - p.u0);
        const T f = newton_in_bracket(
            seg,
            [&](T x) {
                return (x > u_a ? (x - u_a <= short_step ? detail::gauss_length_4(seg, u_a, x)
                                                         : detail::gauss_length_rule(seg, u_a, x, p.rule))
                                : T(0)) - target;
            },
            lo, hi, u, tol);
        s_a = s + f;  // the arc length at u, as integrated
        u_a = u;
        return std::min(seg.t0 + u * seg.h, segments_.back().t0 + segments_.back().h);
    }

    template <class F>
    static T newton_in_bracket(const cubic_segment<D, T>& seg, F f_of, T lo, T hi, T& u, T tol) {
        return detail::newton_in_bracket(seg, f_of, lo, hi, u, tol);
    }

    // Solve s0 + integral_{u0}^{u} speed = s for u inside one piece by Newton
    // steps kept inside a shrinking bracket (bisection when a step leaves it
    // or the speed vanishes), then map u to t.
    T t_in_piece(std::size_t k, T s, std::optional<std::size_t>) const {
        if (pieces_.empty()) return segments_.front().t0;  // constant curve
        const piece& p = pieces_[k];
        const auto& seg = segments_[p.seg];
        const T target = s - p.s0;
        const T len = (k + 1 < pieces_.size() ? piece_start_[k + 1] : total_) - p.s0;
        const T tol = std::max(accuracy_, T(4) * std::numeric_limits<T>::epsilon()) * total_ / T(4);
        T lo = p.u0, hi = p.u1;
        T u = len > 0 ? p.u0 + (p.u1 - p.u0) * std::clamp(target / len, T(0), T(1)) : p.u0;
        newton_in_bracket(
            seg, [&](T x) { return detail::gauss_length_rule(seg, p.u0, x, p.rule) - target; }, lo, hi, u, tol);
        return std::min(seg.t0 + u * seg.h, segments_.back().t0 + segments_.back().h);
    }
};

}  // namespace crspline
