// crspline: from a dimension known at run time to the compile-time one.
//
// The library fixes the dimension at compile time (catmull_rom<D, T>); front
// ends (the CLI, Python, WebAssembly) learn it from their input. with_dimension
// calls a generic callable with std::integral_constant<std::size_t, D> for
// D = 1..4; any other dimension goes to `unsupported(dimension)`, which must
// throw the front end's own error (crspline::invalid_input if it returns).
#pragma once

#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>

#include "error.hpp"

namespace crspline {

/// The dimensions with_dimension() instantiates.
inline constexpr std::size_t max_runtime_dimension = 4;

template <class F, class Unsupported>
decltype(auto) with_dimension(std::size_t dimension, F&& f, Unsupported&& unsupported) {
    switch (dimension) {
        case 1: return std::forward<F>(f)(std::integral_constant<std::size_t, 1>{});
        case 2: return std::forward<F>(f)(std::integral_constant<std::size_t, 2>{});
        case 3: return std::forward<F>(f)(std::integral_constant<std::size_t, 3>{});
        case 4: return std::forward<F>(f)(std::integral_constant<std::size_t, 4>{});
        default:
            std::forward<Unsupported>(unsupported)(dimension);
            throw invalid_input("dimension " + std::to_string(dimension) + " is not 1 to 4");
    }
}

}  // namespace crspline
