// crspline internal: the fast path of arc length. Gauss-Legendre rules of
// 8, 16, 24 and 32 points, the speed |C'(u)| of a segment evaluated at all
// of a rule's nodes in one loop, and an a-priori error bound that picks the
// rule for a piece of a segment without finding the speed's singularities.
//
// Why the bound holds. With P(u) = C'(u) = A + B u + C u^2 (A = c1,
// B = 2 c2, C = 3 c3), the speed is sqrt(q), q(u) = P(u).P(u), a quartic.
// For z = x + i y, P(z) = P(x) - y^2 C + i y P'(x), so
//   Re q(z) = |P(x) - y^2 C|^2 - y^2 |P'(x)|^2
//          >= (|P(x)| - y^2 |C|)^2 - y^2 |P'(x)|^2,
// which is > 0 when |P(x)| - y^2 |C| > |y| |P'(x)|. The Bernstein ellipse
// E_rho of a piece [a, b] (half-width r) lies in the rectangle
// |x - mid| <= r (rho + 1/rho)/2, |y| <= Y = r (rho - 1/rho)/2. If
//   m > Y^2 |C| + Y M1,
// with m a lower bound of |P| on the rectangle's real side (the smallest
// Bernstein coefficient of q there, square-rooted) and M1 the largest |P'|
// there (|P'| is convex in x: its larger end value), then Re q > 0 on the
// whole rectangle, so the principal sqrt(q) is analytic inside E_rho and
// |sqrt(q(z))| <= |P(z)| <= Mq + Y M1 + Y^2 |C| =: M, Mq from the largest
// Bernstein coefficient. Gauss-Legendre with n points then errs by at most
//   r * 64 M / (15 (rho^2 - 1) rho^(2n))
// (Trefethen, "Is Gauss quadrature better than Clenshaw-Curtis?", SIAM
// Review 50 (2008), Theorem 4.5), and the piece is at least 2 r m long, so
// a rule meets relative accuracy acc on the piece when that bound is at most
// acc * 2 r m. Pieces for which no candidate rho proves a rule of at most
// 32 points are halved; the few that still fail (speed zeros inside: cusps,
// folds, tension 1) go to the slower path that cuts at the speed's
// critical points and singularities.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "../segment.hpp"
#include "polynomial.hpp"

namespace crspline::detail {

/// Gauss-Legendre rule with N points on [-1, 1]: the N/2 positive nodes
/// (the others are their negatives) and their weights; exact for
/// polynomials of degree 2N - 1. Values from mpmath at 40 digits.
template <int N, class T>
struct gauss_legendre;

template <class T>
struct gauss_legendre<8, T> {
    static constexpr T x[4] = {T(0.18343464249564980494), T(0.52553240991632898582), T(0.79666647741362673959),
                               T(0.96028985649753623168)};
    static constexpr T w[4] = {T(0.36268378337836198297), T(0.31370664587788728734), T(0.22238103445337447054),
                               T(0.10122853629037625915)};
};

template <class T>
struct gauss_legendre<16, T> {
    static constexpr T x[8] = {T(0.0950125098376374401853), T(0.281603550779258913230), T(0.458016777657227386342), T(0.617876244402643748447),
                                T(0.755404408355003033895), T(0.865631202387831743880), T(0.944575023073232576078), T(0.989400934991649932596)};
    static constexpr T w[8] = {T(0.189450610455068496285), T(0.182603415044923588867), T(0.169156519395002538189), T(0.149595988816576732082),
                                T(0.124628971255533872052), T(0.0951585116824927848099), T(0.0622535239386478928628), T(0.0271524594117540948518)};
};

template <class T>
struct gauss_legendre<24, T> {
    static constexpr T x[12] = {T(0.0640568928626056260850), T(0.191118867473616309159), T(0.315042679696163374387), T(0.433793507626045138487),
                                T(0.545421471388839535658), T(0.648093651936975569252), T(0.740124191578554364244), T(0.820001985973902921954),
                                T(0.886415527004401034213), T(0.938274552002732758524), T(0.974728555971309498198), T(0.995187219997021360180)};
    static constexpr T w[12] = {T(0.127938195346752156974), T(0.125837456346828296121), T(0.121670472927803391204), T(0.115505668053725601353),
                                T(0.107444270115965634783), T(0.0976186521041138882699), T(0.0861901615319532759172), T(0.0733464814110803057340),
                                T(0.0592985849154367807464), T(0.0442774388174198061686), T(0.0285313886289336631813), T(0.0123412297999871995468)};
};

template <class T>
struct gauss_legendre<32, T> {
    static constexpr T x[16] = {T(0.0483076656877383162348), T(0.144471961582796493485), T(0.239287362252137074545), T(0.331868602282127649780),
                                T(0.421351276130635345364), T(0.506899908932229390024), T(0.587715757240762329041), T(0.663044266930215200975),
                                T(0.732182118740289680387), T(0.794483795967942406963), T(0.849367613732569970134), T(0.896321155766052123965),
                                T(0.934906075937739689171), T(0.964762255587506430774), T(0.985611511545268335400), T(0.997263861849481563545)};
    static constexpr T w[16] = {T(0.0965400885147278005668), T(0.0956387200792748594191), T(0.0938443990808045656392), T(0.0911738786957638847129),
                                T(0.0876520930044038111428), T(0.0833119242269467552222), T(0.0781938957870703064717), T(0.0723457941088485062254),
                                T(0.0658222227763618468377), T(0.0586840934785355471453), T(0.0509980592623761761962), T(0.0428358980222266806569),
                                T(0.0342738629130214331027), T(0.0253920653092620594558), T(0.0162743947309056706052), T(0.00701861000947009660041)};
};

/// q[i] = sqrt(q[i]) for non-negative q: two at a time with SSE2 for
/// double (std::sqrt keeps errno semantics, which stops the compiler from
/// vectorizing it).
template <int N, class T>
[[gnu::always_inline]] inline void sqrt_all(T (&q)[N]) noexcept {
#if defined(__SSE2__)
    if constexpr (std::is_same_v<T, double> && N % 2 == 0) {
        for (int i = 0; i < N; i += 2) _mm_storeu_pd(q + i, _mm_sqrt_pd(_mm_loadu_pd(q + i)));
        return;
    }
#endif
    for (int i = 0; i < N; ++i) q[i] = std::sqrt(q[i]);
}

/// Integral of the speed of s over [a, b] by the N-point rule: all nodes
/// first, then the components (a loop the compiler vectorizes), then the
/// square roots and the weighted sum.
template <int N, std::size_t D, class T>
T gauss_length_n(const cubic_segment<D, T>& s, T a, T b) noexcept {
    using G = gauss_legendre<N, T>;
    constexpr int H = N / 2;
    const T m = (a + b) / 2, r = (b - a) / 2;
    T u[N], q[N];
    for (int i = 0; i < H; ++i) {
        u[i] = m - r * G::x[i];
        u[H + i] = m + r * G::x[i];
    }
    for (int i = 0; i < N; ++i) q[i] = 0;
    for (std::size_t k = 0; k < D; ++k) {
        const T A = s.c1[k], B = T(2) * s.c2[k], C = T(3) * s.c3[k];
        for (int i = 0; i < N; ++i) {
            const T p = A + u[i] * (B + u[i] * C);
            q[i] += p * p;
        }
    }
    sqrt_all<N>(q);
    T sum = 0;
    for (int i = 0; i < H; ++i) sum += G::w[i] * (q[i] + q[H + i]);
    return sum * r;
}

/// Integral of the speed by a rule chosen at run time (8, 16, 24 or 32).
template <std::size_t D, class T>
T gauss_length_rule(const cubic_segment<D, T>& s, T a, T b, int n) noexcept {
    switch (n) {
        case 16: return gauss_length_n<16>(s, a, b);
        case 24: return gauss_length_n<24>(s, a, b);
        case 32: return gauss_length_n<32>(s, a, b);
        default: return gauss_length_n<8>(s, a, b);
    }
}

/// The speed squared of a segment as scalars: q(u) = |P(u)|^2 in the power
/// basis and |P'(u)|^2 = pp0 + pp1 u + pp2 u^2, with |C| for the bound.
struct speed_model {
    std::array<double, 5> q;
    double pp0, pp1, pp2;
    double a_norm, b_norm, c_norm;

    template <std::size_t D, class T>
    explicit speed_model(const cubic_segment<D, T>& s) noexcept {
        double AA = 0, AB = 0, AC = 0, BB = 0, BC = 0, CC = 0;
        for (std::size_t k = 0; k < D; ++k) {
            const double A = double(s.c1[k]), B = 2.0 * double(s.c2[k]), C = 3.0 * double(s.c3[k]);
            AA += A * A, AB += A * B, AC += A * C, BB += B * B, BC += B * C, CC += C * C;
        }
        q[0] = AA, q[1] = 2 * AB, q[2] = BB + 2 * AC, q[3] = 2 * BC, q[4] = CC;
        // P' = B + 2 C u
        pp0 = BB, pp1 = 4 * BC, pp2 = 4 * CC;
        a_norm = std::sqrt(AA), b_norm = std::sqrt(BB), c_norm = std::sqrt(CC);
    }

    /// Lower and upper bounds of the quartic p on [lo, hi]: its extreme
    /// Bernstein coefficients on that interval.
    static void bernstein_range(const std::array<double, 5>& p, double lo, double hi, double& qmin,
                                double& qmax) noexcept {
        // Taylor shift to lo and scale to s in [0, 1]: c_j = p^(j)(lo)/j! w^j.
        double c[5] = {p[0], p[1], p[2], p[3], p[4]};
        for (int i = 0; i < 4; ++i)
            for (int j = 3; j >= i; --j) c[j] += lo * c[j + 1];
        const double w = hi - lo;
        double wj = w;
        for (int j = 1; j < 5; ++j) c[j] *= wj, wj *= w;
        const double b[5] = {c[0], c[0] + c[1] / 4, c[0] + c[1] / 2 + c[2] / 6,
                             c[0] + 0.75 * c[1] + c[2] / 2 + c[3] / 4, c[0] + c[1] + c[2] + c[3] + c[4]};
        qmin = std::min({b[0], b[1], b[2], b[3], b[4]});
        qmax = std::max({b[0], b[1], b[2], b[3], b[4]});
    }
    double dspeed_sq(double x) const noexcept { return pp0 + x * (pp1 + x * pp2); }
};

/// The rule a piece needs (0 when none was proved), the rho that proved it
/// and the ratio M / m of the bound.
struct rule_choice {
    int n = 0;
    double rho = 0, ratio = 0;
    double bound = 0;  ///< the rule's error bound on the piece

    /// The largest sub-interval, as a fraction of the piece, on which the
    /// 3-point rule is proved by the same rectangle (for short increments
    /// inside the piece): a sub-interval of relative width w has rho_w >=
    /// g / w, g the rectangle's margin beyond the piece in units of its
    /// half-width, and the 3-point rule meets eff when rho_w^8 >= 4.3 M /
    /// (eff m) (the bound above with n = 3 and rho_w^2 - 1 >= rho_w^2 / 2).
    /// For the slower path's pieces (rho == 0), cut for the 8-point rule at
    /// rho_min with rho_min^-16 = eff / 100, the fraction derived in
    /// arc_length_table::t_from_anchor.
    double short_fraction(double eff) const noexcept {
        if (rho == 0) return std::pow(100.0 / eff, -5.0 / 48.0) / 2.2;
        const double g = std::min(rho - 1 / rho, rho + 1 / rho - 2);
        return g / std::pow(4.3 * ratio / eff, 0.125);
    }
};

/// The complex roots of q (the speed's branch points), one of each
/// conjugate pair, in the segment's local u. Newton on the monic quartic
/// from a point off the real axis, deflation by the pair found, the other
/// pair from the quadratic left. False when q is not a true quartic, when
/// Newton does not settle, or when a root is (numerically) real: the speed
/// vanishes there, and the slower path cuts at it.
inline bool speed_branch_points(const speed_model& sm, std::complex<double> (&z)[2]) noexcept {
    const auto& q = sm.q;
    const double scale = q[0] + q[2] + q[4];
    if (!(q[4] > 1e-12 * scale && scale < 1e280 && q[4] > 1e-280)) return false;
    const double c0 = q[0] / q[4], c1 = q[1] / q[4], c2 = q[2] / q[4], c3 = q[3] / q[4];
    // Complex arithmetic written out: std::complex's division and abs()
    // guard against overflow (hypot, __divdc3) at several times the cost,
    // and the coefficients here are within range (checked above).
    // Start: a root of q's quadratic Taylor model at the smallest of five
    // samples of q on [0, 1] (near the closest pair when there is one: a few
    // Newton steps then suffice), else 0.5 + 0.6 i.
    double xr = 0.5, xi = 0.6;
    {
        double u = 0, low = q[0];
        for (double v : {0.25, 0.5, 0.75, 1.0}) {
            const double qv = horner(q, v);
            if (qv < low) low = qv, u = v;
        }
        const double q1 = ((4 * q[4] * u + 3 * q[3]) * u + 2 * q[2]) * u + q[1];
        const double q2h = (6 * q[4] * u + 3 * q[3]) * u + q[2];  // q''(u) / 2
        const double disc = 4 * low * q2h - q1 * q1;
        if (q2h > 0 && disc > 0) xr = u - q1 / (2 * q2h), xi = std::sqrt(disc) / (2 * q2h);
    }
    // Stops when a step is below 1e-8 of |x|: Newton's error after it is
    // about its square, and the rule needs rho only to a few per cent.
    bool settled = false;
    for (int it = 0; it < 60; ++it) {
        // f = (((x + c3) x + c2) x + c1) x + c0, df = ((4 x + 3 c3) x + 2 c2) x + c1
        double fr = xr + c3, fi = xi, dr = 4 * xr + 3 * c3, di = 4 * xi, t;
        t = fr * xr - fi * xi + c2, fi = fr * xi + fi * xr, fr = t;
        t = dr * xr - di * xi + 2 * c2, di = dr * xi + di * xr, dr = t;
        t = fr * xr - fi * xi + c1, fi = fr * xi + fi * xr, fr = t;
        t = dr * xr - di * xi + c1, di = dr * xi + di * xr, dr = t;
        t = fr * xr - fi * xi + c0, fi = fr * xi + fi * xr, fr = t;
        const double dd = dr * dr + di * di;
        if (!(dd > 0)) return false;
        const double sr = (fr * dr + fi * di) / dd, si = (fi * dr - fr * di) / dd;
        xr -= sr, xi -= si;
        if (sr * sr + si * si <= 1e-16 * (1 + xr * xr + xi * xi)) {
            settled = true;
            break;
        }
    }
    const std::complex<double> x(xr, xi);
    if (!settled || !(xi * xi > 1e-18 * (1 + xr * xr + xi * xi))) return false;
    // x^4 + c3 x^3 + c2 x^2 + c1 x + c0 = (x^2 + p x + s)(x^2 + e x + f)
    const double p = -2 * x.real(), sq = std::norm(x);
    const double e = c3 - p, f = c2 - sq - p * e;
    const double disc = f - e * e / 4;
    if (!(disc > 1e-18 * (1 + f))) return false;
    z[0] = x;
    z[1] = std::complex<double>(-e / 2, std::sqrt(disc));
    return true;
}

/// Bernstein-ellipse parameter of z for [a, b]: rho + 1/rho is the sum of
/// the distances from z to a and b over b - a.
inline double ellipse_parameter(std::complex<double> z, double a, double b) noexcept {
    const double y2 = z.imag() * z.imag(), da = z.real() - a, db = z.real() - b;
    const double s = (std::sqrt(da * da + y2) + std::sqrt(db * db + y2)) / (b - a);
    return s + std::sqrt(std::max(s * s - 1, 0.0));
}

/// The smallest rule of 8, 16, 24 or 32 points whose error bound on [a, b]
/// is at most eff * length, from the branch points z (Trefethen's bound with
/// rho 10% closer to 1 than the nearest branch point, as a margin for the
/// roots' rounding, and M = |A| + |B| |u| + |C| |u|^2 >= |P(u)| >=
/// |sqrt q(u)| over that ellipse).
inline rule_choice choose_rule(const speed_model& sm, const std::complex<double> (&z)[2], double a, double b,
                               double eff, double length) noexcept {
    rule_choice best;
    const double rho_z = std::min(ellipse_parameter(z[0], a, b), ellipse_parameter(z[1], a, b));
    const double rho = 1 + 0.9 * (rho_z - 1);
    if (!(rho > 1.05)) return best;
    const double r = (b - a) / 2, mid = a + r;
    const double reach = std::abs(mid) + r * (rho + 1 / rho) / 2;
    const double M = sm.a_norm + reach * (sm.b_norm + reach * sm.c_norm);
    const double K = r * 64 * M / (15 * (rho * rho - 1));
    // rho^(2n) for n = 8, 16, 24, 32 by squaring (no pow or log per piece).
    const double r2 = rho * rho, r4 = r2 * r2, r8 = r4 * r4, r16 = r8 * r8, r32 = r16 * r16;
    const double grow[4] = {r16, r32, r32 * r16, r32 * r32};
    const double ratio = K / (eff * length);
    for (int k = 0; k < 4; ++k)
        if (grow[k] >= ratio) {
            best = {8 * (k + 1), rho, 2 * r * M / length};
            best.bound = K / grow[k];
            break;
        }
    return best;
}

}  // namespace crspline::detail
