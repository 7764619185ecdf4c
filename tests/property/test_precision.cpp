// Precision and degenerate input: large offsets, coincident points as a limit.
#include "test_support.hpp"

namespace {
using namespace crspline;
using crspline::test::random_polygon;
using crspline::test::scale_of;
using P2 = vec<2>;
using P3 = vec<3>;
using crspline::test::eps;

TEST(Precision, OffsetsOf1e8KeepFullPrecision) {
    // Evaluation is relative to each segment's first point: a curve moved by
    // 1e8 is the moved curve up to the rounding of the final sum (eps * 1e8)
    // plus a few roundings of the curve's own size.
    CRSPLINE_SEEDED(s, 201);
    std::mt19937_64 rng(s);
    for (double alpha : {0.0, 0.5, 1.0})
        for (int rep = 0; rep < 30; ++rep) {
            auto p = random_polygon<2>(rng, 6, 2.0);
            // Snap to a 2^-20 grid so the shifted points are exact doubles.
            for (auto& x : p) for (auto& v : x.v) v = std::ldexp(std::round(std::ldexp(v, 20)), -20);
            const P2 off{{1e8, -1e8}};
            std::vector<P2> q;
            for (auto& x : p) q.push_back(x + off);
            catmull_rom<2> c(p, {.alpha = alpha}), d(q, {.alpha = alpha});
            for (std::size_t i = 0; i < c.grid().size(); ++i) ASSERT_EQ(c.grid()[i], d.grid()[i]);
            for (int j = 0; j <= 40; ++j) {
                const double t = std::min(c.t_max() * j / 40.0, c.t_max());  // the product can round past t_max
                const P2 a = c.evaluate(t) + off, b = d.evaluate(t);
                EXPECT_LE(norm(a - b), 2 * eps * 1e8 + 64 * eps * scale_of(p)) << "t " << t;
            }
        }
}

TEST(Precision, CoincidentPointsAreTheLimitOfNearbyInputs) {
    // P2 -> P1 along a direction: for 0 < alpha < 1 the curve converges to
    // the zero-chord-velocity convention, with no NaN on the way. The tangent
    // at P1 is (h2 v1 + h1 v2) / (h1 + h2) with h2 = d^alpha and
    // |v2| = d^(1 - alpha): it vanishes like d^alpha + d^(1 - alpha).
    CRSPLINE_SEEDED(s, 202);
    std::mt19937_64 rng(s);
    for (double alpha : {0.25, 0.5, 0.75})
        for (int rep = 0; rep < 10; ++rep) {
            auto p = random_polygon<2>(rng, 5, 1.0);
            p[2] = p[1];
            catmull_rom<2> limit(p, {.alpha = alpha});
            P2 dir{{std::cos(rep * 1.1), std::sin(rep * 1.1)}};
            double previous_gap = INFINITY;
            for (int k = 2; k <= 14; k += 2) {
                const double d = std::pow(10.0, -k);
                auto q = p;
                q[2] = p[1] + d * dir;
                catmull_rom<2> c(q, {.alpha = alpha});
                double gap = 0;
                for (int j = 0; j <= 64; ++j) {
                    const double u = j / 64.0;
                    const P2 x = c.evaluate(std::min(u * c.t_max(), c.t_max())), y = limit.evaluate(std::min(u * limit.t_max(), limit.t_max()));
                    ASSERT_TRUE(std::isfinite(x[0]) && std::isfinite(x[1]));
                    gap = std::max(gap, norm(x - y));
                }
                EXPECT_LE(gap, 10 * (std::pow(d, alpha) + std::pow(d, 1 - alpha)) * scale_of(p)) << "d " << d;
                EXPECT_LE(gap, previous_gap * 1.01 + 1e-14) << "d " << d;
                previous_gap = gap;
            }
        }
}

TEST(Precision, CoincidenceIsJudgedRelativeToTheLocalScale) {
    // A legitimate 1.2e-6 chord (three.js treats it as a repeated point) is a
    // real chord for crspline; a difference at the rounding level of 1e8
    // coordinates is not.
    std::vector<P2> p{P2{{0, 0}}, P2{{1, 0}}, P2{{1 + 1.2e-6, 0}}, P2{{2, 1}}};
    auto k = knots(std::span<const P2>(p), 0.5);
    // (1 + 1.2e-6) - 1 carries a rounding of eps in 1.2e-6: 1e-10 relative.
    EXPECT_NEAR(k[2] - k[1], std::sqrt(1.2e-6), 1e-10 * std::sqrt(1.2e-6));
    EXPECT_GT(k[2] - k[1], 0.0);
    std::vector<P2> q{P2{{1e8, 0}}, P2{{1e8 + 1, 0}}, P2{{std::nextafter(1e8 + 1, 2e8), 0}}, P2{{1e8 + 2, 1}}};
    auto kq = knots(std::span<const P2>(q), 0.5);
    EXPECT_EQ(kq[2], kq[1]);
    catmull_rom<2> c(q);
    EXPECT_TRUE(std::isfinite(c.evaluate(c.t_max() / 2)[0]));
}

TEST(Precision, HugeAndTinyCoordinatesStayFinite) {
    for (double scale : {1e-300, 1e-150, 1e150, 1e300}) {
        std::vector<P3> p{P3{{0, 0, 0}}, P3{{1, 2, 0}}, P3{{3, 1, 1}}, P3{{4, 0, 2}}, P3{{4, 1, 3}}};
        for (auto& x : p) x = scale * x;
        for (double alpha : {0.0, 0.5, 1.0}) {
            catmull_rom<3> c(p, {.alpha = alpha});
            for (int j = 0; j <= 10; ++j) {
                const P3 x = c.evaluate(std::min(c.t_max() * j / 10.0, c.t_max()));
                for (double v : x.v) EXPECT_TRUE(std::isfinite(v)) << scale << " " << alpha;
            }
            EXPECT_EQ(c.evaluate(c.grid()[2]), p[2]);
        }
    }
}

}  // namespace
