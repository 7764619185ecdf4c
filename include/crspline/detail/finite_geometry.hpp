// crspline internal: the check, at construction, that a curve's numbers
// are finite (issue 31): finite coordinates can still have a difference,
// a knot interval, a sum of knots, a tangent or a Bezier point that
// overflows (points (-1.5e308, 0) and (1.5e308, 0): the chord is 3e308).
// crspline refuses such a curve, naming the points, rather than compute it
// rescaled: every later answer (arc length, bounds, analysis) would need the
// same rescaling, and a curve spanning more than the double range has no
// finite length to report anyway.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>

#include "../vec.hpp"
#include "format.hpp"
#include "validate.hpp"

namespace crspline::detail {

/// Throws spec_error (field "points", the index of the first point named)
/// unless every chord P(j) - P(i) and its length, every knot interval and
/// knot, every tangent dx/dt, and every segment's Bezier points and
/// power-basis coefficients (the numbers evaluation sums) are finite.
/// points, h (the knot intervals), grid (the knots), out(i) and in(i) (the
/// outgoing and incoming tangents dx/dt at vertex i) as catmull_rom stores
/// them; segment i runs from point i to point (i + 1) mod n.
///
/// Fast path: with mp, mm, mh the largest |coordinate| of the points, of
/// the tangents and the largest interval, every chord is at most 2 mp, every
/// u-tangent h m at most mh mm, the power coefficients (c1 = m0, c2 = 3 (P1
/// - P0) - 2 m0 - m1, c3 = m0 + m1 - 2 (P1 - P0), u-tangents) at most 6 mp
/// + 3 mh mm, a Bezier point at most mp + mh mm / 3, and the sums that
/// evaluate a point or a u-derivative at u in [0, 1] at most |P0| + |c1| +
/// 2 |c2| + 6 |c3| <= 25 mp + 13 mh mm. So when 32 mp + 16 mh mm is finite
/// (and the last knot is), all of them are: one pass over the arrays, no
/// per-segment work. Otherwise the slow path checks each of them, segment
/// by segment, and names the first that fails.
/// The fast path's test: with mp, mm, mh the largest magnitudes of the
/// points, the tangents and the intervals (all finite), everything named
/// below is finite when 32 mp + 16 mh mm and the last knot are.
template <class T>
bool finite_geometry_bounded(T mp, T mm, T mh, T last_knot) noexcept {
    return std::isfinite(T(32) * mp + T(16) * (mh * mm)) && std::isfinite(last_knot);
}

template <std::size_t D, class T, class Out, class In>
void check_finite_geometry(std::span<const vec<D, T>> points, std::span<const T> h, std::span<const T> grid,
                           Out&& out, In&& in) {
    const std::size_t n = points.size(), nseg = h.size();
    if (n == 0 || nseg == 0) return;
    // 1. The largest magnitudes; probe = x - x summed is 0 while every x is
    //    finite, NaN once one is not (a max alone would skip a NaN).
    T mp = 0, mm = 0, mh = 0, probe = 0;
    const auto grow = [&](T& m, const vec<D, T>& x) {
        for (std::size_t k = 0; k < D; ++k) {
            m = std::max(m, std::abs(x[k]));
            probe += x[k] - x[k];
        }
    };
    for (std::size_t i = 0; i < n; ++i) grow(mp, points[i]), grow(mm, out(i)), grow(mm, in(i));
    for (std::size_t i = 0; i < nseg; ++i) mh = std::max(mh, h[i]), probe += h[i] - h[i];
    if (probe == 0 && finite_geometry_bounded(mp, mm, mh, grid.back())) return;

    // 2. The first failure by name, causes before what they cause: every
    //    chord, then every knot interval and knot, then every tangent (a
    //    natural end's tangent is made from its neighbour's), then every
    //    segment's Bezier points and coefficients.
    const auto finite = [](const vec<D, T>& x) {
        for (std::size_t k = 0; k < D; ++k)
            if (!std::isfinite(x[k])) return false;
        return true;
    };
    const auto next = [&](std::size_t i) { return i + 1 == n ? std::size_t(0) : i + 1; };
    const auto pair = [&](std::size_t i) {
        return "points " + std::to_string(i) + " and " + std::to_string(next(i)) + ": ";
    };
    for (std::size_t i = 0; i < nseg; ++i) {
        const vec<D, T> chord = points[next(i)] - points[i];
        if (!finite(chord) || !std::isfinite(norm(chord)))
            spec_fail("points", i, std::nullopt, "",
                      pair(i) + "the chord between them overflows (|P" + std::to_string(next(i)) + " - P" +
                          std::to_string(i) + "| is not finite)");
    }
    for (std::size_t i = 0; i < nseg; ++i) {
        if (!std::isfinite(h[i]))
            spec_fail("points", i, std::nullopt, num(double(h[i])),
                      pair(i) + "the knot interval between them overflows (t(" + std::to_string(i + 1) + ") - t(" +
                          std::to_string(i) + ") = " + num(double(h[i])) + ")");
        if (!std::isfinite(grid[i + 1]))
            spec_fail("points", i, std::nullopt, num(double(grid[i + 1])),
                      pair(i) + "the knot t(" + std::to_string(i + 1) + ") overflows (the sum of the intervals " +
                          "up to it is " + num(double(grid[i + 1])) + ")");
    }
    for (std::size_t v = 0; v < n; ++v)
        if (!finite(out(v)) || !finite(in(v)))
            spec_fail("points", v, std::nullopt, "",
                      "point " + std::to_string(v) + ": the tangent there overflows (dx/dt is not finite)");
    for (std::size_t i = 0; i < nseg; ++i) {
        // The Bezier points and the power coefficients of the segment (as
        // cubic_segment::hermite forms them), and the sums that evaluate it
        // and its u-derivatives: |P0| + |c1| + |c2| + |c3| bounds Horner's
        // partial sums at u in [0, 1], |c1| + 2 |c2| + 3 |c3| the first
        // derivative's, 2 |c2| + 6 |c3| the second's and third's.
        const std::size_t j = next(i);
        const vec<D, T> chord = points[j] - points[i];
        const vec<D, T> m0 = h[i] * out(i), m1 = h[i] * in(j);
        const vec<D, T> b1 = points[i] + m0 / T(3), b2 = points[j] - m1 / T(3);
        const vec<D, T> c2 = T(3) * chord - T(2) * m0 - m1, c3 = m0 + m1 - T(2) * chord;
        bool ok = finite(b1) && finite(b2) && finite(c2) && finite(c3);
        for (std::size_t k = 0; k < D && ok; ++k) {
            const T a0 = std::abs(points[i][k]), a1 = std::abs(m0[k]), a2 = std::abs(c2[k]), a3 = std::abs(c3[k]);
            ok = std::isfinite(a0 + a1 + a2 + a3) && std::isfinite(a1 + T(2) * a2 + T(3) * a3) &&
                 std::isfinite(T(2) * a2 + T(6) * a3);
        }
        if (!ok)
            spec_fail("points", i, std::nullopt, "",
                      pair(i) + "the segment between them overflows (its Bezier points or coefficients are " +
                          "not finite)");
    }
}

}  // namespace crspline::detail
