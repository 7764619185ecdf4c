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
#include <concepts>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <type_traits>
#include <utility>

#include "error.hpp"
#include "detail/format.hpp"

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

/// The spacing of T at magnitude |m| (that of the smallest positive normal T
/// for m = 0, so that the result is never 0; finite for the largest T too).
template <std::floating_point T>
inline T ulp_at(T m) noexcept {
    m = std::max(std::abs(m), std::numeric_limits<T>::min());
    const T up = std::nextafter(m, std::numeric_limits<T>::infinity());
    return std::isfinite(up) ? up - m : m - std::nextafter(m, T(0));  // the largest T: the spacing below it
}

/// The smallest meaningful distance tolerance for coordinates of type T whose
/// largest magnitude is max_abs: tolerance_floor_ulps * ulp(max_abs). Unit
/// double coordinates give about 1.4e-14, coordinates near 1e6 about 7.5e-9.
template <std::floating_point T>
inline T min_distance_tolerance(T max_abs) noexcept {
    return T(tolerance_floor_ulps) * ulp_at(max_abs);
}

/// The same for flat coordinates (any dimension): their largest magnitude.
inline double min_distance_tolerance(std::span<const double> coords) noexcept {
    double m = 0;
    for (const double x : coords) m = std::max(m, std::abs(x));
    return min_distance_tolerance(m);
}

// The words every front end uses (CLI, Python, WebAssembly): each prefixes
// them with the name of its option or argument ("--tolerance: ...",
// "tolerance: ...").

/// Why a distance tolerance is below what coordinates of type T with largest
/// magnitude max_abs resolve, naming the smallest meaningful value; "" when
/// it is not below, and for a tolerance that is not a positive number (the
/// caller refuses those in its own words).
template <std::floating_point T>
std::string tolerance_floor_problem(double tolerance, T max_abs) {
    const T floor = min_distance_tolerance(max_abs);
    if (!(tolerance > 0 && tolerance < double(floor))) return {};
    return detail::num(tolerance) + " is below what the coordinates resolve (their largest magnitude is spaced " +
           detail::num(double(ulp_at(max_abs))) + " apart); the smallest meaningful tolerance for this input is " +
           detail::num(double(floor));
}

/// Why a relative accuracy is below what double arithmetic resolves, naming
/// min_relative_accuracy; "" when it is not below, and for an accuracy that
/// is not a positive number (the caller refuses those in its own words).
inline std::string accuracy_floor_problem(double accuracy) {
    if (!(accuracy > 0 && accuracy < min_relative_accuracy)) return {};
    return detail::num(accuracy) + " is below what double arithmetic resolves; the smallest meaningful relative "
                                   "accuracy is " + detail::num(min_relative_accuracy);
}

/// The largest coordinate magnitude of a curve's points (anything with
/// points() giving fixed-size vectors: catmull_rom, hermite).
template <class Curve>
auto largest_magnitude(const Curve& c) noexcept {
    using P = typename decltype(c.points())::value_type;
    std::remove_cvref_t<decltype(std::declval<const P&>()[0])> m = 0;
    for (const auto& p : c.points())
        for (std::size_t k = 0; k < p.size(); ++k) m = std::max(m, std::abs(p[k]));
    return m;
}

/// Throws invalid_input("<name>: " + tolerance_floor_problem(...)) when a
/// distance tolerance is below what the curve's coordinates resolve.
template <class Curve>
void check_distance_tolerance(const Curve& c, double tolerance, const std::string& name = "tolerance") {
    const std::string why = tolerance_floor_problem(tolerance, largest_magnitude(c));
    if (!why.empty()) throw invalid_input(name + ": " + why);
}

/// Throws invalid_input("<name>: " + accuracy_floor_problem(...)) when a
/// relative accuracy is below min_relative_accuracy.
inline void check_relative_accuracy(double accuracy, const std::string& name = "accuracy") {
    const std::string why = accuracy_floor_problem(accuracy);
    if (!why.empty()) throw invalid_input(name + ": " + why);
}

}  // namespace crspline
