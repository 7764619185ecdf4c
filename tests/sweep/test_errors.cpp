// Bad input to sweep() and stroke(): spec_error naming the field, with the
// value in the message.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <crspline/stroke.hpp>
#include <crspline/sweep.hpp>

using namespace crspline;

namespace {

template <class F>
void expect_field(F&& f, const std::string& field, const std::string& words) {
    try {
        f();
        ADD_FAILURE() << "no error for " << field;
    } catch (const spec_error& e) {
        EXPECT_EQ(e.field(), field) << e.what();
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
}

const catmull_rom<3> line3(std::vector<vec<3>>{{{0, 0, 0}}, {{1, 0, 0}}, {{2, 1, 0}}, {{3, 1, 1}}});
const catmull_rom<2> line2(std::vector<vec<2>>{{{0, 0}}, {{1, 0}}, {{2, 1}}});

}  // namespace

TEST(SweepErrors, RadiusMustBePositiveAndFinite) {
    for (double r : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        sweep_options o;
        o.profile = sweep_profile::circle(r);
        expect_field([&] { sweep(line3, o); }, "radius", "radius: must be positive and finite, got ");
    }
}

TEST(SweepErrors, ProfileNeedsTwoFinitePoints) {
    sweep_options o;
    o.profile = sweep_profile::polyline({{{1, 0}}});
    expect_field([&] { sweep(line3, o); }, "profile", "profile: needs at least 2 points, got 1");
    o.profile = sweep_profile::curve({});
    expect_field([&] { sweep(line3, o); }, "profile", "got 0");
    o.profile = sweep_profile::polyline({{{1, 0}}, {{0, std::numeric_limits<double>::quiet_NaN()}}});
    expect_field([&] { sweep(line3, o); }, "profile", "profile[1][1]: coordinate nan is not finite");
}

TEST(SweepErrors, CurvesOfTheWrongDimension) {
    expect_field([&] { sweep(line2); }, "curve", "curve: sweep needs a 3-D curve, got a 2-D one");
    expect_field([&] { stroke(line3, 1.0); }, "curve", "curve: stroke needs a 2-D curve, got a 3-D one");
}

TEST(SweepErrors, RollScaleUpTolerance) {
    sweep_options o;
    o.roll = {0, 1};
    expect_field([&] { sweep(line3, o); }, "roll", "roll: 2 angles for 4 knots");
    o.roll = {0, 1, 4.5, 4};
    expect_field([&] { sweep(line3, o); }, "roll", "roll[2]: angle 4.5 is pi or more from the previous key");
    o = {};
    o.scale_s = {0, 1};
    o.scale = {1, -2};
    expect_field([&] { sweep(line3, o); }, "scale", "scale[1]: value -2 must be positive");
    o.scale_s = {0, 0};
    o.scale = {1, 2};
    expect_field([&] { sweep(line3, o); }, "scale", "scale[1]: positions must increase");
    o = {};
    o.up = vec<3>{};
    expect_field([&] { sweep(line3, o); }, "up", "up: must not be the zero vector");
    o = {};
    o.tolerance = -1;
    expect_field([&] { sweep(line3, o); }, "tolerance", "tolerance: must be positive");
}

TEST(SweepErrors, StrokeWidthAndMiterLimit) {
    for (double w : {0.0, -2.0, std::numeric_limits<double>::quiet_NaN()})
        expect_field([&] { stroke(line2, w); }, "width", "width: must be positive and finite");
    stroke_options o;
    o.miter_limit = 0.5;
    expect_field([&] { stroke(line2, 1.0, o); }, "miter_limit", "miter_limit: must be at least 1");
}
