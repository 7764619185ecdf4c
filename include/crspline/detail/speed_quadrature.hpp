// crspline internal: the fast path of arc length. Gauss-Legendre rules of
// 8 to 64 points, the speed |C'(u)| of a segment evaluated at all of a
// rule's nodes in one loop (gauss_legendre.hpp), the speed's complex branch
// points (speed_branch_points.hpp), and an a-priori error bound that picks
// the rule for a piece of a segment (quadrature_rule.hpp). This file runs
// them over many segments and pieces at once: the first pass and the
// pieces' rules, in lanes (simd_lanes.hpp), baseline and AVX2.
//
// Why the bound holds. With P(u) = C'(u) = A + B u + C u^2 (A = c1,
// B = 2 c2, C = 3 c3), the speed is sqrt(q), q(u) = P(u).P(u), a quartic
// with real coefficients; its complex zeros (two conjugate pairs) are the
// branch points of the speed. speed_first_pass finds them (Halley's method
// on q, deflation, a quadratic), sixteen segments at a time in vector lanes.
// choose_rule then takes the Bernstein ellipse E_rho of the piece just
// inside the nearest of them and proves, by Rouche's theorem with the
// deflation's remainder, that q has no zero in E_rho, so that sqrt(q) is
// analytic there, bounded by M = |P(m)| + |P'(m)| R + |C| R^2 (m the piece's
// middle, R the ellipse's semi-major axis). Gauss-Legendre with n points
// then errs by at most
//   r * 2 (2 + 2 / (4 n^2 - 1)) M / ((1 - rho^-2) rho^(2n)),
// r the piece's half-width. (On [-1, 1], the Chebyshev coefficients of
// such a function are |a_k| <= 2 M rho^-k (Trefethen, Approximation Theory
// and Approximation Practice, Theorem 8.1); the rule is exact for T_k with
// k < 2n and for odd k, and errs on T_k by at most |integral| + sum of
// weights = 2 / (k^2 - 1) + 2 otherwise; summed over even k >= 2n. This
// is Trefethen's Theorem 19.3 with 64/15 sharpened for n >= 8, and with
// the factor 1 / (1 - rho^-2) = rho^2 / (rho^2 - 1) that the form
// 1 / (rho^2 - 1) of "Is Gauss quadrature better than Clenshaw-Curtis?",
// SIAM Review 2008, Theorem 4.5, leaves out.) That bound uses only the
// ellipse, not the type of the singularity on it: the speed behaves like
// sqrt(u - z0) at a branch point, whose Chebyshev coefficients fall a
// further k^(-3/2). choose_rule tries that first (sqrt_type_bound in
// quadrature_rule.hpp: the same quadrature argument with the contour taken
// past the branch points along cuts, each root placed in a proved disk),
// and this bound where it fails. The smallest rule whose bound is below
// the accuracy times the length it computes is the piece's.
// Pieces with no rule of at most 64 points proved are cut at the nearest
// branch point's real part; the few that still fail (speed zeros inside:
// cusps, folds, tension 1) go to the slower path that cuts at the speed's
// critical points and singularities.
#pragma once

#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>

#include "../segment.hpp"
#include "gauss_legendre.hpp"
#include "polynomial.hpp"
#include "quadrature_rule.hpp"
#include "simd_lanes.hpp"
#include "speed_branch_points.hpp"
#include "x86_kernels.hpp"

namespace crspline::detail {

/// The first pass over count <= G W segments, in G groups of W lanes of V:
/// the branch points of each (Halley, then deflate_lanes) and, unless rc is
/// null, its first rule over [0, 1], as first_rule(sm[i], bp[i], 0, 1, eff)
/// gives it, bit for bit. The segments' numbers go into the lanes from
/// registers and the results come out lane by lane, with no round trip
/// through memory in between (a vector loaded from scalars just stored
/// stalls the processor).
// (GCC 12 takes the four-lane constructor below for a partial write and
// warns that the vector's other lanes may be uninitialized; every lane is
// written.)
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
template <int G, class V, class M, class S>
[[gnu::always_inline]] inline void first_pass_group(const speed_model* sm, int count, double eff, branch_points* bp,
                                                    rule_choice* rc) noexcept {
    constexpr int W = std::is_same_v<V, double> ? 1 : int(sizeof(V) / sizeof(double));
    // The speed models' fields in lanes: v[g][k] holds field k of group g's
    // segments (segment 0 again past count): q[0..4], dq[0..2], err, cc.
    constexpr int F = 10;
    auto field = [](const speed_model& m, int k) {
        return k < 5 ? m.q[std::size_t(k)] : k < 8 ? m.dq[std::size_t(k - 5)] : k == 8 ? m.err : m.cc;
    };
    V v[G][F];
    branch_root<V, M> n[G];
    for (int g = 0; g < G; ++g) {
        for (int k = 0; k < F; ++k) {
            if constexpr (W == 1) {
                v[g][k] = field(sm[g < count ? g : 0], k);
            } else {
                static_assert(W == 4);
                const int i = g * W;
                v[g][k] = V{field(sm[i], k), field(sm[i + 1 < count ? i + 1 : 0], k),
                            field(sm[i + 2 < count ? i + 2 : 0], k), field(sm[i + 3 < count ? i + 3 : 0], k)};
            }
        }
        branch_root_start<V, M, S>(reinterpret_cast<const V(&)[5]>(v[g][0]), n[g]);
    }
    branch_root_run<G>(n);
    for (int g = 0; g < G; ++g) {
        V zr[2], zi[2], rem[4];
        M ok;
        deflate_lanes<V, M, S>(n[g].c, n[g].xr, n[g].xi, zr, zi, rem, ok);
        ok = ok & n[g].settled;
        V rn = zr[0] - zr[0], rho = rn, ratio = rn, bound = rn, cut = rn;
        M chosen = ok;
        if (rc) {
            const V(&qg)[5] = reinterpret_cast<const V(&)[5]>(v[g][0]);
            const V(&dq)[3] = reinterpret_cast<const V(&)[3]>(v[g][5]);
            const V& err = v[g][8];
            V cn = v[g][9];
            S::apply(cn);
            const V zero = cn - cn, one = zero + 1, half = zero + 0.5;
            V pm, dpm;
            middle_norms<V, S>(qg, dq, err, half, pm, dpm);
            // The length estimate, as first_rule's: half the speed at the
            // middle (as middle_norms bounds it) times the width.
            const V estimate = one * pm / 2;
            choose_rule_lanes<V, M, S>(zero, one, zr, zi, rem, qg, err, pm, dpm, cn, eff, estimate, rn, rho, ratio,
                                       bound, cut);
            chosen = ok & (estimate > zero);
        }
        for (int l = 0; l < W && g * W + l < count; ++l) {
            const int i = g * W + l;
            bp[i] = branch_points{};
            if (lanes_get(ok, l)) {
                for (int k = 0; k < 2; ++k) bp[i].z[k] = {lanes_get(zr[k], l), lanes_get(zi[k], l)};
                for (int k = 0; k < 4; ++k) bp[i].rem[k] = lanes_get(rem[k], l);
                bp[i].ok = true;
            }
            if (rc) rc[i] = lanes_get(chosen, l) ? lane_rule(rn, rho, ratio, bound, cut, l) : rule_choice{};
        }
    }
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

/// first_pass_group over count segments: up to four groups of lanes at a
/// time (as many as there are segments left), else one segment per lane of
/// double without the vector extension. The same bits either way. Inlined
/// into the baseline function and into its AVX2 clone
/// (detail/x86_kernels.hpp).
template <class S>
[[gnu::always_inline]] inline void first_pass_all(const speed_model* sm, int count, double eff, branch_points* bp,
                                                  rule_choice* rc) noexcept {
#if CRSPLINE_LANES4
    using V = lanes;
    using M = lanes_mask;
    constexpr int W = lanes_width;
#else
    using V = double;
    using M = bool;
    constexpr int W = 1;
#endif
    for (int i = 0; i < count; i += 4 * W) {
        const int left = std::min(4 * W, count - i);
        rule_choice* r = rc ? rc + i : nullptr;
        if (left > 3 * W) first_pass_group<4, V, M, S>(sm + i, left, eff, bp + i, r);
        else if (left > 2 * W) first_pass_group<3, V, M, S>(sm + i, left, eff, bp + i, r);
        else if (left > W) first_pass_group<2, V, M, S>(sm + i, left, eff, bp + i, r);
        else first_pass_group<1, V, M, S>(sm + i, left, eff, bp + i, r);
    }
}
inline void first_pass_portable(const speed_model* sm, int count, double eff, branch_points* bp,
                                rule_choice* rc) noexcept {
    first_pass_all<sqrt_baseline>(sm, count, eff, bp, rc);
}
#if CRSPLINE_X86_DISPATCH && CRSPLINE_LANES4
CRSPLINE_TARGET_AVX2 inline void first_pass_avx2(const speed_model* sm, int count, double eff, branch_points* bp,
                                                 rule_choice* rc) noexcept {
    first_pass_all<sqrt_avx>(sm, count, eff, bp, rc);
}
#endif

/// The complex roots of q (the speed's branch points) of count segments,
/// one of each conjugate pair, in each segment's local u (bp[i].ok false
/// when q is not a true quartic, when Halley does not settle, or when a
/// root is numerically real: the speed vanishes there, and the slower path
/// cuts at it), and unless rc is null the first rule of each over [0, 1].
/// Halley's method on the monic quartic, deflation by the pair found, the
/// other pair from the quadratic left. Several segments side by side: one
/// segment's Halley steps and rule choice are chains of dependent divisions
/// and square roots that leave the processor waiting.
inline void speed_first_pass(const speed_model* sm, int count, double eff, branch_points* bp,
                             rule_choice* rc) noexcept {
#if CRSPLINE_X86_DISPATCH && CRSPLINE_LANES4
    if (avx2_enabled()) return first_pass_avx2(sm, count, eff, bp, rc);
#endif
    first_pass_portable(sm, count, eff, bp, rc);
}

/// A piece [a, b] of a segment whose branch points are known, for
/// piece_rules.
struct piece_ref {
    const speed_model* sm;
    const branch_points* bp;  ///< ok
    double a, b;
};

/// first_rule for count <= W pieces in the lanes of V, bit for bit.
template <class V, class M, class S>
[[gnu::always_inline]] inline void piece_rules_group(const piece_ref* p, int count, double eff,
                                                     rule_choice* out) noexcept {
    constexpr int W = std::is_same_v<V, double> ? 1 : int(sizeof(V) / sizeof(double));
    // Field k of piece l's numbers (piece 0 again past count): a, b, z (4),
    // rem (4), q (5), dq (3), err, cc.
    constexpr int F = 20;
    auto field = [](const piece_ref& r, int k) {
        const speed_model& m = *r.sm;
        const branch_points& bp = *r.bp;
        switch (k) {
            case 0: return r.a;
            case 1: return r.b;
            case 2: return bp.z[0].real();
            case 3: return bp.z[1].real();
            case 4: return bp.z[0].imag();
            case 5: return bp.z[1].imag();
            case 18: return m.err;
            case 19: return m.cc;
            default:
                return k < 10   ? bp.rem[std::size_t(k - 6)]
                       : k < 15 ? m.q[std::size_t(k - 10)]
                                : m.dq[std::size_t(k - 15)];
        }
    };
    V v[F];
#pragma GCC unroll 32
    for (int k = 0; k < F; ++k)
        lanes_make(v[k], [&](int l) { return field(p[l < count ? l : 0], k); });
    const V &a = v[0], &b = v[1], &err = v[18];
    const V(&zr)[2] = reinterpret_cast<const V(&)[2]>(v[2]);
    const V(&zi)[2] = reinterpret_cast<const V(&)[2]>(v[4]);
    const V(&rem)[4] = reinterpret_cast<const V(&)[4]>(v[6]);
    const V(&q)[5] = reinterpret_cast<const V(&)[5]>(v[10]);
    const V(&dq)[3] = reinterpret_cast<const V(&)[3]>(v[15]);
    V cn = v[19];
    S::apply(cn);
    V pm, dpm, n, rho, ratio, bound, cut;
    middle_norms<V, S>(q, dq, err, a + (b - a) / 2, pm, dpm);
    const V estimate = (b - a) * pm / 2;
    choose_rule_lanes<V, M, S>(a, b, zr, zi, rem, q, err, pm, dpm, cn, eff, estimate, n, rho, ratio, bound, cut);
    const M chosen = estimate > 0;
    for (int l = 0; l < W && l < count; ++l)
        out[l] = lanes_get(chosen, l) ? lane_rule(n, rho, ratio, bound, cut, l) : rule_choice{};
}

/// piece_rules_group over count pieces, W at a time.
template <class S>
[[gnu::always_inline]] inline void piece_rules_all(const piece_ref* p, int count, double eff,
                                                   rule_choice* out) noexcept {
#if CRSPLINE_LANES4
    for (int i = 0; i < count; i += lanes_width)
        piece_rules_group<lanes, lanes_mask, S>(p + i, std::min(lanes_width, count - i), eff, out + i);
#else
    for (int i = 0; i < count; ++i) piece_rules_group<double, bool, S>(p + i, 1, eff, out + i);
#endif
}
inline void piece_rules_portable(const piece_ref* p, int count, double eff, rule_choice* out) noexcept {
    piece_rules_all<sqrt_baseline>(p, count, eff, out);
}
#if CRSPLINE_X86_DISPATCH && CRSPLINE_LANES4
CRSPLINE_TARGET_AVX2 inline void piece_rules_avx2(const piece_ref* p, int count, double eff,
                                                  rule_choice* out) noexcept {
    piece_rules_all<sqrt_avx>(p, count, eff, out);
}
#endif

/// first_rule(*p[i].sm, *p[i].bp, p[i].a, p[i].b, eff) for count pieces of
/// segments (of the same or different segments), several side by side: the
/// same bits as one by one.
inline void piece_rules(const piece_ref* p, int count, double eff, rule_choice* out) noexcept {
#if CRSPLINE_X86_DISPATCH && CRSPLINE_LANES4
    if (avx2_enabled()) return piece_rules_avx2(p, count, eff, out);
#endif
    piece_rules_portable(p, count, eff, out);
}

/// The branch points of one segment (the same bits as in a group).
inline branch_points speed_branch_points(const speed_model& sm) noexcept {
    branch_points bp;
    speed_first_pass(&sm, 1, 1.0, &bp, nullptr);
    return bp;
}

}  // namespace crspline::detail
