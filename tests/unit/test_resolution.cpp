// The floors of resolution.hpp: the smallest distance tolerance and relative
// accuracy an input resolves.
#include <gtest/gtest.h>

#include <crspline/resolution.hpp>

#include <cmath>
#include <limits>
#include <vector>

namespace {
using namespace crspline;

TEST(Resolution, ToleranceFloorIs64UlpsOfTheLargestMagnitude) {
    // ulp(1) = 2^-52 exactly; ulp(1e6) = 2^-33 (2^19 <= 1e6 < 2^20).
    EXPECT_EQ(min_distance_tolerance(1.0), 64 * std::ldexp(1.0, -52));
    EXPECT_EQ(min_distance_tolerance(1e6), 64 * std::ldexp(1.0, -33));
    // The sign and the position of the largest coordinate do not matter.
    const std::vector<double> coords = {0.5, -3.0, 2.0, 1e-9};
    EXPECT_EQ(min_distance_tolerance(coords), min_distance_tolerance(3.0));
    EXPECT_EQ(min_distance_tolerance(3.0), 64 * std::ldexp(1.0, -51));
}

TEST(Resolution, ToleranceFloorIsNeverZero) {
    const std::vector<double> zeros = {0.0, 0.0, 0.0, 0.0};
    EXPECT_GT(min_distance_tolerance(zeros), 0.0);
    EXPECT_GT(min_distance_tolerance(std::numeric_limits<double>::denorm_min()), 0.0);
    EXPECT_TRUE(std::isfinite(min_distance_tolerance(std::numeric_limits<double>::max())));
}

TEST(Resolution, AccuracyFloorIsArcLengthsOwn) {
    // arc_length.hpp's effective_accuracy aims at 8 epsilon when asked for less.
    EXPECT_EQ(min_relative_accuracy, 8 * std::numeric_limits<double>::epsilon());
}

}  // namespace
