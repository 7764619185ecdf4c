// End conditions, closed curves, two points, tension and Kochanek-Bartels.
#include "test_support.hpp"

#include <bit>
#include <cstring>

namespace {
using namespace crspline;
using crspline::test::random_polygon;
using crspline::test::scale_of;
using P2 = vec<2>;
using P3 = vec<3>;
using crspline::test::eps;

TEST(EndConditions, NaturalEndsHaveZeroSecondDerivative) {
    CRSPLINE_SEEDED(s, 11);
    std::mt19937_64 rng(s);
    for (double alpha : {0.0, 0.25, 0.5, 1.0}) {
        for (int rep = 0; rep < 25; ++rep) {
            auto p = random_polygon<3>(rng, 3 + rep % 6);
            catmull_rom<3> c(p, {.alpha = alpha});
            const auto& first = c.segments().front();
            const auto& last = c.segments().back();
            // d2/du2 at the ends against the size of the u-coefficients: the
            // second derivative is a sum of a few terms of that size, so 16 eps.
            const double s0 = max_abs(first.c1) + max_abs(first.c2) + max_abs(first.c3);
            const double s1 = max_abs(last.c1) + max_abs(last.c2) + max_abs(last.c3);
            EXPECT_LE(max_abs(first.du(0, 2)), 16 * eps * s0);
            EXPECT_LE(max_abs(last.du(1, 2)), 16 * eps * s1);
        }
    }
}

TEST(EndConditions, ReflectIsThePhantomPointOfThreeJs) {
    // reflect == the Barry-Goldman segment with phantom point 2 P0 - P1 and
    // knot interval from alpha (|P(-1) - P0| = |P1 - P0|).
    CRSPLINE_SEEDED(s, 12);
    std::mt19937_64 rng(s);
    for (double alpha : {0.0, 0.5, 0.75, 1.0}) {
        for (int rep = 0; rep < 20; ++rep) {
            auto p = random_polygon<2>(rng, 4 + rep % 4);
            catmull_rom<2> c(p, {.alpha = alpha, .start = end_condition<2>::reflect(),
                                 .end = end_condition<2>::reflect()});
            const auto g = c.grid();
            const std::size_t n = p.size();
            const P2 ph0 = 2.0 * p[0] - p[1], ph1 = 2.0 * p[n - 1] - p[n - 2];
            const double h0 = g[1] - g[0], h1 = g[n - 1] - g[n - 2];
            for (double u : {0.1, 0.5, 0.9}) {
                const double t0 = g[0] + u * h0;
                const P2 ref0 = barry_goldman<2, double>({ph0, p[0], p[1], p[2]}, {g[0] - h0, g[0], g[1], g[2]}, t0);
                const double t1 = g[n - 2] + u * h1;
                const P2 ref1 = barry_goldman<2, double>({p[n - 3], p[n - 2], p[n - 1], ph1},
                                                         {g[n - 3], g[n - 2], g[n - 1], g[n - 1] + h1}, t1);
                // Both are a handful of operations on coordinates of size scale.
                const double tol = 64 * eps * scale_of(p);
                EXPECT_LE(norm(c.evaluate(t0) - ref0), tol);
                EXPECT_LE(norm(c.evaluate(t1) - ref1), tol);
            }
        }
    }
}

TEST(EndConditions, ExplicitTangentIsTakenAsGivenEvenWithTension) {
    std::vector<P3> p{P3{{0, 0, 0}}, P3{{1, 2, 0}}, P3{{3, 1, 1}}, P3{{4, 0, 2}}};
    const P3 a{{5, -1, 2}}, b{{0, 3, -4}};
    for (double tau : {0.0, 0.3, 1.0}) {
        catmull_rom<3> c(p, {.start = end_condition<3>::tangent(a), .end = end_condition<3>::tangent(b),
                             .tension = tau});
        EXPECT_LE(norm(c.evaluate(c.t_min(), 1) - a), 8 * eps * norm(a)) << "tension " << tau;
        EXPECT_LE(norm(c.evaluate(c.t_max(), 1) - b), 8 * eps * norm(b)) << "tension " << tau;
    }
}

TEST(EndConditions, ClosedCurveIsPeriodicAndC1AtTheSeam) {
    CRSPLINE_SEEDED(s, 13);
    std::mt19937_64 rng(s);
    for (double alpha : {0.0, 0.5, 1.0}) {
        for (int rep = 0; rep < 30; ++rep) {
            auto p = random_polygon<2>(rng, 3 + rep % 7);
            catmull_rom<2> c(p, {.alpha = alpha, .closed = true});
            ASSERT_EQ(c.segment_count(), p.size());
            ASSERT_EQ(c.grid().size(), p.size() + 1);
            const double sc = scale_of(p);
            EXPECT_EQ(c.evaluate(c.t_min()), p[0]);
            EXPECT_LE(norm(c.evaluate(c.t_max()) - p[0]), 8 * eps * sc);
            const P2 d0 = c.evaluate(c.t_min(), 1), d1 = c.evaluate(c.t_max(), 1);
            EXPECT_LE(norm(d0 - d1), 64 * eps * (norm(d0) + sc));
            // The seam tangent uses P(N-1) and P1 (the splines convention).
            // The knot intervals as the curve computed them (differences of
            // the rounded grid are off by eps grid[n] / h). The bound is on
            // the two terms' sizes, not on the sum's: they can cancel.
            const std::size_t n = p.size();
            const double h0 = c.intervals()[n - 1], h1 = c.intervals()[0];
            const P2 expect = (h1 * h1 * (p[0] - p[n - 1]) + h0 * h0 * (p[1] - p[0])) / (h0 * h1 * (h0 + h1));
            const double terms = (h1 * h1 * norm(p[0] - p[n - 1]) + h0 * h0 * norm(p[1] - p[0])) / (h0 * h1 * (h0 + h1));
            EXPECT_LE(norm(d0 - expect), 64 * eps * terms);
        }
    }
}

TEST(EndConditions, TwoPointsGiveAStraightLineWhateverTheEnds) {
    const std::vector<P3> p{P3{{0, 0, 0}}, P3{{1, 2, 2}}};
    for (auto e : {end_condition<3>::natural(), end_condition<3>::reflect(), end_condition<3>::tangent(P3{{5, 0, 0}})}) {
        for (double tau : {0.0, 0.5, 1.0}) {
            catmull_rom<3> c(p, {.start = e, .end = e, .tension = tau});
            for (double u : {0.0, 0.2, 0.5, 0.7, 1.0}) {
                const double t = u * c.t_max();
                EXPECT_LE(norm(c.evaluate(t) - u * p[1]), 8 * eps * 3);
                EXPECT_LE(norm(c.evaluate(t, 1) - p[1] / c.t_max()), 8 * eps * 3);
            }
        }
    }
}

TEST(Tension, OneIsThePolyline) {
    CRSPLINE_SEEDED(s, 14);
    std::mt19937_64 rng(s);
    int checked = 0;
    for (double alpha : {0.0, 0.5, 1.0}) {
        for (bool closed : {false, true}) {
            auto p = random_polygon<3>(rng, 7);
            catmull_rom<3> c(p, {.alpha = alpha, .closed = closed, .tension = 1.0});
            for (std::size_t i = 0; i < c.segment_count(); ++i) {
                const P3 a = p[i], b = p[(i + 1) % p.size()];
                for (double u : {0.1, 0.37, 0.5, 0.81}) {
                    const P3 x = c.segment(i).at(u);
                    // Distance from x to the chord [a, b].
                    const double w = dot(x - a, b - a) / dot(b - a, b - a);
                    EXPECT_GE(w, -1e-15);
                    EXPECT_LE(w, 1 + 1e-15);
                    EXPECT_LE(norm(x - (a + w * (b - a))), 16 * eps * scale_of(p));
                    ++checked;
                }
            }
        }
    }
    EXPECT_EQ(checked, 3 * (6 + 7) * 4);
}

TEST(Tension, ScalesComputedTangentsByOneMinusTau) {
    std::vector<P2> p{P2{{0, 0}}, P2{{1, 2}}, P2{{5, 3}}, P2{{6, 0}}, P2{{8, 1}}};
    catmull_rom<2> plain(p), tense(p, {.tension = 0.3});
    for (std::size_t i = 0; i < plain.segment_count(); ++i) {
        const auto a = plain.tangents(i), b = tense.tangents(i);
        for (int k = 0; k < 2; ++k) EXPECT_LE(norm(b[k] - 0.7 * a[k]), 4 * eps * norm(a[k]));
    }
}

template <std::size_t D>
bool same_bits(const catmull_rom<D>& a, const catmull_rom<D>& b) {
    if (a.segment_count() != b.segment_count()) return false;
    for (std::size_t i = 0; i < a.segment_count(); ++i) {
        const auto sa = a.segment(i), sb = b.segment(i);
        if (std::memcmp(&sa, &sb, sizeof sa) != 0) return false;
    }
    return true;
}

TEST(KochanekBartels, ZerosAreBitForBitThePlainCurve) {
    CRSPLINE_SEEDED(s, 15);
    std::mt19937_64 rng(s);
    for (double alpha : {0.0, 0.5, 1.0})
        for (bool closed : {false, true})
            for (double tau : {0.0, 0.4}) {
                auto p = random_polygon<3>(rng, 8);
                std::vector<double> z(p.size(), 0.0);
                catmull_rom<3> plain(p, {.alpha = alpha, .closed = closed, .tension = tau});
                catmull_rom<3> kb(p, {.alpha = alpha, .closed = closed, .tension = tau,
                                      .kb = {.tension = z, .continuity = z, .bias = z}});
                EXPECT_TRUE(same_bits(plain, kb)) << "alpha " << alpha << " closed " << closed;
            }
}

TEST(KochanekBartels, ContinuityBreaksTheTangentAndKnotsBelongToTheRight) {
    std::vector<P2> p{P2{{0, 0}}, P2{{1, 2}}, P2{{3, 3}}, P2{{4, 1}}};
    catmull_rom<2> c(p, {.alpha = 0.0, .kb = {.continuity = {0, 0.8, 0, 0}}});
    const auto before = c.tangents(0)[1], after = c.tangents(1)[0];
    EXPECT_GT(norm(before - after), 0.1);
    // A knot belongs to the segment on its right: the derivative there is the
    // outgoing tangent.
    EXPECT_EQ(c.locate(1.0), 1u);
    EXPECT_LE(norm(c.evaluate(1.0, 1) - after), 8 * eps * norm(after));
}

}  // namespace
