// Evaluation mechanics: knot ownership, batch paths, degenerate segments.
#include "test_support.hpp"

namespace {
using namespace crspline;
using crspline::test::random_polygon;
using P2 = vec<2>;
using P3 = vec<3>;
constexpr double eps = std::numeric_limits<double>::epsilon();

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
        for (int order = 0; order <= 3; ++order) {
            const auto a = c.evaluate(std::span<const double>(t), order);
            const auto b = c.evaluate(std::span<const double>(sorted), order);
            for (std::size_t k = 0; k < t.size(); ++k) {
                const P3 x = c.evaluate(t[k], order);
                const P3 y = c.evaluate(sorted[k], order);
                // The sorted path folds 1/h into the coefficients for order 1:
                // a few roundings of the derivative's size apart.
                EXPECT_LE(norm(a[k] - x), 16 * eps * (norm(x) + max_abs(c.segment(c.locate(t[k])).c1) * c.segment(c.locate(t[k])).inv_h));
                EXPECT_LE(norm(b[k] - y), 16 * eps * (norm(y) + max_abs(c.segment(c.locate(sorted[k])).c1) * c.segment(c.locate(sorted[k])).inv_h));
            }
        }
    }
}

TEST(Evaluation, StoredKnotsDefineTheCurve) {
    // grid() passed back as an explicit grid reproduces the curve bit for
    // bit, for every alpha, including a tiny chord after long ones.
    CRSPLINE_SEEDED(s, 22);
    std::mt19937_64 rng(s);
    int checked = 0;
    for (double alpha : {0.25, 0.5, 1.0})
        for (bool closed : {false, true}) {
            auto p = random_polygon<2>(rng, 9, 6.0);
            p[5] = p[4] + P2{{1e-9, -2e-9}};
            catmull_rom<2> a(p, {.alpha = alpha, .closed = closed});
            std::vector<double> g(a.grid().begin(), a.grid().end());
            catmull_rom<2> b(p, {.grid = g, .closed = closed});
            for (std::size_t i = 0; i < a.segment_count(); ++i) {
                EXPECT_EQ(a.bezier(i), b.bezier(i)) << "segment " << i;
                ++checked;
            }
        }
    EXPECT_EQ(checked, 3 * (8 + 9));
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
