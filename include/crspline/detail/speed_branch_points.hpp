// crspline internal: the speed of a segment as a polynomial and the
// branch points of its square root. speed_model holds q(u) = |C'(u)|^2;
// Halley's method on q, deflation by the root found and a quadratic give
// q's complex zeros, one of each conjugate pair, with bounds of the
// deflation's remainder (branch_points), lane by lane (simd_lanes.hpp).
// The rule choice (quadrature_rule.hpp) proves its bound from them.
#pragma once

#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "../segment.hpp"
#include "simd_lanes.hpp"

namespace crspline::detail {

/// The speed squared of a segment as scalars: q(u) = |P(u)|^2 and
/// |P'(u)|^2 = |B + 2 C u|^2 in the power basis, |C|, and the relative
/// rounding of those coefficients (for the bound's slack).
struct speed_model {
    std::array<double, 5> q{};
    std::array<double, 3> dq{};  ///< |P'(u)|^2 = dq[0] + dq[1] u + dq[2] u^2
    double cc = 0;               ///< |C|^2, rounded up (its root is taken with the bound's)
    double err = 0;              ///< rounding of q and dq relative to |A|^2 + |B|^2 u^2 + |C|^2 u^4

    speed_model() = default;
    template <std::size_t D, class T>
    explicit speed_model(const cubic_segment<D, T>& s) noexcept {
        double AA = 0, AB = 0, AC = 0, BB = 0, BC = 0, CC = 0;
        for (std::size_t k = 0; k < D; ++k) {
            const double A = double(s.c1[k]), B = 2.0 * double(s.c2[k]), C = 3.0 * double(s.c3[k]);
            AA += A * A, AB += A * B, AC += A * C, BB += B * B, BC += B * C, CC += C * C;
        }
        q[0] = AA, q[1] = 2 * AB, q[2] = BB + 2 * AC, q[3] = 2 * BC, q[4] = CC;
        dq[0] = BB, dq[1] = 4 * BC, dq[2] = 4 * CC;
        // A sum of D products errs by (D + 1) eps times the sum of their
        // magnitudes, each |X.Y| <= (|X|^2 + |Y|^2) / 2; Horner at |u| <= 2
        // adds 8 eps of (|A| + |B| |u| + |C| u^2)^2 <= 3 (|A|^2 + |B|^2 u^2 +
        // |C|^2 u^4). Ten times that covers both with room.
        err = 30 * double(D + 9) * std::numeric_limits<double>::epsilon();
        cc = CC * (1 + err);
    }
};


/// The speed's branch points for one segment as speed_branch_points finds
/// them: one of each conjugate pair of q's complex roots, z[0] from Halley
/// and z[1] from the quadratic left by deflation, with bounds of the
/// remainder of that deflation (q / q4 - (u^2 + p u + s)(u^2 + e u + f) =
/// r3 u^3 + r2 u^2 + r1 u + r0, |r_k| <= rem[k], rounding included). The
/// remainder is what choose_rule's Rouche test needs: it proves that q has
/// no zero in the ellipse it picks, however accurate the roots are.
struct branch_points {
    std::complex<double> z[2];
    double rem[4] = {0, 0, 0, 0};
    bool ok = false;
};

/// Upper bounds on |P(m)| and |P'(m)| of a speed_model's segment (their
/// computed squares plus the rounding speed_model::err covers), for the
/// bound on |P| over an ellipse about m in [0, 1].
template <class V, class S = sqrt_baseline>
[[gnu::always_inline]] inline void middle_norms(const V (&q)[5], const V (&dq)[3], const V& err, const V& m, V& pm,
                                                V& dpm) noexcept {
    const V m2 = m * m, zero = m - m;
    pm = (((q[4] * m + q[3]) * m + q[2]) * m + q[1]) * m + q[0] + err * (q[0] + dq[0] * m2 + dq[2] * m2 * m2);
    dpm = (dq[2] * m + dq[1]) * m + dq[0] + err * (dq[0] + dq[2] * m2);
    lanes_set(pm, pm < zero, zero);
    lanes_set(dpm, dpm < zero, zero);
    S::apply(pm);
    S::apply(dpm);
}

/// Halley's iterations at most.
inline constexpr int branch_root_steps = 60;

/// The root finding of speed_first_pass for W segments in the lanes of V
/// (M its comparison mask): q's coefficients in, the monic quartic's, the
/// root Halley's method settled on (xi its imaginary part) and whether it
/// settled out. Start: a root of q's quadratic Taylor model at the smallest
/// of five samples of q on [0, 1] (near the closest pair when there is
/// one), else 0.5 + 0.6 i. Halley's method (cubic convergence: 2.9 steps a
/// segment on a random walk, where Newton took 4.3) then runs until its
/// step is below 1e-4 of the root's imaginary part (or 1e-16 of its size):
/// the error after such a step is about its cube, and choose_rule checks
/// whatever it gets. The complex arithmetic is written out (std::complex
/// guards its division and abs() against overflow at several times the
/// cost; the coefficients are in range, checked first). A lane stops when
/// it settles or fails, so each segment takes its own steps, whatever the
/// others in its group do.
template <class V, class M>
struct branch_root {
    V c[4], xr, xi;
    M moving, settled;
};

template <class V, class M, class S = sqrt_baseline>
[[gnu::always_inline]] inline void branch_root_start(const V (&q)[5], branch_root<V, M>& n) noexcept {
    const V zero = q[0] - q[0];
    const V scale = q[0] + q[2] + q[4];
    n.moving = (q[4] > 1e-12 * scale) & (scale < 1e280) & (q[4] > 1e-280);
    const V inv4 = 1 / q[4];
    for (int k = 0; k < 4; ++k) n.c[k] = q[k] * inv4;
    V u = zero, low = q[0];
    for (double v : {0.25, 0.5, 0.75, 1.0}) {
        const V qv = (((q[4] * v + q[3]) * v + q[2]) * v + q[1]) * v + q[0];
        const M lower = qv < low;
        lanes_set(low, lower, qv);
        lanes_set(u, lower, zero + v);
    }
    const V q1 = ((4 * q[4] * u + 3 * q[3]) * u + 2 * q[2]) * u + q[1];
    const V q2h = (6 * q[4] * u + 3 * q[3]) * u + q[2];  // q''(u) / 2
    const V disc = 4 * low * q2h - q1 * q1;
    const M model = (q2h > 0) & (disc > 0);
    V root = zero;
    lanes_set(root, model, disc);
    S::apply(root);
    n.xr = zero + 0.5, n.xi = zero + 0.6;
    const V inv2 = 1 / (2 * q2h);
    // (The model's root moved by 1/128 of its imaginary part along the real
    // axis: where q is even about the start, as when C'(u) = A + C u^2, the
    // iteration would otherwise stay on the line Re u = const, which holds
    // no root but a fixed point of Halley's method where q' = 0.)
    lanes_set(n.xr, model, u - q1 * inv2 + root * inv2 * (1.0 / 128));
    lanes_set(n.xi, model, root * inv2);
    n.settled = n.moving;
    lanes_clear(n.settled, n.moving);
}

template <class V, class M>
[[gnu::always_inline]] inline void branch_root_step(branch_root<V, M>& n) noexcept {
    const V xr = n.xr, xi = n.xi;
    const V(&c)[4] = n.c;
    // f = (((x + c3) x + c2) x + c1) x + c0, df = ((4 x + 3 c3) x + 2 c2) x + c1,
    // h = f'' / 2 = (6 x + 3 c3) x + c2
    V fr = xr + c[3], fi = xi, dr = 4 * xr + 3 * c[3], di = 4 * xi, hr = 6 * xr + 3 * c[3], hi = 6 * xi, t;
    t = fr * xr - fi * xi + c[2], fi = fr * xi + fi * xr, fr = t;
    t = dr * xr - di * xi + 2 * c[2], di = dr * xi + di * xr, dr = t;
    t = hr * xr - hi * xi + c[2], hi = hr * xi + hi * xr, hr = t;
    t = fr * xr - fi * xi + c[1], fi = fr * xi + fi * xr, fr = t;
    t = dr * xr - di * xi + c[1], di = dr * xi + di * xr, dr = t;
    t = fr * xr - fi * xi + c[0], fi = fr * xi + fi * xr, fr = t;
    // Halley: step = f f' / (f'^2 - f f''/2) = f f' / (f'^2 - f h)
    const V nr = fr * dr - fi * di, ni = fr * di + fi * dr;
    const V er = (dr * dr - di * di) - (fr * hr - fi * hi), ei = 2 * dr * di - (fr * hi + fi * hr);
    const V dd = er * er + ei * ei;
    n.moving = n.moving & (dd > 0);  // a failed lane stops, unsettled
    const V inv = 1 / dd;
    const V sr = (nr * er + ni * ei) * inv, si = (ni * er - nr * ei) * inv;
    lanes_set(n.xr, n.moving, xr - sr);
    lanes_set(n.xi, n.moving, xi - si);
    const V step = sr * sr + si * si;
    const M done = n.moving & ((step <= 1e-8 * (n.xi * n.xi)) | (step <= 1e-32 * (1 + n.xr * n.xr + n.xi * n.xi)));
    n.settled = n.settled | done;
    lanes_clear(n.moving, done);
}

/// Whether the branch point Halley settled on (bp.z[0]) is a root of q:
/// Halley's step also vanishes where q' = 0 and q does not, a fixed point
/// of the iteration (it repels, |H'| = 3, but an iterate can pass close
/// enough to stop there), and deflating by such a point fails the rule's
/// proof on every piece of the segment. True where Newton's step from it,
/// q / q', is within Halley's stop (1e-4 of the imaginary part, or 1e-15
/// of the size): at a simple root, and at a double or triple one (Newton's
/// step is then a half or a third of the distance to it); false where q' is
/// near zero and q is not. Asked only of segments whose first rule was not
/// proved (checked in every step or after the iteration, in lanes, the
/// same test cost 1.5-2% of arc_length_walk20k's time).
inline bool branch_point_is_root(const speed_model& sm, const branch_points& bp) noexcept {
    const std::complex<double> z = bp.z[0];
    std::complex<double> f = 0, d = 0;
    for (std::size_t k = 5; k-- > 0;) {
        d = d * z + f;
        f = f * z + sm.q[k];
    }
    const double xi = z.imag(), size2 = 1 + std::norm(z);
    return std::norm(f) <= (1e-8 * xi * xi + 1e-30 * size2) * std::norm(d);
}

/// G groups of lanes side by side (independent chains the processor
/// overlaps), each lane until it settles or fails.
template <int G, class V, class M>
[[gnu::always_inline]] inline void branch_root_run(branch_root<V, M> (&n)[G]) noexcept {
    for (int it = 0; it < branch_root_steps; ++it) {
        bool any = false;
        for (int g = 0; g < G; ++g)
            if (lanes_any(n[g].moving)) {
                branch_root_step(n[g]);
                any = true;
            }
        if (!any) break;
    }
}

/// The branch points from settled Halley roots (xr, xi) of the monic
/// quartics c, lane by lane: z[0] = (xr, |xi|), z[1] from the quadratic
/// left by deflation, and bounds of the deflation's remainder (see
/// branch_points). ok is false in a lane unless the root is off the real
/// axis and the quadratic has a pair off it too (a real root is a zero of
/// the speed: the slower path cuts there).
template <class V, class M, class S = sqrt_baseline>
[[gnu::always_inline]] inline void deflate_lanes(const V (&c)[4], const V& xr, const V& xi, V (&zr)[2], V (&zi)[2],
                                                V (&rem)[4], M& ok) noexcept {
    const V zero = xr - xr;
    // u^4 + c3 u^3 + c2 u^2 + c1 u + c0 = (u^2 + p u + s)(u^2 + e u + f) + remainder
    const V p = -2 * xr, s = xr * xr + xi * xi;
    const V e = c[3] - p, f = c[2] - s - p * e;
    const V disc = f - e * e / 4;
    V abs_f = zero;
    lanes_add_abs(abs_f, f);
    ok = (xi * xi > 1e-18 * (1 + s)) & (disc > 1e-18 * (1 + abs_f));
    zr[0] = xr, zi[0] = zero, zr[1] = -e / 2, zi[1] = disc;
    lanes_add_abs(zi[0], xi);
    lanes_set(zi[1], disc < zero, zero);
    S::apply(zi[1]);
    // Each remainder coefficient as computed, plus the rounding of its terms
    // and of p, s, e, f (a few ulps of the largest term: 1e-15 relative).
    const double tol = 1e-15;
    const V pe = p * e, pf = p * f, se = s * e, sf = s * f;
    const V terms[4][4] = {{c[0], sf, zero, zero}, {c[1], pf, se, zero}, {c[2], s, pe, f}, {c[3], p, e, zero}};
    const V left[4] = {c[0] - sf, c[1] - (pf + se), c[2] - s - pe - f, c[3] - p - e};
    for (int k = 0; k < 4; ++k) {
        V t = zero;
        for (const V& x : terms[k]) lanes_add_abs(t, x);
        rem[k] = tol * t;
        lanes_add_abs(rem[k], left[k]);
    }
}

/// deflate_lanes for one root into bp (false, bp unchanged, when it fails).
inline bool branch_points_finish(const double (&c)[4], double xr, double xi, branch_points& bp) noexcept {
    double zr[2], zi[2], rem[4];
    bool ok;
    deflate_lanes<double, bool>(c, xr, xi, zr, zi, rem, ok);
    if (!ok) return false;
    for (int k = 0; k < 2; ++k) bp.z[k] = {zr[k], zi[k]};
    for (int k = 0; k < 4; ++k) bp.rem[k] = rem[k];
    bp.ok = true;
    return true;
}

}  // namespace crspline::detail
