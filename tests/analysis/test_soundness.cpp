// Soundness of the whole-curve analysis (issue 13).
//
//  * A certified curve never crosses itself: thousands of certified curves
//    with every end condition (natural, reflect, given tangents), tension,
//    Kochanek-Bartels values, open and closed, in 2-D and 3-D, each searched
//    by an independent method -- a long-double Bézier subdivision written
//    here, not find_intersections -- which must find no meeting.
//  * The answers do not depend on where the curve lies: every random case,
//    moved by 1e3, 3e7 and 1e8 and scaled by 1e-8 and 1e8, gets the same
//    classification, certificate, crossings and bounds.
//  * The cases the issue reported, one by one.
#include <cstdlib>
#include <map>

#include <crspline/certify.hpp>
#include <crspline/intersections.hpp>

#include "test_support.hpp"

namespace {
using namespace crspline;
using P2 = vec<2>;
using P3 = vec<3>;
using crspline::test::pi;
using test::smooth_polygon;

// CRSPLINE_PROPERTY_SCALE < 1 runs fewer cases and says so (scaled()
// prints the reduced count); a Debug + AddressSanitizer build, some 30 times
// slower, runs a fifth of them by default.
double soundness_scale() {
    if (std::getenv("CRSPLINE_PROPERTY_SCALE")) return test::property_scale();
#if defined(__SANITIZE_ADDRESS__)
    return 0.2;
#else
    return 1.0;
#endif
}
std::size_t scaled(std::size_t n) {
    const std::size_t m = std::max<std::size_t>(1, std::size_t(double(n) * soundness_scale()));
    if (m < n) std::printf("reduced run: %zu of %zu cases (sanitizer build or CRSPLINE_PROPERTY_SCALE)\n", m, n);
    return m;
}


// ---------------------------------------------------------------------------
// The independent checker: long-double subdivision of every pair of segments
// ---------------------------------------------------------------------------

template <std::size_t D>
using lvec = std::array<long double, D>;
template <std::size_t D>
using lbez = std::array<lvec<D>, 4>;

// Bézier points of segment i in long double, relative to `origin`, from the
// curve's stored data (points, tangents dx/dt, and the knot interval h as the
// curve takes it: the double difference of its knots). B1 = P0 + h/3 v0,
// B2 = P1 - h/3 v1: the Hermite form, not the curve's power basis.
template <std::size_t D>
lbez<D> long_bezier(const catmull_rom<D>& c, std::size_t i, const vec<D>& origin) {
    const auto pts = c.points();
    const std::size_t j = (i + 1) % pts.size();
    const auto [v0, v1] = c.tangents(i);
    const long double h3 = (long double)(c.grid()[i + 1] - c.grid()[i]) / 3;
    lbez<D> b;
    for (std::size_t k = 0; k < D; ++k) {
        const long double p0 = (long double)pts[i][k] - origin[k], p1 = (long double)pts[j][k] - origin[k];
        b[0][k] = p0;
        b[1][k] = p0 + h3 * v0[k];
        b[2][k] = p1 - h3 * v1[k];
        b[3][k] = p1;
    }
    return b;
}

template <std::size_t D>
std::array<lbez<D>, 2> long_split(const lbez<D>& b) {
    auto mid = [](const lvec<D>& x, const lvec<D>& y) {
        lvec<D> r;
        for (std::size_t k = 0; k < D; ++k) r[k] = (x[k] + y[k]) / 2;
        return r;
    };
    const auto a0 = mid(b[0], b[1]), a1 = mid(b[1], b[2]), a2 = mid(b[2], b[3]);
    const auto q0 = mid(a0, a1), q1 = mid(a1, a2), m = mid(q0, q1);
    return {lbez<D>{b[0], a0, q0, m}, lbez<D>{m, q1, a2, b[3]}};
}

struct checker_counts {
    std::size_t pairs = 0, undecided = 0;
};

// Do segments A and B come closer than tol anywhere except at their joint?
// joint: 0 none, 1 A(1) = B(0), 2 A(0) = B(1). Pieces that both lie within
// `window` (in u) of the joint are not searched: there they touch by
// construction (so a crossing closer than that to the joint is not seen;
// the crossings of the issue lie at u ~ 0.1 - 0.9 of the joint). Returns
// the parameters of one meeting, if any.
template <std::size_t D>
std::optional<std::array<long double, 2>> long_meeting(const lbez<D>& A, const lbez<D>& B, int joint, long double tol,
                                                       checker_counts& counts) {
    struct item {
        lbez<D> a, b;
        long double a0, a1, b0, b1;
    };
    const long double window = 1.0L / 1024;
    auto box = [](const lbez<D>& q) {
        std::array<lvec<D>, 2> r{q[0], q[0]};
        for (const auto& x : q)
            for (std::size_t k = 0; k < D; ++k) r[0][k] = std::min(r[0][k], x[k]), r[1][k] = std::max(r[1][k], x[k]);
        return r;
    };
    std::vector<item> stack{{A, B, 0, 1, 0, 1}};
    std::size_t visits = 0;
    ++counts.pairs;
    while (!stack.empty()) {
        if (++visits > 400000) { ++counts.undecided; return std::nullopt; }
        const item it = stack.back();
        stack.pop_back();
        const auto ba = box(it.a), bb = box(it.b);
        bool apart = false;
        long double sa = 0, sb = 0;
        for (std::size_t k = 0; k < D; ++k) {
            apart = apart || ba[0][k] > bb[1][k] + tol || bb[0][k] > ba[1][k] + tol;
            sa = std::max(sa, ba[1][k] - ba[0][k]);
            sb = std::max(sb, bb[1][k] - bb[0][k]);
        }
        if (apart) continue;
        if (joint == 1 && it.a0 >= 1 - window && it.b1 <= window) continue;
        if (joint == 2 && it.a1 <= window && it.b0 >= 1 - window) continue;
        if (sa <= tol && sb <= tol) return std::array<long double, 2>{(it.a0 + it.a1) / 2, (it.b0 + it.b1) / 2};
        if (sa >= sb) {
            const auto h = long_split<D>(it.a);
            const long double m = (it.a0 + it.a1) / 2;
            stack.push_back({h[0], it.b, it.a0, m, it.b0, it.b1});
            stack.push_back({h[1], it.b, m, it.a1, it.b0, it.b1});
        } else {
            const auto h = long_split<D>(it.b);
            const long double m = (it.b0 + it.b1) / 2;
            stack.push_back({it.a, h[0], it.a0, it.a1, it.b0, m});
            stack.push_back({it.a, h[1], it.a0, it.a1, m, it.b1});
        }
    }
    return std::nullopt;
}

// Every pair of different segments of c: the first meeting found, as
// {i, j, u, v}.
template <std::size_t D>
std::optional<std::array<double, 4>> independent_meeting(const catmull_rom<D>& c, checker_counts& counts) {
    const std::size_t n = c.segment_count();
    const vec<D> origin = c.points()[0];
    double scale = 0;
    for (const auto& p : c.points()) scale = std::max(scale, norm(p - origin));
    // Meetings closer than 1e-12 of the curve's size: far below any gap the
    // certificate leaves (its margins are ~1e-14), far above long double's
    // rounding of the subdivision (~1e-17).
    const long double tol = 1e-12L * scale;
    std::vector<lbez<D>> b(n);
    for (std::size_t i = 0; i < n; ++i) b[i] = long_bezier(c, i, origin);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            const int joint = j == i + 1 ? 1 : (c.closed() && i == 0 && j == n - 1) ? 2 : 0;
            if (const auto m = long_meeting<D>(b[i], b[j], joint, tol, counts))
                return std::array<double, 4>{double(i), double(j), double((*m)[0]), double((*m)[1])};
        }
    return std::nullopt;
}

// A random curve of every kind the certificate meets: end conditions,
// tension, Kochanek-Bartels, closed.
template <std::size_t D>
catmull_rom<D> random_curve(std::mt19937_64& rng, std::size_t rep, std::string& kind) {
    std::uniform_real_distribution<double> U(0.0, 1.0);
    std::normal_distribution<double> G(0.0, 1.0);
    const std::size_t n = 3 + rep % 8;
    const double turn = (0.3 + 0.9 * U(rng)) * 2 * pi / 3;
    const auto p = smooth_polygon<D>(rng, n, turn, 1.0);
    options<D> o;
    auto random_tangent = [&](const vec<D>& chord) {
        // A given dx/dt: around the chord velocity (the knot interval is
        // |chord|^(1/2)), in any direction, from a tenth to ten times as fast.
        vec<D> d{};
        for (std::size_t k = 0; k < D; ++k) d[k] = G(rng);
        const double speed = std::sqrt(norm(chord)) * std::pow(10.0, 2 * U(rng) - 1);
        return (speed / norm(d)) * d;
    };
    switch (rep % 6) {
        case 0: kind = "natural"; break;
        case 1:
            kind = "reflect";
            o.start = end_condition<D>::reflect();
            o.end = end_condition<D>::reflect();
            break;
        case 2:
            kind = "tangents";
            o.start = end_condition<D>::tangent(random_tangent(p[1] - p[0]));
            if (U(rng) < 0.5) o.end = end_condition<D>::tangent(random_tangent(p[n - 1] - p[n - 2]));
            break;
        case 3:
            kind = "tension";
            o.tension = U(rng);
            break;
        case 4:
            kind = "kochanek-bartels";
            for (auto* v : {&o.kb.tension, &o.kb.continuity, &o.kb.bias}) {
                v->resize(n);
                for (auto& x : *v) x = 1.6 * U(rng) - 0.8;
            }
            break;
        default:
            kind = "closed";
            o.closed = n >= 3;
            if (U(rng) < 0.5) o.tension = 0.5 * U(rng);
    }
    return catmull_rom<D>(p, o);
}

template <std::size_t D>
void falsify(std::uint64_t seed, std::size_t tries, std::size_t& certified, std::size_t& crossing_found,
             std::size_t& agreed) {
    std::mt19937_64 rng(seed);
    checker_counts counts;
    std::map<std::string, std::size_t> per_kind;
    for (std::size_t rep = 0; rep < tries; ++rep) {
        std::string kind;
        const auto c = random_curve<D>(rng, rep, kind);
        const auto cert = certify_intersection_free(c, {.search_on_failure = false});
        const auto meet = independent_meeting(c, counts);
        if (cert.certified) {
            ++certified;
            ++per_kind[kind];
            EXPECT_FALSE(meet.has_value()) << "rep " << rep << " (" << kind << "): certified, but segments "
                                           << (*meet)[0] << " and " << (*meet)[1] << " meet at u = " << (*meet)[2]
                                           << ", " << (*meet)[3];
            continue;
        }
        // The checker can fail: on curves that are not certified, it finds
        // the crossings find_intersections finds (away from joints).
        if constexpr (D == 2) {
            const auto r = find_intersections(c);
            bool far = false;
            for (const auto& x : r.intersections)
                if (x.segments[0] != x.segments[1]) {
                    const bool next = x.segments[1] == x.segments[0] + 1;
                    const bool wrap = c.closed() && x.segments[0] == 0 && x.segments[1] + 1 == c.segment_count();
                    const double du = next ? std::max(1 - x.u[0], x.u[1]) : wrap ? std::max(x.u[0], 1 - x.u[1]) : 1;
                    far = far || du > 0.01;
                }
            if (far) {
                ++crossing_found;
                if (meet) ++agreed;
            }
        }
    }
    std::printf("falsification %zu-D: %zu tries, %zu certified (", D, tries, certified);
    for (const auto& [k, v] : per_kind) std::printf(" %s %zu", k.c_str(), v);
    std::printf(" ), %zu pairs searched, %zu undecided\n", counts.pairs, counts.undecided);
    EXPECT_EQ(counts.undecided, 0u);
    // Every kind gets certified curves (so every kind was really tested).
    if (soundness_scale() >= 1) {
        EXPECT_EQ(per_kind.size(), 6u);
    }
}

TEST(Soundness, CertifiedCurvesNeverMeetAnIndependentCheck) {
    CRSPLINE_SEEDED(seed, 1301);
    std::size_t cert2 = 0, cert3 = 0, found = 0, agreed = 0, f3 = 0, a3 = 0;
    falsify<2>(seed, scaled(6000), cert2, found, agreed);
    falsify<3>(seed + 1, scaled(1500), cert3, f3, a3);
    std::printf("certified: %zu in 2-D, %zu in 3-D; crossings of uncertified 2-D curves: %zu, independent check "
                "agreed on %zu\n",
                cert2, cert3, found, agreed);
    if (soundness_scale() >= 1) {
        EXPECT_GE(cert2, 1500u);
        EXPECT_GE(cert3, 300u);
        EXPECT_GE(found, 100u);
    }
    EXPECT_EQ(agreed, found);
}

// ---------------------------------------------------------------------------
// The reported cases
// ---------------------------------------------------------------------------

// Issue 13, item 1: a given start tangent makes the end segment cross its
// neighbour; the angle rule never covered it. Now: not certified, the
// adjacent pair named, the crossing found by the search and by the
// independent check. The same in 3-D and with the end tangent.
TEST(Soundness, GivenEndTangentThatCrossesIsNotCertified) {
    auto check = [](const auto& c, std::size_t i, std::size_t j) {
        const auto cert = certify_intersection_free(c);
        EXPECT_FALSE(cert.certified);
        EXPECT_EQ(cert.failed_rule, certify_rule::adjacent_pair) << cert.detail;
        EXPECT_EQ(cert.segments, (std::optional<std::array<std::size_t, 2>>({i, j})));
        EXPECT_TRUE(cert.intersects.value_or(false));
        checker_counts counts;
        EXPECT_TRUE(independent_meeting(c, counts).has_value());
    };
    const catmull_rom<2> c({P2{{0, 0}}, P2{{1, 0}}, P2{{1, 1}}},
                           {.alpha = 0.5, .start = end_condition<2>::tangent(P2{{10, 10}})});
    check(c, 0, 1);
    EXPECT_EQ(certify_intersection_free(c).detail,
              "segments 0 and 1 (joined at vertex 1, an end segment (end condition), not covered by the angle rule) "
              "could not be proved apart");
    // The crossings the issue lists, u = (0.8523, 0.2054) and (0.1274, 0.9703).
    const auto r = find_intersections(c);
    ASSERT_EQ(r.intersections.size(), 2u);
    std::vector<std::array<double, 2>> u;
    for (const auto& x : r.intersections) u.push_back(x.u);
    std::sort(u.begin(), u.end());
    EXPECT_NEAR(u[0][0], 0.1274, 1e-4);
    EXPECT_NEAR(u[0][1], 0.9703, 1e-4);
    EXPECT_NEAR(u[1][0], 0.8523, 1e-4);
    EXPECT_NEAR(u[1][1], 0.2054, 1e-4);
    check(catmull_rom<3>({P3{{0, 0, 0}}, P3{{1, 0, 0}}, P3{{1, 1, 0}}},
                         {.start = end_condition<3>::tangent(P3{{10, 10, 0}})}),
          0, 1);
    // Mirrored: the given tangent at the end.
    check(catmull_rom<2>({P2{{1, 1}}, P2{{1, 0}}, P2{{0, 0}}}, {.end = end_condition<2>::tangent(P2{{-10, -10}})}), 0,
          1);
    // A gentle given tangent on the same points is proved apart: certified.
    const auto ok = certify_intersection_free(
        catmull_rom<2>({P2{{0, 0}}, P2{{1, 0}}, P2{{1, 1}}}, {.start = end_condition<2>::tangent(P2{{1, 0}})}));
    EXPECT_TRUE(ok.certified) << ok.detail;
}

// Issue 13, item 3: the curve knows how it was built. options() gives the
// construction back (alpha resolved, the grid not copied), and building
// again from it, with grid() where the knots were explicit, gives the same
// curve bit for bit.
TEST(Soundness, CurveRemembersHowItWasBuilt) {
    const std::vector<P2> p{P2{{0, 0}}, P2{{1, 2}}, P2{{3, 1}}, P2{{4, 3}}, P2{{6, 0}}};
    {
        const catmull_rom<2> c(p);
        EXPECT_EQ(c.options().alpha, std::optional<double>(0.5));  // the default, resolved
        EXPECT_FALSE(c.options().grid.has_value());
        EXPECT_FALSE(c.explicit_grid());
    }
    options<2> o{.alpha = 1.0, .start = end_condition<2>::tangent(P2{{1, -1}}), .end = end_condition<2>::reflect(),
                 .tension = 0.25};
    o.kb.bias = {0, 0.1, -0.2, 0.3, 0};
    const catmull_rom<2> c(p, o);
    const auto& b = c.options();
    EXPECT_EQ(b.alpha, std::optional<double>(1.0));
    EXPECT_EQ(b.start, o.start);
    EXPECT_EQ(b.end, o.end);
    EXPECT_EQ(b.tension, 0.25);
    EXPECT_EQ(b.kb.bias, o.kb.bias);
    EXPECT_FALSE(b.closed);
    const catmull_rom<2> again(p, b);
    for (std::size_t i = 0; i < c.segment_count(); ++i) EXPECT_EQ(again.bezier(i), c.bezier(i)) << "segment " << i;
    // An explicit grid: alpha empty, the knots are grid().
    const std::vector<double> g{0, 1, 3, 4, 7};
    const catmull_rom<2> e(p, {.grid = g, .closed = false});
    EXPECT_TRUE(e.explicit_grid());
    EXPECT_FALSE(e.options().alpha.has_value());
    EXPECT_FALSE(e.options().grid.has_value());  // stored once, as grid()
    auto eo = e.options();
    eo.grid.emplace(e.grid().begin(), e.grid().end());
    const catmull_rom<2> e2(p, eo);
    for (std::size_t i = 0; i < e.segment_count(); ++i) EXPECT_EQ(e2.bezier(i), e.bezier(i)) << "segment " << i;
}

// Issue 13, item 2: a crossing of segments 0 and 3 is found however far the
// curve is moved (it was lost at 3e7).
TEST(Soundness, CrossingFoundFarFromTheOrigin) {
    const std::vector<P2> base{P2{{0, 0}}, P2{{4, 0}}, P2{{4, 2}}, P2{{2, 2}}, P2{{2, -2}}};
    const auto r0 = find_intersections(catmull_rom<2>(base));
    ASSERT_EQ(r0.intersections.size(), 1u);
    EXPECT_EQ(r0.intersections[0].segments, (std::array<std::size_t, 2>{0, 3}));
    for (double shift : {1e3, 1e7, 3e7, 1e8, 1e9}) {
        std::vector<P2> p = base;
        for (auto& q : p) q = q + P2{{shift, shift}};  // exact: integers below 2^53
        const auto r = find_intersections(catmull_rom<2>(p));
        ASSERT_EQ(r.intersections.size(), 1u) << "shift " << shift;
        EXPECT_EQ(r.intersections[0].segments, r0.intersections[0].segments);
        // The same crossing to rounding: the curve is the same one, moved
        // exactly, and the search is relative to each segment's origin.
        EXPECT_NEAR(r.intersections[0].u[0], r0.intersections[0].u[0], 1e-12) << "shift " << shift;
        EXPECT_NEAR(r.intersections[0].u[1], r0.intersections[0].u[1], 1e-12) << "shift " << shift;
        EXPECT_LE(r.intersections[0].distance, 1e-12) << "shift " << shift;
    }
}

// Issue 13, item 3: a zigzag near x = 1000 is certified with the same bound
// as at the origin (it failed as "not the plain segment").
TEST(Soundness, ZigzagCertifiedAwayFromTheOrigin) {
    auto zig = [](double x0) {
        return catmull_rom<2>({P2{{x0, 0}}, P2{{x0 + 1, 1}}, P2{{x0 + 2, 0}}, P2{{x0 + 3, 1}}});
    };
    const auto c0 = zig(0);
    const auto a0 = analyze(c0);
    ASSERT_TRUE(a0[1].bounds.has_value());
    for (double x0 : {1000.0, 3e7, 1e8}) {
        const auto c = zig(x0);
        const auto a = analyze(c);
        ASSERT_TRUE(a[1].bounds.has_value()) << x0;
        EXPECT_EQ(a[1].bounds->eq6, a0[1].bounds->eq6) << x0;
        const auto cert = certify_intersection_free(c);
        EXPECT_EQ(cert.certified, certify_intersection_free(c0).certified) << cert.detail;
        EXPECT_EQ(cert.failed_rule, certify_intersection_free(c0).failed_rule) << cert.detail;
    }
}

// ---------------------------------------------------------------------------
// Translation and scale invariance
// ---------------------------------------------------------------------------

// Points on a grid of 2^-20: moving them by 1e3, 3e7 or 1e8 (below 2^27) is
// exact, so the moved curve is the same curve and every answer must agree
// up to the rounding of the search itself. Scaling by 1e8 or 1e-8 is not
// exact (a relative change of one ulp per coordinate), which the tolerances
// below cover.
template <std::size_t D>
std::vector<vec<D>> on_grid(std::vector<vec<D>> p) {
    for (auto& q : p)
        for (std::size_t k = 0; k < D; ++k) q[k] = std::ldexp(std::round(std::ldexp(q[k], 20)), -20);
    return p;
}

template <std::size_t D>
struct answers {
    std::vector<std::array<std::size_t, 3>> classes;  // cusps, loops, fold per segment
    std::vector<std::optional<double>> eq6;           // the paper bound, where defined
    std::vector<double> max_chord_distance;
    bool certified = false;
    certify_rule rule = certify_rule::none;
    std::vector<curve_intersection<D>> crossings;  // points mapped back to the unmoved frame
};

template <std::size_t D>
answers<D> answers_of(const catmull_rom<D>& c, const vec<D>& shift, double factor) {
    answers<D> a;
    for (const auto& s : analyze(c)) {
        a.classes.push_back({s.cusp_u.size(), s.self_intersection.size(), std::size_t(s.fold)});
        a.eq6.push_back(s.bounds ? std::optional<double>(s.bounds->eq6 / factor) : std::nullopt);
        a.max_chord_distance.push_back(s.max_chord_distance / factor);
    }
    const auto cert = certify_intersection_free(c, {.search_on_failure = false});
    a.certified = cert.certified;
    a.rule = cert.failed_rule;
    for (auto x : find_intersections(c).intersections) {
        x.point = (x.point - shift) / factor;
        a.crossings.push_back(x);
    }
    return a;
}

TEST(Soundness, AnswersDoNotChangeWhenTheCurveIsMovedOrScaled) {
    CRSPLINE_SEEDED(seed, 1302);
    std::mt19937_64 rng(seed);
    const std::size_t count = scaled(400);
    std::size_t compared = 0, crossings = 0, certified = 0;
    for (std::size_t rep = 0; rep < count; ++rep) {
        // The generators of the analysis and intersection suites: uneven
        // random walks (cusps and loops for alpha != 1/2) and smooth
        // polygons (certificates), open and closed.
        const double alpha = std::array{0.0, 0.5, 1.0, 0.5}[rep % 4];
        const bool closed = rep % 5 == 0;
        auto p = on_grid(rep % 2 ? crspline::test::random_polygon<2>(rng, 5 + rep % 5, 1.0)
                                 : smooth_polygon<2>(rng, 4 + rep % 7, (0.4 + 0.8 * double(rep % 7) / 6) * 2 * pi / 3, 1.0));
        const options<2> o{.alpha = alpha, .closed = closed};
        const catmull_rom<2> c0(p, o);
        const double scale = crspline::test::scale_of(p);
        const auto base = answers_of(c0, P2{}, 1.0);
        certified += base.certified;
        crossings += base.crossings.size();
        struct move {
            double shift, factor;
        };
        for (const move m : {move{1e3, 1}, move{3e7, 1}, move{1e8, 1}, move{0, 1e-8}, move{0, 1e8}}) {
            SCOPED_TRACE("rep " + std::to_string(rep) + " shift " + std::to_string(m.shift) + " factor " +
                         std::to_string(m.factor));
            std::vector<P2> q = p;
            for (auto& x : q) x = m.factor * x + P2{{m.shift, m.shift}};
            const auto moved = answers_of(catmull_rom<2>(q, o), P2{{m.shift, m.shift}}, m.factor);
            EXPECT_EQ(moved.classes, base.classes);
            EXPECT_EQ(moved.certified, base.certified);
            EXPECT_EQ(moved.rule, base.rule);
            ASSERT_EQ(moved.eq6.size(), base.eq6.size());
            for (std::size_t i = 0; i < base.eq6.size(); ++i) {
                ASSERT_EQ(moved.eq6[i].has_value(), base.eq6[i].has_value()) << "segment " << i;
                // Exact moves give the same bits; scaling changes each
                // coordinate by an ulp, the bound (products and quotients of
                // lengths) by a few ulps: 1e-13 relative.
                if (base.eq6[i]) {
                    EXPECT_NEAR(*moved.eq6[i], *base.eq6[i], 1e-13 * *base.eq6[i]) << "segment " << i;
                }
                EXPECT_NEAR(moved.max_chord_distance[i], base.max_chord_distance[i], 1e-12 * scale) << "segment " << i;
            }
            // The same crossings: each polished to a residual below the
            // search tolerance (1e-9 of the size), so the same crossing found
            // twice lies within 2e-9 of the size; distinct crossings of a
            // pair are more than twice the tolerance apart. Match by point
            // within 4e-9 of the size (points mapped back to the base frame,
            // whose rounding there is an ulp of the shift: 1.5e-8 at 1e8 for
            // a size of ~10, hence the second term).
            const double match = 4e-9 * scale + 4 * std::numeric_limits<double>::epsilon() * m.shift;
            EXPECT_EQ(moved.crossings.size(), base.crossings.size());
            for (const auto& x : base.crossings) {
                bool found = false;
                for (const auto& y : moved.crossings)
                    found = found || (y.segments == x.segments && norm(y.point - x.point) <= match);
                EXPECT_TRUE(found) << "crossing of segments " << x.segments[0] << ", " << x.segments[1] << " at u "
                                   << x.u[0] << ", " << x.u[1] << " lost";
            }
            ++compared;
        }
    }
    std::printf("invariance: %zu cases x 5 moves = %zu compared, %zu crossings, %zu certified\n", count, compared,
                crossings, certified);
    EXPECT_EQ(compared, 5 * count);
    if (soundness_scale() >= 1) {
        EXPECT_GT(crossings, count / 4);
        EXPECT_GT(certified, count / 20);
    }
}

}  // namespace
