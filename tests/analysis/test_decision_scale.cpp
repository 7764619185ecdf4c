// The crossing decision at scale (issue 27, point 1): the pieces that made
// it fast are checked here for what they must keep.
//
//  * detail/interval.hpp's outward steps (inline arithmetic, not
//    std::nextafter): at least one ulp and at most two (three near the
//    subnormals), at every magnitude
//    from subnormals to DBL_MAX and at the infinities; sums and products
//    enclose the exact result (its rounding error found exactly with
//    TwoSum and an FMA).
//  * The index of proved crossings (each filed under the curve cells its
//    ranges cover): on long random walks, open and closed, no two reported
//    crossings are the same crossing (their ranges overlap on both curves),
//    which the index must find as the scan of every crossing did.
#include <cfloat>
#include <cmath>
#include <limits>
#include <random>

#include <crspline/decision.hpp>

#include "test_support.hpp"

namespace {
using namespace crspline;
using detail::interval;
using P = vec<2>;

double next_up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }
double next_down(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }

// Is the exact value p + e (p the rounded result, e its exact error) in [lo, hi]?
bool encloses(const interval& r, double p, double e) {
    const bool above_lo = r.lo < p || (r.lo == p && e >= 0);
    const bool below_hi = r.hi > p || (r.hi == p && e <= 0);
    return above_lo && below_hi;
}

TEST(DecisionScale, IntervalStepsAreOneOrTwoUlps) {
    CRSPLINE_SEEDED(seed, 2027);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> mant(1.0, 2.0);
    std::uniform_int_distribution<int> expo(-1074, 1023);
    std::vector<double> xs = {0.0, -0.0, DBL_MIN, -DBL_MIN, DBL_TRUE_MIN, -DBL_TRUE_MIN, DBL_MAX, -DBL_MAX, 1.0, -1.0,
                              0.5, -0.5, std::nextafter(DBL_MIN, 0.0), 3 * DBL_TRUE_MIN};
    for (int e = -1074; e <= 1023; e += 7) xs.push_back(std::ldexp(1.0, e)), xs.push_back(-std::ldexp(1.0, e));
    for (int k = 0; k < 20000; ++k) xs.push_back((k % 2 ? -1 : 1) * std::ldexp(mant(rng), expo(rng)));
    std::size_t checked = 0;
    for (const double x : xs) {
        SCOPED_TRACE(x);
        const double u = detail::up(x), d = detail::down(x);
        // Strictly outward (up(DBL_MAX) is infinity, as nextafter's), by at
        // most two ulps; three just above the subnormals, where |x| eps is
        // itself rounded to a multiple of the least subnormal.
        EXPECT_GT(u, x);
        EXPECT_LT(d, x);
        const bool tiny = std::abs(x) < std::ldexp(1.0, -1000);
        EXPECT_LE(u, tiny ? next_up(next_up(next_up(x))) : next_up(next_up(x)));
        EXPECT_GE(d, tiny ? next_down(next_down(next_down(x))) : next_down(next_down(x)));
        ++checked;
    }
    EXPECT_EQ(checked, xs.size());
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(detail::up(-inf), -DBL_MAX);
    EXPECT_EQ(detail::down(inf), DBL_MAX);
    EXPECT_EQ(detail::up(inf), inf);
    EXPECT_EQ(detail::down(-inf), -inf);
}

TEST(DecisionScale, IntervalArithmeticEncloses) {
    CRSPLINE_SEEDED(seed, 2028);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> mant(-2.0, 2.0);
    std::uniform_int_distribution<int> expo(-60, 60);
    auto draw = [&] { return std::ldexp(mant(rng), expo(rng)); };
    std::size_t sums = 0, products = 0;
    for (int k = 0; k < 20000; ++k) {
        const double a = draw(), b = draw();
        SCOPED_TRACE(std::to_string(a) + " " + std::to_string(b));
        // TwoSum: s + t == a + b exactly.
        const double s = a + b, bb = s - a, t = (a - (s - bb)) + (b - bb);
        const interval sum = interval::point(a) + interval::point(b);
        EXPECT_TRUE(encloses(sum, s, t));
        const double q = a - b, qb = q - a, tq = (a - (q - qb)) + (-b - qb);
        EXPECT_TRUE(encloses(interval::point(a) - interval::point(b), q, tq));
        ++sums;
        // The product's error with an FMA: p + e == a b exactly (no underflow at these exponents).
        const double p = a * b, e = std::fma(a, b, -p);
        EXPECT_TRUE(encloses(interval::point(a) * interval::point(b), p, e));
        EXPECT_TRUE(encloses(a * interval::point(b), p, e));
        ++products;
    }
    EXPECT_EQ(sums, 20000u);
    EXPECT_EQ(products, 20000u);
}

// Two crossings are the same when their ranges (curve coordinates: the
// segment's rank plus u) overlap on both curves, either way round; on a
// closed curve of n segments, also with one range moved by n (the seam).
bool same_crossing(const proved_crossing& x, const proved_crossing& y, double period) {
    auto range = [](const proved_crossing& c, int k) {
        return std::array<double, 2>{double(c.segment[std::size_t(k)]) + c.u[std::size_t(k)][0],
                                     double(c.segment[std::size_t(k)]) + c.u[std::size_t(k)][1]};
    };
    auto meet = [&](std::array<double, 2> a, std::array<double, 2> b) {
        for (const double k : {-period, 0.0, period})
            if (a[0] <= b[1] + k && b[0] + k <= a[1]) return true;
        return false;
    };
    for (const int flip : {0, 1})
        if (meet(range(x, 0), range(y, flip)) && meet(range(x, 1), range(y, 1 - flip))) return true;
    return false;
}

TEST(DecisionScale, CrossingsOfLongWalksAreDistinct) {
    CRSPLINE_SEEDED(seed, 2029);
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g(0.0, 1.0);
    std::size_t curves = 0, crossings = 0;
    for (const bool closed : {false, true}) {
        std::vector<P> p(1500);
        for (std::size_t i = 1; i < p.size(); ++i) p[i] = p[i - 1] + P{{g(rng), g(rng)}};
        const catmull_rom<2> c(p, {.alpha = 0.5, .closed = closed});
        const decision d = decide(c, {.record_pairs = false});
        ASSERT_EQ(d.result, verdict::crosses);
        // A 2-D walk of n unit steps crosses itself about n times (n log n / const).
        EXPECT_GT(d.crossings.size(), 1000u);
        // No segment of these walks is a point, so the segment index is the rank.
        const double period = closed ? double(c.segment_count()) : 0.0;
        for (std::size_t i = 0; i < d.crossings.size(); ++i)
            for (std::size_t j = i + 1; j < d.crossings.size(); ++j)
                EXPECT_FALSE(same_crossing(d.crossings[i], d.crossings[j], period)) << i << " " << j;
        crossings += d.crossings.size();
        ++curves;
    }
    EXPECT_EQ(curves, 2u);
    std::printf("2 walks of 1500 points: %zu crossings, all distinct\n", crossings);
}

}  // namespace
