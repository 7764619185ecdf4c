// fit()'s bad input: clear errors naming what is wrong (invalid_input).
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <random>
#include <limits>
#include <string>
#include <vector>

#include <crspline/fit.hpp>

namespace {

using crspline::fit;
using crspline::fit_options;
using crspline::vec;

template <std::size_t D, class T>
std::string error_of(const std::vector<vec<D, T>>& pts, const fit_options<D, T>& o) {
    try {
        (void)fit(pts, o);
    } catch (const crspline::invalid_input& e) {
        return e.what();
    }
    return "";
}

const std::vector<vec<2>> line{vec<2>{{0, 0}}, vec<2>{{1, 0.5}}, vec<2>{{2, 0}}, vec<2>{{3, 1}}};

TEST(FitErrors, Tolerance) {
    for (double t : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
        fit_options<2> o;
        o.tolerance = t;
        EXPECT_NE(error_of(line, o).find("fit: tolerance must be a positive finite number"), std::string::npos) << t;
    }
}

TEST(FitErrors, NonFiniteCoordinateNamed) {
    auto bad = line;
    bad[2][1] = std::nan("");
    fit_options<2> o;
    o.tolerance = 0.1;
    EXPECT_EQ(error_of(bad, o), "fit: point 2 has a non-finite coordinate 1: nan");
}

TEST(FitErrors, TooFewPoints) {
    fit_options<2> o;
    o.tolerance = 0.1;
    EXPECT_EQ(error_of(std::vector<vec<2>>{line[0]}, o), "fit: needs at least 2 points, got 1");
    EXPECT_EQ(error_of(std::vector<vec<2>>{}, o), "fit: needs at least 2 points, got 0");
    EXPECT_EQ(error_of(std::vector<vec<2>>{line[1], line[1], line[1]}, o), "fit: needs at least 2 distinct points, got 1");
    o.closed = true;
    EXPECT_EQ(error_of(std::vector<vec<2>>{line[0], line[1]}, o), "fit: needs at least 3 points (closed), got 2");
}

TEST(FitErrors, ToleranceBelowTheRoundingFloor) {
    // Coordinates near 1e6: 256 ulps (256 * 2^-52) of 1000003 is 5.68e-8.
    std::vector<vec<2>> far;
    for (const auto& p : line) far.push_back(p + vec<2>{{1e6, 0}});
    fit_options<2> o;
    o.tolerance = 1e-8;
    const std::string e = error_of(far, o);
    EXPECT_EQ(e, "fit: tolerance 1e-08 is at or below the rounding floor 5.68435893910646e-08 of the coordinates "
                 "(256 ulps of the largest, 1000003)");
    o.tolerance = 1e-7;  // above it: fits
    EXPECT_EQ(error_of(far, o), "");
    // float: the floor is 2^29 times larger.
    std::vector<vec<2, float>> ff{vec<2, float>{{1000, 0}}, vec<2, float>{{1001, 1}}, vec<2, float>{{1002, 0}}};
    fit_options<2, float> of;
    of.tolerance = 1e-3;
    EXPECT_NE(error_of(ff, of).find("is at or below the rounding floor 0.0305"), std::string::npos) << error_of(ff, of);
}

// Beyond the range where the proof's squared distances stay finite (and
// the tolerance's square normal), an error naming the point, or the
// tolerance, and the limit: before, coordinates near 1e200 gave a "proof"
// of a straight line through a random walk (deviation 4e-12 of the
// tolerance where it is 7.9 times the tolerance), and a tolerance near
// 1e-170 a logic_error. Inside the range, the same random walk at scale
// 1e150 is fitted within its tolerance (checked by sampling in long double
// scaled back to 1).
TEST(FitErrors, CoordinatesAndToleranceOutsideTheProofsArithmetic) {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> g(0, 1);
    auto walk = [&](double scale) {
        std::vector<vec<2>> p;
        double x = 0, y = 0;
        for (int i = 0; i < 200; ++i) {
            x += 1 + 0.3 * g(rng), y += 0.5 * g(rng);
            p.push_back(vec<2>{{x * scale, y * scale}});
        }
        return p;
    };
    fit_options<2> o;
    o.tolerance = 0.5e200;
    const std::string big = error_of(walk(1e200), o);
    EXPECT_EQ(big.rfind("fit: point 0 coordinate 0 is 1.26", 0), 0u) << big;
    EXPECT_NE(big.find("beyond the 2.370187977027294e+153 the proof's arithmetic covers"), std::string::npos) << big;
    o.tolerance = 0.5e-170;
    const std::string small = error_of(walk(1e-170), o);
    EXPECT_EQ(small, "fit: tolerance 5e-171 is below 1.4916681462400413e-154, the smallest the proof's arithmetic "
                     "covers (its square must be a normal number): scale the points and the tolerance");
    // Floats: the limit is sqrt(max / 32) = 3.26e18 in 2-D; a point beyond
    // it is refused by name.
    std::vector<vec<2, float>> ff{vec<2, float>{{0, 0}}, vec<2, float>{{1, 1}}, vec<2, float>{{4e18f, 0}}};
    fit_options<2, float> of;
    of.tolerance = 1e15;
    EXPECT_EQ(error_of(ff, of).rfind("fit: point 2 coordinate 0 is 3.99", 0), 0u) << error_of(ff, of);
    EXPECT_NE(error_of(ff, of).find("beyond the 3.26"), std::string::npos) << error_of(ff, of);
    // Inside: scale 1e150 (coordinates up to about 2e152).
    const auto p = walk(1e150);
    o.tolerance = 0.5e150;
    const auto r = fit(p, o);
    EXPECT_LE(double(r.deviation), o.tolerance);
    EXPECT_GT(r.count, 20u);  // measured 49: a random walk of 200 steps
    long double worst = 0;  // curve samples against the polyline, scaled back to 1
    for (std::size_t s = 0; s < r.curve.segment_count(); ++s) {
        const auto seg = r.curve.segment(s);
        for (int k = 0; k <= 40; ++k) {
            const auto c = seg.at(k / 40.0);
            long double best = 1e30L;
            for (std::size_t i = 0; i + 1 < p.size(); ++i) {
                const long double ax = p[i][0] / 1e150L, ay = p[i][1] / 1e150L;
                const long double dx = p[i + 1][0] / 1e150L - ax, dy = p[i + 1][1] / 1e150L - ay;
                const long double wx = c[0] / 1e150L - ax, wy = c[1] / 1e150L - ay, l2 = dx * dx + dy * dy;
                const long double t = l2 > 0 ? std::clamp((wx * dx + wy * dy) / l2, 0.0L, 1.0L) : 0.0L;
                best = std::min(best, std::hypot(wx - t * dx, wy - t * dy));
            }
            worst = std::max(worst, best);
        }
    }
    // 1e-9: the rounding of the scaling and of the samples, far below the
    // tolerance of 0.5 (a broken proof is off by a whole tolerance).
    EXPECT_LE(double(worst), 0.5 + 1e-9);
}

TEST(FitErrors, OptionsOutOfRange) {
    fit_options<2> o;
    o.tolerance = 0.1;
    o.alpha = 1.5;
    EXPECT_EQ(error_of(line, o), "fit: alpha must be in [0, 1], got 1.5");
    o.alpha.reset();
    o.tension = -0.5;
    EXPECT_EQ(error_of(line, o), "fit: tension must be in [0, 1], got -0.5");
    o.tension = 0;
    o.start = crspline::end_condition<2>::tangent(vec<2>{{1, 0}});
    EXPECT_EQ(error_of(line, o), "fit: the end conditions must be natural or reflect (the fit chooses the end tangents)");
    // A ring has no ends: said before any work, in fit's words.
    o.start = crspline::end_condition<2>::natural();
    o.end = crspline::end_condition<2>::reflect();
    o.closed = true;
    EXPECT_EQ(error_of(line, o), "fit: a closed curve takes no end conditions, got end reflect");
}

// Options the fit keeps: alpha, tension, reflect ends, duplicates dropped
// (indices point at the input as given).
TEST(FitErrors, OptionsKeptAndDuplicatesDropped) {
    std::vector<vec<2>> pts{line[0], line[0], line[1], line[2], line[2], line[3]};
    fit_options<2> o;
    o.tolerance = 1e-3;
    o.alpha = 0.0;
    o.tension = 0.25;
    o.end = crspline::end_condition<2>::reflect();
    const auto r = fit(pts, o);
    EXPECT_EQ(r.curve.options().alpha, 0.0);
    EXPECT_EQ(r.curve.options().tension, 0.25);
    EXPECT_EQ(r.curve.options().end, crspline::end_condition<2>::reflect());
    ASSERT_EQ(r.indices.size(), 4u);
    EXPECT_EQ(r.indices, (std::vector<std::size_t>{0, 2, 3, 5}));
}

}  // namespace
