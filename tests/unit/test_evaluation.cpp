// Evaluation mechanics: knot ownership, batch paths, degenerate segments.
#include "test_support.hpp"

namespace {
using namespace crspline;
using crspline::test::random_polygon;
using P2 = vec<2>;
using P3 = vec<3>;
using crspline::test::eps;

TEST(Evaluation, KnotBelongsToTheSegmentOnItsRightLastKnotToLast) {
    std::vector<P2> p{P2{{0, 0}}, P2{{1, 0}}, P2{{2, 1}}, P2{{3, 1}}};
    catmull_rom<2> c(p, {.alpha = 0.0});
    EXPECT_EQ(c.locate(0.0), 0u);
    EXPECT_EQ(c.locate(0.999), 0u);
    EXPECT_EQ(c.locate(1.0), 1u);
    EXPECT_EQ(c.locate(2.0), 2u);
    EXPECT_EQ(c.locate(3.0), 2u);
    EXPECT_EQ(c.locate(-5.0), 0u);
    EXPECT_EQ(c.locate(50.0), 2u);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(c.evaluate(double(i)), p[i]);
}

TEST(Evaluation, BatchSortedUnsortedAndScalarAgree) {
    CRSPLINE_SEEDED(s, 21);
    std::mt19937_64 rng(s);
    for (int rep = 0; rep < 20; ++rep) {
        auto p = random_polygon<3>(rng, 5 + rep);
        catmull_rom<3> c(p, {.alpha = 0.5, .closed = rep % 2 == 1});
        std::uniform_real_distribution<double> u(c.t_min(), c.t_max());
        std::vector<double> t(500);
        for (auto& x : t) x = u(rng);
        t[0] = c.t_min();
        t[1] = c.t_max();
        for (std::size_t i = 0; i < c.grid().size(); ++i) t[2 + i] = c.grid()[i];
        std::vector<double> sorted = t;
        std::sort(sorted.begin(), sorted.end());
        // The value of order r is a sum of terms k!/(k-r)! c_k u^(k-r) / h^r;
        // the sorted path folds 1/h^r into the coefficients, so the two
        // paths are a few roundings of those terms' sizes apart (of the
        // derivative's own size alone, as once asserted, the bound was 2
        // times too tight at seed 101, where the terms cancel).
        auto terms = [&](double tk, int order) {
            const auto& sg = c.segment(c.locate(tk));
            const double a0 = max_abs(sg.origin), a1 = max_abs(sg.c1), a2 = max_abs(sg.c2), a3 = max_abs(sg.c3);
            const std::array<double, 4> sz{a0 + a1 + a2 + a3, a1 + 2 * a2 + 3 * a3, 2 * a2 + 6 * a3, 6 * a3};
            return sz[std::size_t(order)] * std::pow(sg.inv_h, order);
        };
        for (int order = 0; order <= 3; ++order) {
            const auto a = c.evaluate(std::span<const double>(t), order);
            const auto b = c.evaluate(std::span<const double>(sorted), order);
            for (std::size_t k = 0; k < t.size(); ++k) {
                const P3 x = c.evaluate(t[k], order);
                const P3 y = c.evaluate(sorted[k], order);
                EXPECT_LE(norm(a[k] - x), 16 * eps * terms(t[k], order)) << "order " << order << " t " << t[k];
                EXPECT_LE(norm(b[k] - y), 16 * eps * terms(sorted[k], order)) << "order " << order << " t " << sorted[k];
            }
        }
    }
}

TEST(Evaluation, RebuildingReproducesTheCurve) {
    // The curve keeps its knot intervals as computed and grid() holds their
    // rounded running sums (catmull_rom's class comment). What reproduces
    // it: options() (with grid() when the grid was explicit) bit for bit;
    // grid() passed back as an explicit grid of an alpha curve gives the
    // same knots, intervals within eps * grid[i+1] of the originals, and a
    // shape within the first-order effect of that change. Random polygons
    // with chords over 6 decades and a tiny chord after long ones, where
    // intervals lose digits in the sums.
    CRSPLINE_SEEDED(s, 22);
    std::mt19937_64 rng(s);
    int checked = 0, rounded_intervals = 0;
    for (double alpha : {0.0, 0.25, 0.5, 1.0})
        for (bool closed : {false, true}) {
            auto p = random_polygon<2>(rng, 9, 6.0);
            p[5] = p[4] + P2{{1e-9, -2e-9}};
            const catmull_rom<2> a(p, {.alpha = alpha, .closed = closed});
            const auto g = a.grid();
            const auto h = a.intervals();
            const std::size_t nseg = a.segment_count();
            auto same_bits = [&](const catmull_rom<2>& b) {
                ASSERT_EQ(b.segment_count(), nseg);
                for (std::size_t i = 0; i <= nseg; ++i) EXPECT_EQ(b.grid()[i], g[i]) << "knot " << i;
                for (std::size_t i = 0; i < nseg; ++i) {
                    EXPECT_EQ(b.intervals()[i], h[i]) << "interval " << i;
                    EXPECT_EQ(b.bezier(i), a.bezier(i)) << "segment " << i;
                }
            };
            // 1. options() rebuilds the same curve bit for bit.
            same_bits(catmull_rom<2>(p, a.options()));
            // 2. An explicit grid: its intervals are its differences, and
            //    options() + grid() rebuild it bit for bit.
            const catmull_rom<2> e(p, {.grid = std::vector<double>(g.begin(), g.end()), .closed = closed});
            auto eo = e.options();
            ASSERT_FALSE(eo.alpha.has_value());
            eo.grid.emplace(e.grid().begin(), e.grid().end());
            const catmull_rom<2> e2(p, eo);
            for (std::size_t i = 0; i < nseg; ++i) {
                EXPECT_EQ(e.intervals()[i], g[i + 1] - g[i]);
                EXPECT_EQ(e2.bezier(i), e.bezier(i)) << "segment " << i;
            }
            // 3. grid() passed back (the curve e): the same knots; intervals
            //    d(i) = g[i+1] - g[i] within eps * g[i+1] of h(i) (one
            //    rounding of the sum, one of the difference); exact for
            //    alpha = 0, whose sums of ones are exact.
            for (std::size_t i = 0; i <= nseg; ++i) EXPECT_EQ(e.grid()[i], g[i]);
            std::vector<double> delta(nseg);  // relative change of each interval
            for (std::size_t i = 0; i < nseg; ++i) {
                const double d = e.intervals()[i];
                EXPECT_LE(std::abs(d - h[i]), eps * g[i + 1]) << "interval " << i;
                if (alpha == 0) {
                    EXPECT_EQ(d, h[i]);
                }
                if (d != h[i]) ++rounded_intervals;
                delta[i] = h[i] > 0 ? std::abs(d - h[i]) / h[i] : 0;
            }
            //    The shape: B1 - B0 = h(i) m(i) / 3 with h(i) m(i) = a c(i-1) + b c(i)
            //    (c the chords), a = h(i)^2 / (h(i-1) (h(i-1) + h(i))) <= h(i) / h(i-1)
            //    and b = h(i-1) / (h(i-1) + h(i)) <= 1; relative changes delta of the
            //    intervals change log a by at most 4 delta and log b by 2 delta, so
            //    B1 moves by at most 4/3 delta (a |c(i-1)| + b |c(i)|), likewise B2
            //    with c(i+1) and h(i) / h(i+1); a natural end, (3 c - h m) / 2, by
            //    no more. 3 delta S, S = |c(i-1)| h(i)/h(i-1) + |c(i)| + |c(i+1)| h(i)/h(i+1),
            //    covers both with second-order room; plus rounding of the points.
            auto chord = [&](std::size_t k) { return norm(p[(k + 1) % p.size()] - p[k]); };
            for (std::size_t i = 0; i < nseg; ++i) {
                const bool has_prev = closed || i > 0, has_next = closed || i + 1 < nseg;
                const std::size_t ip = (i + nseg - 1) % nseg, in = (i + 1) % nseg;
                double S = chord(i), dl = delta[i];
                if (has_prev && h[ip] > 0) S += chord(ip) * h[i] / h[ip], dl = std::max(dl, delta[ip]);
                if (has_next && h[in] > 0) S += chord(in) * h[i] / h[in], dl = std::max(dl, delta[in]);
                const auto A = a.bezier(i), B = e.bezier(i);
                const double size = max_abs(A[0]) + max_abs(A[3]) + S;
                for (int k = 1; k <= 2; ++k)
                    EXPECT_LE(norm(A[k] - B[k]), 3 * dl * S + 64 * eps * size) << "segment " << i << " B" << k;
                ++checked;
            }
        }
    EXPECT_EQ(checked, 4 * (8 + 9));
    // The sums did round somewhere, so part 3 checked a real difference.
    EXPECT_GT(rounded_intervals, 0);
}

TEST(Evaluation, DegenerateSegmentsNeverGiveNaN) {
    // A repeated point in the middle and at the end, all-equal points.
    std::vector<P2> p{P2{{0, 0}}, P2{{1, 1}}, P2{{1, 1}}, P2{{2, 0}}, P2{{2, 0}}};
    for (double alpha : {0.0, 0.5, 1.0}) {
        catmull_rom<2> c(p, {.alpha = alpha});
        for (int order = 0; order <= 3; ++order)
            for (double t : {c.t_min(), c.grid()[1], c.grid()[2], c.grid()[3], c.t_max(), 0.5 * c.t_max()}) {
                const P2 x = c.evaluate(t, order);
                EXPECT_TRUE(std::isfinite(x[0]) && std::isfinite(x[1])) << alpha << " " << t << " " << order;
            }
        EXPECT_EQ(c.evaluate(c.t_max()), p.back());
    }
    std::vector<P2> same(4, P2{{3, 4}});
    catmull_rom<2> c(same);
    EXPECT_EQ(c.t_min(), 0.0);
    EXPECT_EQ(c.t_max(), 0.0);
    EXPECT_EQ(c.evaluate(0.0), same[0]);
    EXPECT_EQ(c.evaluate(0.0, 1), P2{});
}

TEST(Evaluation, ExplicitGridWithLargeOffsetKeepsPrecision) {
    // Knots near 1e9: u = (t - t0) / h is computed from a difference of
    // nearby numbers, exact by Sterbenz's lemma.
    std::vector<P2> p{P2{{0, 0}}, P2{{1, 2}}, P2{{5, 3}}, P2{{6, 0}}};
    catmull_rom<2> a(p, {.alpha = 0.0});
    catmull_rom<2> b(p, {.grid = std::vector<double>{1e9, 1e9 + 1, 1e9 + 2, 1e9 + 3}});
    for (double u : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        EXPECT_LE(norm(a.evaluate(1 + u) - b.evaluate(1e9 + 1 + u)), 8 * eps * 6);
        EXPECT_LE(norm(a.evaluate(1 + u, 1) - b.evaluate(1e9 + 1 + u, 1)), 8 * eps * 6);
    }
}

}  // namespace
