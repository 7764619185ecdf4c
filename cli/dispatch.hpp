// crspline command line: from the run-time dimension to the compile-time one.
//
// The library fixes the dimension at compile time (catmull_rom<D, T>); the
// input fixes it at run time. with_dimension() calls a generic lambda with
// std::integral_constant<std::size_t, D> for D = 1..4, and make_curve<D>()
// builds the curve from the run-time description.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <crspline/crspline.hpp>
#include <crspline/dispatch.hpp>

#include "json_input.hpp"

namespace crspline::cli {

inline constexpr std::size_t max_dimension = max_runtime_dimension;

/// f(std::integral_constant<std::size_t, D>{}) for the given dimension 1..4
/// (crspline::with_dimension with the CLI's error).
template <class F>
decltype(auto) with_dimension(std::size_t dimension, F&& f) {
    return crspline::with_dimension(dimension, std::forward<F>(f), [](std::size_t d) {
        throw input_error("points: expected 1 to 4 coordinates per point, got " + std::to_string(d));
    });
}

/// The coordinates of a run-time point as a vec<D> (the size was validated).
template <std::size_t D>
vec<D, double> to_point(const std::vector<double>& c) {
    vec<D, double> p;
    for (std::size_t k = 0; k < D; ++k) p[k] = c[k];
    return p;
}

template <std::size_t D>
end_condition<D, double> to_end_condition(const end_spec& e) {
    switch (e.type) {
        case end_spec::kind::reflect: return end_condition<D, double>::reflect();
        case end_spec::kind::tangent: return end_condition<D, double>::tangent(to_point<D>(e.velocity));
        case end_spec::kind::natural: break;
    }
    return end_condition<D, double>::natural();
}

/// The library's options for a validated description.
template <std::size_t D>
options<D, double> to_options(const curve_spec& c) {
    options<D, double> opt;
    opt.alpha = c.alpha;
    opt.grid = c.grid;
    opt.closed = c.closed;
    if (!c.closed) {
        opt.start = to_end_condition<D>(c.start);
        opt.end = to_end_condition<D>(c.end);
    }
    opt.tension = c.tension;
    opt.kb.tension = c.kb_tension;
    opt.kb.continuity = c.kb_continuity;
    opt.kb.bias = c.kb_bias;
    opt.strict = c.strict;
    return opt;
}

/// Builds the curve; the library throws invalid_input for what the
/// description cannot rule out by itself (coincident points in strict mode).
template <std::size_t D>
catmull_rom<D, double> make_curve(const curve_spec& c) {
    std::vector<vec<D, double>> pts;
    pts.resize(c.point_count());
    for (std::size_t i = 0; i < pts.size(); ++i)
        for (std::size_t k = 0; k < D; ++k) pts[i][k] = c.coords[i * D + k];
    if (!c.tangents_out.empty()) {
        // Given tangents: the Hermite curve on the given grid or alpha's knots.
        std::vector<vec<D, double>> out(pts.size()), in(pts.size());
        const std::vector<double>& given_in = c.tangents_in.empty() ? c.tangents_out : c.tangents_in;
        for (std::size_t i = 0; i < pts.size(); ++i)
            for (std::size_t k = 0; k < D; ++k) out[i][k] = c.tangents_out[i * D + k], in[i][k] = given_in[i * D + k];
        const std::span<const vec<D, double>> p(pts);
        const std::vector<double> grid = c.grid ? *c.grid : knots(p, c.alpha.value_or(centripetal), c.closed);
        return catmull_rom<D, double>::hermite(p, out, in, grid, c.closed);
    }
    return catmull_rom<D, double>(std::span<const vec<D, double>>(pts), to_options<D>(c));
}

}  // namespace crspline::cli
