// crspline command line: from the run-time dimension to the compile-time one.
//
// The library fixes the dimension at compile time (catmull_rom<D, T>); the
// input fixes it at run time. with_dimension() calls a generic lambda with
// std::integral_constant<std::size_t, D> for the storage dimension (the
// input's for 1..4, the zero-padded wide curve of 16 for 5..16; see
// crspline/dispatch.hpp), and make_curve<D>() builds the curve from the
// run-time description.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <crspline/crspline.hpp>
#include <crspline/dispatch.hpp>
#include <crspline/spec.hpp>

#include "json_input.hpp"

namespace crspline::cli {

inline constexpr std::size_t max_dimension = max_runtime_dimension;

/// f(std::integral_constant<std::size_t, D>{}) for the given dimension 1..16
/// (crspline::with_dimension with the CLI's error).
template <class F>
decltype(auto) with_dimension(std::size_t dimension, F&& f) {
    return crspline::with_dimension(dimension, std::forward<F>(f), [](std::size_t d) {
        throw input_error("points: expected 1 to " + std::to_string(max_dimension) + " coordinates per point, got " + std::to_string(d));
    });
}

/// Builds the curve of storage dimension D (the description's own, or the
/// zero-padded wide one, see crspline/dispatch.hpp); the library throws
/// invalid_input for what the description cannot rule out by itself
/// (coincident points in strict mode).
template <std::size_t D>
catmull_rom<D, double> make_curve(const curve_spec& c) {
    if (!c.tangents_out.empty()) {
        // Given tangents: the Hermite curve on the given grid or alpha's
        // knots (coordinates past the description's dimension stay zero).
        const std::size_t dim = c.dimension, n = c.point_count();
        std::vector<vec<D, double>> pts(n), out(n), in(n);
        const std::vector<double>& given_in = c.tangents_in.empty() ? c.tangents_out : c.tangents_in;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t k = 0; k < dim && k < D; ++k) {
                pts[i][k] = c.points[i * dim + k];
                out[i][k] = c.tangents_out[i * dim + k];
                in[i][k] = given_in[i * dim + k];
            }
        const std::span<const vec<D, double>> p(pts);
        const std::vector<double> grid = c.grid ? *c.grid : knots(p, c.alpha.value_or(centripetal), c.closed);
        return catmull_rom<D, double>::hermite(p, out, in, grid, c.closed);
    }
    try {
        return crspline::make_curve<D, double>(c.core());
    } catch (const crspline::spec_error& e) {  // coincident points in strict mode
        throw input_error(describe_spec_error(e, c));
    }
}

/// The first `dimension` coordinates of a point: the input's own, without the
/// padding of a wide curve.
template <std::size_t D>
std::vector<double> coords(const vec<D, double>& p, std::size_t dimension) {
    return std::vector<double>(p.v.begin(), p.v.begin() + std::ptrdiff_t(std::min(dimension, D)));
}

}  // namespace crspline::cli
