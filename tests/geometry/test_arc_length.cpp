// Arc length, its inverse and arc-length sampling, held to their accuracy
// promise at every accuracy from 1e-2 to 1e-12.
#include "test_support.hpp"

#include <crspline/arc_length.hpp>

#include <nlohmann/json.hpp>

#include <fstream>

namespace {
using namespace crspline;
using crspline::test::random_polygon;
using P2 = vec<2>;
using P3 = vec<3>;
constexpr double accuracies[] = {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12};

// Closed-form lengths, independent of the arc-length code: points
// a + x_i dir with random x_i make the curve a + x(t) dir, x a piecewise
// cubic that folds back and forth. Its length over [t0, t1] is the total
// variation: the sum of the chords between the roots of x'(u) (a quadratic
// per segment), each piece being monotone along the line.
struct folded_line {
    std::vector<P3> points;
    P3 dir;
};
folded_line random_folded_line(std::mt19937_64& rng, std::size_t n) {
    std::normal_distribution<double> g(0, 1);
    const P3 a{{g(rng), g(rng), g(rng)}}, dir{{g(rng), g(rng), g(rng)}};
    folded_line f{{}, dir};
    for (std::size_t i = 0; i < n; ++i) f.points.push_back(a + (3 * g(rng)) * dir);
    return f;
}
double line_length(const catmull_rom<3>& c, const P3& dir, double t0, double t1) {
    double total = 0;
    for (std::size_t i = 0; i < c.segment_count(); ++i) {
        const auto& seg = c.segment(i);
        const double g0 = c.grid()[i], g1 = c.grid()[i + 1];
        if (g1 <= t0 || g0 >= t1) continue;
        const double ua = t0 > g0 ? (t0 - g0) / (g1 - g0) : 0.0, ub = t1 < g1 ? (t1 - g0) / (g1 - g0) : 1.0;
        // x'(u) along dir: b1 + 2 b2 u + 3 b3 u^2.
        const double b1 = dot(seg.c1, dir), b2 = dot(seg.c2, dir), b3 = dot(seg.c3, dir);
        std::vector<double> cuts{ua, ub};
        const double A = 3 * b3, B = 2 * b2, C = b1;
        if (A != 0) {
            const double disc = B * B - 4 * A * C;
            if (disc > 0) {
                const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
                for (double r : {q / A, q != 0 ? C / q : -1.0})
                    if (r > ua && r < ub) cuts.push_back(r);
            }
        } else if (B != 0 && -C / B > ua && -C / B < ub) {
            cuts.push_back(-C / B);
        }
        std::sort(cuts.begin(), cuts.end());
        for (std::size_t k = 0; k + 1 < cuts.size(); ++k) total += norm(seg.at(cuts[k + 1]) - seg.at(cuts[k]));
    }
    return total;
}

TEST(ArcLength, GaussLegendreRuleIsExactToDegree15) {
    // The rule's nodes and weights, checked: integral of x^k over [0, 1].
    using G = detail::gauss_legendre_8<double>;
    for (int k = 0; k <= 15; ++k) {
        double sum = 0;
        for (int i = 0; i < 4; ++i)
            sum += G::w[i] * (std::pow(0.5 - 0.5 * G::x[i], k) + std::pow(0.5 + 0.5 * G::x[i], k));
        EXPECT_NEAR(0.5 * sum, 1.0 / (k + 1), 4e-16) << "degree " << k;
    }
}

TEST(ArcLength, StraightLinesAtEveryAccuracy) {
    // Collinear points with uneven spacing: straight, with varying speed
    // (and, for uniform knots, overshooting folds that retrace the line).
    CRSPLINE_SEEDED(s, 301);
    std::mt19937_64 rng(s);
    std::uniform_real_distribution<double> U(0.1, 3.0);
    for (double alpha : {0.5, 1.0})
        for (int rep = 0; rep < 10; ++rep) {
            std::vector<P3> p{P3{}};
            const P3 dir = P3{{1, 2, -2}} / 3.0;
            for (int i = 0; i < 6; ++i) p.push_back(p.back() + U(rng) * dir);
            catmull_rom<3> c(p, {.alpha = alpha});
            // Monotone along the line for alpha >= 1/2: the length is the chord.
            const double exact = norm(p.back() - p.front());
            for (double acc : accuracies) {
                EXPECT_LE(std::abs(arc_length(c, acc) - exact), acc * exact) << "accuracy " << acc;
            }
        }
}

TEST(ArcLength, ParabolaHasItsClosedFormLength) {
    // C(u) = (u, a u^2): length = [u w / 2 + asinh(2 a u) / (4 a)]_0^1, w = sqrt(1 + 4 a^2 u^2).
    for (double a : {0.1, 1.0, 10.0, 1000.0}) {
        const auto seg = cubic_segment<2>::hermite(P2{{0, 0}}, P2{{1, a}}, P2{{1, 0}}, P2{{1, 2 * a}}, 0.0, 1.0);
        ASSERT_EQ(seg.c3, P2{});
        const double w = std::sqrt(1 + 4 * a * a);
        const double exact = w / 2 + std::asinh(2 * a) / (4 * a);
        for (double acc : accuracies) {
            EXPECT_LE(std::abs(arc_length(seg, acc) - exact), acc * exact) << "a " << a << " accuracy " << acc;
        }
    }
}

TEST(ArcLength, TensionOneIsThePolylineLength) {
    // Zero speed at every knot: the integrand has a sqrt-type zero at each
    // end of each segment, and the length is exactly the sum of the chords.
    CRSPLINE_SEEDED(s, 302);
    std::mt19937_64 rng(s);
    for (int rep = 0; rep < 20; ++rep) {
        auto p = random_polygon<2>(rng, 8, 2.0);
        catmull_rom<2> c(p, {.tension = 1.0});
        double chords = 0;
        for (std::size_t i = 0; i + 1 < p.size(); ++i) chords += norm(p[i + 1] - p[i]);
        for (double acc : accuracies) {
            EXPECT_LE(std::abs(arc_length(c, acc) - chords), acc * chords) << "accuracy " << acc;
        }
    }
}

TEST(ArcLength, OracleLengthsTo1e12) {
    std::ifstream f(std::string(CRSPLINE_REFERENCE_DIR) + "/oracle.json");
    const auto data = nlohmann::json::parse(f);
    std::size_t checked = 0;
    for (const auto& c : data.at("cases")) {
        SCOPED_TRACE(c.at("name").get<std::string>());
        if (c.at("dim") != 2) continue;  // the 1-, 3- and 4-D cases below
        std::vector<P2> p;
        for (const auto& q : c.at("points")) p.push_back(P2{{q[0].get<double>(), q[1].get<double>()}});
        catmull_rom<2> curve(p, {.alpha = c.at("alpha").get<double>(), .tension = c.at("tension").get<double>()});
        const double exact = std::stod(c.at("arc_length_hp").get<std::string>());
        const double got = arc_length(curve.segment(1));
        EXPECT_LE(std::abs(got - exact), 1e-12 * exact + 1e-300) << got << " vs " << exact;
        ++checked;
    }
    for (const auto& c : data.at("cases")) {
        const int dim = c.at("dim").get<int>();
        if (dim == 2) continue;
        const double exact = std::stod(c.at("arc_length_hp").get<std::string>());
        auto run = [&]<std::size_t D>() {
            std::vector<vec<D>> p;
            for (const auto& q : c.at("points")) {
                vec<D> x;
                for (std::size_t k = 0; k < D; ++k) x[k] = q[k].get<double>();
                p.push_back(x);
            }
            catmull_rom<D> curve(p, {.alpha = c.at("alpha").get<double>(), .tension = c.at("tension").get<double>()});
            return arc_length(curve.segment(1));
        };
        const double got = dim == 1 ? run.operator()<1>() : dim == 3 ? run.operator()<3>() : run.operator()<4>();
        EXPECT_LE(std::abs(got - exact), 1e-12 * exact) << c.at("name");
        ++checked;
    }
    EXPECT_EQ(checked, 38u);
}

TEST(ArcLength, InverseRoundTripsAtEveryAccuracy) {
    CRSPLINE_SEEDED(s, 303);
    std::mt19937_64 rng(s);
    for (double alpha : {0.0, 0.5, 1.0})
        for (double acc : accuracies) {
            const auto f = random_folded_line(rng, 12);
            catmull_rom<3> c(f.points, {.alpha = alpha, .closed = acc < 1e-9});
            const arc_length_table<3> table(c, acc);
            const double L = table.total();
            // Against the closed form (the folds make speed zeros to cross).
            EXPECT_NEAR(L, line_length(c, f.dir, c.t_min(), c.t_max()), acc * L);
            std::uniform_real_distribution<double> S(0, L);
            std::vector<double> sv(200);
            for (auto& x : sv) x = S(rng);
            sv[0] = 0;
            sv[1] = L;
            for (double si : sv) {
                const double t = table.t_at(si);
                ASSERT_GE(t, c.t_min());
                ASSERT_LE(t, c.t_max());
                // s -> t -> s within the accuracy (plus the table's own error).
                EXPECT_LE(std::abs(table.s_at(t) - si), 2 * acc * L) << "s " << si;
                // and against the closed-form length of [t_min, t].
                EXPECT_LE(std::abs(line_length(c, f.dir, c.t_min(), t) - si), 2 * acc * L) << "s " << si;
            }
            // Sorted batch == one by one.
            std::sort(sv.begin(), sv.end());
            const auto tb = table.t_at(std::span<const double>(sv));
            // (Compared in arc length, where the promise is: where the curve is
            // slow a tiny error in s is a larger one in t.)
            for (std::size_t k = 0; k < sv.size(); ++k)
                EXPECT_LE(std::abs(table.s_at(tb[k]) - table.s_at(table.t_at(sv[k]))), 4 * acc * L) << "s " << sv[k];
        }
}

TEST(ArcLength, EvenSamplesAreEvenlySpacedToTheAccuracy) {
    CRSPLINE_SEEDED(s, 304);
    std::mt19937_64 rng(s);
    for (double acc : {1e-6, 1e-12}) {
        const auto f = random_folded_line(rng, 10);
        catmull_rom<3> c(f.points);
        const auto smp = sample_arc_length(c, 101, acc);
        ASSERT_EQ(smp.points.size(), 101u);
        EXPECT_EQ(smp.points.front(), f.points.front());
        EXPECT_EQ(smp.points.back(), f.points.back());
        // Closed-form lengths (folded line): the whole and each piece.
        const double L = line_length(c, f.dir, c.t_min(), c.t_max()), step = L / 100;
        for (std::size_t k = 1; k < 101; ++k) {
            const double piece = line_length(c, f.dir, smp.t[k - 1], smp.t[k]);
            EXPECT_LE(std::abs(piece - step), 4 * acc * L) << "sample " << k;
        }
    }
}

TEST(ArcLength, FewEvenSamplesOnManySegmentsNeedNoTable) {
    // Fewer samples than segments take the path without a table (segment
    // lengths, then each sample's segment alone): the same promise against
    // the same closed form, and the same total as the table.
    CRSPLINE_SEEDED(s, 305);
    std::mt19937_64 rng(s);
    for (double acc : {1e-6, 1e-12}) {
        const auto f = random_folded_line(rng, 400);
        catmull_rom<3> c(f.points);
        for (std::size_t n : {2u, 7u, 101u}) {
            ASSERT_LT(n, c.segment_count());
            const auto smp = sample_arc_length(c, n, acc);
            ASSERT_EQ(smp.points.size(), n);
            EXPECT_EQ(smp.points.front(), f.points.front());
            EXPECT_EQ(smp.points.back(), f.points.back());
            EXPECT_EQ(smp.s.back(), arc_length_table<3>(c, acc).total());
            const double L = line_length(c, f.dir, c.t_min(), c.t_max()), step = L / double(n - 1);
            for (std::size_t k = 1; k < n; ++k) {
                // As in EvenSamplesAreEvenlySpacedToTheAccuracy: both ends of
                // a piece within the accuracy, plus rounding of the sums.
                const double piece = line_length(c, f.dir, smp.t[k - 1], smp.t[k]);
                EXPECT_LE(std::abs(piece - step), 4 * acc * L) << "sample " << k << " of " << n;
            }
        }
    }
    // segment_arc_lengths adds up to arc_length(curve) in order, bit for bit.
    const auto f = random_folded_line(rng, 50);
    catmull_rom<3> c(f.points);
    const auto lengths = segment_arc_lengths(c, 1e-12);
    ASSERT_EQ(lengths.size(), c.segment_count());
    double sum = 0;
    for (double x : lengths) sum += x;
    EXPECT_EQ(sum, arc_length(c, 1e-12));
}

TEST(ArcLength, ZeroSpeedInsideSegments) {
    // A uniform fold-back (the curve stops and retraces) and coincident points.
    const std::vector<P2> fold{P2{{0, 0}}, P2{{3, 0}}, P2{{1, 0}}, P2{{4, 0}}};
    catmull_rom<2> c(fold, {.alpha = 0.0});
    // Length of the 1-D curve = total variation: sum |x(u_k+1) - x(u_k)|
    // between the speed's zeros, found independently by sampling.
    const auto& seg = c.segment(1);
    double tv = 0, prev = seg.at(0)[0];
    for (int k = 1; k <= 200000; ++k) {
        const double x = seg.at(k / 200000.0)[0];
        tv += std::abs(x - prev);
        prev = x;
    }
    EXPECT_NEAR(arc_length(seg), tv, 1e-9);  // the sampled variation is exact up to 1e-10 (turning points)
    const std::vector<P2> dup{P2{{0, 0}}, P2{{1, 1}}, P2{{1, 1}}, P2{{2, 0}}};
    catmull_rom<2> d(dup);
    EXPECT_EQ(arc_length(d.segment(1)), 0.0);
    EXPECT_TRUE(std::isfinite(arc_length(d)));
    const arc_length_table<2> table(d);
    EXPECT_TRUE(std::isfinite(table.t_at(table.total() / 2)));
}

// The length of x(u) = c1 u + c2 u^2 + c3 u^3 over [0, 1] in long double:
// the total variation, the sum of |x(r_k+1) - x(r_k)| between the real roots
// of x' = c1 + 2 c2 u + 3 c3 u^2 (closed form, none of the arc-length code).
long double total_variation(long double c1, long double c2, long double c3) {
    const auto x = [&](long double u) { return ((c3 * u + c2) * u + c1) * u; };
    std::vector<long double> cuts{0.0L, 1.0L};
    const long double disc = c2 * c2 - 3 * c3 * c1;  // x' = 0: u = (-c2 -+ sqrt(disc)) / (3 c3)
    if (c3 != 0 && disc > 0)
        for (long double sign : {-1.0L, 1.0L}) {
            const long double r = (-c2 + sign * std::sqrt(disc)) / (3 * c3);
            if (r > 0 && r < 1) cuts.push_back(r);
        }
    std::sort(cuts.begin(), cuts.end());
    long double tv = 0;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) tv += std::fabs(x(cuts[k + 1]) - x(cuts[k]));
    return tv;
}

TEST(ArcLength, NearDoubleZerosOfTheSpeedEndInFewPieces) {
    // x'(u) = a ((u - v)^2 - d) with |d| from 1e-4 down to 1e-18: two zeros
    // of the speed 2 sqrt(d) apart, or a minimum of a d just above zero.
    // The fast path leaves a short piece around them to the slower one,
    // where the speed is small enough to be mostly rounding; a tolerance
    // relative to that piece's own length was then never met, and every
    // piece was halved to the depth limit (2^48 pieces: std::bad_alloc, or
    // a hang). In 1-D against the closed-form length, in 2-D (a tiny y
    // component, no closed form) for the piece count only.
    CRSPLINE_SEEDED(seed, 312);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0, 1);
    constexpr double eps = std::numeric_limits<double>::epsilon();
    std::size_t most_pieces = 0;
    for (int rep = 0; rep < 400; ++rep) {
        const double a = std::pow(10.0, 4 * U(rng) - 2) * (U(rng) < 0.5 ? -1 : 1);
        const double v = 0.05 + 0.9 * U(rng), d = std::pow(10.0, -4 - 14 * U(rng)) * (U(rng) < 0.5 ? -1 : 1);
        const double e = std::abs(a) * std::pow(10.0, -3 - 14 * U(rng)), w = U(rng);
        cubic_segment<1> s1;
        s1.c1[0] = a * (v * v - d);
        s1.c2[0] = -a * v;
        s1.c3[0] = a / 3;
        s1.h = s1.inv_h = 1;
        cubic_segment<2> s2;
        s2.c1 = P2{{s1.c1[0], -e * w}};
        s2.c2 = P2{{s1.c2[0], e / 2}};
        s2.c3 = P2{{s1.c3[0], 0}};
        s2.h = s2.inv_h = 1;
        const double ref = double(total_variation(s1.c1[0], s1.c2[0], s1.c3[0]));
        // The slower path's rounding floor: 64 eps S per unit width, S =
        // |c1| + 2 |c2| + 3 |c3| (arc_length.hpp, length_pieces); 16 eps of
        // the length for the sums' own rounding.
        const double S = std::abs(s1.c1[0]) + 2 * std::abs(s1.c2[0]) + 3 * std::abs(s1.c3[0]);
        for (double acc : {1e-6, 1e-12}) {
            std::size_t n1 = 0, n2 = 0;
            detail::for_each_length_piece(s1, 0.0, 1.0, acc, [&](double, double, double, const auto&) { ++n1; });
            detail::for_each_length_piece(s2, 0.0, 1.0, acc, [&](double, double, double, const auto&) { ++n2; });
            most_pieces = std::max({most_pieces, n1, n2});
            // Only the pieces at the speed's two zeros and its minimum keep
            // halving (up to 48 levels, about two pieces a level each, under
            // 400 in all; today's most is printed below).
            ASSERT_LE(std::max(n1, n2), 1000u) << "seed " << seed << " rep " << rep << " a " << a << " v " << v
                                               << " d " << d << " e " << e << " acc " << acc;
            EXPECT_LE(std::abs(arc_length(s1, acc) - ref), acc * ref + 64 * eps * S + 16 * eps * ref)
                << "seed " << seed << " rep " << rep << " a " << a << " v " << v << " d " << d << " acc " << acc;
            EXPECT_TRUE(std::isfinite(arc_length(s2, acc)));
        }
    }
    std::printf("most pieces of a segment: %zu\n", most_pieces);
    // The case CI met (tests/python/test_many_curves.py, 1-D, uniform,
    // closed): the segment between the middle two of these points.
    const std::vector<vec<1>> p{vec<1>{{0.3271848757793794}}, vec<1>{{2.142114485080044}},
                                vec<1>{{2.5219032697700725}}, vec<1>{{2.13638224680297}}};
    const catmull_rom<1> c(p, {.alpha = 0.0});
    const auto& seg = c.segment(1);
    const double ref = double(total_variation(seg.c1[0], seg.c2[0], seg.c3[0]));
    EXPECT_NEAR(arc_length(seg), ref, 1e-12 * ref);
    const arc_length_table<1> table(c);
    for (int k = 0; k <= 100; ++k) {
        const double si = table.total() * k / 100;
        EXPECT_LE(std::abs(table.s_at(table.t_at(si)) - si), 2e-12 * table.total()) << "s " << si;
    }
}

TEST(ArcLength, SplinesConstantSpeedAdapterCases) {
    // splines' UnitSpeedAdapter: cumulative length at the knots and the t it
    // found for each s. Its lengths come from scipy quad (SOURCES.md: up to
    // about 1.5e-8 relative), so against the package we allow that; our
    // 1e-12 promise is checked against arc_length_exact.json, 40-digit
    // lengths from tests/reference/arc_length_oracle.py (the package is
    // 2.4e-10 off on the 1e6-offset case 157, beyond its stated lib_err).
    std::ifstream f(std::string(CRSPLINE_REFERENCE_DIR) + "/splines_py.json");
    const auto data = nlohmann::json::parse(f);
    std::ifstream fe(std::string(CRSPLINE_REFERENCE_DIR) + "/arc_length_exact.json");
    const auto exact = nlohmann::json::parse(fe).at("knot_lengths");
    std::size_t cases = 0, values = 0;
    for (const auto& c : data) {
        if (c.at("class") != "ConstantSpeedAdapter") continue;
        SCOPED_TRACE(c.at("id").get<std::string>());
        auto run = [&]<std::size_t D>() {
            std::vector<vec<D>> p;
            for (const auto& q : c.at("points")) {
                vec<D> x;
                for (std::size_t k = 0; k < D; ++k) x[k] = q[k].get<double>();
                p.push_back(x);
            }
            options<D> opt{.alpha = c.at("alpha").get<double>(), .closed = c.at("closed").get<bool>()};
            if (c.at("endconditions").is_object())
                for (const char* which : {"start", "end"}) {
                    const auto& e = c.at("endconditions").at(which);
                    if (e.is_string()) continue;
                    vec<D> v;
                    for (std::size_t k = 0; k < D; ++k) v[k] = e[k].get<double>();
                    (which[0] == 's' ? opt.start : opt.end) = end_condition<D>::tangent(v);
                }
            if (c.contains("tension") && c.at("tension").is_array()) {
                for (const auto& x : c.at("tension")) opt.kb.tension.push_back(x.is_null() ? 0.0 : x.get<double>());
                for (const auto& x : c.at("continuity")) opt.kb.continuity.push_back(x.is_null() ? 0.0 : x.get<double>());
                for (const auto& x : c.at("bias")) opt.kb.bias.push_back(x.is_null() ? 0.0 : x.get<double>());
            }
            const catmull_rom<D> curve(p, opt);
            const arc_length_table<D> table(curve);
            const auto sk = c.at("s_grid_out").get<std::vector<double>>();
            const double L = table.total();
            const double package = 1.5e-8 * L;
            const auto& ex = exact.at(c.at("id").get<std::string>());
            ASSERT_EQ(ex.size(), sk.size());
            for (std::size_t i = 0; i < sk.size(); ++i) {
                EXPECT_LE(std::abs(table.knot_lengths()[i] - sk[i]), package) << "knot " << i;
                const double e = std::stod(ex[i].get<std::string>());
                EXPECT_LE(std::abs(table.knot_lengths()[i] - e), 1e-12 * L) << "knot " << i << " vs 40 digits";
                ++values;
            }
            const auto s = c.at("s").get<std::vector<double>>();
            const auto ts = c.at("t_of_s").get<std::vector<double>>();
            for (std::size_t k = 0; k < s.size(); ++k) {
                // The package's last s is its own total, which may exceed ours
                // within its error.
                ASSERT_LE(s[k], L + package);
                const double sk_ours = std::min(s[k], L);
                const double t = table.t_at(sk_ours);
                // In arc length: the package's t_of_s is good to its length
                // error; ours meets our accuracy (checked by the round trips).
                EXPECT_LE(std::abs(table.s_at(std::min(ts[k], curve.t_max())) - sk_ours), package) << "s " << s[k];
                EXPECT_LE(std::abs(table.s_at(t) - sk_ours), 2e-12 * L) << "s " << s[k];
                ++values;
            }
            // The very end works (the package raises there on some curves).
            EXPECT_NEAR(table.t_at(L), curve.t_max(), 1e-12 * curve.t_max());
        };
        switch (c.at("dim").get<int>()) {
            case 2: run.operator()<2>(); break;
            case 3: run.operator()<3>(); break;
            case 4: run.operator()<4>(); break;
            default: ADD_FAILURE();
        }
        ++cases;
    }
    EXPECT_EQ(cases, 10u);
    EXPECT_GT(values, 500u);
}

TEST(ArcLength, FloatReachesItsOwnPrecision) {
    CRSPLINE_SEEDED(s, 305);
    std::mt19937_64 rng(s);
    for (int rep = 0; rep < 20; ++rep) {
        auto pd = random_polygon<2>(rng, 6, 2.0);
        std::vector<vec<2, float>> pf;
        for (auto& x : pd) {
            pf.push_back(vec<2, float>{{float(x[0]), float(x[1])}});
            x = P2{{double(pf.back()[0]), double(pf.back()[1])}};
        }
        const double ld = arc_length(catmull_rom<2>(pd), 1e-12);
        const float lf = arc_length(catmull_rom<2, float>(pf), 1e-6f);
        // float knots and coefficients carry ~1e-7 relative error each.
        EXPECT_NEAR(double(lf), ld, 2e-5 * ld);
    }
}

// An independent reference for the length of a segment in u: a 12-point
// Gauss-Legendre rule whose nodes and weights are computed here (Newton on
// the Legendre polynomial, in long double), on equal panels, with the speed
// |c1 + 2 c2 u + 3 c3 u^2| summed in long double. Nothing of the library's
// quadrature (its rules, its splitting, its error estimates) is used.
template <std::size_t D>
long double brute_force_length(const cubic_segment<D>& seg, int panels) {
    constexpr int m = 12;
    static const auto rule = [] {
        std::array<std::pair<long double, long double>, m> r{};
        const long double pi = 3.141592653589793238462643383279502884L;
        for (int i = 0; i < m; ++i) {
            long double x = std::cos(pi * (i + 0.75L) / (m + 0.5L)), dp = 0;
            for (int it = 0; it < 100; ++it) {
                long double p0 = 1, p1 = x;  // P_0, P_1; recurrence up to P_m
                for (int k = 2; k <= m; ++k) {
                    const long double pk = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                    p0 = p1, p1 = pk;
                }
                dp = m * (x * p1 - p0) / (x * x - 1);
                const long double dx = p1 / dp;
                x -= dx;
                if (std::abs(dx) < 1e-19L) break;
            }
            r[i] = {x, 2 / ((1 - x * x) * dp * dp)};
        }
        return r;
    }();
    // The rule on [a, a + 2 half].
    auto panel = [&](long double a, long double half) {
        long double sum = 0;
        for (const auto& [x, w] : rule) {
            const long double u = a + half * (1 + x);
            long double sq = 0;
            for (std::size_t d = 0; d < D; ++d) {
                const long double v = (long double)seg.c1[d] + u * (2 * (long double)seg.c2[d] + u * 3 * (long double)seg.c3[d]);
                sq += v * v;
            }
            sum += w * half * std::sqrt(sq);
        }
        return sum;
    };
    // Each panel halved until its halves agree with it to 1e-19 of the
    // segment's first estimate: 400 equal panels alone were off by 1.5e-10
    // on one segment of seed 4 (a speed minimum narrower than a panel, with
    // the branch points near the real axis), where an adaptive long-double
    // quadrature agreed with arc_length to 4e-16.
    auto adapt = [&](auto&& self, long double a, long double half, long double whole, long double scale,
                     int depth) -> long double {
        const long double l = panel(a, half / 2), r = panel(a + half, half / 2);
        if (std::abs(l + r - whole) <= 1e-19L * scale || depth >= 40) return l + r;
        return self(self, a, half / 2, l, scale, depth + 1) + self(self, a + half, half / 2, r, scale, depth + 1);
    };
    long double scale = 0;
    for (int k = 0; k < panels; ++k) scale += panel((long double)k / panels, 0.5L / panels);
    long double total = 0;
    for (int k = 0; k < panels; ++k) {
        const long double a = (long double)k / panels, half = 0.5L / panels;
        total += adapt(adapt, a, half, panel(a, half), scale, 0);
    }
    return total;
}

TEST(ArcLength, AccuracyHoldsAgainstBruteForceQuadrature) {
    // Independent reference: brute_force_length above on 400 equal panels per
    // segment, each halved until its halves agree to 1e-19 of the length. Random walks with chord lengths over
    // three decades make sharp speed minima, whose complex branch points near
    // a piece end once let the rule and its halves agree on a wrong value.
    CRSPLINE_SEEDED(s, 306);
    std::mt19937_64 rng(s);
    for (double alpha : {0.0, 0.5, 1.0})
        for (int rep = 0; rep < 16; ++rep) {
            auto p = random_polygon<3>(rng, 9, 3.0);
            catmull_rom<3> c(p, {.alpha = alpha});
            for (std::size_t i = 0; i < c.segment_count(); ++i) {
                const auto& seg = c.segment(i);
                const double ref = double(brute_force_length(seg, 400));
                for (double acc : {1e-6, 1e-9, 1e-12}) {
                    // The reference: a 12-point rule is exact to degree 23,
                    // on 400 panels halved where their halves disagree; it is
                    // good to ~1e-16 relative here, long double's rounding
                    // of 4,800 terms or more (the slack 1e-14 covers it and
                    // the rounding of the sum).
                    EXPECT_LE(std::abs(arc_length(seg, acc) - ref), acc * ref + 1e-14 * ref)
                        << "alpha " << alpha << " segment " << i << " accuracy " << acc;
                }
            }
        }
}

TEST(ArcLength, SegmentLengthsKeepTheirOwnPrecision) {
    // A 1.3e6-long segment before a unit one: the short segment's length must
    // not be a difference of cumulative sums (that would lose eps * 1.3e6).
    const std::vector<P2> p{P2{{-786432.0, 1048576.0}}, P2{{0, 0}}, P2{{1, 0}}, P2{{2, 1}}};
    const catmull_rom<2> c(p);
    const arc_length_table<2> table(c);
    const double exact = 1.05425374920139075974502183369;  // oracle.json, ratio_d1_1e6_centripetal
    EXPECT_LE(std::abs(table.segment_length(1) - exact), 1e-12 * exact);
    EXPECT_LE(std::abs(arc_length(c.segment(1)) - exact), 1e-12 * exact);
}

// Issue 26 point 1: an arc length within the promised accuracy of either
// end of [0, total] is that end (a length computed by another tool is only
// known to that accuracy); further out it is still out_of_domain. Both the
// scalar and the batch t_at, on seeded random curves at every accuracy.
TEST(ArcLength, ArcLengthsWithinTheAccuracyOfAnEndAreThatEnd) {
    CRSPLINE_SEEDED(seed, 2611);
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int trial = 0; trial < 20; ++trial) {
        const catmull_rom<2> c(test::random_polygon<2>(rng, 3 + std::size_t(trial % 7)), {.alpha = 0.1 * (trial % 11)});
        for (const double acc : accuracies) {
            const arc_length_table<2> table(c, acc);
            const double total = table.total();
            ASSERT_GT(total, 0);
            // The slack is the tolerance t_at promises: max(accuracy, 4 eps) * total.
            EXPECT_EQ(table.end_slack(), std::max(acc, 4 * std::numeric_limits<double>::epsilon()) * total);
            // The case: 8e-15 relative past the end (inside the promise at
            // every accuracy here, >= 1e-12), and half the slack past either end.
            const double inside[] = {total * (1 + 8e-15), total + table.end_slack() / 2, total + table.end_slack(),
                                     -table.end_slack() / 2, -table.end_slack(), -0.0};
            for (const double s : inside) {
                const double want = s > total / 2 ? c.t_max() : c.t_min();
                EXPECT_TRUE(table.in_range(s)) << "s = " << s << " total " << total;
                EXPECT_EQ(table.t_at(s), want) << "s = " << s << " total " << total << " accuracy " << acc;
                ++checked;
            }
            // The batch form, sorted and unsorted, with an interior value between.
            const std::vector<double> batch{inside[4], total / 3, inside[0], inside[3], inside[2]};
            const std::vector<double> t = table.t_at(std::span<const double>(batch));
            ASSERT_EQ(t.size(), batch.size());
            EXPECT_EQ(t[0], c.t_min());
            // (t_at's promise, |s_at(t) - s| <= slack, doubled for s_at's own rounding.)
            EXPECT_NEAR(table.s_at(t[1]), total / 3, 2 * table.end_slack());
            EXPECT_EQ(t[2], c.t_max());
            EXPECT_EQ(t[3], c.t_min());
            EXPECT_EQ(t[4], c.t_max());
            // Further out: twice the slack, and the 1e-9 relative where the
            // accuracy is finer than that. The message names the value and the range.
            std::vector<double> outside{total + 2 * table.end_slack(), -2 * table.end_slack()};
            if (acc < 1e-9) outside.push_back(total * (1 + 1e-9));
            for (const double s : outside) {
                EXPECT_FALSE(table.in_range(s)) << "s = " << s;
                try {
                    (void)table.t_at(s);
                    ADD_FAILURE() << "s = " << s << " accepted, total " << total;
                } catch (const out_of_domain& e) {
                    EXPECT_EQ(std::string(e.what()), "s = " + detail::num(s) + " is outside the arc-length range [0, " +
                                                         detail::num(total) + "]");
                }
                const std::vector<double> b{total / 2, s};
                try {
                    (void)table.t_at(std::span<const double>(b));
                    ADD_FAILURE() << "s = " << s << " accepted in a batch";
                } catch (const out_of_domain& e) {
                    EXPECT_NE(std::string(e.what()).find("(index 1)"), std::string::npos) << e.what();
                }
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, 20 * 6 * (6 + 2) + 20 * 2);  // 1e-10 and 1e-12 add the 1e-9 case
}

TEST(ArcLength, BadArguments) {
    catmull_rom<2> c({P2{{0, 0}}, P2{{1, 0}}, P2{{2, 1}}});
    EXPECT_THROW(arc_length(c, 0.0), invalid_input);
    EXPECT_THROW(arc_length(c, 2.0), invalid_input);
    const arc_length_table<2> t(c);
    try {
        t.t_at(t.total() * 2);
        ADD_FAILURE();
    } catch (const out_of_domain& e) {
        EXPECT_NE(std::string(e.what()).find("is outside the arc-length range [0, "), std::string::npos) << e.what();
    }
    EXPECT_THROW(t.t_at(std::nan("")), out_of_domain);
    EXPECT_THROW(arc_length(c, 1.5, 0.5), invalid_input);
}

}  // namespace
