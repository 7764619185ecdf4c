// fit()'s bad input: clear errors naming what is wrong (invalid_input).
#include <gtest/gtest.h>

#include <cmath>
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
