// crspline: the parameterization step, points (+ alpha or a grid) -> knots.
//
//   t(0) = 0,  t(i+1) = t(i) + |P(i+1) - P(i)|^alpha,  alpha in [0, 1]
//
// A closed curve has one more knot than points: the last interval is
// |P(0) - P(N-1)|^alpha.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "detail/format.hpp"
#include "detail/magnitude.hpp"
#include "detail/validate.hpp"
#include "error.hpp"
#include "vec.hpp"

namespace crspline {

inline constexpr double uniform = 0.0;      ///< alpha = 0: every knot interval is 1
inline constexpr double centripetal = 0.5;  ///< alpha = 1/2: the default; no cusps or loops in a segment
inline constexpr double chordal = 1.0;      ///< alpha = 1: intervals equal to chord lengths

/// Throws invalid_input (a spec_error) unless alpha is a number in [0, 1]. Never clamps.
inline void check_alpha(double alpha) { detail::check_alpha_value(alpha); }

/// Throws invalid_input (a spec_error) naming the first point and coordinate
/// that is NaN or infinite.
template <std::size_t D, class T>
void check_finite(std::span<const vec<D, T>> points) {
    detail::check_coordinates(points.size(), D, [&](std::size_t i, std::size_t k) { return points[i][k]; });
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

namespace detail {

/// In place, x[i] = x[i] > 0 ? sqrt(x[i]) : 0 - x[i] for i < n: two square
/// roots per instruction with SSE2 (correctly rounded, so the same bits as
/// std::sqrt), which halves the cost of the knots' roots.
template <class T>
void sqrt_or_negate(T* x, std::size_t n) noexcept {
    std::size_t i = 0;
#if defined(__SSE2__)
    if constexpr (std::is_same_v<T, double>) {
        const __m128d zero = _mm_setzero_pd();
        for (; i + 2 <= n; i += 2) {
            const __m128d v = _mm_loadu_pd(x + i);
            const __m128d pos = _mm_cmpgt_pd(v, zero);
            const __m128d r = _mm_sqrt_pd(_mm_max_pd(v, zero));
            _mm_storeu_pd(x + i, _mm_or_pd(_mm_and_pd(pos, r), _mm_andnot_pd(pos, _mm_sub_pd(zero, v))));
        }
    }
#endif
    for (; i < n; ++i) x[i] = x[i] > 0 ? std::sqrt(x[i]) : T(0) - x[i];
}

/// The squared length of chord i (or its negated length where norm()
/// rescales, or 0 when it is coincident), decided on the window of three
/// chords as coincident_chords() does: the chord and its two neighbours set
/// the scale.
template <std::size_t D, class T>
T interval_square_in_window(std::span<const vec<D, T>> p, bool closed, std::size_t i) noexcept {
    const std::size_t n = p.size(), chords = closed ? n : n - 1;
    auto chord = [&](std::size_t j) { return p[j + 1 == n ? 0 : j + 1] - p[j]; };
    const T tiny = T(8) * std::numeric_limits<T>::epsilon();  // as coincident()
    const vec<D, T> d = chord(i);
    const T m = max_abs(d);
    const T m_prev = i > 0 ? max_abs(chord(i - 1)) : closed ? max_abs(chord(chords - 1)) : T(0);
    const T m_next = i + 1 < chords ? max_abs(chord(i + 1)) : closed ? max_abs(chord(0)) : T(0);
    const T a_here = max_abs(p[i]), a_next = max_abs(p[i + 1 == n ? 0 : i + 1]);
    const T scale = std::max(std::max(a_here, a_next), std::max(m_prev, m_next));
    const bool zero = m <= tiny * scale, plain = plain_norm_range<D>(m);
    return zero ? T(0) : plain ? dot(d, d) : -norm(d);
}

/// Writes the knot intervals, as knot_intervals() defines them, to h[0 ..
/// chords): a window of three chords decides coincidence exactly as
/// coincident_chords() does, and the roots are taken afterwards two at a
/// time. Points must be finite. max_abs_points, the largest |coordinate|,
/// when the caller knows it (else computed here).
///
/// Fast path (issue 30): every scale of the window is at most 2 M, M the
/// largest |coordinate| (a chord's coordinate is a difference of two), so a
/// chord with max_abs(d) > L = max(fl(8 eps 2 M), the plain norm's lower
/// limit) is neither coincident nor rescaled by norm(); and max_abs(d)^2 >=
/// d.d / D, so d.d > 2 D L^2 (the 2 covers the roundings of both sides)
/// shows it from the square alone. Such a chord's entry is d.d, as in the
/// window; every other chord (and all of them when 2 M reaches the plain
/// norm's upper limit) takes the window's decision.
template <std::size_t D, class T>
void fill_intervals(std::span<const vec<D, T>> p, double alpha, bool closed, T* h, T max_abs_points = T(-1)) {
    const std::size_t n = p.size();
    if (n < 2) return;
    const std::size_t chords = closed ? n : n - 1;
    if (alpha == 0) {
        std::fill(h, h + chords, T(1));
        return;
    }
    const T mp = max_abs_points >= 0 ? max_abs_points : max_abs_finite(p.front().data(), n * D).max_abs;
    const T lo = std::sqrt(std::numeric_limits<T>::min()) / std::numeric_limits<T>::epsilon();
    const T hi = std::sqrt(std::numeric_limits<T>::max() / T(D));
    const T L = std::max(T(8) * std::numeric_limits<T>::epsilon() * (T(2) * mp), lo);
    const T threshold = T(2 * D) * (L * L);  // inf when L * L overflows: every chord goes to the window
    bool all_fast = T(2) * mp < hi;
    if (all_fast) {
        for (std::size_t i = 0; i < chords; ++i) {
            const vec<D, T> d = p[i + 1 == n ? 0 : i + 1] - p[i];
            const T dd = dot(d, d);
            h[i] = dd;
            all_fast &= dd > threshold;
        }
    }
    if (!all_fast)
        for (std::size_t i = 0; i < chords; ++i)
            if (!(T(2) * mp < hi) || !(h[i] > threshold)) h[i] = interval_square_in_window(p, closed, i);
    // 2. Lengths, then length^alpha.
    sqrt_or_negate(h, chords);
    if (alpha == 0.5) sqrt_or_negate(h, chords);
    else if (alpha != 1)
        for (std::size_t i = 0; i < chords; ++i) h[i] = T(std::pow(double(h[i]), alpha));
}

}  // namespace detail

/// Knot intervals |P(i+1) - P(i)|^alpha, one per chord (n - 1, or n when
/// closed, the last one wrapping to P(0)). Coincident chords (see
/// coincident()) get a zero interval when alpha > 0.
template <std::size_t D, class T>
std::vector<T> knot_intervals(std::span<const vec<D, T>> p, double alpha, bool closed = false) {
    check_alpha(alpha);
    check_finite(p);
    const std::size_t n = p.size();
    std::vector<T> h(n < 2 ? 0 : (closed ? n : n - 1));
    detail::fill_intervals(p, alpha, closed, h.data());
    return h;
}

/// Knots t(0) = 0, t(i+1) = t(i) + interval(i): n knots, n + 1 when closed.
template <std::size_t D, class T>
std::vector<T> knots(std::span<const vec<D, T>> p, double alpha, bool closed = false) {
    check_alpha(alpha);
    check_finite(p);
    const std::size_t n = p.size();
    std::vector<T> t(n == 0 ? 0 : n < 2 ? 1 : (closed ? n : n - 1) + 1);
    if (t.empty()) return t;
    t[0] = 0;
    detail::fill_intervals(p, alpha, closed, t.data() + 1);
    for (std::size_t i = 1; i < t.size(); ++i) t[i] += t[i - 1];
    return t;
}

/// Throws invalid_input (a spec_error) unless the grid has `expected`
/// finite, strictly increasing values.
template <class T>
void check_grid(std::span<const T> grid, std::size_t expected, bool closed) {
    detail::check_grid_values(grid, expected, closed);
}

}  // namespace crspline
