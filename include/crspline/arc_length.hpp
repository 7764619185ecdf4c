// crspline: arc length, its inverse, and sampling by arc length.
//
// Lengths come from Gauss-Legendre quadrature of the speed |C'(u)|. The fast
// path (detail/speed_quadrature.hpp) proves, before integrating, which rule
// of 8 to 64 points meets the accuracy on a segment (or on the pieces it is
// cut into) from the speed's complex singularities, found for several
// segments at once and checked by Rouche's theorem: one rule evaluation per
// piece, no search, no allocation. Pieces it cannot prove
// (the speed vanishes in or near them) take the slower path: each is first split where |C'|^2 has a critical point, so that a
// zero of the speed (a cusp, a fold, tension 1, a coincident neighbour) sits
// at the end of a piece, where sqrt(|C'|^2) is analytic: the quadrature then
// converges geometrically instead of stalling on a kink. Pieces are halved
// until an 8-point rule and its two halves agree to the requested accuracy.
//
// Accuracy is relative to the length measured: the default 1e-12 means
// |computed - exact| <= 1e-12 * length (clamped to a few ulps of the scalar
// type: float reaches about 1e-6).
//
// The parts: detail/length_quadrature.hpp (the pieces and rules),
// arc_length_table.hpp (the table for many queries); here the lengths of a
// segment and of a curve, t at arc length, and sampling by arc length.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "arc_length_table.hpp"
#include "catmull_rom.hpp"
#include "detail/format.hpp"
#include "detail/length_quadrature.hpp"
#include "error.hpp"
#include "segment.hpp"

namespace crspline {

/// Length of a segment over local [u0, u1] (default the whole segment), to
/// relative accuracy `accuracy`, give or take the rounding of the speed
/// itself: at most 64 eps (|c1| + 2 |c2| + 3 |c3|) (u1 - u0) more, which
/// matters only for a short range where the curve nearly stops.
template <std::size_t D, class T>
T arc_length(const cubic_segment<D, T>& s, T u0, T u1, T accuracy = T(default_accuracy)) {
    detail::check_accuracy(accuracy);
    if (!(u0 >= 0 && u1 <= 1 && u0 <= u1))
        throw invalid_input("segment range [" + detail::num(double(u0)) + ", " + detail::num(double(u1)) +
                            "] is not inside [0, 1]");
    return detail::segment_length(s, u0, u1, accuracy);
}
template <std::size_t D, class T>
T arc_length(const cubic_segment<D, T>& s, T accuracy = T(default_accuracy)) {
    return arc_length(s, T(0), T(1), accuracy);
}

/// Length of the whole curve.
template <std::size_t D, class T>
T arc_length(const catmull_rom<D, T>& curve, T accuracy = T(default_accuracy)) {
    detail::check_accuracy(accuracy);
    // Summed per segment, then segment by segment (as arc_length_table).
    T sum = 0, within = 0;
    std::size_t current = 0;
    const auto segments = curve.segments();
    detail::for_each_segment_length_piece(
        curve.segment_count(), [&](std::size_t i) { return segments[i]; }, accuracy,
        [&](std::size_t i, T, T, T len, const detail::rule_choice&) {
            if (i != current) sum += within, within = 0, current = i;
            within += len;
        });
    return sum + within;
}

/// Length of every segment, each to relative accuracy `accuracy` (their
/// sum in order is arc_length(curve, accuracy), bit for bit). Memory: the
/// answer only (no table of quadrature pieces).
template <std::size_t D, class T>
std::vector<T> segment_arc_lengths(const catmull_rom<D, T>& curve, T accuracy = T(default_accuracy)) {
    detail::check_accuracy(accuracy);
    std::vector<T> out(curve.segment_count(), T(0));
    const auto segments = curve.segments();
    detail::for_each_segment_length_piece(
        curve.segment_count(), [&](std::size_t i) { return segments[i]; }, accuracy,
        [&](std::size_t i, T, T, T len, const detail::rule_choice&) { out[i] += len; });
    return out;
}

/// Length of the curve between parameters ta <= tb (checked).
template <std::size_t D, class T>
T arc_length(const catmull_rom<D, T>& curve, T ta, T tb, T accuracy = T(default_accuracy)) {
    detail::check_accuracy(accuracy);
    for (T t : {ta, tb})
        if (!(t >= curve.t_min() && t <= curve.t_max()))
            throw out_of_domain("t = " + detail::num(double(t)) + " is outside the domain [" +
                                detail::num(double(curve.t_min())) + ", " + detail::num(double(curve.t_max())) + "]");
    if (!(ta <= tb))
        throw invalid_input("interval [" + detail::num(double(ta)) + ", " + detail::num(double(tb)) + "] is reversed");
    const std::size_t i0 = curve.locate(ta), i1 = curve.locate(tb);
    T sum = 0;
    for (std::size_t i = i0; i <= i1; ++i) {
        const auto& s = curve.segment(i);
        const T a = i == i0 ? std::clamp(s.local(ta), T(0), T(1)) : T(0);
        const T b = i == i1 ? std::clamp(s.local(tb), T(0), T(1)) : T(1);
        sum += detail::segment_length(s, a, b, accuracy);
    }
    return sum;
}

/// Parameter at arc length s from the start (builds a table: for many
/// queries build an arc_length_table once).
template <std::size_t D, class T>
T t_at_arc_length(const catmull_rom<D, T>& curve, T s, T accuracy = T(default_accuracy)) {
    return arc_length_table<D, T>(curve, accuracy).t_at(s);
}

/// Samples of a curve: parameters, arc lengths and points.
template <std::size_t D, class T>
struct samples {
    std::vector<T> t;
    std::vector<T> s;
    std::vector<vec<D, T>> points;
};

/// Positions at arc lengths s (any order; sorted is fastest).
template <std::size_t D, class T>
std::vector<vec<D, T>> evaluate_at_arc_length(const catmull_rom<D, T>& curve, const arc_length_table<D, T>& table,
                                              std::span<const T> s) {
    const std::vector<T> t = table.t_at(s);
    std::vector<T> tc(t);
    for (T& x : tc) x = std::clamp(x, curve.t_min(), curve.t_max());
    return curve.evaluate(std::span<const T>(tc));
}

/// n >= 2 points evenly spaced in arc length, first and last at the ends of
/// the curve; spacing exact to the table's accuracy. With at least as many
/// samples as segments they come from an arc_length_table (t equal to its
/// t_at(s) bit for bit); with fewer, the memory is the output and one length
/// per segment: no table, a segment's quadrature pieces are rebuilt when a
/// sample falls in it and dropped after (same promise, t within it of the
/// table's).
template <std::size_t D, class T>
samples<D, T> sample_arc_length(const catmull_rom<D, T>& curve, std::size_t n, T accuracy = T(default_accuracy)) {
    if (n < 2) throw invalid_input("need at least 2 samples, got " + std::to_string(n));
    if (n >= curve.segment_count()) {
        const arc_length_table<D, T> table(curve, accuracy);
        samples<D, T> out;
        out.s.resize(n);
        for (std::size_t k = 0; k < n; ++k) out.s[k] = table.total() * (T(k) / T(n - 1));
        out.s.back() = table.total();
        out.t = table.t_at(std::span<const T>(out.s));
        out.t.front() = curve.t_min();
        out.t.back() = curve.t_max();
        out.points = curve.evaluate(std::span<const T>(out.t));
        return out;
    }
    const std::vector<T> lengths = segment_arc_lengths(curve, accuracy);  // checks accuracy
    // Summed in order, as arc_length(curve) and arc_length_table::total().
    T total = 0;
    for (T len : lengths) total += len;
    samples<D, T> out;
    out.s.resize(n);
    for (std::size_t k = 0; k < n; ++k) out.s[k] = total * (T(k) / T(n - 1));
    out.s.back() = total;
    out.t.resize(n);
    // The tolerance of arc_length_table::t_at: a quarter of the accuracy.
    const T tol = std::max(accuracy, T(4) * std::numeric_limits<T>::epsilon()) * total / T(4);
    std::size_t i = 0;  // the segment holding the sample: the last to start at or before it
    T start = 0;        // arc length at its start
    std::optional<detail::segment_inverse<D, T>> inverse;
    std::size_t inverse_of = lengths.size();
    for (std::size_t k = 0; k < n; ++k) {
        while (i + 1 < lengths.size() && start + lengths[i] <= out.s[k]) start += lengths[i++];
        if (inverse_of != i) inverse.emplace(curve.segment(i), accuracy), inverse_of = i;
        const auto& seg = inverse->segment();
        const T u = inverse->u_at(out.s[k] - start, tol);
        out.t[k] = std::min(seg.t0 + u * seg.h, curve.t_max());
    }
    out.t.front() = curve.t_min();
    out.t.back() = curve.t_max();
    out.points = curve.evaluate(std::span<const T>(out.t));
    return out;
}

}  // namespace crspline
