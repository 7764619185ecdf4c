// find_intersections on collinear overlaps: one interval per pair of
// segments (intersection_result::overlaps) instead of hundreds of point
// meetings along it (820 on the curve below before the merge), and no
// overlaps where curves only cross.
#include <cstdio>

#include <crspline/intersections.hpp>

#include "test_support.hpp"

namespace {
using namespace crspline;
using P = vec<2, double>;

// Along the x axis from 0 to 4, a detour up to (5, 3), and back along the
// axis from 3.5 to 0.5. A segment whose four points are collinear is a
// straight piece of the axis: segments 1 (1 -> 2) and 2 (2 -> 3) on the way
// out, segment 7 (2.5 -> 1.5) on the way back, which covers the second half
// of segment 1 and the first half of segment 2.
const std::vector<P> retrace = {{{0, 0}}, {{1, 0}}, {{2, 0}}, {{3, 0}}, {{4, 0}}, {{5, 3}},
                                {{3.5, 0}}, {{2.5, 0}}, {{1.5, 0}}, {{0.5, 0}}, {{-0.5, -1}}};

TEST(Overlaps, RetracedAxisIsOneIntervalPerPair) {
    const catmull_rom<2, double> c{std::span<const P>(retrace)};
    const auto r = find_intersections(c);
    ASSERT_EQ(r.overlaps.size(), 2u);
    // The tolerance: default_intersection_tolerance times the Bezier box's
    // diagonal; the interval ends are where the other segment leaves it,
    // so they are exact up to that distance over the speed (about 1 here).
    const double tol = default_intersection_tolerance * 7.0, slack = 2 * tol;
    const auto& a = r.overlaps[0];
    EXPECT_EQ(a.segments, (std::array<std::size_t, 2>{1, 7}));
    EXPECT_NEAR(a.u[0], 0.5, slack);
    EXPECT_EQ(a.u[1], 1.0);
    EXPECT_EQ(a.v[0], 1.0);  // u runs 2 -> 1.5 while v runs 1.5 <- 2: opposite directions
    EXPECT_NEAR(a.v[1], 0.5, slack);
    const auto& b = r.overlaps[1];
    EXPECT_EQ(b.segments, (std::array<std::size_t, 2>{2, 7}));
    EXPECT_EQ(b.u[0], 0.0);
    EXPECT_NEAR(b.u[1], 0.5, slack);
    EXPECT_NEAR(b.v[0], 0.5, slack);
    EXPECT_EQ(b.v[1], 0.0);
    // Every point of each interval, on either segment, is on the shared
    // stretch of the axis, x in [1.5, 2.5] (to the tolerance at the ends).
    for (const auto& o : r.overlaps)
        for (int k = 0; k <= 64; ++k) {
            const double s = k / 64.0;
            for (const P p : {c.segment(o.segments[0]).at(o.u[0] + s * (o.u[1] - o.u[0])),
                              c.segment(o.segments[1]).at(o.v[0] + s * (o.v[1] - o.v[0]))}) {
                EXPECT_LE(std::abs(p[1]), 1e-15) << "overlap " << o.segments[0] << "," << o.segments[1] << " at " << s;
                EXPECT_GE(p[0], 1.5 - slack);
                EXPECT_LE(p[0], 2.5 + slack);
            }
        }
    // No point meeting is left between the overlapping pairs; the others are
    // the true touches where the curved segments reach the axis (5 of them).
    std::size_t points = 0;
    for (const auto& x : r.intersections) {
        EXPECT_FALSE(x.segments[1] == 7 && (x.segments[0] == 1 || x.segments[0] == 2)) << x.u[0] << " " << x.u[1];
        ++points;
    }
    EXPECT_LE(points, 8u);
    EXPECT_TRUE(r.any());
}

TEST(Overlaps, CrossingCurvesHaveNone) {
    CRSPLINE_SEEDED(s, 20261124);
    std::mt19937_64 rng(s);
    std::size_t crossings = 0;
    for (int k = 0; k < 40; ++k) {
        const auto pts = test::random_polygon<2>(rng, 30, 1.0);
        const catmull_rom<2, double> c{std::span<const P>(pts)};
        const auto r = find_intersections(c);
        EXPECT_TRUE(r.overlaps.empty()) << "curve " << k;
        crossings += r.intersections.size();
    }
    // Random walks of 30 points cross themselves: the check above was not vacuous.
    EXPECT_GT(crossings, 40u);
}

}  // namespace
