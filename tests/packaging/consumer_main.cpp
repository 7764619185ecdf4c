// A downstream program: builds a centripetal curve and checks a few values.
// Returns non-zero if any check fails, so CTest sees a broken package.
#include <crspline/crspline.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

int main() {
    const std::vector<std::array<double, 2>> points{{{0, 0}}, {{1, 2}}, {{3, 3}}, {{4, 0}}};
    const auto curve = crspline::make_catmull_rom(points);
    int failures = 0;
    // Interpolation at every knot.
    for (std::size_t i = 0; i < points.size(); ++i) {
        const auto p = curve.evaluate_as<std::array<double, 2>>(curve.grid()[i]);
        if (p != points[i]) ++failures;
    }
    // Centripetal knots: t1 = |P1 - P0|^(1/2) = 5^(1/4).
    if (std::abs(curve.grid()[1] - std::pow(5.0, 0.25)) > 1e-15) ++failures;
    // The arc length of a segment is at least its chord.
    if (crspline::arc_length(curve.segment(1)) < std::hypot(2.0, 1.0)) ++failures;
    std::printf("crspline %s consumer: %d failures\n", crspline::version, failures);
    return failures == 0 ? 0 : 1;
}
