// The transversal shortcut of the per-pair intersection search
// (detail::segment_pair_meetings, issue 26 point 4): a cell whose pieces
// are nearly straight and at an angle meets at most once, so one polish
// closes it instead of a subdivision down to the tolerance. Checked here:
// it costs a few sub-pair visits where the subdivision needs well over a
// hundred, and through the seam (pair_workspace::shortcut) the search finds
// the same meetings with it and without it, on seeded random curves in
// 2-D and 3-D with many crossings, near misses and adjacent pairs.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <crspline/detail/box_tree.hpp>
#include <crspline/intersections.hpp>

#include "test_support.hpp"

namespace {
using namespace crspline;

// How two segments of an open curve touch by construction.
detail::pair_joint joint_of(std::size_t i, std::size_t j) {
    return j == i + 1 ? detail::pair_joint::next : detail::pair_joint::none;
}

// The crossing angle of segments A at u and B at v, as its sine.
double crossing_sine(const cubic_segment<2>& A, double u, const cubic_segment<2>& B, double v) {
    const auto ta = A.du(u, 1), tb = B.du(v, 1);
    return std::abs(ta[0] * tb[1] - ta[1] * tb[0]) / (norm(ta) * norm(tb));
}

TEST(PairShortcut, TransversalCrossingTakesFewVisits) {
    // Crossings of non-adjacent segments of random 2-D curves at more than
    // 10 degrees, each pair searched with a budget of 120 sub-pair visits.
    // Subdividing to the tolerance (1e-9 of the curve's size) splits each
    // piece about 30 times, every split a visit of both halves: before the
    // shortcut a pair took 141 visits at the least (median about 270, over
    // seeds 1-6 and this one), so the budget ran out (complete = false).
    // With it, a pair takes 15 at the median and 87 at the most over seeds
    // 1-40.
    CRSPLINE_SEEDED(seed, 2602);
    std::mt19937_64 rng(seed);
    std::size_t checked = 0;
    for (int round = 0; round < 20; ++round) {
        const auto p = test::random_polygon<2>(rng, 40, 1.0);
        const catmull_rom<2> c(p);
        const double tol = default_intersection_tolerance * test::scale_of(p);
        const auto all = find_intersections(c).intersections;
        for (const auto& x : all) {
            const auto [i, j] = x.segments;
            if (j <= i + 1) continue;
            const auto &A = c.segment(i), &B = c.segment(j);
            if (crossing_sine(A, x.u[0], B, x.u[1]) < std::sin(10 * std::numbers::pi / 180)) continue;
            bool complete = true;
            const auto found = detail::segment_pair_meetings(A, B, detail::pair_joint::none, tol, complete, 120);
            ASSERT_TRUE(complete) << "segments " << i << ", " << j;
            // The pair's meetings as the whole search found them (a pair may
            // cross more than once).
            std::size_t expected = 0;
            for (const auto& y : all) expected += y.segments == x.segments;
            EXPECT_EQ(found.size(), expected) << "segments " << i << ", " << j;
            ++checked;
        }
    }
    // Random 40-point walks cross themselves often: enough pairs to mean
    // something (245 at the default seed).
    EXPECT_GE(checked, 150u);
}

// Every candidate pair of c (boxes meeting, as the whole-curve search has
// them) searched with and without the shortcut: the same meetings, pair by
// pair. Returns {meetings compared, cells the shortcut closed}.
template <std::size_t D>
std::array<std::size_t, 2> compare_with_and_without(const catmull_rom<D>& c, double tol, double scale) {
    const std::size_t n = c.segment_count();
    std::vector<detail::box<D, double>> boxes(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto bx = detail::box_of(c.bezier(i));
        boxes[i] = {bx[0], bx[1]};
    }
    const auto rows = detail::tree_pairs{}(boxes, tol);
    detail::pair_workspace<D, double> with, without;
    without.shortcut = false;
    std::size_t compared = 0;
    for (std::size_t i = 0; i < n; ++i)
        for (const std::size_t j : rows.row(i)) {
            const auto &A = c.segment(i), &B = c.segment(j);
            bool complete_with = true, complete_without = true;
            detail::segment_pair_meetings(A, B, joint_of(i, j), tol, complete_with, with);
            detail::segment_pair_meetings(A, B, joint_of(i, j), tol, complete_without, without);
            EXPECT_EQ(complete_with, complete_without) << "segments " << i << ", " << j;
            if (!complete_without) continue;
            auto a = with.found, b = without.found;
            const auto by_u = [](const auto& x, const auto& y) { return x[0] < y[0]; };
            std::sort(a.begin(), a.end(), by_u);
            std::sort(b.begin(), b.end(), by_u);
            EXPECT_EQ(a.size(), b.size()) << "segments " << i << ", " << j;
            if (a.size() != b.size()) continue;
            for (std::size_t k = 0; k < a.size(); ++k) {
                EXPECT_LE(a[k][2], tol) << "segments " << i << ", " << j;
                // The same meeting: where a crossing is, is known to the
                // rounding of the coordinates over the sine of the crossing
                // angle (the residual is flat along each curve by that
                // factor); 64 eps scale allows for the polish stopping
                // anywhere within that. A near miss (3-D) or a tangential
                // touch is a flat minimum of the distance, known only to
                // about the square root of tol times the curve's size.
                const auto pa = A.at(a[k][0]), pb = A.at(b[k][0]);
                double allowed = std::sqrt(tol * scale);
                if constexpr (D == 2) {
                    const double s = crossing_sine(A, b[k][0], B, b[k][1]);
                    constexpr double eps = std::numeric_limits<double>::epsilon();
                    if (b[k][2] <= 64 * eps * scale && s > 1e-3) allowed = 64 * eps * scale / s;
                }
                EXPECT_LE(norm(pa - pb), allowed) << "segments " << i << ", " << j << " meeting " << k;
                ++compared;
            }
        }
    EXPECT_EQ(without.shortcuts, 0u);
    return {compared, with.shortcuts};
}

TEST(PairShortcut, SameMeetingsWithAndWithout2D) {
    CRSPLINE_SEEDED(seed, 2604);
    std::mt19937_64 rng(seed);
    std::size_t compared = 0, shortcuts = 0;
    for (int round = 0; round < 20; ++round) {
        // Uneven steps over two decades (shallow and steep crossings,
        // sharp turns) and, every third curve, far from the origin.
        const auto p = test::random_polygon<2>(rng, 60, 2.0, round % 3 == 2 ? 1e5 : 0.0);
        const catmull_rom<2> c(p);
        const double scale = test::scale_of(p);
        const auto r = compare_with_and_without(c, default_intersection_tolerance * scale, scale);
        compared += r[0], shortcuts += r[1];
    }
    // Many meetings compared, most closed by the shortcut (417 and 417 at
    // the default seed).
    EXPECT_GE(compared, 300u);
    EXPECT_GE(shortcuts, 300u);
}

TEST(PairShortcut, SameMeetingsWithAndWithout3D) {
    // Flattened 3-D walks: closest approaches within a loose tolerance
    // (1e-3 of the size) as well as the skew pairs that never come close.
    CRSPLINE_SEEDED(seed, 2603);
    std::mt19937_64 rng(seed);
    std::size_t compared = 0, shortcuts = 0;
    for (int round = 0; round < 20; ++round) {
        auto p = test::random_polygon<3>(rng, 60, 1.0);
        for (auto& q : p) q[2] *= 1e-3;
        const catmull_rom<3> c(p);
        const double scale = test::scale_of(p);
        const auto r = compare_with_and_without(c, 1e-3 * scale, scale);
        compared += r[0], shortcuts += r[1];
    }
    // 572 and 467 at the default seed.
    EXPECT_GE(compared, 400u);
    EXPECT_GE(shortcuts, 300u);
}

}  // namespace
