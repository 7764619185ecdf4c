// crspline: the parameterization step, points (+ alpha or a grid) -> knots.
//
//   t(0) = 0,  t(i+1) = t(i) + |P(i+1) - P(i)|^alpha,  alpha in [0, 1]
//
// A closed curve has one more knot than points: the last interval is
// |P(0) - P(N-1)|^alpha.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "detail/format.hpp"
#include "error.hpp"
#include "vec.hpp"

namespace crspline {

inline constexpr double uniform = 0.0;      ///< alpha = 0: every knot interval is 1
inline constexpr double centripetal = 0.5;  ///< alpha = 1/2: the default; no cusps or loops in a segment
inline constexpr double chordal = 1.0;      ///< alpha = 1: intervals equal to chord lengths

/// Throws invalid_input unless alpha is a number in [0, 1]. Never clamps.
inline void check_alpha(double alpha) {
    if (!(alpha >= 0.0 && alpha <= 1.0))
        throw invalid_input("alpha must be in [0, 1], got " + detail::num(alpha));
}

/// Throws invalid_input naming the first point and coordinate that is NaN or infinite.
template <std::size_t D, class T>
void check_finite(std::span<const vec<D, T>> points) {
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t k = 0; k < D; ++k)
            if (!std::isfinite(points[i][k]))
                throw invalid_input("point " + std::to_string(i) + ", coordinate " + std::to_string(k) +
                                    " is not finite (" + detail::num(double(points[i][k])) + ")");
}

/// True when the chord from a to b is zero up to rounding: its length is at
/// most a few ulps of the local scale (the larger coordinate magnitude of the
/// two points and of the neighbouring chords). Such a chord gets a zero knot
/// interval when alpha > 0: the "zero chord velocity" limit convention.
template <std::size_t D, class T>
bool coincident(const vec<D, T>& a, const vec<D, T>& b, T neighbour_scale = T(0)) noexcept {
    const T scale = std::max({max_abs(a), max_abs(b), neighbour_scale});
    // 8 ulps: a chord that small is below the rounding noise of coordinates
    // of that size, so its direction (and for alpha = 1 its tangent) is noise.
    return max_abs(b - a) <= T(8) * std::numeric_limits<T>::epsilon() * scale;
}

/// Indices i of the chords P(i) -> P(i+1) (wrapping for a closed curve) that
/// are coincident in the sense above.
template <std::size_t D, class T>
std::vector<std::size_t> coincident_chords(std::span<const vec<D, T>> p, bool closed) {
    std::vector<std::size_t> out;
    const std::size_t n = p.size();
    if (n < 2) return out;
    const std::size_t chords = closed ? n : n - 1;
    auto chord = [&](std::size_t i) { return max_abs(p[(i + 1) % n] - p[i % n]); };
    for (std::size_t i = 0; i < chords; ++i) {
        T scale = 0;
        if (i > 0 || closed) scale = std::max(scale, chord((i + chords - 1) % chords));
        if (i + 1 < chords || closed) scale = std::max(scale, chord((i + 1) % chords));
        if (coincident(p[i], p[(i + 1) % n], scale)) out.push_back(i);
    }
    return out;
}

/// Knot intervals |P(i+1) - P(i)|^alpha, one per chord (n - 1, or n when
/// closed, the last one wrapping to P(0)). Coincident chords (see
/// coincident()) get a zero interval when alpha > 0.
template <std::size_t D, class T>
std::vector<T> knot_intervals(std::span<const vec<D, T>> p, double alpha, bool closed = false) {
    check_alpha(alpha);
    check_finite(p);
    const std::size_t n = p.size();
    std::vector<T> h(n < 2 ? 0 : (closed ? n : n - 1));
    std::vector<bool> zero(h.size(), false);
    if (alpha > 0)
        for (std::size_t i : coincident_chords(p, closed)) zero[i] = true;
    for (std::size_t i = 0; i < h.size(); ++i) {
        if (alpha == 0) h[i] = 1;
        else if (zero[i]) h[i] = 0;
        else {
            const T d = norm(p[(i + 1) % n] - p[i]);
            h[i] = alpha == 1 ? d : alpha == 0.5 ? std::sqrt(d) : T(std::pow(double(d), alpha));
        }
    }
    return h;
}

/// Knots t(0) = 0, t(i+1) = t(i) + interval(i): n knots, n + 1 when closed.
template <std::size_t D, class T>
std::vector<T> knots(std::span<const vec<D, T>> p, double alpha, bool closed = false) {
    const std::vector<T> h = knot_intervals(p, alpha, closed);
    std::vector<T> t(p.empty() ? 0 : h.size() + 1);
    if (t.empty()) return t;
    t[0] = 0;
    for (std::size_t i = 0; i < h.size(); ++i) t[i + 1] = t[i] + h[i];
    return t;
}

/// Throws invalid_input unless the grid has `expected` finite, strictly
/// increasing values.
template <class T>
void check_grid(std::span<const T> grid, std::size_t expected, bool closed) {
    if (grid.size() != expected)
        throw invalid_input("grid has " + std::to_string(grid.size()) + " values, expected " +
                            std::to_string(expected) +
                            (closed ? " (one per point plus one: a closed curve repeats the first knot)"
                                    : " (one per point)"));
    for (std::size_t i = 0; i < grid.size(); ++i) {
        if (!std::isfinite(grid[i]))
            throw invalid_input("grid[" + std::to_string(i) + "] is not finite (" + detail::num(double(grid[i])) + ")");
        if (i > 0 && !(grid[i] > grid[i - 1]))
            throw invalid_input("grid must be strictly increasing: grid[" + std::to_string(i) + "] = " +
                                detail::num(double(grid[i])) + " is not greater than grid[" +
                                std::to_string(i - 1) + "] = " + detail::num(double(grid[i - 1])));
    }
}

}  // namespace crspline
