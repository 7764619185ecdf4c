// Nearest point on a curve: the exact per-segment solver, the pruned global
// search, the bounding-volume index and the batch forms, against an
// independent brute force. Every test prints its seed and counts its checks.
#include "test_support.hpp"

#include <crspline/nearest.hpp>

#include <cmath>
#include <limits>

namespace {
using namespace crspline;
using crspline::test::random_polygon;
using crspline::test::scale_of;
using crspline::test::alphas;

// The promise of nearest.hpp: distance exact to 1e-12 of the scale.
constexpr double promise = 1e-12;

// Brute force, independent of the solver: sample each segment at 2048 + 1
// values of u in long double, then refine every sampled local minimum by
// golden-section search on its two neighbouring intervals (100 steps shrink
// 1/1024 to below 1e-23). Returns the smallest distance (not squared).
template <std::size_t D, class T>
long double brute_distance(const catmull_rom<D, T>& c, const vec<D, T>& q) {
    using L = long double;
    constexpr int m = 2048;
    L best = std::numeric_limits<L>::infinity();
    for (const auto& s : c.segments()) {
        auto dist_sq = [&](L u) {
            L acc = 0;
            for (std::size_t k = 0; k < D; ++k) {
                const L e = u * (L(s.c1[k]) + u * (L(s.c2[k]) + u * L(s.c3[k]))) - (L(q[k]) - L(s.origin[k]));
                acc += e * e;
            }
            return acc;
        };
        std::vector<L> v(m + 1);
        for (int j = 0; j <= m; ++j) v[j] = dist_sq(L(j) / m);
        for (int j = 0; j <= m; ++j) {
            const bool left_ok = j == 0 || v[j] <= v[j - 1];
            const bool right_ok = j == m || v[j] < v[j + 1];
            if (!(left_ok && right_ok)) continue;
            L a = L(std::max(0, j - 1)) / m, b = L(std::min(m, j + 1)) / m;
            const L r = (std::sqrt(L(5)) - 1) / 2;
            for (int it = 0; it < 100; ++it) {
                const L x1 = b - r * (b - a), x2 = a + r * (b - a);
                if (dist_sq(x1) <= dist_sq(x2)) b = x2;
                else a = x1;
            }
            best = std::min({best, v[j], dist_sq((a + b) / 2)});
        }
    }
    return std::sqrt(best);
}

// Queries of three kinds around a curve: near it (a random curve point
// moved by 1e-3 of the scale), in its box (widened by 20%), far (10 scales).
template <std::size_t D>
std::vector<vec<D>> queries_around(std::mt19937_64& rng, const catmull_rom<D>& c, double scale, int per_kind) {
    std::uniform_real_distribution<double> U(0.0, 1.0);
    std::normal_distribution<double> G(0.0, 1.0);
    auto unit = [&] {
        vec<D> v;
        for (std::size_t k = 0; k < D; ++k) v[k] = G(rng);
        return v / norm(v);
    };
    vec<D> lo = c.points()[0], hi = lo;
    for (const auto& p : c.points())
        for (std::size_t k = 0; k < D; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    std::vector<vec<D>> q;
    for (int i = 0; i < per_kind; ++i) {
        const double t = c.t_min() + U(rng) * (c.t_max() - c.t_min());
        q.push_back(c.evaluate(t) + (1e-3 * scale) * unit());
        vec<D> b;
        for (std::size_t k = 0; k < D; ++k) b[k] = lo[k] - 0.2 * (hi[k] - lo[k]) + 1.4 * U(rng) * (hi[k] - lo[k]);
        q.push_back(b);
        q.push_back((lo + hi) / 2.0 + (10 * scale) * unit());
    }
    return q;
}

// Every field of a result agrees with itself: the point is the curve at t
// and the distance is the distance to it. A knot's point may come from the
// segment on its left, within rounding of the curve's value. Absolute
// coordinates (up to |q|, curves are offset by 100) round at eps |q|: the
// bounds allow 64 such roundings.
template <std::size_t D, class T>
void expect_consistent(const catmull_rom<D, T>& c, const vec<D, T>& q, const nearest_result<D, T>& r, T scale) {
    const T eps = std::numeric_limits<T>::epsilon();
    ASSERT_LT(r.segment, c.segment_count());
    EXPECT_GE(r.t, c.grid()[r.segment]);
    EXPECT_LE(r.t, c.grid()[r.segment + 1]);
    EXPECT_LE(norm(r.point - c.evaluate(r.t)), 64 * eps * (scale + max_abs(q)));
    const T d = norm(r.point - q);
    EXPECT_NEAR(std::sqrt(r.distance_sq), d, 64 * eps * (scale + max_abs(q) + d));
}

template <std::size_t D>
std::size_t check_against_brute_force(std::mt19937_64& rng, int reps, int per_kind) {
    std::size_t checked = 0;
    for (double alpha : alphas)
        for (bool closed : {false, true})
            for (int rep = 0; rep < reps; ++rep) {
                auto p = random_polygon<D>(rng, 4 + std::size_t(rep % 5), 1.5, rep % 3 == 0 ? 100.0 : 0.0);
                catmull_rom<D> c(p, {.alpha = alpha, .closed = closed});
                const double scale = scale_of(p);
                for (const auto& q : queries_around(rng, c, scale, per_kind)) {
                    const auto r = nearest(c, q);
                    const long double want = brute_distance(c, q);
                    EXPECT_NEAR(double(std::sqrt((long double)r.distance_sq) - want), 0.0, promise * scale)
                        << "alpha " << alpha << " closed " << closed << " rep " << rep;
                    expect_consistent(c, q, r, scale);
                    ++checked;
                }
            }
    return checked;
}

TEST(Nearest, MatchesBruteForceIn2DAnd3D) {
    CRSPLINE_SEEDED(s, 501);
    std::mt19937_64 rng(s);
    // 5 alphas x open/closed x 6 curves x 3 kinds x 4 queries, per dimension.
    EXPECT_EQ(check_against_brute_force<2>(rng, 6, 4), 5u * 2 * 6 * 3 * 4);
    EXPECT_EQ(check_against_brute_force<3>(rng, 6, 4), 5u * 2 * 6 * 3 * 4);
}

TEST(Nearest, MatchesBruteForceIn1DAnd4D) {
    CRSPLINE_SEEDED(s, 502);
    std::mt19937_64 rng(s);
    EXPECT_EQ(check_against_brute_force<1>(rng, 2, 3), 5u * 2 * 2 * 3 * 3);
    EXPECT_EQ(check_against_brute_force<4>(rng, 2, 3), 5u * 2 * 2 * 3 * 3);
}

TEST(Nearest, FloatCurvesMatchBruteForceToFloatPrecision) {
    CRSPLINE_SEEDED(s, 503);
    std::mt19937_64 rng(s);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    for (double alpha : alphas)
        for (int rep = 0; rep < 8; ++rep) {
            auto p = random_polygon<3, float>(rng, 6, 1.0);
            catmull_rom<3, float> c(p, {.alpha = alpha, .closed = rep % 2 == 1});
            const float scale = scale_of(p);
            for (int i = 0; i < 10; ++i) {
                vec<3, float> q = p[std::size_t(i) % p.size()];
                for (std::size_t k = 0; k < 3; ++k) q[k] += float(U(rng)) * scale;
                const auto r = nearest(c, q);
                // Float keeps about 7 digits: a few hundred float epsilons of
                // the scale (the coefficients carry rounding of that size).
                EXPECT_NEAR(double(std::sqrt(r.distance_sq)), double(brute_distance(c, q)), 256 * 1.2e-7 * scale);
                expect_consistent(c, q, r, scale);
            }
        }
}

TEST(Nearest, QueriesOnTheCurveFindTheirOwnParameter) {
    CRSPLINE_SEEDED(s, 504);
    std::mt19937_64 rng(s);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (double alpha : alphas)
        for (bool closed : {false, true})
            for (int rep = 0; rep < 10; ++rep) {
                auto p = random_polygon<3>(rng, 5 + std::size_t(rep % 4), 1.5);
                catmull_rom<3> c(p, {.alpha = alpha, .closed = closed});
                const double scale = scale_of(p);
                for (int i = 0; i < 20; ++i) {
                    // Random parameters, and the knots themselves.
                    const double t = i < 4 ? c.grid()[std::size_t(i) % c.grid().size()]
                                           : c.t_min() + U(rng) * (c.t_max() - c.t_min());
                    const auto q = c.evaluate(t);
                    const auto r = nearest(c, q);
                    // q is a rounded curve point: a few eps of the scale away.
                    EXPECT_LE(std::sqrt(r.distance_sq), 1e-14 * scale) << "alpha " << alpha << " t " << t;
                    // Near its own parameter the distance grows like
                    // speed * |dt|, so t comes back to (distance / speed);
                    // a crossing of the curve with itself exactly there has
                    // probability zero.
                    const double speed = norm(c.evaluate(t, 1));
                    EXPECT_LE(std::abs(r.t - t) * speed, 1e-9 * scale) << "t " << t << " found " << r.t;
                }
            }
}

TEST(Nearest, IndexGlobalAndBatchAgreeExactly) {
    CRSPLINE_SEEDED(s, 505);
    std::mt19937_64 rng(s);
    for (double alpha : alphas)
        for (bool closed : {false, true})
            for (int rep = 0; rep < 4; ++rep) {
                auto p = random_polygon<2>(rng, 30 + std::size_t(rep) * 40, 2.0);
                catmull_rom<2> c(p, {.alpha = alpha, .closed = closed});
                const auto q = queries_around(rng, c, scale_of(p), 20);
                const nearest_index<2> index(c);
                const auto batch = nearest(c, std::span<const vec<2>>(q));
                const auto index_batch = index.nearest(std::span<const vec<2>>(q));
                ASSERT_EQ(batch.size(), q.size());
                ASSERT_EQ(index_batch.size(), q.size());
                for (std::size_t j = 0; j < q.size(); ++j) {
                    // Same candidates, same total order (distance, t,
                    // segment): bit-identical answers.
                    const auto g = nearest(c, q[j]);
                    for (const auto& other : {index.nearest(q[j]), batch[j], index_batch[j]}) {
                        EXPECT_EQ(other.t, g.t);
                        EXPECT_EQ(other.distance_sq, g.distance_sq);
                        EXPECT_EQ(other.segment, g.segment);
                        EXPECT_EQ(other.point, g.point);
                    }
                }
            }
}

TEST(Nearest, SmallBatchesAgreeToo) {
    auto p = std::vector<vec<3>>{{{0, 0, 0}}, {{1, 2, 0}}, {{3, 1, 1}}, {{4, 4, 2}}};
    catmull_rom<3> c(p);
    const std::vector<vec<3>> q{{{1, 1, 1}}, {{-2, 0, 5}}, {{3, 3, 3}}};
    const auto r = nearest(c, std::span<const vec<3>>(q));  // below the index threshold
    ASSERT_EQ(r.size(), 3u);
    for (std::size_t j = 0; j < q.size(); ++j) {
        EXPECT_EQ(r[j].t, nearest(c, q[j]).t);
        EXPECT_EQ(r[j].distance_sq, nearest(c, q[j]).distance_sq);
    }
    EXPECT_TRUE(nearest(c, std::span<const vec<3>>()).empty());
    EXPECT_TRUE(nearest_index<3>(c).nearest(std::span<const vec<3>>()).empty());
}

TEST(Nearest, StraightLine) {
    // Equally spaced collinear points: every alpha gives uniform knots and
    // x(t) linear, so the nearest point is the foot of the perpendicular
    // (or an end) and the distance is known in closed form.
    const vec<2> dir{{0.6, 0.8}}, perp{{-0.8, 0.6}}, base{{2.0, -1.0}};
    std::vector<vec<2>> p;
    for (int i = 0; i <= 5; ++i) p.push_back(base + double(i) * dir);
    for (double alpha : alphas) {
        catmull_rom<2> c(p, {.alpha = alpha});
        for (int i = -10; i <= 60; ++i)
            for (double off : {-2.0, -0.5, 0.0, 1e-9, 3.0}) {
                const double along = double(i) / 10;
                const auto q = base + along * dir + off * perp;
                const auto r = nearest(c, q);
                const double a = std::clamp(along, 0.0, 5.0);
                const double want = std::hypot(along - a, off);
                // Coordinates of size ~7 and a handful of roundings: 64 eps.
                EXPECT_NEAR(std::sqrt(r.distance_sq), want, 64 * 2.2e-16 * 8);
                EXPECT_LE(norm(r.point - (base + a * dir)), 1e-7);  // distance is flat near the foot: sqrt(eps)
            }
    }
}

TEST(Nearest, ConstantCurveTiesGoToTheSmallestParameter) {
    for (double alpha : alphas)
        for (bool closed : {false, true}) {
            const vec<3> x{{1.5, -2.0, 4.0}};
            catmull_rom<3> c(std::vector<vec<3>>(4, x), {.alpha = alpha, .closed = closed});
            const nearest_index<3> index(c);
            for (const vec<3> q : {x, vec<3>{{0, 0, 0}}, vec<3>{{10, 10, -10}}}) {
                const auto r = nearest(c, q);
                // Every point of the curve is x: all candidates tie, and the
                // smallest t (then segment) wins.
                EXPECT_EQ(r.t, c.t_min());
                EXPECT_EQ(r.segment, 0u);
                EXPECT_EQ(r.point, x);
                EXPECT_EQ(r.distance_sq, dot(q - x, q - x));
                EXPECT_EQ(index.nearest(q).t, r.t);
                EXPECT_EQ(index.nearest(q).segment, r.segment);
            }
        }
}

TEST(Nearest, TenThousandSegmentsThroughTheIndex) {
    CRSPLINE_SEEDED(s, 506);
    std::mt19937_64 rng(s);
    for (bool closed : {false, true}) {
        auto p = random_polygon<3>(rng, 10000, 1.0);
        catmull_rom<3> c(p, {.alpha = 0.5, .closed = closed});
        const nearest_index<3> index(c);
        ASSERT_EQ(index.segment_count(), c.segment_count());
        const double scale = scale_of(p);
        const auto q = queries_around(rng, c, scale, 30);
        ASSERT_FALSE(q.empty());
        std::size_t solved = 0;
        for (const auto& x : q) {
            const auto found = index.search(x);
            solved += found.segments_solved;
            // Unpruned reference: the exact solver on every segment.
            nearest_result<3> best = detail::no_result<3, double>();
            for (std::size_t i = 0; i < c.segment_count(); ++i) {
                const auto r = detail::solve_segment(c.segments(), c.grid(), i, x);
                if (detail::better(r, best)) best = r;
            }
            EXPECT_EQ(found.result.t, best.t);
            EXPECT_EQ(found.result.distance_sq, best.distance_sq);
            EXPECT_EQ(found.result.segment, best.segment);
        }
        // Counts, not timing: the index solves a few dozen segments per
        // query, not 10^4 (a random walk packs many segments near most
        // queries, hence the generous bound).
        EXPECT_LT(solved / q.size(), 200u) << "segments solved per query";
    }
}

TEST(Nearest, NonFiniteQueriesAreRejectedWithTheirIndex) {
    catmull_rom<2> c({vec<2>{{0, 0}}, {{1, 0}}, {{1, 1}}});
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    EXPECT_THROW(nearest(c, vec<2>{{nan, 0}}), invalid_input);
    EXPECT_THROW(nearest_index<2>(c).nearest(vec<2>{{0, inf}}), invalid_input);
    std::vector<vec<2>> q(6, vec<2>{{0.5, 0.5}});
    q[4][1] = -inf;
    for (int form = 0; form < 2; ++form) {
        try {
            if (form == 0) nearest(c, std::span<const vec<2>>(q));
            else nearest_index<2>(c).nearest(std::span<const vec<2>>(q));
            ADD_FAILURE() << "no exception";
        } catch (const invalid_input& e) {
            EXPECT_NE(std::string(e.what()).find("query 4 coordinate 1"), std::string::npos) << e.what();
        }
    }
}

TEST(Nearest, SegmentSolverFindsInteriorMinimaAndEnds) {
    // A parabola as one Hermite segment: closed-form nearest points.
    const auto s = cubic_segment<2>::hermite(vec<2>{{-1, 1}}, vec<2>{{1, 1}}, vec<2>{{2, -4}}, vec<2>{{2, 4}}, 0, 1);
    // That is x = -1 + 2u, y = (2u - 1)^2: the parabola y = x^2 on [-1, 1].
    EXPECT_NEAR(s.at(0.25)[1], 0.25, 1e-15);
    // Query (0, 1): d^2 = x^2 + (x^2 - 1)^2 is least at x^2 = 1/2 (two
    // symmetric interior minima, d^2 = 3/4), not at the vertex or the ends.
    const auto top = nearest(s, vec<2>{{0, 1}});
    EXPECT_NEAR(top.distance_sq, 0.75, 1e-15);
    EXPECT_NEAR(std::abs(2 * top.u - 1), std::sqrt(0.5), 1e-12);
    // Query (0, -1): the vertex x = 0, u = 1/2.
    const auto below = nearest(s, vec<2>{{0, -1}});
    EXPECT_NEAR(below.u, 0.5, 1e-12);
    EXPECT_NEAR(below.distance_sq, 1.0, 1e-15);
    // Query (0, 2): both ends (x = -1, 1) at d^2 = 2 beat the interior; the
    // ends tie by symmetry (if rounding keeps them equal, u = 0 wins).
    const auto high = nearest(s, vec<2>{{0, 2}});
    EXPECT_NEAR(high.distance_sq, 2.0, 1e-14);
    EXPECT_TRUE(high.u == 0.0 || high.u == 1.0) << high.u;
    const auto side = nearest(s, vec<2>{{5, 1}});
    EXPECT_EQ(side.u, 1.0);
}

}  // namespace
