// crspline internal: which Gauss-Legendre rule a piece of a segment needs.
// From the speed's branch points (speed_branch_points.hpp): first Darboux's
// bound for a square-root singularity, each root located in a small disk by
// Rouche's theorem (sqrt_type_bound, the proof in its comment); where that
// fails, the Bernstein ellipse just inside the nearest branch point,
// Rouche's theorem that the speed is analytic there, and Trefethen's bound
// (speed_quadrature.hpp's head). The smallest rule of rule_sizes
// (gauss_legendre.hpp) whose bound is below the accuracy times the length.
#pragma once

#include <algorithm>
#include <array>
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

/// B(2n - 1/2, 3/2) = Gamma(2n - 1/2) Gamma(3/2) / Gamma(2n + 1) for n in
/// rule_sizes, rounded up (sqrt_type_bound): from B(1/2, 3/2) = pi / 2 by
/// B(a + 1, 3/2) = B(a, 3/2) a / (a + 3/2), 2n - 1 steps of a few ulps.
inline constexpr std::array<double, rule_count> sqrt_type_beta = [] {
    std::array<double, rule_count> out{};
    for (int i = 0; i < rule_count; ++i) {
        double beta = 3.14159265358979323846 / 2, a = 0.5;
        for (int k = 1; k < 2 * rule_sizes[i]; ++k, a += 1) beta *= a / (a + 1.5);
        out[std::size_t(i)] = beta * (1 + 1e-13);
    }
    return out;
}();

/// The second proof of a rule, from the square-root type of the speed's
/// branch points: the n-point rule's error on [a, b] is at most
/// k_sq B(2n - 1/2, 3/2) rho_sq^2 / ((rho_sq^2 - 1) rho_sq^(2n)), ok in
/// the lanes where it holds (ok is and-ed in). Where the bound of
/// choose_rule_lanes (Trefethen's, with M the bound of |sqrt q| on an
/// ellipse inside the nearest branch point) gains nothing from the
/// singularity's type, this one gains (2n)^(-3/2): about 7 nodes a segment
/// on the benchmark's walk.
///
/// The proof. Map [a, b] to [-1, 1] (u = m + r x, r = (b - a) / 2) and
/// write f(x) = sqrt(q(u)), F(w) = f((w + 1/w) / 2). On [-1, 1], f = sum
/// a_k T_k with a_k = (1 / (pi i)) times the integral of F(w) w^(-k-1) dw
/// around |w| = 1 (Trefethen, ATAP, (3.12)). The n-point Gauss rule is
/// exact for T_k with k < 2n and for odd k, and errs on T_k by at most
/// |integral| + sum of weights <= 2 + 2 / (k^2 - 1) <= 2 + 2/255 otherwise
/// (n >= 8); so its error on [a, b] is at most r (2 + 2/255) times the sum
/// of |a_k| over even k >= 2n.
/// (1) Where q's zeros are. q / q4 = Q + R (Q = (u - z0)(u - conj z0)(u -
/// z1)(u - conj z1), R the deflation's remainder, |R(u)| <= sum rem_k
/// |u|^k, branch_points), and the q computed differs from the true |C'|^2
/// by at most q_err S2 sum |u|^j <= q_err S2 (1 + |u|)^4 (speed_model::err:
/// each coefficient errs by at most err (|A|^2 + |B|^2 + |C|^2), and
/// |B|^2 = q2 - 2 A.C <= |q2| + q0 + q4, so S2 = 2 (q0 + q4) + |q2|). On
/// the circle |u - z_j| = delta_j (delta_j = 1e-3 Im z_j) Q is at least
/// (delta - sig)(2 Im z_j - delta - sig)(D - delta0 - delta1 - sig)(D' -
/// delta0 - delta1 - sig), D and D' lower bounds of the distances from z0
/// to z1 and conj z1 (the larger coordinate difference) and sig the slack for the rounding of Q's roots (as in
/// choose_rule_lanes); where that exceeds the remainder and the error
/// there, Rouche's theorem puts exactly one zero of the true q in each of
/// the four disjoint disks about z0, conj z0, z1, conj z1: all four zeros.
/// A zero zeta within delta of z_j has ellipse parameter at least rho_j,
/// the parameter of s_j - 2 delta / (b - a) (s_j = (|z_j - a| + |z_j - b|)
/// / (b - a), rounding allowed for).
/// (2) The contour. F is analytic in 1 <= |w| outside radial cuts from the
/// four zeros' images w (|w| > 1) to infinity (the region deformed across
/// has no hole that the cuts do not join to infinity, so F is one-valued
/// there); the integral over |w| = R tends to 0 as R grows (|F| grows like
/// R^2 and w^(-k-1) falls like R^(-17)). Across a cut F jumps by at most
/// 2 |F|, so |a_k| <= sum over the cuts of (2 / pi) integral of |F(t e^(i
/// theta))| t^(-k-1) dt from rho' = |w(zeta)| to infinity, and the sum over
/// even k >= 2n of t^(-k-1) is t^(-2n-1) / (1 - t^-2) <= t^(-2n-1) / (1 -
/// rho_near^-2).
/// (3) |F| along a cut. q is a quartic: q(u) = sum t_k (u - z_j)^k exactly
/// (its Taylor coefficients about z_j), so with zeta its zero in z_j's
/// disk, |q(u)| = |q(u) - q(zeta)| <= |u - zeta| sum k |t_k| (|u - zeta| +
/// delta)^(k-1) (|x^k - y^k| <= |x - y| k max(|x|, |y|)^(k-1)), and
/// (x + delta)^(k-1) <= 2^(k-2) (x^(k-1) + delta^(k-1)): |q(u)| <= X (T1 +
/// sum_{k>=2} h_k X^(k-1)), X = |u - zeta|, T1 = |t1| + sum h_k
/// delta^(k-1), h_k = k 2^(k-2) |t_k|. On the cut, X <= r (t - rho')
/// (J(w) - J(w') = (r/2)(w - w')(1 - 1/(w w'))). sqrt(T1 + Y) <= sqrt(T1)
/// + Y / (2 sqrt(T1)) gives |F| <= sum of terms c s^(k - 1/2), s = t -
/// rho', and the integral of s^m t^(-2n-1) from rho' is rho'^(m - 2n)
/// B(2n - m, m + 1), smaller for a smaller rho' (m < 2n): rho' >= rho_j.
/// Each term is sqrt(r rho) rho^(-2n) B(2n - 1/2, 3/2) times sqrt(T1) or
/// times gamma_k h_k (r rho)^(k-1) / (2 sqrt(T1)), gamma_k = B(2n - k +
/// 1/2, k + 1/2) / B(2n - 1/2, 3/2), which falls with n (a constant over a
/// product of k - 1 factors 2n - 1/2 - i): its value at n = 8 serves every
/// rule. The conjugate zero gives the same (|t_k| are the same), and the
/// far pair's rho_far^(-2n) <= rho_near^(-2n) (rho_near / rho_far)^16. So
/// the error is at most
///   r (2 + 2/255) (4 / pi) B(2n - 1/2, 3/2) rho_near^(-2n) / (1 -
///   rho_near^-2) [K_near + K_far (rho_near / rho_far)^16],
///   K_j = (T1 + sum_k gamma_k h_k (r rho_j)^(k-1) / 2) sqrt(r rho_j / T1).
/// (This is Darboux's method for the Chebyshev coefficients, as in
/// Trefethen's ATAP, chapter 8's exercises, written with explicit constants.)
/// |t_k| is bounded by |Re| + |Im| (no square root), and each by its
/// rounding and by the error of q: 32 (1 + |z_j|)^4 (q_err S2 + 1e-14 sum
/// |q_i|).
template <class V, class M, class S>
[[gnu::always_inline]] inline void sqrt_type_bound(const V& r, const V& inv_w, const V (&zr)[2], const V (&zi)[2],
                                                   const V (&d)[4], const V (&rem)[4], const V (&q)[5],
                                                   const V& q_err, const V& size, V& k_sq, V& rho_sq, M& ok,
                                                   M& first) noexcept {
    const V zero = r - r;
    V aq2 = zero, q_abs = zero;
    lanes_add_abs(aq2, q[2]);
    for (const V& c : q) lanes_add_abs(q_abs, c);
    const V s2 = 2 * (q[0] + q[4]) + aq2;
    const V sig = 1e-12 * size;
    // Lower bounds of the distances from z0 to z1 and to conj z1: the
    // larger coordinate difference (no square root).
    V adx = zero, adm = zero;
    lanes_add_abs(adx, zr[0] - zr[1]);
    lanes_add_abs(adm, zi[0] - zi[1]);
    V dist = adx, dist_c = adx;
    const V dp = zi[0] + zi[1];
    lanes_set(dist, adm > adx, adm);
    lanes_set(dist_c, dp > adx, dp);
    const V delta[2] = {1e-3 * zi[0], 1e-3 * zi[1]};
    const V apart = dist * (1 - 1e-15) - delta[0] - delta[1] - sig;
    const V apart_c = dist_c * (1 - 1e-15) - delta[0] - delta[1] - sig;
    ok = ok & (apart > 0) & (apart_c > 0);
    V kj[2], rho[2];
    for (int j = 0; j < 2; ++j) {
        const V x = zr[j], y = zi[j], dl = delta[j];
        V az = dl + y;
        lanes_add_abs(az, x);
        const V one_z = 1 + az, pz2 = one_z * one_z, pz4 = pz2 * pz2;
        // Rouche on |u - z_j| = delta_j (times q4 > 0, checked in
        // branch_root_start, to leave out a division).
        const V near = dl - sig, pair = 2 * y - dl - sig;
        const V q_disk = ((near * pair) * (apart * apart_c)) * q[4];
        const V rem_z = ((rem[3] * az + rem[2]) * az + rem[1]) * az + rem[0];
        const V off = rem_z * q[4] + q_err * s2 * pz4;
        ok = ok & (near > 0) & (pair > 0) & (off < q_disk * (1 - 1e-12));
        // The ellipse parameter of the zero in the disk.
        const V s_lo = (d[j] + d[2 + j]) * inv_w * (1 - 1e-14) - 2 * dl * inv_w * (1 + 1e-15);
        ok = ok & (s_lo > 1);
        V root = s_lo * s_lo - 1;
        lanes_set(root, root < zero, zero);
        S::apply(root);
        rho[j] = (s_lo + root) * (1 - 1e-14);
        // Taylor coefficients of q about z_j = x + i y, |t_k| <= |Re| + |Im|.
        const V x2 = x * x - y * y, y2 = 2 * x * y;
        const V x3 = x2 * x - y2 * y, y3 = x2 * y + y2 * x;
        const V slack = 32 * pz4 * (q_err * s2 + 1e-14 * q_abs);
        V t1 = slack, t2 = slack, t3 = slack;
        lanes_add_abs(t1, q[1] + 2 * q[2] * x + 3 * q[3] * x2 + 4 * q[4] * x3);
        lanes_add_abs(t1, 2 * q[2] * y + 3 * q[3] * y2 + 4 * q[4] * y3);
        lanes_add_abs(t2, q[2] + 3 * q[3] * x + 6 * q[4] * x2);
        lanes_add_abs(t2, 3 * q[3] * y + 6 * q[4] * y2);
        lanes_add_abs(t3, q[3] + 4 * q[4] * x);
        lanes_add_abs(t3, 4 * q[4] * y);
        const V h2 = 2 * t2, h3 = 6 * t3, h4 = 16 * (q[4] + slack);
        const V T1 = t1 + dl * (h2 + dl * (h3 + dl * h4));
        ok = ok & (T1 > 0);
        // gamma_k at n = 8: (3/2) / 14.5, (15/4) / (14.5 * 13.5),
        // (105/8) / (14.5 * 13.5 * 12.5), rounded up.
        constexpr double g2 = 1.5 / 14.5 * (1 + 1e-15), g3 = 3.75 / (14.5 * 13.5) * (1 + 1e-15),
                         g4 = 13.125 / (14.5 * 13.5 * 12.5) * (1 + 1e-15);
        const V rr = r * rho[j];
        V root_k = rr / T1;
        S::apply(root_k);
        kj[j] = (T1 + rr * (g2 / 2 * h2 + rr * (g3 / 2 * h3 + rr * (g4 / 2 * h4)))) * root_k;
    }
    first = rho[0] <= rho[1];
    V rn = rho[1], rf = rho[0], kn = kj[1], kf = kj[0];
    lanes_set(rn, first, rho[0]);
    lanes_set(rf, first, rho[1]);
    lanes_set(kn, first, kj[0]);
    lanes_set(kf, first, kj[1]);
    const V x1 = rn / rf, x2 = x1 * x1, x4 = x2 * x2, x8 = x4 * x4;
    rho_sq = rn;
    k_sq = r * ((2 + 2.0 / 255) * (4 / 3.14159265358979323846) * (1 + 1e-13)) * (kn + kf * (x8 * x8));
}

/// The smallest rule of rule_sizes (8 to 64 points) whose error bound on
/// [a, b] is at most eff * length, from the branch points bp. First by
/// sqrt_type_bound (the square-root type of the branch points); in the
/// lanes where that fails (its disks about the roots not proved, as near a
/// double root), by Trefethen's bound on the Bernstein ellipse E_rho with
/// rho 1% closer to 1 than the nearest branch point (10% when that fails
/// the test below), and M >= |P(u)| >= |sqrt q(u)| over that ellipse from
/// P's Taylor expansion about the middle m of [a, b]: M = |P(m)| + |P'(m)|
/// R + |C| R^2, R = r (rho + 1/rho) / 2 the ellipse's semi-major axis (pm
/// and dpm bound |P(m)| and |P'(m)|: middle_norms). (|q(u)| = |P(u).P(u)|
/// <= |P(u)|^2, the Hermitian norm of the complex vector P(u).) Either way
/// the piece's rho (rule_choice::short_fraction) is an ellipse in which
/// sqrt q is analytic, with M its bound there: for the first proof, 1%
/// closer to 1 than the nearest zero's lower bound.
///
/// Why sqrt q is analytic in E_rho for the second (Rouche). q / q4 = Q + R
/// with Q = (u - z0)(u - conj z0)(u - z1)(u - conj z1) and R the
/// deflation's remainder (branch_points::rem). Every root of Q has ellipse
/// parameter rho_k > rho, and a point J(w) = mid + r (w + 1/w) / 2 with |w|
/// = rho is at least r/2 (rho_k - rho)(1 - 1/(rho rho_k)) from the root
/// J(w_k), |w_k| = rho_k (|w - w_k| >= rho_k - rho, |1 - 1/(w w_k)| >= 1 -
/// 1/(rho rho_k)). So on the ellipse |Q| >= (d0 d1)^2 with those distances,
/// and if |R| <= sum rem_k |u|^k is below it there, q has as many zeros
/// inside as Q: none.
///
/// Written for lanes (as branch_root_step): the first rules of four
/// segments or pieces at once (first_pass_group, piece_rules_group), and
/// one piece's with V = double (choose_rule), the same operations in the
/// same order. No branch on the data but two: Trefethen's bound is worked
/// out only when the first proof fails in some lane, and its 10% margin
/// only when the 1% one fails in some lane. Which rule, and whether any, is
/// decided by masks, the largest rule first.
template <class V, class M, class S = sqrt_baseline>
[[gnu::always_inline]] inline void choose_rule_lanes(const V& a, const V& b, const V (&zr)[2], const V (&zi)[2],
                                                     const V (&rem)[4], const V (&q)[5], const V& q_err,
                                                     const V& pm, const V& dpm, const V& c_norm, double eff,
                                                     const V& length, V& n, V& rho_out, V& ratio, V& bound,
                                                     V& cut) noexcept {
    const V zero = a - a, w = b - a;
    V d[4] = {};
    for (int k = 0; k < 2; ++k) {
        const V y2 = zi[k] * zi[k], da = zr[k] - a, db = zr[k] - b;
        d[k] = da * da + y2, d[2 + k] = db * db + y2;
    }
    for (V& x : d) S::apply(x);
    // (Reciprocals once, then products: divisions are the slowest step.)
    const V inv_w = 1 / w;
    const V r = w / 2, mid = a + r;
    // (The roots' size, for the slack of the Rouche tests.)
    const V size = 1 + zr[0] * zr[0] + zi[0] * zi[0] + zr[1] * zr[1] + zi[1] * zi[1];
    // The first proof: k_sq and rho_sq of its bound where sq_ok.
    V k_sq = zero, rho_sq = zero;
    M sq_ok = w == w, near0 = sq_ok;
    sqrt_type_bound<V, M, S>(r, inv_w, zr, zi, d, rem, q, q_err, size, k_sq, rho_sq, sq_ok, near0);
    cut = zr[1];
    lanes_set(cut, near0, zr[0]);
    V rho = 1 + 0.99 * (rho_sq - 1);
    M found = sq_ok & (rho > 1.05);
    const M by_sqrt_type = found;
    V semi = r * (rho + 1 / rho) / 2;
    if (lanes_any_not(found)) {
        // Trefethen's bound where the first proof failed: the ellipse
        // parameters of the branch points, and the nearest's real part as
        // the cut.
        V e[2] = {}, sq[2] = {};
        for (int k = 0; k < 2; ++k) {
            e[k] = (d[k] + d[2 + k]) * inv_w, sq[k] = e[k] * e[k] - 1;
            lanes_set(sq[k], sq[k] < 0, zero);
            S::apply(sq[k]);
            e[k] += sq[k];
        }
        const V inv_e[2] = {1 / e[0], 1 / e[1]};
        const M first = e[0] <= e[1];
        V rho_z = e[1], cut_z = zr[1];
        lanes_set(rho_z, first, e[0]);
        lanes_set(cut_z, first, zr[0]);
        M other = w == w;
        lanes_clear(other, by_sqrt_type);
        lanes_set(cut, other, cut_z);
        V amid = mid;
        lanes_set(amid, mid < 0, -mid);
        // rho and the semi-major axis of its ellipse for the first margin
        // that passes. The 10% margin only where 1% fails (rarely). (A
        // loop, not a lambda: GCC may leave a lambda out of line, outside
        // the AVX2 clone.)
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
    }
    M trefethen = found;
    lanes_clear(trefethen, by_sqrt_type);
    // |P(u)| <= |P(m)| + |P'(m)| |u - m| + |C| |u - m|^2, |u - m| <= semi on
    // the ellipse (the factor covers this sum's rounding).
    const V M_bound = (pm + semi * (dpm + semi * c_norm)) * (1 + 1e-14);
    // Either bound is K B_n / rho_b^(2n), K = k_num / k_den, k_num = c
    // rho_b^2, k_den = rho_b^2 - 1: for the first c = k_sq, rho_b = rho_sq
    // and B_n = sqrt_type_beta; for Trefethen's c = r 2 (2 + 2/255) M (2/255
    // = 2 / (4 n^2 - 1) at n = 8, the smallest rule), rho_b = rho and B_n =
    // 1. rho_b^(2n) for n in rule_sizes by products of r8 = rho_b^8 (no pow
    // or log); a rule passes when K B_n / rho_b^(2n) <= eff length.
    static_assert(rule_sizes[0] == 8);
    V rb = rho_sq;
    lanes_set(rb, trefethen, rho);
    const V r2 = rb * rb, r4 = r2 * r2, r8 = r4 * r4;
    V c_k = k_sq;
    lanes_set(c_k, trefethen, r * (2 * (2 + 2.0 / 255)) * M_bound);
    const V k_num = c_k * r2, k_den = r2 - 1;
    const V scale = k_den * eff * length;
    // grow[j] = r8^j = rho_b^(8 j), the rule of n = 4 j points' rho_b^(2n),
    // by a tree of products (no long chain of dependent ones).
    constexpr int P = max_rule / 4 + 1;
    V grow[P];
    grow[0] = zero + 1, grow[1] = r8;
#pragma GCC unroll 32
    for (int j = 2; j < P; ++j) grow[j] = grow[j / 2] * grow[j - j / 2];
    n = zero, rho_out = zero, ratio = zero, bound = zero;
    const V one = zero + 1;
    V g = grow[P - 1], beta = one;
    lanes_set(beta, by_sqrt_type, zero + sqrt_type_beta[rule_count - 1]);
#pragma GCC unroll 32
    for (int i = 0; i < rule_count; ++i) {  // the largest first: the smallest that passes stays
        const int k = rule_count - 1 - i;
        const V& gk = grow[rule_sizes[k] / 4];
        V bk = one;
        lanes_set(bk, by_sqrt_type, zero + sqrt_type_beta[k]);
        const M pass = found & (gk * scale >= k_num * bk);
        lanes_set(n, pass, zero + rule_sizes[k]);
        lanes_set(g, pass, gk);
        lanes_set(beta, pass, bk);
    }
    const M chosen = n > 0;
    lanes_set(rho_out, chosen, rho);
    lanes_set(ratio, chosen, 2 * r * M_bound / length);
    lanes_set(bound, chosen, k_num * beta / (k_den * g));
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
    choose_rule_lanes<double, bool>(a, b, zr, zi, rem, q, sm.err, pm, dpm, std::sqrt(sm.cc), eff, length, n, rho,
                                    ratio, bound, cut);
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
