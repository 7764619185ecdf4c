// crspline: the smallest tolerance and accuracy an input can resolve.
//
// Coordinates are doubles: near a magnitude m they are spaced ulp(m) apart,
// and every evaluation of a curve through them is rounded at that spacing.
// A distance tolerance of a few ulps asks for a polyline the arithmetic
// cannot tell apart from any other (tessellate() subdivides without end:
// 1e-16 on unit coordinates ran for minutes, 1e-300 for ten and 660 MB); a
// relative accuracy below a few machine epsilons cannot be met by any sum of
// doubles (arc_length() aims at 8 epsilon instead). Front ends reject such
// values with these floors, so that one argument cannot stall a run, and the
// message can say what the smallest meaningful value is for this input.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

namespace crspline {

/// How many ulps of the largest coordinate magnitude the smallest meaningful
/// distance tolerance is. Evaluating a cubic Bezier segment (three rounds of
/// lerps, about ten rounded operations per coordinate) and the flatness
/// bound each carry rounding errors of a few ulps of the magnitude; 64 leaves
/// the tolerance an order of magnitude above that noise, so that a
/// tolerance at the floor is met and proved by the arithmetic.
inline constexpr double tolerance_floor_ulps = 64;

/// The smallest relative accuracy of arc lengths that means anything in
/// double arithmetic: the accuracy arc_length() aims at when asked for less
/// (8 machine epsilons, about 1.8e-15).
inline constexpr double min_relative_accuracy = 8 * std::numeric_limits<double>::epsilon();

/// The spacing of doubles at magnitude |m| (that of the smallest positive
/// normal double for m = 0, so that the result is never 0; finite for the
/// largest double too).
inline double ulp_at(double m) noexcept {
    m = std::max(std::abs(m), std::numeric_limits<double>::min());
    const double up = std::nextafter(m, std::numeric_limits<double>::infinity());
    return std::isfinite(up) ? up - m : m - std::nextafter(m, 0.0);  // the largest double: the spacing below it
}

/// The smallest meaningful distance tolerance for coordinates whose largest
/// magnitude is max_abs: tolerance_floor_ulps * ulp(max_abs). Unit
/// coordinates give about 1.4e-14, coordinates near 1e6 about 7.5e-9.
inline double min_distance_tolerance(double max_abs) noexcept {
    return tolerance_floor_ulps * ulp_at(max_abs);
}

/// The same for flat coordinates (any dimension): their largest magnitude.
inline double min_distance_tolerance(std::span<const double> coords) noexcept {
    double m = 0;
    for (const double x : coords) m = std::max(m, std::abs(x));
    return min_distance_tolerance(m);
}

}  // namespace crspline
