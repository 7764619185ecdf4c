// crspline internal: which Gauss-Legendre rule a piece of a segment needs.
// From the speed's branch points (speed_branch_points.hpp), the Bernstein
// ellipse just inside the nearest of them, Rouche's theorem that the speed
// is analytic there, and Trefethen's bound on the rule's error; the
// smallest rule of rule_sizes (gauss_legendre.hpp) whose bound is below the
// accuracy times the length (the proof is in speed_quadrature.hpp's head).
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include "gauss_legendre.hpp"
#include "simd_lanes.hpp"
#include "speed_branch_points.hpp"

namespace crspline::detail {

/// The rule a piece needs (0 when none was proved), the rho that proved it
/// and the ratio M / m of the bound.
struct rule_choice {
    int n = 0;
    double rho = 0, ratio = 0;
    double bound = 0;  ///< the rule's error bound on the piece
    /// Real part of the branch point nearest to the piece (NaN when not
    /// computed): where to cut it when no rule is proved.
    double cut = std::numeric_limits<double>::quiet_NaN();

    /// The largest sub-interval, as a fraction of the piece, on which the
    /// 4-point rule is proved by the same ellipse (for short increments
    /// inside the piece): a sub-interval of relative width w has rho_w >=
    /// g / w, g twice the ellipse's margin beyond the piece in units of its
    /// half-width, and the 4-point rule meets eff when rho_w^8 >= 4.3 M /
    /// (eff m) (the bound above with n = 4: r_w 2 (2 + 2/63) M rho_w^-8 /
    /// (1 - rho_w^-2) <= 8.2 r_w M rho_w^-8 for rho_w^2 >= 2, against eff
    /// times a length of at least 2 r_w m, m the speed). (A 3-point rule
    /// would need rho_w^6 >= the same: a fraction 3.3 times smaller at
    /// 1e-12, and the batch t_at of 10^6 queries 30% slower.)
    /// For the slower path's pieces (rho == 0), cut for the 8-point rule at
    /// rho_min with rho_min^-16 = eff / 100, the fraction derived in
    /// arc_length_table::t_from_anchor.
    double short_fraction(double eff) const noexcept {
        if (rho == 0) return std::pow(100.0 / eff, -5.0 / 48.0) / 2.2;
        const double g = std::min(rho - 1 / rho, rho + 1 / rho - 2);
        return g / std::pow(4.3 * ratio / eff, 0.125);
    }
};

/// Bernstein-ellipse parameter of z for [a, b]: rho + 1/rho is the sum of
/// the distances from z to a and b over b - a.
inline double ellipse_parameter(std::complex<double> z, double a, double b) noexcept {
    const double y2 = z.imag() * z.imag(), da = z.real() - a, db = z.real() - b;
    const double s = (std::sqrt(da * da + y2) + std::sqrt(db * db + y2)) / (b - a);
    return s + std::sqrt(std::max(s * s - 1, 0.0));
}

/// The smallest rule of rule_sizes (8 to 64 points) whose error bound on
/// [a, b] is at most eff * length, from the branch points bp: Trefethen's
/// bound on the Bernstein ellipse E_rho with rho 1% closer to 1 than the
/// nearest branch point (10% when that fails the test below), and M >=
/// |P(u)| >= |sqrt q(u)| over that ellipse from P's Taylor expansion about
/// the middle m of [a, b]: M = |P(m)| + |P'(m)| R + |C| R^2, R = r (rho +
/// 1/rho) / 2 the ellipse's semi-major axis (pm and dpm bound |P(m)| and
/// |P'(m)|: middle_norms). (|q(u)| = |P(u).P(u)| <= |P(u)|^2, the Hermitian
/// norm of the complex vector P(u).)
///
/// Why sqrt q is analytic in E_rho (Rouche). q / q4 = Q + R with Q = (u -
/// z0)(u - conj z0)(u - z1)(u - conj z1) and R the deflation's remainder
/// (branch_points::rem). Every root of Q has ellipse parameter rho_k > rho,
/// and a point J(w) = mid + r (w + 1/w) / 2 with |w| = rho is at least r/2
/// (rho_k - rho)(1 - 1/(rho rho_k)) from the root J(w_k), |w_k| = rho_k
/// (|w - w_k| >= rho_k - rho, |1 - 1/(w w_k)| >= 1 - 1/(rho rho_k)). So on
/// the ellipse |Q| >= (d0 d1)^2 with those distances, and if |R| <= sum
/// rem_k |u|^k is below it there, q has as many zeros inside as Q: none.
///
/// Written for lanes (as branch_root_step): the first rules of four
/// segments or pieces at once (first_pass_group, piece_rules_group), and
/// one piece's with V = double (choose_rule), the same operations in the
/// same order. No branch on the data but one: the 10% margin is tried only
/// when the 1% one fails in some lane. Which rule, and whether any, is
/// decided by masks, the largest rule first.
template <class V, class M, class S = sqrt_baseline>
[[gnu::always_inline]] inline void choose_rule_lanes(const V& a, const V& b, const V (&zr)[2], const V (&zi)[2],
                                                     const V (&rem)[4], const V& pm, const V& dpm, const V& c_norm,
                                                     double eff, const V& length, V& n, V& rho_out,
                                                     V& ratio, V& bound, V& cut) noexcept {
    const V zero = a - a, w = b - a;
    V e[2] = {}, d[4] = {};
    for (int k = 0; k < 2; ++k) {
        const V y2 = zi[k] * zi[k], da = zr[k] - a, db = zr[k] - b;
        d[k] = da * da + y2, d[2 + k] = db * db + y2;
    }
    for (V& x : d) S::apply(x);
    // (Reciprocals once, then products: divisions are the slowest step.)
    const V inv_w = 1 / w;
    V sq[2] = {};
    for (int k = 0; k < 2; ++k) {
        e[k] = (d[k] + d[2 + k]) * inv_w, sq[k] = e[k] * e[k] - 1;
        lanes_set(sq[k], sq[k] < 0, zero);
        S::apply(sq[k]);
        e[k] += sq[k];
    }
    const V inv_e[2] = {1 / e[0], 1 / e[1]};
    const M first = e[0] <= e[1];
    V rho_z = e[1];
    lanes_set(rho_z, first, e[0]);
    cut = zr[1];
    lanes_set(cut, first, zr[0]);
    const V r = w / 2, mid = a + r;
    V amid = mid;
    lanes_set(amid, mid < 0, -mid);
    // rho and the semi-major axis of its ellipse for the first margin that
    // passes.
    V rho = zero, semi = zero;
    M found = rho_z < rho_z;
    // (The roots' size, for the slack below.)
    const V size = 1 + zr[0] * zr[0] + zi[0] * zi[0] + zr[1] * zr[1] + zi[1] * zi[1];
    // The 10% margin only where 1% fails (rarely: never on the walk's first
    // rules, and the lanes skip it then). (A loop, not a lambda: GCC may
    // leave a lambda out of line, outside the AVX2 clone.)
    for (double keep : {0.99, 0.9}) {
        if (keep < 0.99 && !lanes_any_not(found)) break;
        const V rk = 1 + keep * (rho_z - 1), inv_rk = 1 / rk;
        const V semi_k = r * (rk + inv_rk) / 2, reach_k = amid + semi_k;
        const V rem_k = ((rem[3] * reach_k + rem[2]) * reach_k + rem[1]) * reach_k + rem[0];
        // The distances less 1e-12 of the roots' size (|z| <= (1 + |z|^2) / 2),
        // for the rounding of the ellipse parameters and of Q's roots.
        const V slack = 1e-12 * (reach_k + size);
        const V d0 = r / 2 * (e[0] - rk) * (1 - inv_rk * inv_e[0]) - slack;
        const V d1 = r / 2 * (e[1] - rk) * (1 - inv_rk * inv_e[1]) - slack;
        const V prod = (d0 * d1) * (d0 * d1);
        M pass = (rk > 1.05) & (d0 > 0) & (d1 > 0) & (rem_k < prod * (1 - 1e-12));
        lanes_clear(pass, found);
        lanes_set(rho, pass, rk);
        lanes_set(semi, pass, semi_k);
        found = found | pass;
    }
    // |P(u)| <= |P(m)| + |P'(m)| |u - m| + |C| |u - m|^2, |u - m| <= semi on
    // the ellipse (the factor covers this sum's rounding).
    const V M_bound = (pm + semi * (dpm + semi * c_norm)) * (1 + 1e-14);
    // The bound is K / rho^(2n), K = r 2 (2 + 2/255) M rho^2 / (rho^2 - 1) =
    // k_num / k_den (2/255 = 2 / (4 n^2 - 1) at n = 8, the smallest rule);
    // rho^(2n) for n in rule_sizes by products of r8 = rho^8 (no pow or
    // log); a rule passes when K / rho^(2n) <= eff length.
    static_assert(rule_sizes[0] == 8);
    const V r2 = rho * rho, r4 = r2 * r2, r8 = r4 * r4;
    const V k_num = r * (2 * (2 + 2.0 / 255)) * M_bound * r2, k_den = r2 - 1;
    const V scale = k_den * eff * length;
    // grow[j] = r8^j = rho^(8 j), the rule of n = 4 j points' rho^(2n), by a
    // tree of products (no long chain of dependent ones).
    constexpr int P = max_rule / 4 + 1;
    V grow[P];
    grow[0] = zero + 1, grow[1] = r8;
#pragma GCC unroll 32
    for (int j = 2; j < P; ++j) grow[j] = grow[j / 2] * grow[j - j / 2];
    n = zero, rho_out = zero, ratio = zero, bound = zero;
    V g = grow[P - 1];
#pragma GCC unroll 32
    for (int i = 0; i < rule_count; ++i) {  // the largest first: the smallest that passes stays
        const int k = rule_count - 1 - i;
        const V& gk = grow[rule_sizes[k] / 4];
        const M pass = found & (gk * scale >= k_num);
        lanes_set(n, pass, zero + rule_sizes[k]);
        lanes_set(g, pass, gk);
    }
    const M chosen = n > 0;
    lanes_set(rho_out, chosen, rho);
    lanes_set(ratio, chosen, 2 * r * M_bound / length);
    lanes_set(bound, chosen, k_num / (k_den * g));
}

/// Lane l of choose_rule_lanes' outputs as a rule_choice.
template <class V>
[[gnu::always_inline]] inline rule_choice lane_rule(const V& n, const V& rho, const V& ratio, const V& bound,
                                                    const V& cut, int l) noexcept {
    rule_choice r;
    r.n = int(lanes_get(n, l)), r.rho = lanes_get(rho, l), r.ratio = lanes_get(ratio, l);
    r.bound = lanes_get(bound, l), r.cut = lanes_get(cut, l);
    return r;
}

/// choose_rule_lanes for one piece.
inline rule_choice choose_rule(const speed_model& sm, const branch_points& bp, double a, double b, double eff,
                               double length) noexcept {
    const double zr[2] = {bp.z[0].real(), bp.z[1].real()}, zi[2] = {bp.z[0].imag(), bp.z[1].imag()};
    const double rem[4] = {bp.rem[0], bp.rem[1], bp.rem[2], bp.rem[3]};
    const double q[5] = {sm.q[0], sm.q[1], sm.q[2], sm.q[3], sm.q[4]}, dq[3] = {sm.dq[0], sm.dq[1], sm.dq[2]};
    double pm, dpm, n, rho, ratio, bound, cut;
    middle_norms(q, dq, sm.err, a + (b - a) / 2, pm, dpm);
    choose_rule_lanes<double, bool>(a, b, zr, zi, rem, pm, dpm, std::sqrt(sm.cc), eff, length, n, rho, ratio, bound,
                                    cut);
    return lane_rule(n, rho, ratio, bound, cut, 0);
}

/// The rule the fast path tries first on [a, b] of a segment: choose_rule
/// with the length estimated as half the speed at the middle (as
/// middle_norms bounds it) times the width (the bound is checked against
/// the computed length after).
template <class T>
rule_choice first_rule(const speed_model& sm, const branch_points& bp, T a, T b, double eff) noexcept {
    const double da = double(a), db = double(b);
    const double q[5] = {sm.q[0], sm.q[1], sm.q[2], sm.q[3], sm.q[4]}, dq[3] = {sm.dq[0], sm.dq[1], sm.dq[2]};
    double pm, dpm;
    middle_norms(q, dq, sm.err, da + (db - da) / 2, pm, dpm);
    const double estimate = (db - da) * pm / 2;
    return estimate > 0 ? choose_rule(sm, bp, da, db, eff, estimate) : rule_choice{};
}

}  // namespace crspline::detail
