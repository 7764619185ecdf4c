// The proof's two bounds on their own (detail/fit_proof.hpp), against dense
// sampling on seeded random segments: sound (never proves what sampling
// shows false) and not idle (proves what is clearly true, rejects what is
// clearly false; both counted).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <crspline/fit.hpp>

#include "fit_check.hpp"

namespace {

using crspline::vec;
using p2 = vec<2>;

crspline::cubic_segment<2> random_segment(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0, 10);
    const p2 a{{u(rng), u(rng)}}, b{{u(rng), u(rng)}}, m0{{u(rng) - 5, u(rng) - 5}}, m1{{u(rng) - 5, u(rng) - 5}};
    return crspline::cubic_segment<2>::hermite(a, b, 2.0 * m0, 2.0 * m1, 0.0, 1.0);
}

// Dense samples of the segment and the largest gap between them.
std::vector<p2> samples(const crspline::cubic_segment<2>& s, double& gap) {
    std::vector<p2> out;
    const int n = 20000;
    for (int k = 0; k <= n; ++k) out.push_back(s.at(double(k) / n));
    gap = 0;
    for (std::size_t i = 0; i + 1 < out.size(); ++i) gap = std::max(gap, crspline::norm(out[i + 1] - out[i]));
    return out;
}

TEST(FitBounds, InputPointsAgainstTheCurve) {
    std::size_t proved = 0, rejected = 0, points = 0;
    const double tol = 0.3;
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
        std::mt19937_64 rng(seed);
        const auto seg = random_segment(rng);
        double gap = 0;
        const auto dense = samples(seg, gap);
        std::uniform_real_distribution<double> uu(0, 1), ang(0, 2 * M_PI), mag(0.5, 1.5);
        for (int q = 0; q < 40; ++q) {
            const double a = ang(rng), r = mag(rng) * tol;
            const p2 p = seg.at(uu(rng)) + r * p2{{std::cos(a), std::sin(a)}};
            double best = INFINITY;
            for (const auto& x : dense) best = std::min(best, crspline::norm(p - x));
            const std::vector<p2> one{p, p};
            const crspline::detail::poly_range<2, double> pr{one, 0, 2};
            double worst = 0;
            const bool ok = crspline::detail::input_within(seg, pr, tol, tol / 4, 0, 1, worst);
            ++points;
            if (ok) {
                ++proved;
                // Sound: the true distance (at least best - gap / 2) is within.
                EXPECT_LE(best - 0.6 * gap, tol) << "seed " << seed << " point " << q;
                EXPECT_GE(worst + 0.6 * gap, best - 0.6 * gap) << "seed " << seed << " point " << q;
            } else {
                ++rejected;
                // Not idle: a point clearly within is proved (the exact nearest point decides).
                EXPECT_GT(best, 0.99 * tol) << "seed " << seed << " point " << q;
            }
        }
    }
    EXPECT_EQ(points, 2400u);
    EXPECT_GT(proved, 300u);
    EXPECT_GT(rejected, 300u);
}

TEST(FitBounds, CurveAgainstThePolyline) {
    std::size_t proved = 0, rejected = 0, cases = 0;
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        std::mt19937_64 rng(seed);
        const auto seg = random_segment(rng);
        double gap = 0;
        const auto dense = samples(seg, gap);
        // A polyline near the curve: 12 points of it, each moved at random by up to 0.4.
        std::uniform_real_distribution<double> jit(-0.4, 0.4);
        std::vector<p2> poly;
        for (int k = 0; k <= 12; ++k) poly.push_back(seg.at(k / 12.0) + p2{{jit(rng), jit(rng)}});
        const crspline::detail::poly_range<2, double> pr{poly, 0, poly.size()};
        double far = 0;
        for (const auto& x : dense) {
            double d = INFINITY;
            for (std::size_t i = 0; i + 1 < poly.size(); ++i) d = std::min(d, fit_check::seg_dist(x, poly[i], poly[i + 1]));
            far = std::max(far, d);
        }
        const double tol = 0.35;
        double worst = 0;
        std::size_t hint = 0, h1 = poly.size() - 2;
        const auto b = crspline::to_bezier(seg);
        const double a0 = crspline::detail::range_distance(b[0], pr, hint, true);
        const double a1 = crspline::detail::range_distance(b[3], pr, h1, true);
        const bool ok = a0 <= tol && a1 <= tol && crspline::detail::piece_within(b, a0, a1, pr, tol, 0, worst, hint);
        ++cases;
        if (ok) {
            ++proved;
            EXPECT_LE(far, tol) << "seed " << seed;       // sound
            EXPECT_LE(far, worst + 1e-12) << "seed " << seed;  // the bound bounds
        } else {
            ++rejected;
            EXPECT_GT(far, 0.9 * tol) << "seed " << seed;  // not idle
        }
    }
    EXPECT_EQ(cases, 200u);
    EXPECT_GT(proved, 20u);
    EXPECT_GT(rejected, 20u);
}

}  // namespace
