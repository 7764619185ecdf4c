// fit(): the proved tolerance, checked by dense sampling independent of the
// proof; open and closed, float and double, 2-D and 3-D; tension where no
// choice of points is enough.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <crspline/fit.hpp>

#include "fit_check.hpp"

namespace {

using crspline::fit;
using crspline::fit_mode;
using crspline::fit_options;
using crspline::vec;

// Free mode's control points at the middle of an input segment, over the
// tests (so that a free mode that never moves a point shows).
std::size_t free_middles = 0;

// Checks one fit against sampling; returns the sampled measure.
template <std::size_t D, class T>
fit_check::measured expect_within(const std::vector<vec<D, T>>& pts, const fit_options<D, T>& o, std::uint64_t seed) {
    const auto r = fit(pts, o);
    const auto m = fit_check::measure(r.curve, pts, o.closed);
    // The proved bound is at most the tolerance, and the sampled distances
    // (lower bounds on the true ones) are at most the proved bound, up to
    // the rounding of the sampling itself (double arithmetic on T values:
    // a few ulps of T at the coordinates' scale).
    const double scale = 1e3, round = 64 * double(std::numeric_limits<T>::epsilon()) * scale;
    EXPECT_LE(double(r.deviation), o.tolerance) << "seed " << seed;
    EXPECT_LE(m.curve_to_input, double(r.curve_to_input) + round) << "seed " << seed;
    EXPECT_LE(m.input_to_curve, double(r.input_to_curve) + round) << "seed " << seed;
    EXPECT_EQ(r.count, r.curve.points().size()) << "seed " << seed;
    if (o.mode == fit_mode::subset) {
        EXPECT_EQ(r.indices.size(), r.count);
        for (std::size_t k = 0; k < r.count; ++k) EXPECT_EQ(r.curve.points()[k], pts[r.indices[k]]) << "seed " << seed;
        if (!o.closed) {
            EXPECT_EQ(r.indices.front(), 0u);
            EXPECT_EQ(r.indices.back(), pts.size() - 1);
        }
    } else {
        EXPECT_TRUE(r.indices.empty());
        // Each control point is an input point or the middle of an input
        // segment (computed as fit_free.hpp does: a + (b - a) / 2).
        const std::size_t n = pts.size();
        std::size_t middles = 0;
        for (const auto& c : r.curve.points()) {
            bool found = false;
            for (std::size_t i = 0; i < n && !found; ++i) {
                found = c == pts[i];
                if (!found && (i + 1 < n || o.closed)) {
                    const auto& a = pts[i];
                    const bool mid = c == a + T(0.5) * (pts[(i + 1) % n] - a);
                    found = mid;
                    middles += mid;
                }
            }
            EXPECT_TRUE(found) << "seed " << seed << ": a control point neither an input point nor a middle";
        }
        free_middles += middles;
    }
    return m;
}

TEST(FitProof, OpenAndClosedWithinToleranceByDenseSampling) {
    std::size_t checked = 0, fewer = 0;
    for (std::uint64_t seed = 1; seed <= 24; ++seed) {
        std::mt19937_64 rng(seed);
        const double tol = std::array<double, 3>{0.05, 0.2, 0.6}[seed % 3];
        auto pts = fit_check::noisy_line<2, double>(rng, 150, 0.1);
        for (bool closed : {false, true}) {
            for (auto mode : {fit_mode::subset, fit_mode::free}) {
                fit_options<2> o;
                o.tolerance = tol;
                o.closed = closed;
                o.mode = mode;
                expect_within(pts, o, seed);
                fewer += fit(pts, o).count < pts.size();
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, 96u);
    // Every fit but those at the smallest tolerance on the noisiest lines keeps fewer points.
    EXPECT_GE(fewer, 80u);
    // Free mode uses its middles (measured: 445 of its control points on
    // these noisy lines; a free mode that never moved a point would fail).
    std::printf("free mode: %zu control points at segment middles\n", free_middles);
    EXPECT_GE(free_middles, 100u);
}

TEST(FitProof, FloatAndThreeDimensions) {
    std::size_t checked = 0;
    for (std::uint64_t seed = 100; seed < 108; ++seed) {
        std::mt19937_64 rng(seed);
        auto p3 = fit_check::noisy_line<3, double>(rng, 120, 0.05);
        auto pf = fit_check::noisy_line<2, float>(rng, 120, 0.05);
        fit_options<3> o3;
        o3.tolerance = 0.2;
        o3.closed = seed % 2;
        expect_within(p3, o3, seed);
        fit_options<2, float> of;
        of.tolerance = 0.2;
        of.mode = seed % 2 ? fit_mode::free : fit_mode::subset;
        expect_within(pf, of, seed);
        checked += 2;
    }
    EXPECT_EQ(checked, 16u);
}

// A ring whose tolerance is as large as the ring itself: the search goes
// round in one or two points, but a closed curve keeps three (one point is
// no curve; two go there and back, enclosing nothing), still within the
// tolerance. Seeded rings (circles with noise, squares), tolerances from a
// tenth of the ring's size to a hundred times it.
TEST(FitProof, RingsKeepThreeControlPointsAtAnyTolerance) {
    std::size_t checked = 0, three = 0;
    for (std::uint64_t seed = 300; seed < 312; ++seed) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u(-0.05, 0.05);
        std::vector<vec<2>> ring;
        const std::size_t n = 4 + seed % 40;
        for (std::size_t k = 0; k < n; ++k) {
            const double t = 2 * M_PI * double(k) / double(n);
            if (seed % 3 == 0)  // a square's outline, corners included
                ring.push_back(vec<2>{{std::clamp(1.5 * std::cos(t), -1.0, 1.0), std::clamp(1.5 * std::sin(t), -1.0, 1.0)}});
            else
                ring.push_back(vec<2>{{std::cos(t) + u(rng), std::sin(t) + u(rng)}});
        }
        for (double tol : {0.2, 0.7, 1.5, 5.0, 100.0})
            for (auto mode : {fit_mode::subset, fit_mode::free}) {
                fit_options<2> o;
                o.tolerance = tol;
                o.closed = true;
                o.mode = mode;
                const auto r = fit(ring, o);
                EXPECT_GE(r.count, 3u) << "seed " << seed << " tolerance " << tol;
                three += r.count == 3;
                expect_within(ring, o, seed);
                ++checked;
            }
    }
    EXPECT_EQ(checked, 120u);
    // At the largest tolerances every ring takes the fewest: three.
    EXPECT_GE(three, 48u);
}

// A smooth line sampled far more densely than its tolerance needs: each
// segment covers some 300 input points, where the choice puts its
// candidates on a grid and merges try 64 points (fit_model.hpp; without
// them time grew with the square of the points).
// Still within the tolerance, and few points: measured 8 (subset) and 8
// (free) here; the bound of 14 leaves room for the grid's choices, not for
// a choice that lost its way.
TEST(FitProof, DenselySampledSmoothLine) {
    std::vector<vec<2>> sine(3000);
    for (std::size_t i = 0; i < sine.size(); ++i) {
        const double t = 2 * M_PI * double(i) / double(sine.size() - 1);
        sine[i] = vec<2>{{t, std::sin(t)}};
    }
    std::size_t checked = 0;
    for (auto mode : {fit_mode::subset, fit_mode::free}) {
        fit_options<2> o;
        o.tolerance = 0.01;
        o.mode = mode;
        const auto r = fit(sine, o);
        std::printf("dense sine, %s: %zu control points\n", mode == fit_mode::free ? "free" : "subset", r.count);
        EXPECT_LE(r.count, 14u);
        expect_within(sine, o, 3000);
        ++checked;
    }
    EXPECT_EQ(checked, 2u);
}

// A zigzag with right-angle kinks: the curve through every point overshoots
// each kink by more than a small tolerance, so only tension keeps it.
TEST(FitProof, TensionWhereNoChoiceOfPointsIsEnough) {
    std::vector<vec<2>> zig;
    for (int i = 0; i < 40; ++i) zig.push_back(vec<2>{{double(i / 2 + (i % 2)), double(i / 2)}});
    fit_options<2> o;
    o.tolerance = 0.01;
    crspline::catmull_rom<2> all(zig);  // every point, no tension
    const auto m_all = fit_check::measure(all, zig, false);
    EXPECT_GT(m_all.curve_to_input, 0.05);  // the plain curve overshoots
    const auto r = fit(zig, o);
    EXPECT_GT(r.tensioned, 0u);
    EXPECT_FALSE(r.curve.options().kb.tension.empty());
    EXPECT_LE(r.deviation, 0.01);
    const auto m = fit_check::measure(r.curve, zig, false);
    EXPECT_LE(m.curve_to_input, 0.01);
    EXPECT_LE(m.input_to_curve, 0.01);
}

// The check above can fail: a fit made at twice the tolerance, held to the
// tolerance, is caught by the sampling on most lines (the proof's bounds
// stand for the fit's own tolerance, not for this one).
TEST(FitProof, SamplingCatchesACurveOutsideTheTolerance) {
    std::size_t caught = 0, lines = 0;
    for (std::uint64_t seed = 200; seed < 212; ++seed) {
        std::mt19937_64 rng(seed);
        auto pts = fit_check::noisy_line<2, double>(rng, 150, 0.1);
        fit_options<2> o;
        o.tolerance = 0.6;
        const auto r = fit(pts, o);
        const auto m = fit_check::measure(r.curve, pts, false);
        caught += std::max(m.curve_to_input, m.input_to_curve) > 0.3;
        ++lines;
    }
    EXPECT_EQ(lines, 12u);
    EXPECT_GE(caught, 10u);
}

}  // namespace
