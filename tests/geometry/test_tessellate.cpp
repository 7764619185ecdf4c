// Tessellation: dense sampling proves the tolerance piece by piece, vertex
// counts stay within a small factor of a brute-force minimum, closed curves
// close, straight lines take one piece per segment. Seeded; counts asserted.
#include "test_support.hpp"

#include <crspline/tessellate.hpp>

#include <cstdio>

namespace {
using namespace crspline;
using crspline::test::random_polygon;
using crspline::test::alphas;

// Distance from p to the segment [a, b], in double.
template <std::size_t D, class T>
double to_segment(const vec<D, T>& p, const vec<D, T>& a, const vec<D, T>& b) {
    vec<D, double> x, d;
    for (std::size_t k = 0; k < D; ++k) {
        x[k] = double(p[k]) - double(a[k]);
        d[k] = double(b[k]) - double(a[k]);
    }
    const double len2 = dot(d, d);
    const double f = len2 > 0 ? std::clamp(dot(x, d) / len2, 0.0, 1.0) : 0.0;
    return norm(x - f * d);
}

// Largest distance from the curve on [ta, tb] (m - 1 interior samples,
// evenly spaced in t) to the chord from pa to pb.
template <std::size_t D, class T>
double sampled_error(const catmull_rom<D, T>& c, T ta, T tb, const vec<D, T>& pa, const vec<D, T>& pb,
                     int m = 96) {
    double worst = 0;
    for (int j = 1; j < m; ++j) {
        const T t = ta + (tb - ta) * (T(j) / T(m));
        worst = std::max(worst, to_segment(c.evaluate_unchecked(t), pa, pb));
    }
    return worst;
}

// Largest coordinate and the curve's size: rounding is relative to both.
template <std::size_t D, class T>
double magnitude_of(const catmull_rom<D, T>& c) {
    const crspline::box<D, T> b = bounding_box(c);
    return double(b.diagonal()) + double(std::max(max_abs(b.lo), max_abs(b.hi)));
}

struct tally {
    std::size_t curves = 0, pieces = 0, vertices = 0;
    double worst_use = 0;  // max over pieces of sampled error / tolerance
};

// Everything tessellate() promises, on one curve at one tolerance.
template <std::size_t D, class T>
void check_tessellation(const catmull_rom<D, T>& c, T tol, tally& n) {
    const polyline<D, T> pl = tessellate(c, tol);
    const auto& t = pl.t;
    const auto& x = pl.points;
    ASSERT_EQ(x.size(), t.size());
    ASSERT_GE(x.size(), 2u);
    // 1. Ends exact; a closed curve closes.
    EXPECT_EQ(t.front(), c.t_min());
    EXPECT_EQ(t.back(), c.t_max());
    EXPECT_EQ(x.front(), c.points().front());
    EXPECT_EQ(x.back(), c.closed() ? c.points().front() : c.points().back());
    if (c.closed()) {
        EXPECT_EQ(x.front(), x.back());
    }
    // 2. Vertices on the curve exactly, parameters increasing, every knot a vertex.
    for (std::size_t k = 0; k < x.size(); ++k) {
        EXPECT_EQ(x[k], c.evaluate(t[k])) << "vertex " << k;
        if (k > 0) {
            EXPECT_LT(t[k - 1], t[k]) << "vertex " << k;
        }
    }
    for (T knot : c.grid()) EXPECT_TRUE(std::binary_search(t.begin(), t.end(), knot)) << "knot " << knot;
    // 3. Within tolerance on every piece, by 96 samples; rounding: the
    //    samples and the bound are computed in T, a few eps of the coordinates.
    const double slack = double(tol) * 1e-9 + 16 * double(std::numeric_limits<T>::epsilon()) * magnitude_of(c);
    for (std::size_t k = 0; k + 1 < x.size(); ++k) {
        const double err = sampled_error(c, t[k], t[k + 1], x[k], x[k + 1]);
        EXPECT_LE(err, double(tol) + slack) << "piece " << k << " on [" << t[k] << ", " << t[k + 1] << "]";
        n.worst_use = std::max(n.worst_use, err / double(tol));
        ++n.pieces;
    }
    // 4. Never more pieces per segment than the closed-form uniform count.
    const auto grid = c.grid();
    for (std::size_t i = 0; i < c.segment_count(); ++i) {
        const auto first = std::lower_bound(t.begin(), t.end(), grid[i]);
        const auto last = std::lower_bound(t.begin(), t.end(), grid[i + 1]);
        EXPECT_LE(std::size_t(last - first), uniform_piece_count(c.segment(i), tol)) << "segment " << i;
    }
    n.vertices += x.size();
    ++n.curves;
}

template <std::size_t D, class T>
tally random_tessellations(std::mt19937_64& rng, std::initializer_list<double> relative, int reps) {
    tally n;
    for (double rel : relative)
        for (double alpha : alphas)
            for (bool closed : {false, true})
                for (int rep = 0; rep < reps; ++rep) {
                    const auto p = random_polygon<D, T>(rng, 3 + std::size_t(rep) % 5, 2.0, rep % 3 == 2 ? 50.0 : 0.0);
                    const catmull_rom<D, T> c(p, {.alpha = alpha, .closed = closed});
                    check_tessellation(c, T(rel * double(bounding_box(c).diagonal())), n);
                }
    return n;
}

TEST(Tessellate, WithinToleranceOnRandomCurvesDouble) {
    CRSPLINE_SEEDED(s, 401);
    std::mt19937_64 rng(s);
    const auto rel = {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
    const tally n2 = random_tessellations<2, double>(rng, rel, 4);
    const tally n3 = random_tessellations<3, double>(rng, rel, 2);
    EXPECT_EQ(n2.curves, 8u * 5 * 2 * 4);
    EXPECT_EQ(n3.curves, 8u * 5 * 2 * 2);
    EXPECT_GE(n2.pieces + n3.pieces, 100000u);
    // The bound is not loose: some piece uses most of its tolerance.
    const double use = std::max(n2.worst_use, n3.worst_use);
    std::printf("[ tessellate ] double: %zu pieces checked, largest error / tolerance %.3f\n", n2.pieces + n3.pieces, use);
    EXPECT_GT(use, 0.5);
}

TEST(Tessellate, WithinToleranceOnRandomCurvesFloat) {
    CRSPLINE_SEEDED(s, 402);
    std::mt19937_64 rng(s);
    const tally n2 = random_tessellations<2, float>(rng, {1e-1, 1e-2, 1e-3, 1e-4}, 4);
    const tally n3 = random_tessellations<3, float>(rng, {1e-1, 1e-2, 1e-3, 1e-4}, 2);
    EXPECT_EQ(n2.curves + n3.curves, 4u * 5 * 2 * 6);
    EXPECT_GE(n2.pieces + n3.pieces, 5000u);
    std::printf("[ tessellate ] float: %zu pieces checked, largest error / tolerance %.3f\n", n2.pieces + n3.pieces,
                std::max(n2.worst_use, n3.worst_use));
}

// Brute-force minimum: from each vertex the farthest parameter whose chord
// stays within tolerance by dense sampling (exponential search, then
// bisection to 1e-3 of the piece). Pieces end at knots when `at_knots`;
// otherwise they may run across knots (the minimum for the tolerance itself).
template <std::size_t D>
std::size_t greedy_pieces(const catmull_rom<D>& c, double tol, bool at_knots) {
    std::vector<double> stops;
    if (at_knots) stops.assign(c.grid().begin() + 1, c.grid().end());
    else stops = {c.t_max()};
    std::size_t pieces = 0;
    double a = c.t_min(), guess = (c.t_max() - c.t_min()) / 64;
    for (double end : stops) {
        while (a < end) {
            const vec<D> pa = c.evaluate(a);
            auto ok = [&](double b) { return sampled_error(c, a, b, pa, c.evaluate(b), 64) <= tol; };
            double b;
            if (ok(end)) {
                b = end;
            } else {
                double lo = a, hi = std::min(end, a + guess);
                while (ok(hi)) { lo = hi; hi = std::min(end, a + 2 * (hi - a)); }
                if (lo == a) {
                    while (!ok(lo = a + (hi - a) / 2) && lo > a) hi = lo;
                    if (lo == a) lo = hi;  // no representable piece is within tolerance
                }
                while (hi - lo > 1e-3 * (lo - a)) {
                    const double mid = lo + (hi - lo) / 2;
                    (ok(mid) ? lo : hi) = mid;
                }
                b = lo;
            }
            guess = b - a;
            a = b;
            ++pieces;
        }
    }
    return pieces;
}

TEST(Tessellate, VertexCountNearTheMinimum) {
    // Ours against the brute-force minimum with knots kept as vertices (as
    // ours are): at most 2.5 times. Against the minimum that may cut across
    // knots, also at most 2.5 times once segments need several pieces
    // (tolerance <= 1e-4); coarser, ours pays one vertex per knot.
    CRSPLINE_SEEDED(s, 403);
    std::mt19937_64 rng(s);
    double worst_at_knots = 0, worst_free = 0, worst_free_fine = 0, sum_at_knots = 0;
    std::size_t compared = 0;
    for (double rel : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8})
        for (double alpha : alphas)
            for (bool closed : {false, true})
                for (int rep = 0; rep < (rel < 1e-5 ? 1 : 2); ++rep) {
                    if (rel < 1e-6 && closed) continue;  // the brute force is slow there
                    const auto p = random_polygon<2>(rng, 4 + std::size_t(rep) % 3, 2.0);
                    const catmull_rom<2> c(p, {.alpha = alpha, .closed = closed});
                    const double tol = rel * bounding_box(c).diagonal();
                    const double ours = double(tessellate(c, tol).points.size() - 1);
                    const double at_knots = double(greedy_pieces(c, tol, true));
                    const double free = double(greedy_pieces(c, tol, false));
                    EXPECT_LE(ours, 2.5 * at_knots) << "tolerance " << rel << " alpha " << alpha << " closed " << closed;
                    if (rel <= 1e-4) {
                        EXPECT_LE(ours, 2.5 * free) << "tolerance " << rel << " alpha " << alpha << " closed " << closed;
                        worst_free_fine = std::max(worst_free_fine, ours / free);
                    }
                    worst_at_knots = std::max(worst_at_knots, ours / at_knots);
                    worst_free = std::max(worst_free, ours / free);
                    sum_at_knots += ours / at_knots;
                    ++compared;
                }
    EXPECT_EQ(compared, (5u * 2 * 2 + 1u * 2 * 1 + 2u * 1 * 1) * 5);
    std::printf("[ tessellate ] pieces / greedy minimum with knots as vertices: max %.3f, mean %.3f; "
                "/ greedy minimum across knots: max %.3f (tolerance <= 1e-4: %.3f)\n",
                worst_at_knots, sum_at_knots / double(compared), worst_free, worst_free_fine);
}

TEST(Tessellate, FlatnessBoundHoldsOnRandomPieces) {
    CRSPLINE_SEEDED(s, 404);
    std::mt19937_64 rng(s);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    std::size_t checked = 0;
    double tightest = 0;
    for (double alpha : alphas)
        for (int rep = 0; rep < 40; ++rep) {
            const auto p = random_polygon<3>(rng, 5, 3.0);
            const catmull_rom<3> c(p, {.alpha = alpha});
            for (const auto& seg : c.segments()) {
                double u0 = U(rng), u1 = U(rng);
                if (u0 > u1) std::swap(u0, u1);
                if (rep % 4 == 0) u0 = 0, u1 = 1;
                const double bound = flatness_bound(seg, u0, u1);
                const vec<3> a = seg.at(u0), b = seg.at(u1);
                double worst = 0;
                for (int j = 1; j < 256; ++j) worst = std::max(worst, to_segment(seg.at(u0 + (u1 - u0) * j / 256.0), a, b));
                const double size = max_abs(seg.origin) + max_abs(seg.c1) + max_abs(seg.c2) + max_abs(seg.c3);
                EXPECT_LE(worst, bound + 16 * std::numeric_limits<double>::epsilon() * size);
                if (bound > 0) tightest = std::max(tightest, worst / bound);
                ++checked;
            }
        }
    EXPECT_EQ(checked, 5u * 40 * 4);
    // The bound is attained closely on some pieces (parabola-like ones).
    EXPECT_GT(tightest, 0.9);
}

TEST(Tessellate, StraightLineIsOnePiecePerSegment) {
    for (double alpha : alphas)
        for (double rel : {1e-2, 1e-6, 1e-10}) {
            std::vector<vec<2>> p;
            for (int i = 0; i < 7; ++i) p.push_back({{-3.0 + 1.5 * i, 2.0 + 0.5 * i}});
            const catmull_rom<2> c(p, {.alpha = alpha});
            const polyline<2> pl = tessellate(c, rel * bounding_box(c).diagonal());
            ASSERT_EQ(pl.points.size(), p.size());
            for (std::size_t k = 0; k < p.size(); ++k) {
                EXPECT_EQ(pl.points[k], p[k]);
                EXPECT_EQ(pl.t[k], c.grid()[k]);
            }
        }
}

TEST(Tessellate, ClosedCurvesCloseAndConstantSegmentsAddNoVertex) {
    // A closed square: first == last exactly, every corner once.
    const std::vector<vec<2>> square = {{{0.0, 0.0}}, {{1.0, 0.0}}, {{1.0, 1.0}}, {{0.0, 1.0}}};
    for (double alpha : alphas) {
        const catmull_rom<2> c(square, {.alpha = alpha, .closed = true});
        const polyline<2> pl = tessellate(c, 1e-4);
        EXPECT_EQ(pl.points.front(), pl.points.back());
        EXPECT_EQ(pl.t.back(), c.t_max());
        for (const auto& q : square)
            EXPECT_EQ(std::count(pl.points.begin(), pl.points.end() - 1, q), 1);
    }
    // Repeated points (alpha > 0): constant segments, no duplicate vertex,
    // including a repeated last point.
    const std::vector<vec<2>> dup = {{{0.0, 0.0}}, {{0.0, 0.0}}, {{1.0, 2.0}}, {{1.0, 2.0}}, {{3.0, -1.0}}, {{3.0, -1.0}}};
    for (double alpha : {0.25, 0.5, 1.0}) {
        const catmull_rom<2> c(dup, {.alpha = alpha});
        tally n;
        check_tessellation(c, 1e-3, n);
        const polyline<2> pl = tessellate(c, 1e-3);
        for (std::size_t k = 1; k < pl.points.size(); ++k) EXPECT_NE(pl.points[k - 1], pl.points[k]) << k;
    }
    // A single repeated point: its two ends.
    for (bool closed : {false, true}) {
        const catmull_rom<2> c(std::vector<vec<2>>(4, vec<2>{{2.0, -1.0}}), {.alpha = 0.5, .closed = closed});
        const polyline<2> pl = tessellate(c);
        ASSERT_EQ(pl.points.size(), 2u);
        EXPECT_EQ(pl.points[0], pl.points[1]);
        EXPECT_EQ(pl.t.front(), c.t_min());
        EXPECT_EQ(pl.t.back(), c.t_max());
    }
}

TEST(Tessellate, DefaultToleranceIsRelativeToTheBox) {
    CRSPLINE_SEEDED(s, 405);
    std::mt19937_64 rng(s);
    for (int rep = 0; rep < 10; ++rep) {
        const catmull_rom<2> c(random_polygon<2>(rng, 6, 2.0));
        const double tol = default_tessellation_tolerance * bounding_box(c).diagonal();
        EXPECT_EQ(tessellation_tolerance(c), tol);
        const polyline<2> a = tessellate(c), b = tessellate(c, tol);
        EXPECT_EQ(a.t, b.t);
        EXPECT_EQ(a.points, b.points);
    }
    // A float curve takes a float tolerance (no second template deduction).
    const catmull_rom<2, float> f({vec<2, float>{{0.f, 0.f}}, vec<2, float>{{1.f, 1.f}}, vec<2, float>{{2.f, 0.f}}});
    EXPECT_GE(tessellate(f, 1e-3f).points.size(), 3u);
}

TEST(Tessellate, RejectsBadTolerances) {
    const catmull_rom<2> c({vec<2>{{0.0, 0.0}}, vec<2>{{1.0, 1.0}}, vec<2>{{2.0, 0.0}}});
    for (double bad : {0.0, -1e-3, std::nan(""), std::numeric_limits<double>::infinity()}) {
        try {
            (void)tessellate(c, bad);
            ADD_FAILURE() << "accepted tolerance " << bad;
        } catch (const invalid_input& e) {
            EXPECT_NE(std::string(e.what()).find(detail::num(bad)), std::string::npos) << e.what();
        }
    }
}

TEST(SampleT, EvenlySpacedWithExactEnds) {
    CRSPLINE_SEEDED(s, 406);
    std::mt19937_64 rng(s);
    std::size_t checked = 0;
    for (bool closed : {false, true})
        for (std::size_t n : {2u, 3u, 10u, 101u}) {
            const auto p = random_polygon<3>(rng, 5, 2.0);
            const catmull_rom<3> c(p, {.alpha = 0.5, .closed = closed});
            const auto x = sample_t(c, n);
            ASSERT_EQ(x.size(), n);
            EXPECT_EQ(x.front(), p.front());
            EXPECT_EQ(x.back(), closed ? p.front() : p.back());
            for (std::size_t k = 0; k + 1 < n; ++k) {
                const double t = c.t_min() + (c.t_max() - c.t_min()) * (double(k) / double(n - 1));
                EXPECT_EQ(x[k], c.evaluate(t)) << k;
                ++checked;
            }
        }
    EXPECT_EQ(checked, 2u * (1 + 2 + 9 + 100));
    for (std::size_t bad : {0u, 1u}) EXPECT_THROW((void)sample_t(catmull_rom<2>({vec<2>{}, vec<2>{{1.0, 1.0}}}), bad), invalid_input);
}

}  // namespace
