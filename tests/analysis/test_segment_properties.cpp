// The paper's per-segment claims as seeded properties on at least 10^5
// random segments: chord ratios d1/d2, d3/d2 from 1e-6 to 1e6, polygon angles
// anywhere in [0, pi] and within 1e-9 of 0 and pi (exactly 0 and pi too),
// random orientation, scale and offset.
//
// CRSPLINE_PROPERTY_SCALE (default 1) multiplies the segment count; the count
// is asserted to be >= 10^5 at scale >= 1, and a smaller scale says so.
#include <chrono>
#include <cstdlib>

#include <crspline/analysis.hpp>

#include "test_support.hpp"

namespace {
using namespace crspline;
using P2 = vec<2>;
using crspline::test::eps;
using crspline::test::pi;

// CRSPLINE_PROPERTY_SCALE (default 1: the full run) multiplies the random
// case counts. Below 1 the minimum-count checks are off, and the run says so
// on stderr: a reduced run must never pass for a full one.
using test::property_scale;

// A random angle: uniform, or within 1e-9 of 0 or pi (log-uniform offset,
// sometimes exactly 0 / pi).
double random_angle(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> U(0.0, 1.0);
    const double kind = U(rng);
    if (kind < 0.5) return pi * U(rng);
    const double off = U(rng) < 0.1 ? 0.0 : std::pow(10.0, -9.0 - 6.0 * U(rng));
    return kind < 0.75 ? off : pi - off;
}

// Segment P0..P3 with given chord ratios and polygon angles theta1 (at P1)
// and theta2 (at P2), rotated, scaled and offset at random.
std::array<P2, 4> random_segment(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> U(0.0, 1.0);
    const double d2 = std::pow(10.0, -3.0 + 6.0 * U(rng));
    const double r1 = std::pow(10.0, -6.0 + 12.0 * U(rng)), r3 = std::pow(10.0, -6.0 + 12.0 * U(rng));
    const double t1 = random_angle(rng), t2 = random_angle(rng);
    const double side = U(rng) < 0.5 ? 1.0 : -1.0;
    // Local frame: P1 at 0, P2 on +x.
    std::array<P2, 4> q{P2{{r1 * d2 * std::cos(t1), r1 * d2 * std::sin(t1)}}, P2{{0, 0}}, P2{{d2, 0}},
                        P2{{d2 - r3 * d2 * std::cos(t2), side * r3 * d2 * std::sin(t2)}}};
    const double phi = 2 * pi * U(rng), c = std::cos(phi), s = std::sin(phi);
    const P2 off{{(U(rng) - 0.5) * 10 * d2, (U(rng) - 0.5) * 10 * d2}};
    std::array<P2, 4> p;
    for (std::size_t k = 0; k < 4; ++k) p[k] = P2{{c * q[k][0] - s * q[k][1], s * q[k][0] + c * q[k][1]}} + off;
    return p;
}

std::size_t segment_count() { return std::size_t(100000 * property_scale()); }

// Centripetal: no cusp, no loop, Theorem 3 (B1, B2 project into [0, 1]),
// and the curve stays over its chord (no overshoot, so the distance to the
// chord segment is the distance to the chord line).
TEST(SegmentProperties, CentripetalNeverCuspsOrLoops) {
    CRSPLINE_SEEDED(seed, 2011);
    std::mt19937_64 rng(seed);
    const std::size_t n = segment_count();
    std::size_t checked = 0, near_degenerate = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < n; ++i) {
        const auto p = random_segment(rng);
        const auto a = analyze_segment(p, centripetal);
        ASSERT_FALSE(a.has_cusp()) << "segment " << i << " cusp at " << a.cusp_u[0];
        ASSERT_FALSE(a.has_self_intersection()) << "segment " << i;
        ASSERT_TRUE(a.projection.has_value());
        // Theorem 3: projections in [0, 1] (0 exactly when theta = 0), up to
        // rounding of the Bézier points relative to the chord.
        const double slack = 64 * eps;
        for (double b : a.projection->bezier) {
            EXPECT_GE(b, -slack) << "segment " << i;
            EXPECT_LE(b, 1 + slack) << "segment " << i;
        }
        EXPECT_GE(a.projection->range[0], -slack);
        EXPECT_LE(a.projection->range[1], 1 + slack);
        if (!a.projection->theorem2) {
            ++near_degenerate;
        }
        ++checked;
    }
    const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / double(n);
    std::printf("centripetal: %zu segments, %zu on Theorem 2's boundary, %.2f us per segment\n", checked, near_degenerate, us);
    if (property_scale() >= 1) {
        EXPECT_GE(checked, 100000u);
    }
}


// Do two closed 2-D segments [a, b] and [c, d] cross (proper crossing)?
bool crosses(const P2& a, const P2& b, const P2& c, const P2& d) {
    auto orient = [](const P2& p, const P2& q, const P2& r) {
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    };
    const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
    return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

// The bounds bracket the measured distances, for every alpha:
//   measured B1, B2 heights = Eq. 5;  max distance to the chord line <=
//   3/4 max(heights) <= Eq. 6 two-sided;  the printed one-sided Eq. 6 is
//   exceeded on some segments;  where B1 projects behind B0, |B1 - B0| <=
//   Eq. 8 (alpha >= 1/2, where the paper derives it);  centripetal never
//   overshoots the chord.
// And the detector finds cusps, loops or folds for every alpha but 1/2.
TEST(SegmentProperties, BoundsBracketTheMeasuredDistances) {
    CRSPLINE_SEEDED(seed, 2012);
    std::mt19937_64 rng(seed);
    const std::size_t n = segment_count();
    const double alphas[] = {0.0, 0.25, 0.75, 1.0};
    std::size_t checked = 0, one_sided_exceeded = 0, behind = 0;
    std::array<std::size_t, 4> defects{};  // per alpha in alphas: cusp, loop or fold found
    for (std::size_t i = 0; i < n; ++i) {
        const auto p = random_segment(rng);
        for (double alpha : {0.5, alphas[i % 4]}) {
            const auto a = analyze_segment(p, alpha);
            ASSERT_TRUE(a.bounds.has_value());
            const auto& b = *a.bounds;
            const double d2 = b.d2;
            const double l1 = norm(a.bezier[1] - a.bezier[0]), l2 = norm(a.bezier[3] - a.bezier[2]);
            // Heights: the same quantity two ways, rounding of |B1 - B0|.
            EXPECT_NEAR(a.bezier_height[0], b.h1, 1e-12 * (l1 + d2)) << "segment " << i << " alpha " << alpha;
            EXPECT_NEAR(a.bezier_height[1], b.h2, 1e-12 * (l2 + d2)) << "segment " << i << " alpha " << alpha;
            // The measured maximum is exact up to rounding of the
            // coefficients (|c| <= 3 (l1 + l2 + d2)).
            const double tol = 1e-12 * (l1 + l2 + d2);
            EXPECT_LE(a.max_chord_line_distance, a.bezier_bound + tol) << "segment " << i << " alpha " << alpha;
            EXPECT_LE(a.bezier_bound, b.eq6 + tol) << "segment " << i << " alpha " << alpha;
            if (a.max_chord_line_distance > b.eq6_one_sided + tol) ++one_sided_exceeded;
            // Behind by more than rounding (a B1 on the chord's perpendicular
            // at P1, theta ~ 0 for centripetal, is not behind).
            const double behind_tol = tol / d2;
            if (alpha >= 0.5 && a.projection->bezier[0] < -behind_tol) {
                ++behind;
                EXPECT_LE(l1, b.eq8_start + tol) << "segment " << i << " alpha " << alpha;
            }
            if (alpha >= 0.5 && a.projection->bezier[1] > 1 + behind_tol) {
                EXPECT_LE(l2, b.eq8_end + tol) << "segment " << i << " alpha " << alpha;
            }
            if (alpha == 0.5) {
                // No overshoot: the curve's projection on the chord stays in
                // [0, 1] (Theorem 3), up to rounding. Not asserted on
                // a.overshoot, a distance to B0 or B3 of points projecting
                // beyond them: where the curve meets the chord's end
                // slowly (B2 projecting at 1 - 1e-8, lambda'(1) = 4e-8), a
                // root of lambda = 1 is found 1e-8 inside u = 1, its point
                // then projects beyond 1 by rounding, and its distance to B3
                // (1e-12 of the scale at seed 1000's segment 6882) counts.
                EXPECT_GE(a.projection->range[0], -tol / d2) << "segment " << i;
                EXPECT_LE(a.projection->range[1], 1 + tol / d2) << "segment " << i;
                EXPECT_NEAR(a.max_chord_distance, a.max_chord_line_distance, tol) << "segment " << i;
            } else if (a.has_cusp() || a.has_self_intersection()) {
                ++defects[i % 4];
                for (const auto& [u, v] : a.self_intersection) {
                    // A crossing at angle phi is located to (rounding) / sin(phi):
                    // nearly collinear segments (angles ~1e-9 from 0 or pi)
                    // make thin loops that cross almost tangentially.
                    const P2 ds = a.segment.du(u, 1), dt = a.segment.du(v, 1);
                    const double sin_phi = std::abs(ds[0] * dt[1] - ds[1] * dt[0]) / (norm(ds) * norm(dt));
                    EXPECT_LE(norm(a.segment.at(u) - a.segment.at(v)), tol / std::max(sin_phi, 1e-4))
                        << "segment " << i << " sin(phi) " << sin_phi;
                }
            }
            ++checked;
        }
    }
    std::printf("bounds: %zu analyses; one-sided Eq. 6 exceeded %zu times; B1 behind B0 %zu times\n", checked,
                one_sided_exceeded, behind);
    std::printf("defects found: alpha 0: %zu, 0.25: %zu, 0.75: %zu, 1: %zu\n", defects[0], defects[1], defects[2],
                defects[3]);
    EXPECT_GT(one_sided_exceeded, checked / 100);  // SOURCES.md: 10-16% of segments
    EXPECT_GT(behind, 0u);
    for (std::size_t k = 0; k < 4; ++k) EXPECT_GT(defects[k], 0u) << "alpha " << alphas[k];
}

// An independent check of the loop detector in 2-D: a dense polyline of the
// segment crosses itself iff a loop (or a cusp, whose loop has shrunk to a
// point) is reported. Loops of parameter width >= 0.05 must show in the
// polyline; polyline crossings must have been reported.
TEST(SegmentProperties, LoopsAgreeWithAPolylineSearch) {
    CRSPLINE_SEEDED(seed, 2013);
    std::mt19937_64 rng(seed);
    const std::size_t n = std::size_t(3000 * property_scale());
    const int m = 300;
    std::size_t checked = 0, loops = 0, crossings = 0, near_cusp_crossings = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const auto p = random_segment(rng);
        const double alpha = std::array{0.0, 0.25, 0.5, 0.75, 1.0}[i % 5];
        const auto a = analyze_segment(p, alpha);
        std::vector<P2> poly(m + 1);
        for (int k = 0; k <= m; ++k) poly[k] = a.segment.at(double(k) / m);
        bool crossed = false;
        // Crossings involving the first or last chord are left out: a loop
        // closing just beyond an end (s = -5e-9, say) makes the polyline
        // cross there although the segment does not.
        for (int k = 1; k < m - 1 && !crossed; ++k)
            for (int j = k + 2; j < m - 1 && !crossed; ++j) crossed = crosses(poly[k], poly[k + 1], poly[j], poly[j + 1]);
        const bool wide_loop = !a.self_intersection.empty() &&
                               a.self_intersection[0][1] - a.self_intersection[0][0] >= 0.05 &&
                               a.self_intersection[0][0] > 2.0 / m && a.self_intersection[0][1] < 1 - 2.0 / m;
        if (crossed) {
            ++crossings;
            // A near-cusp (the curve turns back with a tiny speed, no loop)
            // can make the polyline cross where the curve does not: its two
            // legs run within ~sigma^2 / |C''| of each other (sigma the least
            // speed), while the chords deviate from the arcs by their sagitta,
            // |C''| / (8 m^2), 1e-6 of the scale. Seed 123's segment 1183 has
            // sigma = 1.5e-13 of the speed scale, and in 50-digit arithmetic
            // on its coefficients no C(u) = C(v) (the pair's discriminant is
            // -250). Those crossings are left out when sigma < 1e-4 of the
            // largest speed (sampled: an upper bound on sigma), and counted.
            double least = std::numeric_limits<double>::infinity(), most = 0;
            for (int k = 0; k <= 20000; ++k) {
                const double sp = norm(a.segment.du(k / 20000.0, 1));
                least = std::min(least, sp);
                most = std::max(most, sp);
            }
            if (!(a.has_self_intersection() || a.has_cusp()) && least < 1e-4 * most) {
                ++near_cusp_crossings;
            } else {
                EXPECT_TRUE(a.has_self_intersection() || a.has_cusp()) << "segment " << i << " alpha " << alpha;
            }
        }
        if (wide_loop) {
            ++loops;
            EXPECT_TRUE(crossed) << "segment " << i << " alpha " << alpha;
        }
        ++checked;
    }
    std::printf("polyline: %zu segments, %zu wide loops, %zu polyline crossings (%zu at near-cusps)\n", checked,
                loops, crossings, near_cusp_crossings);
    EXPECT_LE(near_cusp_crossings, crossings / 10);  // the exception stays one
    // About 1% of these segments have a wide loop (32 of 3000 at the
    // default seed, 22 to 39 at a dozen others: at n / 100 the count was a
    // coin toss). Half that rate, 15, is over 2.5 standard deviations
    // below the lowest seen.
    EXPECT_GT(loops, n / 200);
}

}  // namespace
