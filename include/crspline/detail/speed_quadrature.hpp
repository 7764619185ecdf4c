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
struct gauss_legendre<12, T> {
    static constexpr T x[6] = {T(0.125233408511468915472441), T(0.367831498998180193752692), T(0.587317954286617447296702),
                                T(0.769902674194304687036894), T(0.904117256370474856678466), T(0.981560634246719250690549)};
    static constexpr T w[6] = {T(0.249147045813402785000562), T(0.233492536538354808760850), T(0.203167426723065921749064),
                                T(0.160078328543346226334653), T(0.106939325995318430960255), T(0.047175336386511827194616)};
};

template <class T>
struct gauss_legendre<16, T> {
    static constexpr T x[8] = {T(0.0950125098376374401853), T(0.281603550779258913230), T(0.458016777657227386342), T(0.617876244402643748447),
                                T(0.755404408355003033895), T(0.865631202387831743880), T(0.944575023073232576078), T(0.989400934991649932596)};
    static constexpr T w[8] = {T(0.189450610455068496285), T(0.182603415044923588867), T(0.169156519395002538189), T(0.149595988816576732082),
                                T(0.124628971255533872052), T(0.0951585116824927848099), T(0.0622535239386478928628), T(0.0271524594117540948518)};
};

template <class T>
struct gauss_legendre<20, T> {
    static constexpr T x[10] = {T(0.0765265211334973337546404), T(0.227785851141645078080496), T(0.373706088715419560672548), T(0.510867001950827098004364),
                                T(0.636053680726515025452837), T(0.746331906460150792614305), T(0.839116971822218823394529), T(0.912234428251325905867752),
                                T(0.963971927277913791267666), T(0.993128599185094924786122)};
    static constexpr T w[10] = {T(0.152753387130725850698084), T(0.149172986472603746787829), T(0.142096109318382051329298), T(0.131688638449176626898494),
                                T(0.118194531961518417312377), T(0.101930119817240435036750), T(0.0832767415767047487247581), T(0.0626720483341090635695065),
                                T(0.0406014298003869413310400), T(0.0176140071391521183118620)};
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
struct gauss_legendre<28, T> {
    static constexpr T x[14] = {T(0.0550792898840342704265165), T(0.164569282133380771281472), T(0.272061627635178077676826), T(0.376251516089078710221357),
                                T(0.475874224955118261034412), T(0.569720471811401719308003), T(0.656651094038864961219898), T(0.735610878013631772028145),
                                T(0.805641370917179171447886), T(0.865892522574395048942255), T(0.915633026392132073869689), T(0.954259280628938197254102),
                                T(0.981303165370872753694560), T(0.996442497573954449950436)};
    static constexpr T w[14] = {T(0.110047013016475196282376), T(0.108711192258294135253572), T(0.106055765922846417910416), T(0.102112967578060769814217),
                                T(0.0969306579979299158504890), T(0.0905717443930328409421860), T(0.0831134172289012183903965), T(0.0746462142345687790239319),
                                T(0.0652729239669995957933976), T(0.0551073456757167454314829), T(0.0442729347590042278395879), T(0.0329014277823043799776308),
                                T(0.0211321125927712597515004), T(0.00912428259309451773881615)};
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

template <class T>
struct gauss_legendre<40, T> {
    static constexpr T x[20] = {T(0.0387724175060508219331934), T(0.116084070675255208483451), T(0.192697580701371099715517), T(0.268152185007253681141184),
                                T(0.341994090825758473007492), T(0.41377920437160500152488), T(0.483075801686178712908567), T(0.549467125095128202075931),
                                T(0.612553889667980237952612), T(0.671956684614179548379355), T(0.727318255189927103280996), T(0.778305651426519387694972),
                                T(0.82461223083331166319632), T(0.865959503212259503820782), T(0.902098806968874296728253), T(0.932812808278676533360852),
                                T(0.957916819213791655804541), T(0.97725994998377426266337), T(0.990726238699457006453054), T(0.998237709710559200349623)};
    static constexpr T w[20] = {T(0.077505947978424811263724), T(0.0770398181642479655883075), T(0.0761103619006262423715581), T(0.0747231690579682642001893),
                                T(0.0728865823958040590605107), T(0.0706116473912867796954836), T(0.0679120458152339038256901), T(0.0648040134566010380745545),
                                T(0.061306242492928939166538), T(0.0574397690993915513666177), T(0.0532278469839368243549965), T(0.0486958076350722320614342),
                                T(0.0438709081856732719916747), T(0.038782167974472017639972), T(0.0334601952825478473926782), T(0.0279370069800234010984892),
                                T(0.0222458491941669572615043), T(0.0164210583819078887128635), T(0.0104982845311528136147422), T(0.00452127709853319125847173)};
};

template <class T>
struct gauss_legendre<48, T> {
    static constexpr T x[24] = {T(0.0323801709628693620333222), T(0.097004699209462698930054), T(0.161222356068891718056437), T(0.224763790394689061224865),
                                T(0.287362487355455576735886), T(0.348755886292160738159818), T(0.408686481990716729916225), T(0.466902904750958404544929),
                                T(0.523160974722233033678226), T(0.577224726083972703817809), T(0.628867396776513623995165), T(0.677872379632663905211851),
                                T(0.724034130923814654674482), T(0.767159032515740339253855), T(0.807066204029442627082553), T(0.84358826162439353071109),
                                T(0.876572020274247885905694), T(0.905879136715569672822075), T(0.931386690706554333114174), T(0.952987703160430860722961),
                                T(0.970591592546247250461412), T(0.984124583722826857744584), T(0.993530172266350757547929), T(0.998771007252426118600541)};
    static constexpr T w[24] = {T(0.0647376968126839225030249), T(0.0644661644359500822065042), T(0.0639242385846481866239062), T(0.063114192286254025657126),
                                T(0.0620394231598926639041978), T(0.0607044391658938800529692), T(0.0591148396983956357464748), T(0.0572772921004032157051502),
                                T(0.0551995036999841628682035), T(0.0528901894851936670955051), T(0.0503590355538544749578076), T(0.0476166584924904748259066),
                                T(0.0446745608566942804194486), T(0.0415450829434647492140588), T(0.0382413510658307063172173), T(0.0347772225647704388925486),
                                T(0.0311672278327980889020658), T(0.0274265097083569482000738), T(0.0235707608393243791405193), T(0.0196161604573555278144607),
                                T(0.015579315722943848728177), T(0.0114772345792345394895927), T(0.00732755390127626210238398), T(0.00315334605230583863267731)};
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

/// The most points of a rule the fast path uses.
inline constexpr int max_rule = 48;

/// Integral of the speed by a rule chosen at run time (8, 12, ..., 32, 40, 48).
template <std::size_t D, class T>
T gauss_length_rule(const cubic_segment<D, T>& s, T a, T b, int n) noexcept {
    switch (n) {
        case 12: return gauss_length_n<12>(s, a, b);
        case 16: return gauss_length_n<16>(s, a, b);
        case 20: return gauss_length_n<20>(s, a, b);
        case 24: return gauss_length_n<24>(s, a, b);
        case 28: return gauss_length_n<28>(s, a, b);
        case 32: return gauss_length_n<32>(s, a, b);
        case 40: return gauss_length_n<40>(s, a, b);
        case 48: return gauss_length_n<48>(s, a, b);
        default: return gauss_length_n<8>(s, a, b);
    }
}

/// The speed squared of a segment as scalars: q(u) = |P(u)|^2 in the power
/// basis and |P'(u)|^2 = pp0 + pp1 u + pp2 u^2, with |C| for the bound.
struct speed_model {
    std::array<double, 5> q{};
    double pp0 = 0, pp1 = 0, pp2 = 0;
    double a_norm = 0, b_norm = 0, c_norm = 0;

    speed_model() = default;
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
    /// Real part of the branch point nearest to the piece (NaN when not
    /// computed): where to cut it when no rule is proved.
    double cut = std::numeric_limits<double>::quiet_NaN();

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

/// speed_branch_points' Newton iteration for one segment: the monic
/// quartic, the current root estimate and whether it is still moving.
struct branch_newton {
    double c0 = 0, c1 = 0, c2 = 0, c3 = 0;
    double xr = 0.5, xi = 0.6;
    int state = -1;  ///< 0: moving, 1: settled, -1: failed
};

/// The iteration's start for segment model sm (state -1 when q is not a
/// true quartic).
inline branch_newton branch_newton_start(const speed_model& sm) noexcept {
    branch_newton n;
    const auto& q = sm.q;
    const double scale = q[0] + q[2] + q[4];
    if (!(q[4] > 1e-12 * scale && scale < 1e280 && q[4] > 1e-280)) return n;
    n.c0 = q[0] / q[4], n.c1 = q[1] / q[4], n.c2 = q[2] / q[4], n.c3 = q[3] / q[4];
    // Start: a root of q's quadratic Taylor model at the smallest of five
    // samples of q on [0, 1] (near the closest pair when there is one: a few
    // Newton steps then suffice), else 0.5 + 0.6 i.
    double u = 0, low = q[0];
    for (double v : {0.25, 0.5, 0.75, 1.0}) {
        const double qv = horner(q, v);
        if (qv < low) low = qv, u = v;
    }
    const double q1 = ((4 * q[4] * u + 3 * q[3]) * u + 2 * q[2]) * u + q[1];
    const double q2h = (6 * q[4] * u + 3 * q[3]) * u + q[2];  // q''(u) / 2
    const double disc = 4 * low * q2h - q1 * q1;
    if (q2h > 0 && disc > 0) n.xr = u - q1 / (2 * q2h), n.xi = std::sqrt(disc) / (2 * q2h);
    n.state = 0;
    return n;
}

/// One Newton step of a moving iteration. Complex arithmetic written out:
/// std::complex's division and abs() guard against overflow (hypot,
/// __divdc3) at several times the cost, and the coefficients here are
/// within range (checked by branch_newton_start). Settles when a step is
/// below 1e-8 of |x|: Newton's error after it is about its square, and the
/// rule needs rho only to a few per cent.
[[gnu::always_inline]] inline void branch_newton_step(branch_newton& n) noexcept {
    const double xr = n.xr, xi = n.xi, c0 = n.c0, c1 = n.c1, c2 = n.c2, c3 = n.c3;
    // f = (((x + c3) x + c2) x + c1) x + c0, df = ((4 x + 3 c3) x + 2 c2) x + c1
    double fr = xr + c3, fi = xi, dr = 4 * xr + 3 * c3, di = 4 * xi, t;
    t = fr * xr - fi * xi + c2, fi = fr * xi + fi * xr, fr = t;
    t = dr * xr - di * xi + 2 * c2, di = dr * xi + di * xr, dr = t;
    t = fr * xr - fi * xi + c1, fi = fr * xi + fi * xr, fr = t;
    t = dr * xr - di * xi + c1, di = dr * xi + di * xr, dr = t;
    t = fr * xr - fi * xi + c0, fi = fr * xi + fi * xr, fr = t;
    const double dd = dr * dr + di * di;
    if (!(dd > 0)) {
        n.state = -1;
        return;
    }
    const double sr = (fr * dr + fi * di) / dd, si = (fi * dr - fr * di) / dd;
    n.xr = xr - sr, n.xi = xi - si;
    if (sr * sr + si * si <= 1e-16 * (1 + n.xr * n.xr + n.xi * n.xi)) n.state = 1;
}

/// Newton's iterations at most.
inline constexpr int branch_newton_steps = 60;

/// The two branch points from a finished iteration: false unless it
/// settled on a root off the real axis and the quadratic left by deflation
/// has one too.
inline bool branch_newton_finish(const branch_newton& n, std::complex<double> (&z)[2]) noexcept {
    const double xr = n.xr, xi = n.xi;
    if (n.state != 1 || !(xi * xi > 1e-18 * (1 + xr * xr + xi * xi))) return false;
    // x^4 + c3 x^3 + c2 x^2 + c1 x + c0 = (x^2 + p x + s)(x^2 + e x + f)
    const double p = -2 * xr, sq = xr * xr + xi * xi;
    const double e = n.c3 - p, f = n.c2 - sq - p * e;
    const double disc = f - e * e / 4;
    if (!(disc > 1e-18 * (1 + f))) return false;
    z[0] = std::complex<double>(xr, xi);
    z[1] = std::complex<double>(-e / 2, std::sqrt(disc));
    return true;
}

/// The complex roots of q (the speed's branch points), one of each
/// conjugate pair, in the segment's local u. Newton on the monic quartic
/// from a point off the real axis, deflation by the pair found, the other
/// pair from the quadratic left. False when q is not a true quartic, when
/// Newton does not settle, or when a root is (numerically) real: the speed
/// vanishes there, and the slower path cuts at it.
inline bool speed_branch_points(const speed_model& sm, std::complex<double> (&z)[2]) noexcept {
    branch_newton n = branch_newton_start(sm);
    for (int it = 0; it < branch_newton_steps && n.state == 0; ++it) branch_newton_step(n);
    return branch_newton_finish(n, z);
}

/// speed_branch_points for count <= L segments at once, the same steps and
/// the same results bit for bit: the iterations run side by side, so the
/// processor overlaps their chains of dependent divisions, which one
/// segment alone leaves waiting.
template <int L>
void speed_branch_points_block(const speed_model* sm, int count, std::complex<double> (*z)[2], bool* ok) noexcept {
    branch_newton n[L];
    for (int l = 0; l < count; ++l) n[l] = branch_newton_start(sm[l]);
    for (int it = 0; it < branch_newton_steps; ++it) {
        bool moving = false;
        for (int l = 0; l < count; ++l)
            if (n[l].state == 0) {
                branch_newton_step(n[l]);
                moving = true;
            }
        if (!moving) break;
    }
    for (int l = 0; l < count; ++l) ok[l] = branch_newton_finish(n[l], z[l]);
}

/// Bernstein-ellipse parameter of z for [a, b]: rho + 1/rho is the sum of
/// the distances from z to a and b over b - a.
inline double ellipse_parameter(std::complex<double> z, double a, double b) noexcept {
    const double y2 = z.imag() * z.imag(), da = z.real() - a, db = z.real() - b;
    const double s = (std::sqrt(da * da + y2) + std::sqrt(db * db + y2)) / (b - a);
    return s + std::sqrt(std::max(s * s - 1, 0.0));
}

/// The smallest rule of 8, 12, ..., 32, 40 or 48 points whose error bound on [a, b]
/// is at most eff * length, from the branch points z (Trefethen's bound with
/// rho 10% closer to 1 than the nearest branch point, as a margin for the
/// roots' rounding, and M = |A| + |B| |u| + |C| |u|^2 >= |P(u)| >=
/// |sqrt q(u)| over that ellipse).
inline rule_choice choose_rule(const speed_model& sm, const std::complex<double> (&z)[2], double a, double b,
                               double eff, double length) noexcept {
    rule_choice best;
    // ellipse_parameter of both points, their square roots two at a time
    // (square roots and divisions are most of this function's time).
    double e[2];
    {
        const double w = b - a;
        double d[4], sq[2];
        for (int k = 0; k < 2; ++k) {
            const double y2 = z[k].imag() * z[k].imag(), da = z[k].real() - a, db = z[k].real() - b;
            d[k] = da * da + y2, d[2 + k] = db * db + y2;
        }
#if defined(__SSE2__)
        _mm_storeu_pd(d, _mm_sqrt_pd(_mm_loadu_pd(d)));
        _mm_storeu_pd(d + 2, _mm_sqrt_pd(_mm_loadu_pd(d + 2)));
#else
        for (double& x : d) x = std::sqrt(x);
#endif
        for (int k = 0; k < 2; ++k) e[k] = (d[k] + d[2 + k]) / w, sq[k] = std::max(e[k] * e[k] - 1, 0.0);
#if defined(__SSE2__)
        _mm_storeu_pd(sq, _mm_sqrt_pd(_mm_loadu_pd(sq)));
#else
        for (double& x : sq) x = std::sqrt(x);
#endif
        for (int k = 0; k < 2; ++k) e[k] += sq[k];
    }
    const double rho_z = std::min(e[0], e[1]);
    best.cut = (e[0] <= e[1] ? z[0] : z[1]).real();
    const double rho = 1 + 0.9 * (rho_z - 1);
    if (!(rho > 1.05)) return best;
    const double r = (b - a) / 2, mid = a + r;
    const double reach = std::abs(mid) + r * (rho + 1 / rho) / 2;
    const double M = sm.a_norm + reach * (sm.b_norm + reach * sm.c_norm);
    // The bound is K / rho^(2n), K = r 64 M / (15 (rho^2 - 1)) = k_num / k_den.
    const double k_num = r * 64 * M, k_den = 15 * (rho * rho - 1);
    // rho^(2n) for n = 8, 12, ..., 32, 40, 48 by products (no pow or log
    // per piece); the test K / rho^(2n) <= eff length without a division.
    const double r2 = rho * rho, r4 = r2 * r2, r8 = r4 * r4;
    const double scale = k_den * eff * length;
    double grow = r8 * r8;
    for (int n = 8; n <= max_rule; n += n < 32 ? 4 : 8, grow *= n <= 32 ? r8 : r8 * r8)
        if (grow * scale >= k_num) {
            best.n = n, best.rho = rho, best.ratio = 2 * r * M / length;
            best.bound = k_num / (k_den * grow);
            break;
        }
    return best;
}

}  // namespace crspline::detail
