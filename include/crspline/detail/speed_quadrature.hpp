// crspline internal: the fast path of arc length. Gauss-Legendre rules of
// 8 to 64 points, the speed |C'(u)| of a segment evaluated at all of a
// rule's nodes in one loop, the speed's complex branch points, and an
// a-priori error bound that picks the rule for a piece of a segment.
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
// SIAM Review 2008, Theorem 4.5, leaves out.) The smallest rule whose bound
// is below the accuracy times the length it computes is the piece's.
// Pieces with no rule of at most 64 points proved are cut at the nearest
// branch point's real part; the few that still fail (speed zeros inside:
// cusps, folds, tension 1) go to the slower path that cuts at the speed's
// critical points and singularities.
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

template <class T>
struct gauss_legendre<36, T> {
    static constexpr T x[18] = {T(0.043018198473708607226969), T(0.128736103809384788651993), T(0.213500892316865578943226), T(0.296684995344028270503239),
                              T(0.377672547119689216322736), T(0.455863944433420267207218), T(0.530680285926245161640709), T(0.601567658135980535079945),
                              T(0.668001236585521062097191), T(0.72948917159355658209026), T(0.785576230132206512827769), T(0.835847166992475306418821),
                              T(0.879929800890397131982427), T(0.917497774515659066075867), T(0.948272984399507545202474), T(0.972027691049697949335605),
                              T(0.988586478902212238073395), T(0.997830462484085836198828)};
    static constexpr T w[18] = {T(0.0859832756703947474900852), T(0.0853466857393386274918505), T(0.0840782189796619349334576), T(0.0821872667043397095172235),
                              T(0.0796878289120716019087247), T(0.0765984106458706745287577), T(0.0729418850056530613538734), T(0.0687453238357364426136896),
                              T(0.0640397973550154895563848), T(0.0588601442453248173096754), T(0.0532447139777599190920256), T(0.0472350834902659784166168),
                              T(0.0408757509236448954741145), T(0.0342138107703072299212451), T(0.0272986214985687790944172), T(0.0201815152977354715320989),
                              T(0.0129159472840655744045034), T(0.00556571966424504536125598)};
};

template <class T>
struct gauss_legendre<44, T> {
    static constexpr T x[22] = {T(0.0352892369641353590581967), T(0.105691901708653247117306), T(0.175568014775516785746508), T(0.244569456928201251507302),
                              T(0.312352466502785812236545), T(0.378579352014707132511765), T(0.442920174525411483834827), T(0.505054391388202317982798),
                              T(0.564672453185470768424637), T(0.621477345903575847802425), T(0.675186070666122365333699), T(0.725531053660717002606965),
                              T(0.772261479248755899017759), T(0.815144539645135010487438), T(0.853966595004710378728302), T(0.888534238286043202338368),
                              T(0.918675259984175774323001), T(0.944239509118194099203255), T(0.965099650422493139394398), T(0.981151833077913966662749),
                              T(0.992316392138515808483338), T(0.998540200636774224936057)};
    static constexpr T w[22] = {T(0.0705491577893540688113383), T(0.070197685473558212587142), T(0.0694964918615725780370841), T(0.0684490702693666609854587),
                              T(0.0670606389062936523957049), T(0.0653381148791814349842409), T(0.0632900797332038549501389), T(0.0609267367015619680385578),
                              T(0.0582598598775954953342107), T(0.0553027355637280525487466), T(0.0520700960917044618812318), T(0.0485780464483520375276394),
                              T(0.0448439840819700314462432), T(0.0408865123103462189084472), T(0.0367253478138088736429093), T(0.0323812228120698208808469),
                              T(0.0278757828212810100811143), T(0.0232314819020192106289583), T(0.0184714817368147491720422), T(0.0136195867555799855202051),
                              T(0.00870048136752484412256562), T(0.00374540480311277751517378)};
};

template <class T>
struct gauss_legendre<56, T> {
    static constexpr T x[28] = {T(0.0277970352872754370940612), T(0.0833051868224353744402874), T(0.138555846810376242012887), T(0.193378238635275258240185),
                              T(0.247602909434337203972967), T(0.301062253867220669053094), T(0.353591032174954520969707), T(0.405026880927091278118867),
                              T(0.455210814878459578948832), T(0.503987718384381714195224), T(0.551206824855534618754364), T(0.596722182770663320104135),
                              T(0.640393106807006894267939), T(0.682084612694470455501561), T(0.721667834450188083522594), T(0.759020422705128902202413),
                              T(0.794026922893866498030008), T(0.826579132142881651672127), T(0.856576433762748635402991), T(0.883926108327827540789012),
                              T(0.908543620420655490846107), T(0.930352880247496300547273), T(0.949286479561962635646738), T(0.965285901905490183626195),
                              T(0.978301709140256383376991), T(0.988293715540161511089925), T(0.995231226081069747216309), T(0.999094343801465584353154)};
    static constexpr T w[28] = {T(0.0555797463065143958462734), T(0.0554079525032451232177934), T(0.0550648959017624257963046), T(0.0545516368708894210617507),
                              T(0.0538697618657144857089544), T(0.0530213785240107639679916), T(0.0520091091517413998430523), T(0.050836082617798480560124),
                              T(0.049505924683047578919966), T(0.0480227467936002581207355), T(0.0463911333730018967621902), T(0.0446161276526922832134152),
                              T(0.0427032160846670865110386), T(0.040658311384744517880125), T(0.0384877342592476624868256), T(0.0361981938723151860358845),
                              T(0.0337967671156117612954266), T(0.0312908767473104478678355), T(0.0286882684738227417298859), T(0.0259969870583919521918194),
                              T(0.0232253515625653169372582), T(0.020381929882402572634806), T(0.0174755129114009465049594), T(0.0145150892780214718077707),
                              T(0.0115098243403833821737728), T(0.00846906316330788766162711), T(0.00540252224601533776131126), T(0.00232385537577321550110228)};
};

template <class T>
struct gauss_legendre<64, T> {
    static constexpr T x[32] = {T(0.0243502926634244325089558), T(0.0729931217877990394495429), T(0.121462819296120554470376), T(0.169644420423992818037314),
                              T(0.217423643740007084149649), T(0.264687162208767416373964), T(0.311322871990210956157513), T(0.357220158337668115950443),
                              T(0.402270157963991603695767), T(0.446366017253464087984948), T(0.489403145707052957478526), T(0.531279464019894545658014),
                              T(0.571895646202634034283878), T(0.611155355172393250248853), T(0.648965471254657339857761), T(0.685236313054233242563558),
                              T(0.71988185017161082684894), T(0.752819907260531896611864), T(0.783972358943341407610221), T(0.813265315122797559741923),
                              T(0.840629296252580362751692), T(0.865999398154092819760783), T(0.889315445995114105853404), T(0.910522137078502805756381),
                              T(0.92956917213193957582149), T(0.946411374858402816062481), T(0.961008799652053718918614), T(0.973326827789910963741854),
                              T(0.983336253884625956931299), T(0.991013371476744320739382), T(0.996340116771955279346925), T(0.999305041735772139456906)};
    static constexpr T w[32] = {T(0.0486909570091397203833654), T(0.0485754674415034269347991), T(0.0483447622348029571697695), T(0.0479993885964583077281262),
                              T(0.0475401657148303086622822), T(0.0469681828162100173253263), T(0.0462847965813144172959532), T(0.045491627927418144479771),
                              T(0.0445905581637565630601347), T(0.0435837245293234533768279), T(0.0424735151236535890073398), T(0.0412625632426235286101563),
                              T(0.0399537411327203413866569), T(0.0385501531786156291289625), T(0.0370551285402400460404151), T(0.0354722132568823838106931),
                              T(0.0338051618371416093915655), T(0.0320579283548515535854675), T(0.0302346570724024788679741), T(0.0283396726142594832275113),
                              T(0.0263774697150546586716918), T(0.0243527025687108733381776), T(0.0222701738083832541592983), T(0.0201348231535302093723403),
                              T(0.0179517157756973430850453), T(0.015726030476024719321966), T(0.0134630478967186425980608), T(0.0111681394601311288185905),
                              T(0.00884675982636394772303091), T(0.00650445796897836285611736), T(0.00414703326056246763528754), T(0.00178328072169643294729608)};
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
/// square roots and the weighted sum. Always inlined: gauss_length_rule
/// holds every rule's loop in one function, and a loop over segments with
/// one fixed rule (the benchmark's 16-point baseline) gets the rule in its
/// body (whether GCC inlined it on its own changed that loop's time by a
/// third from one build to the next).
template <int N, std::size_t D, class T>
[[gnu::always_inline]] inline T gauss_length_n(const cubic_segment<D, T>& s, T a, T b) noexcept {
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

/// The rules the fast path chooses from, by points: every fourth up to 48,
/// then 56 and 64.
inline constexpr int rule_sizes[] = {8, 12, 16, 20, 24, 28, 32, 36, 40, 44, 48, 56, 64};
inline constexpr int rule_count = int(std::size(rule_sizes));
/// The most points of a rule the fast path uses.
inline constexpr int max_rule = rule_sizes[rule_count - 1];
static_assert([] {
    for (int n : rule_sizes)
        if (n % 4 != 0) return false;  // choose_rule_lanes steps by rho^8
    return true;
}());

/// Integral of the speed by a rule of rule_sizes chosen at run time.
template <std::size_t D, class T>
T gauss_length_rule(const cubic_segment<D, T>& s, T a, T b, int n) noexcept {
    switch (n) {
        case 12: return gauss_length_n<12>(s, a, b);
        case 16: return gauss_length_n<16>(s, a, b);
        case 20: return gauss_length_n<20>(s, a, b);
        case 24: return gauss_length_n<24>(s, a, b);
        case 28: return gauss_length_n<28>(s, a, b);
        case 32: return gauss_length_n<32>(s, a, b);
        case 36: return gauss_length_n<36>(s, a, b);
        case 40: return gauss_length_n<40>(s, a, b);
        case 44: return gauss_length_n<44>(s, a, b);
        case 48: return gauss_length_n<48>(s, a, b);
        case 56: return gauss_length_n<56>(s, a, b);
        case 64: return gauss_length_n<64>(s, a, b);
        default: return gauss_length_n<8>(s, a, b);
    }
}

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
[[gnu::always_inline]] inline bool lanes_any_not(const lanes_mask& m) noexcept {
    long long all = -1;
    for (int l = 0; l < lanes_width; ++l) all &= m[l];
    return all == 0;
}
template <class F>
[[gnu::always_inline]] inline void lanes_make(lanes& x, F f) noexcept {
    x = lanes{f(0), f(1), f(2), f(3)};
}
[[gnu::always_inline]] inline void lanes_add_abs(lanes& acc, const lanes& x) noexcept {
    acc += lanes(lanes_mask(x) & (lanes_mask{} + 0x7fffffffffffffffLL));
}
template <class V>
[[gnu::always_inline]] inline auto lanes_get(const V& x, int l) noexcept -> std::remove_cvref_t<decltype(x[0])> {
    return x[l];
}
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
/// Whether m fails in any lane.
[[gnu::always_inline]] inline bool lanes_any_not(bool m) noexcept { return !m; }
/// x = the lanes f(0), f(1), ... (built in registers).
template <class F>
[[gnu::always_inline]] inline void lanes_make(double& x, F f) noexcept {
    x = f(0);
}
/// x = sqrt(x) (x >= 0), lane by lane.
[[gnu::always_inline]] inline void lanes_sqrt(double& x) noexcept { x = std::sqrt(x); }
/// acc += |x|, lane by lane.
[[gnu::always_inline]] inline void lanes_add_abs(double& acc, double x) noexcept { acc += std::abs(x); }
/// Lane l of x (x itself for one lane).
[[gnu::always_inline]] inline double lanes_get(double x, int) noexcept { return x; }
[[gnu::always_inline]] inline bool lanes_get(bool x, int) noexcept { return x; }

/// Square roots lane by lane for the lanes code below, a template argument
/// of it: sqrt_baseline is lanes_sqrt (four lanes in two SSE2 instructions
/// on the x86-64 baseline); sqrt_avx, for the AVX2 clones only, takes four
/// in one instruction, as fast as one SSE2 one. Both round correctly: the
/// same bits.
struct sqrt_baseline {
    template <class V>
    [[gnu::always_inline]] static void apply(V& x) noexcept {
        lanes_sqrt(x);
    }
};
#if CRSPLINE_X86_DISPATCH && CRSPLINE_LANES4
struct sqrt_avx {
    // Not always_inline: the generic code that calls it is inlined into
    // an AVX2 function first, and this then into that.
    CRSPLINE_TARGET_AVX2 static void apply(lanes& x) noexcept { x = lanes(_mm256_sqrt_pd(__m256d(x))); }
    [[gnu::always_inline]] static void apply(double& x) noexcept { x = std::sqrt(x); }
};
#endif

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
    lanes_set(n.xr, model, u - q1 * inv2);
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
            choose_rule_lanes<V, M, S>(zero, one, zr, zi, rem, pm, dpm, cn, eff, estimate, rn, rho, ratio, bound,
                                       cut);
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
    choose_rule_lanes<V, M, S>(a, b, zr, zi, rem, pm, dpm, cn, eff, estimate, n, rho, ratio, bound, cut);
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
