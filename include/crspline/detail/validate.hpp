// crspline internal: the validation of a curve description, in one place.
//
// catmull_rom's constructor (typed points, compile-time dimension) and
// crspline::validate(curve_spec) (flat doubles, run-time dimension) both call
// validate_description(); parameterization's public checks (check_alpha,
// check_finite, check_grid) are the pieces of it. Every failure is a
// spec_error naming the field, the index and the value.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "../error.hpp"
#include "format.hpp"

namespace crspline::detail {

[[noreturn]] inline void spec_fail(std::string field, std::optional<std::size_t> index,
                                   std::optional<std::size_t> component, std::string value,
                                   const std::string& message) {
    throw spec_error(std::move(field), index, component, std::move(value), message);
}

inline void check_alpha_value(double alpha) {
    if (!(alpha >= 0.0 && alpha <= 1.0))
        spec_fail("alpha", std::nullopt, std::nullopt, num(alpha), "alpha must be in [0, 1], got " + num(alpha));
}

inline void check_point_count(std::size_t n, bool closed) {
    if (n < 2)  // a closed curve through 2 points is a loop of two segments
        spec_fail("points", std::nullopt, std::nullopt, std::to_string(n),
                  std::string(closed ? "a closed curve" : "a curve") + " needs at least 2 points, got " +
                      std::to_string(n));
}

inline void check_alpha_or_grid(bool alpha, bool grid) {
    if (alpha && grid) spec_fail("grid", std::nullopt, std::nullopt, "", "give alpha or grid, not both");
}

/// coord(i, k): coordinate k of point i, for i < n, k < dim.
template <class Coord>
void check_coordinates(std::size_t n, std::size_t dim, Coord&& coord) {
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < dim; ++k) {
            const double x = double(coord(i, k));
            if (!std::isfinite(x))
                spec_fail("points", i, k, num(x),
                          "point " + std::to_string(i) + ", coordinate " + std::to_string(k) + " is not finite (" +
                              num(x) + ")");
        }
}

template <class T>
void check_grid_values(std::span<const T> grid, std::size_t expected, bool closed) {
    if (grid.size() != expected)
        spec_fail("grid", std::nullopt, std::nullopt, std::to_string(grid.size()),
                  "grid has " + std::to_string(grid.size()) + " values, expected " + std::to_string(expected) +
                      (closed ? " (one per point plus one: a closed curve repeats the first knot)"
                              : " (one per point)"));
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const double g = double(grid[i]);
        if (!std::isfinite(g))
            spec_fail("grid", i, std::nullopt, num(g), "grid[" + std::to_string(i) + "] is not finite (" + num(g) + ")");
        if (i > 0 && !(grid[i] > grid[i - 1]))
            spec_fail("grid", i, std::nullopt, num(g),
                      "grid must be strictly increasing: grid[" + std::to_string(i) + "] = " + num(g) +
                          " is not greater than grid[" + std::to_string(i - 1) + "] = " + num(double(grid[i - 1])));
    }
}

/// One end of an open curve as the checks see it: natural, reflect, or a
/// tangent with its coordinates.
enum class end_kind { natural, reflect, tangent };
template <class T>
struct end_view {
    end_kind type = end_kind::natural;
    std::span<const T> velocity{};
};

/// The whole description: n points of dim coordinates (coord(i, k)), alpha
/// or grid, closed, the two ends, tension, Kochanek-Bartels values. The
/// geometric check of strict mode (coincident points) is the constructor's.
template <class T, class Coord>
void validate_description(std::size_t n, std::size_t dim, Coord&& coord, const std::optional<double>& alpha,
                          const std::optional<std::vector<T>>& grid, bool closed, end_view<T> start,
                          end_view<T> end, double tension, const std::vector<T>& kb_tension,
                          const std::vector<T>& kb_continuity, const std::vector<T>& kb_bias,
                          bool coordinates_checked = false) {
    check_point_count(n, closed);
    // (The curve's constructor checks the coordinates itself, in one
    // reduction over the flat array: detail/magnitude.hpp.)
    if (!coordinates_checked) check_coordinates(n, dim, coord);
    check_alpha_or_grid(alpha.has_value(), grid.has_value());
    if (!(tension >= 0 && tension <= 1))
        spec_fail("tension", std::nullopt, std::nullopt, num(tension),
                  "tension must be in [0, 1], got " + num(tension));
    if (closed && (start.type != end_kind::natural || end.type != end_kind::natural))
        spec_fail(start.type != end_kind::natural ? "start" : "end", std::nullopt, std::nullopt, "",
                  "a closed curve takes no end conditions");
    for (const auto& [e, name] : {std::pair{start, "start"}, std::pair{end, "end"}}) {
        if (e.type != end_kind::tangent) continue;
        if (e.velocity.size() != dim)
            spec_fail(name, std::nullopt, std::nullopt, std::to_string(e.velocity.size()),
                      std::string(name) + " tangent has " + std::to_string(e.velocity.size()) +
                          " coordinates, expected " + std::to_string(dim) + " like the points");
        for (std::size_t k = 0; k < dim; ++k)
            if (!std::isfinite(double(e.velocity[k])))
                spec_fail(name, std::nullopt, k, num(double(e.velocity[k])),
                          std::string(name) + " tangent coordinate " + std::to_string(k) + " is not finite (" +
                              num(double(e.velocity[k])) + ")");
    }
    const std::size_t first_kb = closed ? 0 : 1, last_kb = closed ? n : n - 1;  // vertices that use TCB
    const std::pair<const std::vector<T>*, const char*> tcb[3] = {
        {&kb_tension, "tension"}, {&kb_continuity, "continuity"}, {&kb_bias, "bias"}};
    for (const auto& [vals, name] : tcb) {
        if (vals->empty()) continue;
        const std::string field = std::string("kb.") + name;
        if (vals->size() != n)
            spec_fail(field, std::nullopt, std::nullopt, std::to_string(vals->size()),
                      std::string("kb ") + name + " has " + std::to_string(vals->size()) +
                          " values, expected one per point (" + std::to_string(n) + ")");
        for (std::size_t i = first_kb; i < last_kb; ++i)
            if (!std::isfinite(double((*vals)[i])))
                spec_fail(field, i, std::nullopt, num(double((*vals)[i])),
                          std::string("kb ") + name + "[" + std::to_string(i) + "] is not finite (" +
                              num(double((*vals)[i])) + ")");
    }
    if (grid) check_grid_values(std::span<const T>(*grid), closed ? n + 1 : n, closed);
    else check_alpha_value(alpha.value_or(0.5));
}

}  // namespace crspline::detail
