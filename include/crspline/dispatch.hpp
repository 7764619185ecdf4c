// crspline: from a dimension known at run time to the compile-time one.
//
// The library fixes the dimension at compile time (catmull_rom<D, T>); front
// ends (the CLI, Python, WebAssembly) learn it from their input. Instantiating
// every front end's whole API for each of 16 dimensions would multiply their
// build time by four, so the table has two kinds of entry:
//
//  - D = 1..4 (max_exact_dimension): the curve has exactly the input's
//    dimension (the fast path: 2-D and 3-D are the common cases);
//  - 5..16: one wide curve of wide_dimension = 16 coordinates, the input's
//    followed by zeros. Every coordinate of a Catmull-Rom curve is computed
//    on its own, and the zeros add exact zeros to dot products and norms, so
//    the first d coordinates are the numbers catmull_rom<d> gives, bit for bit
//    (tests/unit/test_spec.cpp checks 7-D against catmull_rom<7>); the
//    caller reports only those (storage_dimension() tells it which kind).
//
// with_dimension calls a generic callable with std::integral_constant<
// std::size_t, D> for the storage dimension D; any other dimension goes to
// `unsupported(dimension)`, which must throw the front end's own error
// (crspline::invalid_input if it returns).
#pragma once

#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>

#include "error.hpp"

namespace crspline {

/// Run-time dimensions 1..max_exact_dimension get a curve of exactly that dimension.
inline constexpr std::size_t max_exact_dimension = 4;
/// The dimension of the one wide curve that carries the others, zero-padded.
inline constexpr std::size_t wide_dimension = 16;
/// The dimensions with_dimension() accepts.
inline constexpr std::size_t max_runtime_dimension = wide_dimension;

/// The compile-time dimension with_dimension() uses for a run-time one.
constexpr std::size_t storage_dimension(std::size_t dimension) noexcept {
    return dimension <= max_exact_dimension ? dimension : wide_dimension;
}

template <class F, class Unsupported>
decltype(auto) with_dimension(std::size_t dimension, F&& f, Unsupported&& unsupported) {
    switch (dimension) {
        case 1: return std::forward<F>(f)(std::integral_constant<std::size_t, 1>{});
        case 2: return std::forward<F>(f)(std::integral_constant<std::size_t, 2>{});
        case 3: return std::forward<F>(f)(std::integral_constant<std::size_t, 3>{});
        case 4: return std::forward<F>(f)(std::integral_constant<std::size_t, 4>{});
        default:
            if (dimension > max_exact_dimension && dimension <= wide_dimension)
                return std::forward<F>(f)(std::integral_constant<std::size_t, wide_dimension>{});
            std::forward<Unsupported>(unsupported)(dimension);
            throw invalid_input("dimension " + std::to_string(dimension) + " is not 1 to " +
                                std::to_string(max_runtime_dimension));
    }
}

}  // namespace crspline
