// crspline for JavaScript: one segment analysed from its four control
// points (analyzeSegment, the oracle's case) and the library's version,
// bound with Embind beside bindings.cpp (web/build.sh links every
// web/src/*.cpp into one module).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <crspline/analysis.hpp>
#include <crspline/dispatch.hpp>
#include <crspline/report.hpp>
#include <crspline/version.hpp>

#include <array>
#include <string>
#include <vector>

#include "js_values.hpp"

namespace {

using namespace crspline_js;

// One segment analysed from its four control points (the oracle's case):
// alpha, tension as in options.
template <std::size_t D>
val analyze_segment_d(const std::vector<double>& flat, std::size_t dim, double alpha, double tension) {
    const auto p = to_points<D>(flat, "points", dim);
    if (p.size() != 4) throw cr::invalid_input("a segment needs 4 points, got " + std::to_string(p.size()));
    const auto a = cr::analyze_segment(std::array<cr::vec<D>, 4>{p[0], p[1], p[2], p[3]}, alpha, tension);
    js_builder b;
    return cr::report_segment(b, a, a.segment.t0, a.segment.t0 + a.segment.h);
}

val analyzeSegment(val points, int dimension, double alpha, double tension) {
    return guarded([&] {
        const std::vector<double> flat = numbers(points, "points");
        const std::size_t dim = dimension > 0 ? std::size_t(dimension) : 0;
        return cr::with_dimension(
            dim, [&](auto d) { return analyze_segment_d<decltype(d)::value>(flat, dim, alpha, tension); },
            [&](std::size_t) {
                throw cr::invalid_input("dimension must be 1 to " + std::to_string(cr::max_runtime_dimension) +
                                        ", got " + std::to_string(dimension));
            });
    });
}

std::string version() { return cr::version; }

}  // namespace

EMSCRIPTEN_BINDINGS(crspline_segment) {
    using namespace emscripten;
    function("analyzeSegment", &analyzeSegment);
    function("version", &version);
}
