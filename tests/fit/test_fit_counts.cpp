// fit()'s counts: against the true optimum (exhaustive dynamic programming,
// tests/fit/fit_optimum.hpp) on a seeded corpus of short lines, and against
// Ramer-Douglas-Peucker on the real corpus (tests/reference/fit, see its
// README). The counts are asserted, so a change that keeps more points
// fails here.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <crspline/fit.hpp>

#include "fit_check.hpp"
#include "fit_corpus.hpp"
#include "fit_optimum.hpp"

namespace {

using crspline::fit;
using crspline::fit_mode;
using crspline::fit_options;
using crspline::vec;

// Lines of 50 points (a noisy turning walk, seeded) at tolerances of 0.3
// and 0.5 of the point spacing's order. The optimum is the fewest points of
// a curve without tension (lines where none exists are counted and
// skipped); the fit may also use tension, so it can come in under it.
TEST(FitCounts, WithinFifteenPercentOfTheOptimum) {
    std::size_t total_fit = 0, total_opt = 0, lines = 0, skipped = 0;
    for (std::uint64_t seed = 1; seed <= 16; ++seed) {
        std::mt19937_64 rng(seed);
        const auto pts = fit_check::noisy_line<2, double>(rng, 50, 0.15);
        fit_options<2> o;
        o.tolerance = seed % 2 ? 0.3 : 0.5;
        const auto r = fit(pts, o);
        crspline::detail::fit_problem<2, double> pb;
        pb.pts = pts;
        pb.tolerance = o.tolerance;
        pb.slack = r.rounding_floor / 4;
        const std::size_t opt = fit_optimum::optimum_count(pb, 20);
        if (opt == std::size_t(-1)) {
            ++skipped;
            continue;
        }
        EXPECT_LE(double(r.count), 1.3 * double(opt) + 1) << "seed " << seed;  // no line far off
        total_fit += r.count;
        total_opt += opt;
        ++lines;
    }
    std::printf("fit %zu, optimum %zu over %zu lines (%zu skipped): %.3f\n", total_fit, total_opt, lines, skipped,
                double(total_fit) / double(total_opt));
    EXPECT_EQ(lines + skipped, 16u);
    EXPECT_GE(lines, 14u);
    EXPECT_LE(double(total_fit), 1.15 * double(total_opt));
}

// A larger tolerance never needs more points on a smooth closed or open
// curve. Before the search tried candidates backed off from the reach, an
// ellipse of 400 points took 8 points at tolerance 0.04 and 14 at 0.05 (a
// point chosen at the end of one reach left its next segment a tangent it
// could keep for one input step only, and the repairs added tension and
// points). Deterministic input: no seed.
TEST(FitCounts, NoMorePointsAtALargerTolerance) {
    std::vector<vec<2, double>> ellipse;
    for (int i = 0; i < 400; ++i) {
        const double a = 2 * 3.141592653589793 * i / 400;
        ellipse.push_back({3 * std::cos(a), 1.5 * std::sin(a)});
    }
    for (bool closed : {true, false}) {
        std::size_t before = ellipse.size();
        for (double tol : {0.003, 0.01, 0.02, 0.03, 0.04, 0.05, 0.07, 0.1, 0.2}) {
            fit_options<2> o;
            o.tolerance = tol;
            o.closed = closed;
            const auto r = fit(ellipse, o);
            EXPECT_LE(r.deviation, tol);
            EXPECT_LE(r.count, before) << "closed " << closed << ", tolerance " << tol;
            EXPECT_EQ(r.tensioned, 0u) << "closed " << closed << ", tolerance " << tol;  // a smooth curve needs none
            before = r.count;
        }
        EXPECT_LE(before, 6u);  // measured: 5 closed, 6 open at 0.2
    }
}

// Smooth lines with a little noise: a sine of amplitude 5 over 500 points
// with a faster sine of amplitude 0.02, 0.05 or 0.1 on it, three periods,
// five tolerances (45 lines; deterministic input, no seed). fit() walks
// greedily with tension at every vertex first and, where that choice
// hardly needs its tension, runs a second search from level 0 that looks
// two segments ahead (fit.hpp, fit_subset.hpp). Measured: 1,290 points in
// all; with the second search only where one vertex in 20 needs tension
// (instead of one in 5) 1,376; with the lookahead in both searches and one
// in 20 (before) 1,298. The bound sits between: a change that runs the
// second search on fewer such lines fails here. (With the greedy walk in
// both searches these take 1,302, but the ellipse above then keeps tension
// and more points at smaller tolerances: that test fails.)
TEST(FitCounts, NoisySmoothLinesGetTheSecondSearch) {
    std::size_t total = 0, lines = 0;
    for (double noise : {0.02, 0.05, 0.1})
        for (double tol : {0.05, 0.1, 0.2, 0.3, 0.5})
            for (double period : {20.0, 40.0, 80.0}) {
                std::vector<vec<2>> s(500);
                for (std::size_t i = 0; i < s.size(); ++i) {
                    const double x = double(i);
                    s[i] = vec<2>{{x / 10, 5 * std::sin(x / period) + noise * std::sin(x * 7.3)}};
                }
                fit_options<2> o;
                o.tolerance = tol;
                const auto r = fit(s, o);
                EXPECT_LE(r.deviation, tol) << "noise " << noise << ", tolerance " << tol << ", period " << period;
                total += r.count;
                ++lines;
            }
    std::printf("45 noisy sines: %zu control points\n", total);
    EXPECT_EQ(lines, 45u);
    EXPECT_LE(total, 1320u);
}

struct corpus_counts {
    std::size_t lines = 0, points = 0, rdp = 0, fit = 0;
};

corpus_counts run_corpus(const std::string& file, fit_mode mode, std::size_t max_lines) {
    corpus_counts c;
    for (const auto& l : fit_corpus::read(std::string(CRSPLINE_FIT_CORPUS_DIR) + "/" + file)) {
        if (c.lines == max_lines) break;
        fit_options<2> o;
        o.tolerance = l.tolerance;
        o.closed = l.closed;
        o.mode = mode;
        const auto r = fit(l.points, o);
        EXPECT_LE(r.deviation, l.tolerance) << l.name;
        c.fit += r.count;
        c.rdp += fit_corpus::rdp(l.points, l.tolerance, l.closed).size();
        c.points += l.points.size();
        ++c.lines;
    }
    return c;
}

// The issue asks for 0.8 (subset) and 0.6 (free) of RDP's count. Subset
// mode is held to the 0.8 asked on each corpus (measured: 0.778 on the
// topobathy contours, 0.745 and 0.742 on the parts of the others read
// here; BENCHMARKS.md has the whole corpus); free mode, which does not
// reach 0.6, is asserted a little above what it reaches (0.706), so that
// a regression fails and an improvement shows.
TEST(FitCounts, FewerPointsThanRamerDouglasPeuckerOnRealLines) {
    const auto dem = run_corpus("dem_topobathy.txt", fit_mode::subset, 1000);
    EXPECT_EQ(dem.lines, 78u);
    EXPECT_EQ(dem.points, 6722u);
    std::printf("topobathy subset: fit %zu rdp %zu (%.3f)\n", dem.fit, dem.rdp, double(dem.fit) / double(dem.rdp));
    EXPECT_LE(double(dem.fit), 0.8 * double(dem.rdp));
    const auto free = run_corpus("dem_topobathy.txt", fit_mode::free, 1000);
    std::printf("topobathy free: fit %zu rdp %zu (%.3f)\n", free.fit, free.rdp, double(free.fit) / double(free.rdp));
    EXPECT_LE(double(free.fit), 0.74 * double(free.rdp));
    const auto jb = run_corpus("dem_jacksboro.txt", fit_mode::subset, 40);
    EXPECT_EQ(jb.lines, 40u);
    std::printf("jacksboro (40 lines, %zu points) subset: fit %zu rdp %zu (%.3f)\n", jb.points, jb.fit, jb.rdp,
                double(jb.fit) / double(jb.rdp));
    EXPECT_LE(double(jb.fit), 0.8 * double(jb.rdp));
    const auto ny = run_corpus("outlines_nybb.txt", fit_mode::subset, 6);
    EXPECT_EQ(ny.lines, 6u);
    std::printf("nybb (6 rings, %zu points) subset: fit %zu rdp %zu (%.3f)\n", ny.points, ny.fit, ny.rdp,
                double(ny.fit) / double(ny.rdp));
    EXPECT_LE(double(ny.fit), 0.8 * double(ny.rdp));
}

}  // namespace
