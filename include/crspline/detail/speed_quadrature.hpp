// crspline internal: the fast path of arc length. Gauss-Legendre rules of
// 8 to 48 points, the speed |C'(u)| of a segment evaluated at all of a
// rule's nodes in one loop, the speed's complex branch points, and an
// a-priori error bound that picks the rule for a piece of a segment.
//
// Why the bound holds. With P(u) = C'(u) = A + B u + C u^2 (A = c1,
// B = 2 c2, C = 3 c3), the speed is sqrt(q), q(u) = P(u).P(u), a quartic
// with real coefficients; its complex zeros (two conjugate pairs) are the
// branch points of the speed. speed_branch_points finds them (Newton on q,
// deflation, a quadratic), four segments at a time in vector lanes.
// choose_rule then takes the Bernstein ellipse E_rho of the piece just
// inside the nearest of them and proves, by Rouche's theorem with the
// deflation's remainder, that q has no zero in E_rho, so that sqrt(q) is
// analytic there, bounded by M = |A| + |B| |u| + |C| |u|^2. Gauss-Legendre
// with n points then errs by at most
//   r * 64 M / (15 (rho^2 - 1) rho^(2n))
// (Trefethen, "Is Gauss quadrature better than Clenshaw-Curtis?", SIAM
// Review 50 (2008), Theorem 4.5), r the piece's half-width; the smallest
// rule whose bound is below the accuracy times the length it computes is
// the piece's. Pieces with no rule of at most 48 points proved are cut at
// the nearest branch point's real part; the few that still fail (speed
// zeros inside: cusps, folds, tension 1) go to the slower path that cuts
// at the speed's critical points and singularities.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "../segment.hpp"
#include "polynomial.hpp"
#include "x86_kernels.hpp"

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
/// basis, with |A|, |B| and |C| for the bound.
struct speed_model {
    std::array<double, 5> q{};
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
        a_norm = std::sqrt(AA), b_norm = std::sqrt(BB), c_norm = std::sqrt(CC);
    }
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

/// The speed's branch points for one segment as speed_branch_points finds
/// them: one of each conjugate pair of q's complex roots, z[0] from Newton
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

/// Lanes of doubles for the branch points and the first rule choices: four side by side with
/// the GCC/Clang vector extension (two SSE2 instructions each on the x86-64
/// baseline, one in the AVX2 clone), else one. Every operation is the
/// scalar one lane by lane (no FMA contraction: the library is built
/// without it), so a segment gets the same bits in any lane width.
#if defined(__GNUC__) || defined(__clang__)
#define CRSPLINE_LANES4 1
inline constexpr int lanes_width = 4;
using lanes = double __attribute__((vector_size(8 * lanes_width)));
using lanes_mask = long long __attribute__((vector_size(8 * lanes_width)));
// (Operands by reference: a 32-byte vector by value changes the calling
// convention without AVX, which GCC warns about.)
[[gnu::always_inline]] inline void lanes_set(lanes& x, const lanes_mask& m, const lanes& a) noexcept {
    x = lanes((lanes_mask(a) & m) | (lanes_mask(x) & ~m));
}
[[gnu::always_inline]] inline bool lanes_any(const lanes_mask& m) noexcept {
    long long any = 0;
    for (int l = 0; l < lanes_width; ++l) any |= m[l];
    return any != 0;
}
[[gnu::always_inline]] inline void lanes_clear(lanes_mask& m, const lanes_mask& off) noexcept { m = m & ~off; }
[[gnu::always_inline]] inline void lanes_sqrt(lanes& x) noexcept {
#if defined(__SSE2__)
    // Two halves in registers (through memory they would stall the AVX2
    // clone on store forwarding), each one SSE2 square root.
    static_assert(lanes_width == 4);
    const __m128d lo = _mm_sqrt_pd(__m128d(__builtin_shufflevector(x, x, 0, 1)));
    const __m128d hi = _mm_sqrt_pd(__m128d(__builtin_shufflevector(x, x, 2, 3)));
    x = __builtin_shufflevector(lo, hi, 0, 1, 2, 3);
#else
    for (int l = 0; l < lanes_width; ++l) x[l] = std::sqrt(x[l]);
#endif
}
#else
#define CRSPLINE_LANES4 0
#endif
/// x = a in the lanes where m holds.
[[gnu::always_inline]] inline void lanes_set(double& x, bool m, double a) noexcept {
    if (m) x = a;
}
[[gnu::always_inline]] inline bool lanes_any(bool m) noexcept { return m; }
/// m = m and not off.
[[gnu::always_inline]] inline void lanes_clear(bool& m, bool off) noexcept { m = m && !off; }
/// x = sqrt(x) (x >= 0), lane by lane.
[[gnu::always_inline]] inline void lanes_sqrt(double& x) noexcept { x = std::sqrt(x); }

/// Newton's iterations at most.
inline constexpr int branch_newton_steps = 60;

/// The core of speed_branch_points for W segments in the lanes of V (M
/// its comparison mask): q's coefficients in, the monic quartic's, the root
/// Newton settled on (xi its imaginary part) and whether it settled out.
/// Start: a root of q's quadratic Taylor model at the smallest of five
/// samples of q on [0, 1] (near the closest pair when there is one), else
/// 0.5 + 0.6 i. Newton then runs until its step is below 1e-6 of the
/// root's imaginary part (or 1e-16 of its size): the error after such a
/// step is about its square, and choose_rule checks whatever it gets. The
/// complex arithmetic is written out (std::complex guards its division and
/// abs() against overflow at several times the cost; the coefficients are
/// in range, checked first). A lane stops when it settles or fails, so each
/// segment takes its own steps, whatever the others in its group do.
template <class V, class M>
struct branch_newton {
    V c[4], xr, xi;
    M moving, settled;
};

template <class V, class M>
[[gnu::always_inline]] inline void branch_newton_start(const V (&q)[5], branch_newton<V, M>& n) noexcept {
    const V zero = q[0] - q[0];
    const V scale = q[0] + q[2] + q[4];
    n.moving = (q[4] > 1e-12 * scale) & (scale < 1e280) & (q[4] > 1e-280);
    for (int k = 0; k < 4; ++k) n.c[k] = q[k] / q[4];
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
    lanes_sqrt(root);
    n.xr = zero + 0.5, n.xi = zero + 0.6;
    lanes_set(n.xr, model, u - q1 / (2 * q2h));
    lanes_set(n.xi, model, root / (2 * q2h));
    n.settled = n.moving;
    lanes_clear(n.settled, n.moving);
}

template <class V, class M>
[[gnu::always_inline]] inline void branch_newton_step(branch_newton<V, M>& n) noexcept {
    const V xr = n.xr, xi = n.xi;
    const V(&c)[4] = n.c;
    // f = (((x + c3) x + c2) x + c1) x + c0, df = ((4 x + 3 c3) x + 2 c2) x + c1
    V fr = xr + c[3], fi = xi, dr = 4 * xr + 3 * c[3], di = 4 * xi, t;
    t = fr * xr - fi * xi + c[2], fi = fr * xi + fi * xr, fr = t;
    t = dr * xr - di * xi + 2 * c[2], di = dr * xi + di * xr, dr = t;
    t = fr * xr - fi * xi + c[1], fi = fr * xi + fi * xr, fr = t;
    t = dr * xr - di * xi + c[1], di = dr * xi + di * xr, dr = t;
    t = fr * xr - fi * xi + c[0], fi = fr * xi + fi * xr, fr = t;
    const V dd = dr * dr + di * di;
    n.moving = n.moving & (dd > 0);  // a failed lane stops, unsettled
    const V sr = (fr * dr + fi * di) / dd, si = (fi * dr - fr * di) / dd;
    lanes_set(n.xr, n.moving, xr - sr);
    lanes_set(n.xi, n.moving, xi - si);
    const V step = sr * sr + si * si;
    const M done = n.moving & ((step <= 1e-12 * (n.xi * n.xi)) | (step <= 1e-32 * (1 + n.xr * n.xr + n.xi * n.xi)));
    n.settled = n.settled | done;
    lanes_clear(n.moving, done);
}

/// G groups of lanes side by side (independent chains the processor
/// overlaps), each lane until it settles or fails.
template <int G, class V, class M>
[[gnu::always_inline]] inline void branch_newton_run(branch_newton<V, M> (&n)[G]) noexcept {
    for (int it = 0; it < branch_newton_steps; ++it) {
        bool any = false;
        for (int g = 0; g < G; ++g)
            if (lanes_any(n[g].moving)) {
                branch_newton_step(n[g]);
                any = true;
            }
        if (!any) break;
    }
}

/// The branch points from a settled Newton root (xr, xi) of the monic
/// quartic c: false unless the root is off the real axis and the quadratic
/// left by deflation has a pair off it too (a real root is a zero of the
/// speed: the slower path cuts there).
inline bool branch_points_finish(const double (&c)[4], double xr, double xi, branch_points& bp) noexcept {
    if (!(xi * xi > 1e-18 * (1 + xr * xr + xi * xi))) return false;
    // u^4 + c3 u^3 + c2 u^2 + c1 u + c0 = (u^2 + p u + s)(u^2 + e u + f) + remainder
    const double p = -2 * xr, s = xr * xr + xi * xi;
    const double e = c[3] - p, f = c[2] - s - p * e;
    const double disc = f - e * e / 4;
    if (!(disc > 1e-18 * (1 + std::abs(f)))) return false;
    bp.z[0] = std::complex<double>(xr, std::abs(xi));
    bp.z[1] = std::complex<double>(-e / 2, std::sqrt(disc));
    // Each remainder coefficient as computed, plus the rounding of its terms
    // and of p, s, e, f (a few ulps of the largest term: 1e-15 relative).
    const double tol = 1e-15;
    const double t3 = std::abs(c[3]) + std::abs(p) + std::abs(e);
    const double t2 = std::abs(c[2]) + std::abs(s) + std::abs(p * e) + std::abs(f);
    const double t1 = std::abs(c[1]) + std::abs(p * f) + std::abs(s * e);
    const double t0 = std::abs(c[0]) + std::abs(s * f);
    bp.rem[3] = std::abs(c[3] - p - e) + tol * t3;
    bp.rem[2] = std::abs(c[2] - s - p * e - f) + tol * t2;
    bp.rem[1] = std::abs(c[1] - (p * f + s * e)) + tol * t1;
    bp.rem[0] = std::abs(c[0] - s * f) + tol * t0;
    bp.ok = true;
    return true;
}

/// speed_branch_points for count <= G W segments in G groups of W lanes of V.
template <int G, class V, class M>
[[gnu::always_inline]] inline void branch_points_group(const speed_model* sm, int count, branch_points* out) noexcept {
    constexpr int W = std::is_same_v<V, double> ? 1 : int(sizeof(V) / sizeof(double));
    branch_newton<V, M> n[G];
    for (int g = 0; g < G; ++g) {
        V q[5] = {};
        for (int k = 0; k < 5; ++k) {
            if constexpr (W == 1) q[k] = sm[g < count ? g : 0].q[std::size_t(k)];
            else
                for (int l = 0; l < W; ++l) q[k][l] = sm[g * W + l < count ? g * W + l : 0].q[std::size_t(k)];
        }
        branch_newton_start(q, n[g]);
    }
    branch_newton_run<G>(n);
    for (int i = 0; i < count && i < G * W; ++i) {
        const int g = i / W, l = i % W;
        out[i] = branch_points{};
        if constexpr (W == 1) {
            const double cc[4] = {n[g].c[0], n[g].c[1], n[g].c[2], n[g].c[3]};
            if (n[g].settled) branch_points_finish(cc, n[g].xr, n[g].xi, out[i]);
        } else {
            const double cc[4] = {n[g].c[0][l], n[g].c[1][l], n[g].c[2][l], n[g].c[3][l]};
            if (n[g].settled[l]) branch_points_finish(cc, n[g].xr[l], n[g].xi[l], out[i]);
        }
    }
}

/// speed_branch_points for count segments: two groups of lanes at a time
/// (one when no more are left), else one segment per lane of double
/// without the vector extension. The same bits either way. Inlined into
/// the baseline function and into its AVX2 clone (detail/x86_kernels.hpp).
[[gnu::always_inline]] inline void branch_points_all(const speed_model* sm, int count, branch_points* out) noexcept {
#if CRSPLINE_LANES4
    using V = lanes;
    using M = lanes_mask;
    constexpr int W = lanes_width;
#else
    using V = double;
    using M = bool;
    constexpr int W = 1;
#endif
    for (int i = 0; i < count; i += 2 * W) {
        const int left = std::min(2 * W, count - i);
        if (left > W) branch_points_group<2, V, M>(sm + i, left, out + i);
        else branch_points_group<1, V, M>(sm + i, left, out + i);
    }
}
inline void branch_points_portable(const speed_model* sm, int count, branch_points* out) noexcept {
    branch_points_all(sm, count, out);
}
#if CRSPLINE_X86_DISPATCH && CRSPLINE_LANES4
CRSPLINE_TARGET_AVX2 inline void branch_points_avx2(const speed_model* sm, int count, branch_points* out) noexcept {
    branch_points_all(sm, count, out);
}
#endif

/// The complex roots of q (the speed's branch points) of count segments,
/// one of each conjugate pair, in each segment's local u (out[i].ok false
/// when q is not a true quartic, when Newton does not settle, or when a
/// root is numerically real: the speed vanishes there, and the slower path
/// cuts at it). Newton on the monic quartic, deflation by the pair found,
/// the other pair from the quadratic left. Four segments side by side: one
/// segment's Newton steps are a chain of dependent multiplications and
/// divisions that leaves the processor waiting.
inline void speed_branch_points(const speed_model* sm, int count, branch_points* out) noexcept {
#if CRSPLINE_X86_DISPATCH && CRSPLINE_LANES4
    if (avx2_enabled()) return branch_points_avx2(sm, count, out);
#endif
    branch_points_portable(sm, count, out);
}

/// speed_branch_points of one segment (the same bits as in a group).
inline branch_points speed_branch_points(const speed_model& sm) noexcept {
    branch_points bp;
    speed_branch_points(&sm, 1, &bp);
    return bp;
}

/// Bernstein-ellipse parameter of z for [a, b]: rho + 1/rho is the sum of
/// the distances from z to a and b over b - a.
inline double ellipse_parameter(std::complex<double> z, double a, double b) noexcept {
    const double y2 = z.imag() * z.imag(), da = z.real() - a, db = z.real() - b;
    const double s = (std::sqrt(da * da + y2) + std::sqrt(db * db + y2)) / (b - a);
    return s + std::sqrt(std::max(s * s - 1, 0.0));
}

/// The smallest rule of 8, 12, ..., 32, 40 or 48 points whose error bound on
/// [a, b] is at most eff * length, from the branch points bp: Trefethen's
/// bound on the Bernstein ellipse E_rho with rho 1% closer to 1 than the
/// nearest branch point (10% when that fails the test below), and M = |A| +
/// |B| |u| + |C| |u|^2 >= |P(u)| >= |sqrt q(u)| over that ellipse.
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
/// Written for lanes (as branch_newton_lanes): the first rules of four
/// segments at once (choose_rules), and one piece's with V = double, the
/// same operations in the same order. No branch on the data: which rule,
/// and whether any, is a count of the rules that fail.
template <class V, class M>
[[gnu::always_inline]] inline void choose_rule_lanes(const V& a, const V& b, const V (&zr)[2], const V (&zi)[2],
                                                     const V (&rem)[4], const V& a_norm, const V& b_norm,
                                                     const V& c_norm, double eff, const V& length, V& n, V& rho_out,
                                                     V& ratio, V& bound, V& cut) noexcept {
    const V zero = a - a, w = b - a;
    V e[2] = {}, d[4] = {};
    for (int k = 0; k < 2; ++k) {
        const V y2 = zi[k] * zi[k], da = zr[k] - a, db = zr[k] - b;
        d[k] = da * da + y2, d[2 + k] = db * db + y2;
    }
    for (V& x : d) lanes_sqrt(x);  // two at a time with SSE2
    V sq[2] = {};
    for (int k = 0; k < 2; ++k) {
        e[k] = (d[k] + d[2 + k]) / w, sq[k] = e[k] * e[k] - 1;
        lanes_set(sq[k], sq[k] < 0, zero);
        lanes_sqrt(sq[k]);
        e[k] += sq[k];
    }
    const M first = e[0] <= e[1];
    V rho_z = e[1];
    lanes_set(rho_z, first, e[0]);
    cut = zr[1];
    lanes_set(cut, first, zr[0]);
    const V r = w / 2, mid = a + r;
    V amid = mid;
    lanes_set(amid, mid < 0, -mid);
    // rho and the reach of its ellipse for the first margin that passes.
    V rho = zero, reach = zero;
    M found = rho_z < rho_z;
    for (double keep : {0.99, 0.9}) {
        const V rk = 1 + keep * (rho_z - 1);
        const V reach_k = amid + r * (rk + 1 / rk) / 2;
        const V rem_k = ((rem[3] * reach_k + rem[2]) * reach_k + rem[1]) * reach_k + rem[0];
        // The distances less 1e-12 of the roots' size (|z| <= (1 + |z|^2) / 2),
        // for the rounding of the ellipse parameters and of Q's roots.
        const V slack = 1e-12 * (reach_k + 1 + zr[0] * zr[0] + zi[0] * zi[0] + zr[1] * zr[1] + zi[1] * zi[1]);
        const V d0 = r / 2 * (e[0] - rk) * (1 - 1 / (rk * e[0])) - slack;
        const V d1 = r / 2 * (e[1] - rk) * (1 - 1 / (rk * e[1])) - slack;
        const V prod = (d0 * d1) * (d0 * d1);
        M pass = (rk > 1.05) & (d0 > 0) & (d1 > 0) & (rem_k < prod * (1 - 1e-12));
        lanes_clear(pass, found);
        lanes_set(rho, pass, rk);
        lanes_set(reach, pass, reach_k);
        found = found | pass;
    }
    const V M_bound = a_norm + reach * (b_norm + reach * c_norm);
    // The bound is K / rho^(2n), K = r 64 M / (15 (rho^2 - 1)) = k_num / k_den;
    // rho^(2n) for n = 8, 12, ..., 32, 40, 48 by products of r8 = rho^8 (no
    // pow or log); a rule passes when K / rho^(2n) <= eff length.
    const V k_num = r * 64 * M_bound, k_den = 15 * (rho * rho - 1);
    const V r2 = rho * rho, r4 = r2 * r2, r8 = r4 * r4;
    const V scale = k_den * eff * length;
    V grow[9];
    grow[0] = r8 * r8;
    for (int k = 1; k < 7; ++k) grow[k] = grow[k - 1] * r8;  // n = 12 .. 32
    grow[7] = grow[6] * (r8 * r8), grow[8] = grow[7] * (r8 * r8);  // n = 40, 48
    constexpr double rules[9] = {8, 12, 16, 20, 24, 28, 32, 40, 48};
    static_assert(rules[8] == max_rule);
    n = zero, rho_out = zero, ratio = zero, bound = zero;
    V g = grow[8];
    for (int k = 9; k-- > 0;) {
        const M pass = found & (grow[k] * scale >= k_num);
        lanes_set(n, pass, zero + rules[k]);
        lanes_set(g, pass, grow[k]);
    }
    const M chosen = n > 0;
    lanes_set(rho_out, chosen, rho);
    lanes_set(ratio, chosen, 2 * r * M_bound / length);
    lanes_set(bound, chosen, k_num / (k_den * g));
}

/// choose_rule_lanes for one piece.
inline rule_choice choose_rule(const speed_model& sm, const branch_points& bp, double a, double b, double eff,
                               double length) noexcept {
    const double zr[2] = {bp.z[0].real(), bp.z[1].real()}, zi[2] = {bp.z[0].imag(), bp.z[1].imag()};
    const double rem[4] = {bp.rem[0], bp.rem[1], bp.rem[2], bp.rem[3]};
    double n, rho, ratio, bound, cut;
    choose_rule_lanes<double, bool>(a, b, zr, zi, rem, sm.a_norm, sm.b_norm, sm.c_norm, eff, length, n, rho, ratio,
                                    bound, cut);
    rule_choice rc;
    rc.n = int(n), rc.rho = rho, rc.ratio = ratio, rc.bound = bound, rc.cut = cut;
    return rc;
}

/// The first rule of each of count segments over their whole [0, 1] with
/// the length estimated as half the speed at the middle (the estimate is
/// checked against the computed length after), four at a time; the same
/// bits as first_rule(sm[i], bp[i], 0, 1, eff) one by one.
template <class V, class M>
[[gnu::always_inline]] inline void first_rules_group(const speed_model* sm, const branch_points* bp, int count,
                                                     double eff, rule_choice* out) noexcept {
    constexpr int W = sizeof(V) / sizeof(double);
    // The inputs lane by lane in plain arrays, then as lanes (lane l holds
    // segment l, or segment 0 again past count).
    constexpr int F = 17;  // zr[2], zi[2], rem[4], a_norm, b_norm, c_norm, q[5]
    double t[F][W];
    for (int l = 0; l < W; ++l) {
        const int i = l < count ? l : 0;
        const double f[F] = {bp[i].z[0].real(), bp[i].z[1].real(), bp[i].z[0].imag(), bp[i].z[1].imag(),
                             bp[i].rem[0],      bp[i].rem[1],      bp[i].rem[2],      bp[i].rem[3],
                             sm[i].a_norm,      sm[i].b_norm,      sm[i].c_norm,      sm[i].q[0],
                             sm[i].q[1],        sm[i].q[2],        sm[i].q[3],        sm[i].q[4],
                             0};
        for (int k = 0; k < F; ++k) t[k][l] = f[k];
    }
    V v[F];
    static_assert(sizeof(V) == sizeof(t[0]));
    std::memcpy(v, t, sizeof v);
    const V zr[2] = {v[0], v[1]}, zi[2] = {v[2], v[3]}, rem[4] = {v[4], v[5], v[6], v[7]};
    const V &an = v[8], &bn = v[9], &cn = v[10], (&q)[5] = reinterpret_cast<const V(&)[5]>(v[11]);
    const V zero = an - an, one = zero + 1;
    V speed2 = (((q[4] * 0.5 + q[3]) * 0.5 + q[2]) * 0.5 + q[1]) * 0.5 + q[0];
    lanes_set(speed2, speed2 < 0, zero);
    lanes_sqrt(speed2);
    const V estimate = one * speed2 / 2;
    V n, rho, ratio, bound, cut;
    choose_rule_lanes<V, M>(zero, one, zr, zi, rem, an, bn, cn, eff, estimate, n, rho, ratio, bound, cut);
    for (int l = 0; l < count && l < W; ++l) {
        rule_choice& rc = out[l];
        rc = rule_choice{};
        if (!bp[l].ok || !(estimate[l] > 0)) continue;
        rc.n = int(n[l]), rc.rho = rho[l], rc.ratio = ratio[l], rc.bound = bound[l], rc.cut = cut[l];
    }
}

/// The rule the fast path tries first on [a, b] of a segment: choose_rule
/// with the length estimated as half the speed at the middle times the
/// width (the bound is checked against the computed length after).
template <class T>
rule_choice first_rule(const speed_model& sm, const branch_points& bp, T a, T b, double eff) noexcept {
    const T m = a + (b - a) / 2;
    const double estimate = double(b - a) * std::sqrt(std::max(horner(sm.q, double(m)), 0.0)) / 2;
    return estimate > 0 ? choose_rule(sm, bp, double(a), double(b), eff, estimate) : rule_choice{};
}

/// first_rule over [0, 1] for count segments, four at a time with the
/// vector extension (first_rules_group), else one by one: the same bits
/// every way. Inlined into the baseline function and its AVX2 clone.
[[gnu::always_inline]] inline void first_rules_all(const speed_model* sm, const branch_points* bp, int count,
                                                   double eff, rule_choice* out) noexcept {
#if CRSPLINE_LANES4
    for (int i = 0; i < count; i += lanes_width)
        first_rules_group<lanes, lanes_mask>(sm + i, bp + i, std::min(lanes_width, count - i), eff, out + i);
#else
    for (int i = 0; i < count; ++i) out[i] = bp[i].ok ? first_rule(sm[i], bp[i], 0.0, 1.0, eff) : rule_choice{};
#endif
}
inline void first_rules_portable(const speed_model* sm, const branch_points* bp, int count, double eff,
                                 rule_choice* out) noexcept {
    first_rules_all(sm, bp, count, eff, out);
}
#if CRSPLINE_X86_DISPATCH && CRSPLINE_LANES4
CRSPLINE_TARGET_AVX2 inline void first_rules_avx2(const speed_model* sm, const branch_points* bp, int count,
                                                  double eff, rule_choice* out) noexcept {
    first_rules_all(sm, bp, count, eff, out);
}
#endif
inline void first_rules(const speed_model* sm, const branch_points* bp, int count, double eff,
                        rule_choice* out) noexcept {
#if CRSPLINE_X86_DISPATCH && CRSPLINE_LANES4
    if (avx2_enabled()) return first_rules_avx2(sm, bp, count, eff, out);
#endif
    first_rules_portable(sm, bp, count, eff, out);
}

}  // namespace crspline::detail
