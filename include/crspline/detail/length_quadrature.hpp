// crspline: the quadrature behind arc_length.hpp: which pieces of a segment,
// and which Gauss-Legendre rule on each, integrate the speed |C'(u)| to a
// relative accuracy (the fast path proved from the speed's branch points,
// the slower path cut at the speed's extrema and halved until checked), the
// Newton step on arc length, and the inverse of one segment's length.
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

#include "../error.hpp"
#include "../segment.hpp"
#include "format.hpp"
#include "polynomial.hpp"
#include "speed_quadrature.hpp"

namespace crspline {

namespace detail {

// Gauss-Legendre, 8 points on [-1, 1]: exact for polynomials of degree 15.
template <class T>
using gauss_legendre_8 = gauss_legendre<8, T>;

/// |dC/du| of a segment.
template <std::size_t D, class T>
[[gnu::always_inline]] inline T speed_du(const cubic_segment<D, T>& s, T u) noexcept {
    return norm(s.c1 + u * (T(2) * s.c2 + T(3) * u * s.c3));
}

/// Integral of the speed over [a, b] by the 8-point rule.
template <std::size_t D, class T>
T gauss_length(const cubic_segment<D, T>& s, T a, T b) noexcept {
    using G = gauss_legendre_8<T>;
    const T m = (a + b) / 2, r = (b - a) / 2;
    T sum = 0;
    for (int i = 0; i < 4; ++i) sum += G::w[i] * (speed_du(s, m - r * G::x[i]) + speed_du(s, m + r * G::x[i]));
    return sum * r;
}

/// Integral of the speed over [a, b] by the 4-point rule (exact for degree
/// 7): for increments much shorter than a piece (see t_from_anchor).
template <std::size_t D, class T>
T gauss_length_4(const cubic_segment<D, T>& s, T a, T b) noexcept {
    const T m = (a + b) / 2, r = (b - a) / 2;
    const T x0 = T(0.33998104358485626480), x1 = T(0.86113631159405257522);
    const T w0 = T(0.65214515486254614263), w1 = T(0.34785484513745385737);
    return r * (w0 * (speed_du(s, m - r * x0) + speed_du(s, m + r * x0)) +
                w1 * (speed_du(s, m - r * x1) + speed_du(s, m + r * x1)));
}

/// Critical points of |C'(u)|^2 strictly inside (a, b), sorted: the roots of
/// C'.C'' = (A + B u + C u^2).(B + 2 C u), with A = c1, B = 2 c2, C = 3 c3.
template <std::size_t D, class T>
std::vector<T> speed_critical_points(const cubic_segment<D, T>& s, T a, T b) {
    const vec<D, T> A = s.c1, B = T(2) * s.c2, C = T(3) * s.c3;
    const std::array<T, 4> p{dot(A, B), T(2) * dot(A, C) + dot(B, B), T(3) * dot(B, C), T(2) * dot(C, C)};
    std::vector<T> r;
    for (T x : real_roots(p, a, b))
        if (x > a && x < b) r.push_back(x);
    return r;
}

/// A piece of a segment over which the 8-point rule is accurate.
template <class T>
struct length_piece {
    T u0, u1;  ///< local parameter range
    T length;  ///< arc length over [u0, u1]
};

/// Halves [a, b] until the rule and its two halves agree to tol (an a
/// posteriori check on top of the a priori cut), appending pieces in order.
template <std::size_t D, class T>
void adapt_length(const cubic_segment<D, T>& s, T a, T b, T whole, T tol, int depth,
                  std::vector<length_piece<T>>& out) {
    const T m = a + (b - a) / 2;
    const T left = gauss_length(s, a, m), right = gauss_length(s, m, b);
    if (std::abs(left + right - whole) <= tol || depth >= 48 || !(m > a && m < b)) {
        out.push_back({a, m, left});
        out.push_back({m, b, right});
        return;
    }
    adapt_length(s, a, m, left, tol / 2, depth + 1, out);
    adapt_length(s, m, b, right, tol / 2, depth + 1, out);
}

/// Complex roots of |C'(u)|^2, a quartic in u: the branch points of the
/// speed sqrt(|C'|^2), i.e. the singularities that limit quadrature.
/// Durand-Kerner (Weierstrass) iteration on the monic quartic, then each
/// pair of roots that is a double root to rounding (a zero of the speed:
/// tension 1, a cusp) replaced by that root to full precision.
template <std::size_t D, class T>
std::vector<std::complex<double>> speed_singularities(const cubic_segment<D, T>& s) {
    using C = std::complex<double>;
    vec<D, double> A, B, Cc;
    for (std::size_t k = 0; k < D; ++k) {
        A[k] = double(s.c1[k]);
        B[k] = 2.0 * double(s.c2[k]);
        Cc[k] = 3.0 * double(s.c3[k]);
    }
    // |A + B u + C u^2|^2 = a0 + a1 u + a2 u^2 + a3 u^3 + a4 u^4
    std::array<double, 5> a{dot(A, A), 2 * dot(A, B), dot(B, B) + 2 * dot(A, Cc), 2 * dot(B, Cc), dot(Cc, Cc)};
    std::size_t deg = 4;
    const double scale = a[0] + a[2] + a[4];
    while (deg > 0 && std::abs(a[deg]) <= 1e-14 * scale) --deg;
    std::vector<C> z;
    if (deg == 0) return z;
    std::vector<C> c(deg + 1);
    for (std::size_t i = 0; i <= deg; ++i) c[i] = a[i] / a[deg];
    const C seed(0.4, 0.9);
    for (std::size_t i = 0; i < deg; ++i) z.push_back(std::pow(seed, double(i)));
    auto eval = [&](C x) {
        C r = 0;
        for (std::size_t i = deg + 1; i-- > 0;) r = r * x + c[i];
        return r;
    };
    // Stop when the steps are below rounding, or when small steps (below
    // 1e-3 of the roots' size: not the first wandering ones) have stopped
    // shrinking: 8 of them without one halving the smallest so far. A
    // double root (a zero of the speed: tension 1, a cusp) converges only
    // linearly, to about sqrt(eps), and its steps then jitter at that level
    // without reaching the first test: they ran all 500 iterations (most of
    // the slower path's time on tensioned curves), where convergence at any
    // rate faster than 2^(-1/8) per iteration keeps going.
    double smallest = std::numeric_limits<double>::infinity();
    int stalled = 0;
    for (int it = 0; it < 500; ++it) {
        double change = 0;
        for (std::size_t i = 0; i < deg; ++i) {
            C den = 1;
            for (std::size_t j = 0; j < deg; ++j)
                if (j != i) den *= z[i] - z[j];
            if (den == C(0)) den = C(1e-300);
            const C step = eval(z[i]) / den;
            z[i] -= step;
            change = std::max(change, std::abs(step));
        }
        if (change <= 1e-15 * (1 + std::abs(z[0]))) break;
        if (change <= smallest / 2) smallest = change, stalled = 0;
        else if (change <= 1e-3 * (1 + std::abs(z[0])) && ++stalled >= 8) break;
    }
    // A double root comes out as two roots up to about 1e-4 apart, not
    // either side of it (Durand-Kerner jumps about it at rounding level;
    // 5e-7 and 9e-5 from a speed zero at u = 1 were seen): cut_for_rule
    // would then cut towards the stray one, some fifty times. Two roots
    // within 1e-3 are replaced by the zero of q' between them (a simple zero
    // of q' where q has a double one), found by Newton's method to full
    // precision, if q vanishes there to rounding (1e-12 of the sum of its
    // terms' magnitudes: roots closer than about 1e-6, which the length's
    // accuracy cannot tell from a double one): for a true double root, the
    // root itself. A pair farther apart is left as it is.
    auto deval = [&](C x) {
        C r = 0;
        for (std::size_t i = deg; i >= 1; --i) r = r * x + double(i) * c[i];
        return r;
    };
    auto d2eval = [&](C x) {
        C r = 0;
        for (std::size_t i = deg; i >= 2; --i) r = r * x + double(i * (i - 1)) * c[i];
        return r;
    };
    for (std::size_t i = 0; i < deg; ++i)
        for (std::size_t j = i + 1; j < deg; ++j) {
            if (!(std::abs(z[i] - z[j]) <= 1e-3 * (1 + std::abs(z[i])))) continue;
            C x = (z[i] + z[j]) / 2.0;
            for (int it = 0; it < 20; ++it) {
                const C h = d2eval(x);
                if (h == C(0)) break;
                const C step = deval(x) / h;
                x -= step;
                if (std::abs(step) <= 1e-16 * (1 + std::abs(x))) break;
            }
            double size = 0;
            for (std::size_t k = deg + 1; k-- > 0;) size = size * std::abs(x) + std::abs(c[k]);
            if (std::abs(x - (z[i] + z[j]) / 2.0) <= 1e-3 * (1 + std::abs(z[i])) && std::abs(eval(x)) <= 1e-12 * size)
                z[i] = z[j] = x;
        }
    return z;
}

/// Bernstein ellipse parameter of the point z for the interval [a, b]: the
/// 8-point Gauss rule's error on a function analytic inside the ellipse with
/// foci a, b and parameter rho decays like rho^-16.
inline double ellipse_rho(std::complex<double> z, double a, double b) {
    const std::complex<double> w = (2.0 * z - (a + b)) / (b - a);
    const std::complex<double> r = w + std::sqrt(w - 1.0) * std::sqrt(w + 1.0);
    return std::max(std::abs(r), 1.0 / std::abs(r));
}

/// Cuts [a, b] (no speed extremum inside) into pieces on which every
/// singularity of the speed is far enough for the 8-point rule to reach the
/// accuracy: rho^-16 (with a factor 100 of margin) below acc. Branch points
/// within 1e-7 of a piece end and of the real axis are the double zeros of
/// the speed at the cut points themselves (computed to ~sqrt(eps)): there
/// the speed is |u - u0| times an analytic function, analytic on each side,
/// and treating a genuine branch point that close as one changes the length
/// by at most ~|C''| d^2 log(1/d) < 1e-12 of it.
template <std::size_t D, class T>
void cut_for_rule(const cubic_segment<D, T>& s, const std::vector<std::complex<double>>& sing, double a, double b,
                  double rho_min, int depth, std::vector<length_piece<T>>& out) {
    bool ok = true;
    for (const auto& z : sing) {
        const bool at_end = std::abs(z.imag()) < 1e-7 && (std::abs(z.real() - a) < 1e-7 || std::abs(z.real() - b) < 1e-7);
        if (!at_end && ellipse_rho(z, a, b) < rho_min) { ok = false; break; }
    }
    const double m = a + (b - a) / 2;
    if (ok || depth >= 60 || !(m > a && m < b)) {
        out.push_back({T(a), T(b), gauss_length(s, T(a), T(b))});
        return;
    }
    cut_for_rule(s, sing, a, m, rho_min, depth + 1, out);
    cut_for_rule(s, sing, m, b, rho_min, depth + 1, out);
}

/// The relative accuracy actually aimed at: acc, but not below a few ulps.
template <class T>
double effective_accuracy(T acc) noexcept {
    return std::max(double(acc), 8.0 * double(std::numeric_limits<T>::epsilon()));
}

/// The pieces of a segment over [a, b] for relative accuracy acc: cut at
/// the speed's extrema (where its zeros sit), then a priori by the distance
/// of the speed's singularities, then checked a posteriori: a piece whose
/// halves disagree with it is halved again.
template <std::size_t D, class T>
std::vector<length_piece<T>> length_pieces(const cubic_segment<D, T>& s, T a, T b, T acc) {
    std::vector<length_piece<T>> out;
    if (!(b > a)) return out;
    std::vector<T> cuts{a};
    for (T x : speed_critical_points(s, a, b)) cuts.push_back(x);
    cuts.push_back(b);
    const double eff = effective_accuracy(acc);
    const double rho_min = std::pow(100.0 / eff, 1.0 / 16.0);
    const auto sing = speed_singularities(s);
    std::vector<length_piece<T>> coarse;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
        cut_for_rule(s, sing, double(cuts[i]), double(cuts[i + 1]), rho_min, 0, coarse);
    T estimate = 0;
    for (const auto& p : coarse) estimate += p.length;
    const T tol = T(eff) * estimate;
    // The rounding floor: C'(u) = c1 + u (2 c2 + 3 u c3) is computed on [0, 1]
    // with an absolute error of a few eps (|c1| + 2|c2| + 3|c3|), so a rule's
    // sum over a piece of width w carries that error times w, and so does
    // the difference of a piece and its halves (about 8 eps S w; 64 leaves
    // a margin of 8). Where the speed is that small (a short [a, b] next to
    // a near-double zero of C', which the fast path hands over after
    // max_depth halvings), the halves agree no better: without the floor a
    // tolerance relative to [a, b]'s own tiny length is never met and every
    // piece is halved to adapt_length's depth limit, 2^48 pieces. The floor
    // adds at most 64 eps S (b - a) to the length, an error the speed's own
    // rounding makes anyway.
    const T S = norm(s.c1) + T(2) * norm(s.c2) + T(3) * norm(s.c3);
    const T rounding_floor = T(64) * std::numeric_limits<T>::epsilon() * S;
    for (const auto& p : coarse)
        adapt_length(s, p.u0, p.u1, p.length,
                     std::max(tol * (p.u1 - p.u0) / (b - a), rounding_floor * (p.u1 - p.u0)), 0, out);
    return out;
}

/// Halvings of a piece before the fast path gives it to the slower one.
inline constexpr int max_depth = 10;

/// What the fast path does with [a, b] of segment s at a depth of cuts,
/// given rc = first_rule(sm, bp, a, b, eff): take it whole (len its length
/// by rc's rule, whose bound holds against it), cut it in two at m (at the
/// nearest branch point's real part, which then sits at the end of both
/// halves, where it slows the rule least; else in the middle), or leave it
/// to the slower path.
enum class piece_step : unsigned char { slow, whole, halves };
template <std::size_t D, class T>
piece_step next_piece_step(const cubic_segment<D, T>& s, const rule_choice& rc, T a, T b, double eff, int depth,
                           T& len, T& m) noexcept {
    if (rc.n) {
        len = gauss_length_rule(s, a, b, rc.n);
        if (rc.bound <= eff * double(len)) return piece_step::whole;
    }
    const T w = b - a;
    m = rc.cut > double(a + w / 16) && rc.cut < double(b - w / 16) ? T(rc.cut) : a + w / 2;
    return depth < max_depth && m > a && m < b ? piece_step::halves : piece_step::slow;
}

/// The fast path over [a, b] of segment s, whose speed's branch points are
/// bp, with rc = first_rule(sm, bp, a, b, eff): the smallest rule proved for
/// [a, b], else its halves, recursively; slow(a, b) for what it cannot prove.
template <std::size_t D, class T, class F, class Slow>
void fast_length_pieces(const cubic_segment<D, T>& s, const speed_model& sm, const branch_points& bp, T a, T b,
                        double eff, F& emit, Slow& slow, int depth, const rule_choice& rc) {
    T len = 0, m = 0;
    switch (next_piece_step(s, rc, a, b, eff, depth, len, m)) {
        case piece_step::whole: emit(a, b, len, rc); break;
        case piece_step::halves:
            fast_length_pieces(s, sm, bp, a, m, eff, emit, slow, depth + 1, first_rule(sm, bp, a, m, eff));
            fast_length_pieces(s, sm, bp, m, b, eff, emit, slow, depth + 1, first_rule(sm, bp, m, b, eff));
            break;
        case piece_step::slow: slow(a, b); break;
    }
}

/// The slower path's pieces of [u0, u1] for emit: cut for the 8-point rule
/// (rho = 0: see rule_choice::short_fraction).
template <std::size_t D, class T, class F>
void slow_length_pieces(const cubic_segment<D, T>& s, T u0, T u1, double eff, F& emit) {
    for (const auto& p : length_pieces(s, u0, u1, T(eff))) emit(p.u0, p.u1, p.length, rule_choice{8, 0, 0, 0, std::numeric_limits<double>::quiet_NaN()});
}

/// Calls emit(u0, u1, length, rule_choice) for consecutive pieces covering
/// [a, b] of segment s, each integrated to relative accuracy acc by the
/// rule of rule_choice.n points (the 4-point rule is as accurate on any
/// sub-interval up to rule_choice.short_fraction() of the piece). The fast path
/// (detail/speed_quadrature.hpp) picks the rule from the speed's branch
/// points; where the speed vanishes (a real branch point) or a piece stays
/// unproved after max_depth halvings, length_pieces() takes over.
template <std::size_t D, class T, class F>
void for_each_length_piece(const cubic_segment<D, T>& s, T a, T b, T acc, F&& emit) {
    if (!(b > a)) return;
    const double eff = effective_accuracy(acc);
    auto slow = [&](T u0, T u1) { slow_length_pieces(s, u0, u1, eff, emit); };
    const speed_model sm(s);
    const branch_points bp = speed_branch_points(sm);
    const rule_choice rc = bp.ok ? first_rule(sm, bp, a, b, eff) : rule_choice{};
    // (No rule proved from a point that is no branch point: halving would
    // fail on every piece. As for_each_segment_length_piece does.)
    if (!bp.ok || (!rc.n && !branch_point_is_root(sm, bp))) {
        slow(a, b);
        return;
    }
    fast_length_pieces(s, sm, bp, a, b, eff, emit, slow, 0, rc);
}

/// for_each_length_piece over the whole of segments 0 .. n-1 (segment_at(i)
/// gives segment i), with the same pieces bit for bit, calling emit(i, u0,
/// u1, length, rule_choice). Sixteen segments at a time: their branch points
/// and first rule choices side by side in vector lanes (speed_first_pass),
/// since one segment's are chains of dependent divisions and square roots
/// that leave the processor waiting; then the whole of each segment where
/// its first rule is proved; then the rules of the halves of those cut, side
/// by side too (piece_rules); then each segment's pieces, in order, as
/// fast_length_pieces makes them.
template <class T, class SegmentAt, class F>
void for_each_segment_length_piece(std::size_t n, const SegmentAt& segment_at, T acc, F&& emit) {
    constexpr int L = 16;
    using segment = std::remove_cvref_t<decltype(segment_at(std::size_t(0)))>;
    const double eff = effective_accuracy(acc);
    segment seg[L];
    speed_model sm[L];
    branch_points bp[L];
    rule_choice rc[L], half_rc[2 * L];
    piece_ref half_pieces[2 * L];
    piece_step how[L];
    T whole[L], cut[L];
    for (std::size_t i0 = 0; i0 < n; i0 += L) {
        const int count = int(std::min<std::size_t>(L, n - i0));
        for (int l = 0; l < count; ++l) {
            seg[l] = segment_at(i0 + std::size_t(l));
            sm[l] = speed_model(seg[l]);
        }
        speed_first_pass(sm, count, eff, bp, rc);
        // fast_length_pieces' first step for each segment over [0, 1].
        int nh = 0;
        for (int l = 0; l < count; ++l) {
            const bool fast = bp[l].ok && (rc[l].n || branch_point_is_root(sm[l], bp[l]));
            how[l] = fast ? next_piece_step(seg[l], rc[l], T(0), T(1), eff, 0, whole[l], cut[l]) : piece_step::slow;
            if (how[l] != piece_step::halves) continue;
            half_pieces[nh++] = {&sm[l], &bp[l], 0.0, double(cut[l])};
            half_pieces[nh++] = {&sm[l], &bp[l], double(cut[l]), 1.0};
        }
        piece_rules(half_pieces, nh, eff, half_rc);
        int h = 0;
        for (int l = 0; l < count; ++l) {
            const std::size_t i = i0 + std::size_t(l);
            auto emit_i = [&](T u0, T u1, T len, const rule_choice& r) { emit(i, u0, u1, len, r); };
            auto slow = [&](T u0, T u1) { slow_length_pieces(seg[l], u0, u1, eff, emit_i); };
            switch (how[l]) {
                case piece_step::whole: emit_i(T(0), T(1), whole[l], rc[l]); break;
                case piece_step::halves:
                    fast_length_pieces(seg[l], sm[l], bp[l], T(0), cut[l], eff, emit_i, slow, 1, half_rc[h]);
                    fast_length_pieces(seg[l], sm[l], bp[l], cut[l], T(1), eff, emit_i, slow, 1, half_rc[h + 1]);
                    h += 2;
                    break;
                case piece_step::slow: slow(T(0), T(1)); break;
            }
        }
    }
}

/// Length of segment s over [a, b] to relative accuracy acc.
template <std::size_t D, class T>
T segment_length(const cubic_segment<D, T>& s, T a, T b, T acc) {
    T sum = 0;
    for_each_length_piece(s, a, b, acc, [&](T, T, T len, const rule_choice&) { sum += len; });
    return sum;
}

/// Newton on f(u) = (arc length to u) - target, whose derivative is the
/// speed, kept inside the shrinking bracket [lo, hi] (bisection when a step
/// leaves it or the speed vanishes), until |f| <= tol. Updates u and
/// returns f(u).
template <std::size_t D, class T, class F>
T newton_in_bracket(const cubic_segment<D, T>& seg, F f_of, T lo, T hi, T& u, T tol) {
    T f = 0;
    for (int it = 0; it < 100; ++it) {
        f = f_of(u);
        if (std::abs(f) <= tol) break;
        if (f < 0) lo = u;
        else hi = u;
        const T v = speed_du(seg, u);
        T next = v > 0 ? u - f / v : lo + (hi - lo) / 2;
        if (!(next > lo && next < hi)) next = lo + (hi - lo) / 2;
        if (next == u || !(hi > lo)) break;
        u = next;
    }
    return f;
}

/// Inverse arc length on one segment: its pieces (as for_each_length_piece
/// makes them, kept only while this object lives) and u at a length from
/// the segment's start, solved on the piece that holds it as
/// arc_length_table does.
template <std::size_t D, class T>
class segment_inverse {
public:
    segment_inverse(const cubic_segment<D, T>& s, T acc) : seg_(s) {
        for_each_length_piece(seg_, T(0), T(1), acc, [&](T u0, T u1, T len, const rule_choice& rc) {
            pieces_.push_back({u0, u1, length_, rc.n});
            length_ += len;
        });
    }
    const cubic_segment<D, T>& segment() const noexcept { return seg_; }

    /// u with |(length from u = 0 to u) - target| <= tol, target clamped to
    /// [0, the segment's length].
    T u_at(T target, T tol) const {
        if (pieces_.empty()) return T(0);
        target = std::clamp(target, T(0), length_);
        std::size_t k = 0;
        while (k + 1 < pieces_.size() && pieces_[k + 1].s0 <= target) ++k;
        const piece& p = pieces_[k];
        const T len = (k + 1 < pieces_.size() ? pieces_[k + 1].s0 : length_) - p.s0;
        const T want = target - p.s0;
        T u = len > 0 ? p.u0 + (p.u1 - p.u0) * std::clamp(want / len, T(0), T(1)) : p.u0;
        newton_in_bracket(
            seg_, [&](T x) { return gauss_length_rule(seg_, p.u0, x, p.rule) - want; }, p.u0, p.u1, u, tol);
        return u;
    }

private:
    struct piece {
        T u0, u1, s0;  // local range, length from the segment's start to u0
        int rule;
    };
    cubic_segment<D, T> seg_;
    std::vector<piece> pieces_;
    T length_ = 0;
};

template <class T>
void check_accuracy(T accuracy) {
    if (!(accuracy > 0 && accuracy < 1))
        throw invalid_input("accuracy must be in (0, 1), got " + num(double(accuracy)));
}

}  // namespace detail

}  // namespace crspline
