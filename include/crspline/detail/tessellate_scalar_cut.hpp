// crspline internal: tessellate()'s greedy cut of one segment, scalar: the
// text tessellate() had before the lanes (tessellate_lanes.hpp), the
// reference they are tested against bit for bit, and the path for float.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

#include "../segment.hpp"
#include "../vec.hpp"

namespace crspline::detail {

/// The cut of one segment as tessellate() made it before the lanes: calls
/// vertex(t) for each vertex strictly inside segment s (its parameter t),
/// in order, from the segment's start a to its end t_end. The reference
/// the lanes are tested against, and the path for float.
template <std::size_t D, class T, class Bound, class Vertex>
void tessellate_scalar_cut(const cubic_segment<D, T>& s, T a, T t_end, T tolerance, std::size_t n_uniform,
                           const Bound& flatness_bound, Vertex&& vertex) {
    // Local u of a vertex parameter, as evaluate() computes it.
    auto u_of = [&](T t) { return t == t_end ? T(1) : s.local(t); };
    for (;;) {
        const T u0 = u_of(a);
        // A piece bound (1) of flatness_bound proves, in closed form:
        // |C''| is convex in u, so on [u0, u0 + w] with w <= w0 its
        // maximum is at most max(|C''(u0)|, |C''(u0 + w0)|), and
        // w = sqrt(8 tol / that maximum) meets w^2 / 8 max|C''| <= tol.
        const T k0 = norm(s.du(u0, 2));
        const T w0 = k0 > 0 ? std::sqrt(T(8) * tolerance / k0) : T(1) - u0;
        const T k1 = std::max(k0, norm(s.du(std::min(T(1), u0 + w0), 2)));
        const T w1 = k1 > 0 ? std::sqrt(T(8) * tolerance / k1) : T(1) - u0;
        // lo: the end of the longest piece proved so far (f its bound);
        // hi: the nearest end not proved (t_end until tested).
        T lo = a, hi = t_end, f = 0, f_hi = 0;
        bool end_failed = false;
        auto test = [&](T t) {
            const T ft = flatness_bound(s, u0, u_of(t), k0);
            if (ft <= tolerance) {
                lo = t, f = ft;
                return true;
            }
            hi = t, f_hi = ft;
            end_failed = end_failed || t == t_end;
            return false;
        };
        auto open = [&](T t) { return t > lo && (t < hi || (t == t_end && !end_failed)); };
        const T first = std::min(t_end, a + w1 * s.h);
        if (open(first)) test(first);
        // No closed-form start proved (rounding): bisect from a until a
        // piece is.
        for (int halve = 0; halve < 64 && !(lo > a); ++halve) {
            const T mid = lo + (hi - lo) / 2;
            if (!(mid > lo && mid < hi)) break;
            test(mid);
        }
        // Both bounds grow about like the square of the piece's width
        // (bound (1) exactly; bound (2) as the control points' distance
        // to the chord): from a proved width w with bound f, the longest
        // width is about w sqrt(tol / f). Steps to 1% short of that
        // prediction (the segment's end when it is within reach), each
        // checked by the full bound, and after a failed one a step back
        // from its end, bring lo within a few per cent of the longest
        // piece the bound allows: about two bounds per vertex, where
        // testing the rest of the segment, doubling and four halvings
        // took nine.
        for (int step = 0; step < 4 && lo > a && lo < t_end; ++step) {
            const T grow = f > 0 ? std::min(T(4), T(0.99) * std::sqrt(tolerance / f)) : T(4);
            if (!(grow > T(1.02))) break;
            T next = std::min(t_end, a + grow * (lo - a));
            if (!open(next)) next = lo + (hi - lo) / 2;
            if (!open(next)) break;
            if (test(next)) continue;
            const T back = a + (next - a) * T(0.99) * std::sqrt(tolerance / f_hi);
            if (back > lo + (hi - lo) / 8 && back < hi) test(back);
            break;
        }
        if (lo == t_end) return;
        // Never shorter than the uniform pieces (1/n of the segment, n =
        // uniform_piece_count, proved by bound (1) with |C''| at its
        // larger end), so a segment never gets more than n pieces.
        lo = std::max(lo, std::min(t_end, a + s.h / T(n_uniform)));
        // Below rounding no piece qualifies: step to the next parameter.
        if (lo == a) lo = hi;
        if (lo == t_end) return;
        vertex(lo);
        a = lo;
    }
}

}  // namespace crspline::detail
