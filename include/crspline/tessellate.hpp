// crspline: sampling and adaptive tessellation of a curve into a polyline.
//
// tessellate() returns a polyline within a distance tolerance of the curve,
// proved piece by piece by a closed-form flatness bound (pbrt-v4 style: the
// error is guaranteed, not hoped for), with pieces chosen greedily as long
// as that bound allows, so vertex counts stay close to the minimum.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "bounds.hpp"
#include "catmull_rom.hpp"
#include "detail/format.hpp"
#include "detail/storage.hpp"
#include "detail/tessellate_lanes.hpp"
#include "error.hpp"
#include "segment.hpp"
#include "vec.hpp"

namespace crspline {

/// The default tessellation tolerance, relative to the curve's bounding-box
/// diagonal (see tessellation_tolerance).
inline constexpr double default_tessellation_tolerance = 1e-3;

/// Vertices of a polyline and the curve parameter t of each:
/// points[k] == curve.evaluate(t[k]) exactly, t increasing.
template <std::size_t D, class T = double>
struct polyline {
    std::vector<vec<D, T>> points;
    std::vector<T> t;
};

/// n points evenly spaced in t from t_min to t_max inclusive (n >= 2). The
/// ends are exact: the first and last control points of an open curve; a
/// closed curve gives its start point at both ends (first == last).
template <std::size_t D, class T>
std::vector<vec<D, T>> sample_t(const catmull_rom<D, T>& c, std::size_t n) {
    if (n < 2) throw invalid_input("sample_t needs at least 2 points, got " + std::to_string(n));
    const T a = c.t_min(), b = c.t_max();
    std::vector<vec<D, T>> out(n);
    for (std::size_t k = 0; k < n; ++k) {
        // The last parameter is t_max itself, never a rounding of it.
        const T t = k + 1 == n ? b : std::min(b, a + (b - a) * (T(k) / T(n - 1)));
        out[k] = c.evaluate_unchecked(t);
    }
    return out;
}

/// Upper bound on the distance between the piece u in [u0, u1] of segment s
/// and its chord from s.at(u0) to s.at(u1), both ways (every point of the
/// piece is that close to the chord and every point of the chord that close
/// to the piece). The smaller of two bounds, each a proof:
///
/// 1. Second differences. Let e(u) = C(u) - L(u), L the linear interpolant
///    of C at u0 and u1 (so L(u) runs over the chord). e vanishes at both
///    ends and e'' = C'', so e(u) = -int G(u, v) C''(v) dv with the Green's
///    function G >= 0 of d^2/du^2 on [u0, u1], int G(u, v) dv = (u - u0)(u1 - u)/2:
///        |e(u)| <= (u - u0)(u1 - u)/2 max|C''| <= (u1 - u0)^2 / 8 max|C''|.
///    C'' = 2 c2 + 6 c3 u is affine in u, so |C''| is convex and its maximum
///    on the piece is at u0 or u1: the bound is exact in closed form.
/// 2. Convex hull. The piece lies in the hull of its Bézier points Q0..Q3
///    and the distance to the chord Q0Q3 is convex, so it is at most
///    max(dist(Q1, chord), dist(Q2, chord)). The piece runs from Q0 to Q3,
///    so every chord point is the foot of some curve point, no farther.
///
/// (1) is exact for a parabola-like piece; (2) sees that acceleration along
/// the chord (a change of speed, not of direction) adds no distance.
/// Computed relative to s.at(u0), so to within rounding of the coordinates.
/// `k0` is |C''(u0)| (tessellate() tests many pieces from one u0).
template <std::size_t D, class T>
T flatness_bound(const cubic_segment<D, T>& s, T u0, T u1, T k0) {
    using point = vec<D, T>;
    const T w = u1 - u0;
    // 1. (u1 - u0)^2 / 8 times |C''| at the worse end.
    const T curvature = std::max(k0, norm(s.du(u1, 2)));
    const T by_second_difference = w * w / T(8) * curvature;
    // 2. Bézier points of the piece relative to Q0: Q1 = Q0 + w/3 C'(u0),
    //    Q2 = Q3 - w/3 C'(u1), and Q3 - Q0 = C(u1) - C(u0) factored as
    //    w [c1 + (u0 + u1) c2 + (u0^2 + u0 u1 + u1^2) c3] (no cancellation).
    const point chord = w * (s.c1 + (u0 + u1) * s.c2 + (u0 * u0 + u0 * u1 + u1 * u1) * s.c3);
    const point q1 = (w / T(3)) * s.du(u0, 1);
    const point q2 = chord - (w / T(3)) * s.du(u1, 1);
    const T len2 = dot(chord, chord);
    auto to_chord = [&](const point& q) __attribute__((always_inline)) {
        const T f = len2 > 0 ? std::clamp(dot(q, chord) / len2, T(0), T(1)) : T(0);
        return q - f * chord;
    };
    const point e1 = to_chord(q1), e2 = to_chord(q2);
    // max(|e1|, |e2|) with one square root where norm() takes the plain
    // formula for both (sqrt is monotone: the same number).
    T by_hull;
    if constexpr (D == 1) {
        by_hull = std::max(norm(e1), norm(e2));
    } else {
        const T m = std::max(max_abs(e1), max_abs(e2));
        by_hull = detail::plain_norm_range<D>(m) ? std::sqrt(std::max(dot(e1, e1), dot(e2, e2)))
                                                 : std::max(norm(e1), norm(e2));
    }
    return std::min(by_second_difference, by_hull);
}

/// flatness_bound for a piece from u0 alone.
template <std::size_t D, class T>
T flatness_bound(const cubic_segment<D, T>& s, T u0, T u1) {
    return flatness_bound(s, u0, u1, norm(s.du(u0, 2)));
}

/// Number of equal pieces in u that bound (1) of flatness_bound proves
/// enough for a whole segment: ceil(sqrt(max|C''| / (8 tolerance))), at
/// least 1 (pbrt-v4's subdivision count). tessellate() never uses more
/// pieces on a segment than this.
template <std::size_t D, class T>
std::size_t uniform_piece_count(const cubic_segment<D, T>& s, std::type_identity_t<T> tolerance) {
    const T curvature = std::max(norm(s.du(T(0), 2)), norm(s.du(T(1), 2)));
    const double n = std::ceil(std::sqrt(double(curvature) / (8.0 * double(tolerance))));
    return n > 1 ? std::size_t(n) : std::size_t(1);
}

/// The tolerance `relative` times the curve's bounding-box diagonal (the
/// smallest normal number of T for a curve that is a single point, so that
/// it is always a valid tolerance).
template <std::size_t D, class T>
T tessellation_tolerance(const catmull_rom<D, T>& c, double relative = default_tessellation_tolerance) {
    const T tol = T(relative * double(bounding_box(c).diagonal()));
    return tol > 0 ? tol : std::numeric_limits<T>::min();
}

/// Adaptive tessellation: a polyline whose distance to the curve (both ways,
/// piece by piece) is at most `tolerance`, an absolute distance, up to the
/// rounding of the coordinates.
///
/// - Vertices lie on the curve: points[k] == c.evaluate(t[k]) exactly.
/// - Every knot is a vertex, once; the first vertex is the curve's start,
///   the last its end (a closed curve ends at its first point exactly).
/// - Each segment is cut greedily: from a vertex, a piece that bound (1) of
///   flatness_bound proves in closed form, grown while flatness_bound still
///   proves it, by steps predicted from the bound's growth like the width
///   squared (usually within a few per cent of the longest provable piece),
///   so a segment gets at most uniform_piece_count pieces and usually fewer.
/// - A constant segment (a repeated point) adds no vertex; a straight
///   segment at constant speed is one piece; a curve that is a single point
///   gives its two ends (t_min and t_max, equal when all knots coincide).
///
/// Throws invalid_input when the tolerance is not positive and finite.
/// Tolerances below the rounding of the coordinates cannot be met; pieces
/// then stop shrinking at adjacent floating-point parameters.
template <std::size_t D, class T>
polyline<D, T> tessellate(const catmull_rom<D, T>& c, std::type_identity_t<T> tolerance) {
    if (!(tolerance > 0 && std::isfinite(tolerance)))
        throw invalid_input("tolerance must be positive and finite, got " + detail::num(double(tolerance)));
    polyline<D, T> out;
    const auto grid = c.grid();
    const std::size_t n = c.segment_count();
    // With AVX2 (or AVX-512) and enough segments: several segments at a time
    // (detail/tessellate_lanes.hpp), the same vertices. (Short curves one
    // by one: the lanes' buffers cost more than they save there; smoothing
    // GIS lines of 10-50 vertices, each tessellated alone, grew from 23 to
    // 34 us per line between 10^4 and 10^6 lines through the lanes, 27 to
    // 29-30 one by one: BENCHMARKS.md, issue 29.)
    bool lanes = false;
    if constexpr (std::is_same_v<T, double>) lanes = n >= detail::cut_lanes_from && detail::cut_in_lanes();
    // Room for the most vertices there can be (uniform_piece_count per
    // segment bounds them), capped: the pages never written are never
    // touched (where large, they are advised for huge pages), and the
    // vectors neither grow nor copy on the way.
    std::size_t most = 2;
    for (std::size_t i = 0; i < n && most < (std::size_t(1) << 24); ++i)
        most += uniform_piece_count(c.segment(i), tolerance);
    most = std::min(most, std::size_t(1) << 24);
    out.t.reserve(most);
    detail::advise_huge_pages(out.t.data(), most * sizeof(T));
    if (!lanes) out.points.reserve(most);
    out.t.push_back(c.t_min());
    if (!lanes) out.points.push_back(c.evaluate_unchecked(c.t_min()));
    if (lanes) {
        if constexpr (std::is_same_v<T, double>) {
            // Each segment's vertices put back in order, by blocks of
            // segments, so that the lanes' buffers stay small and warm.
            constexpr std::size_t block = 1024;
            std::vector<double> buf[detail::cut_width];
            std::vector<detail::cut_record> rec(std::min(n, block));
            for (std::size_t i0 = 0; i0 < n; i0 += block) {
                const std::size_t m = std::min(block, n - i0);
                for (auto& b : buf) b.clear();
                detail::cut_segments<D>(
                    m, [&](std::size_t j) { return c.segment(i0 + j); }, grid.data() + i0, double(tolerance), buf,
                    rec.data());
                for (std::size_t j = 0; j < m; ++j) {
                    const detail::cut_record& r = rec[j];
                    if (r.lane < 0) continue;  // a constant segment: its end is its start, already a vertex
                    const double* from = buf[r.lane].data() + r.start;
                    out.t.insert(out.t.end(), from, from + r.count);
                    out.t.push_back(grid[i0 + j + 1]);
                }
            }
        }
    } else {
        // One segment at a time; a vertex strictly inside segment s is what
        // evaluate_unchecked(t) computes there (its segment is s), without
        // locating it.
        for (std::size_t i = 0; i < n; ++i) {
            const cubic_segment<D, T>& s = c.segment(i);
            // A constant segment: its end is its start, already a vertex.
            if (s.c1 == vec<D, T>{} && s.c2 == vec<D, T>{} && s.c3 == vec<D, T>{}) continue;
            detail::tessellate_scalar_cut(
                s, grid[i], grid[i + 1], tolerance, uniform_piece_count(s, tolerance),
                [](const cubic_segment<D, T>& seg, T u0, T u1, T k0) { return flatness_bound(seg, u0, u1, k0); },
                [&](T t) {
                    out.t.push_back(t);
                    out.points.push_back(s.dt(s.local(t), 0));
                });
            out.t.push_back(grid[i + 1]);
            out.points.push_back(c.evaluate_unchecked(grid[i + 1]));
        }
    }
    // Trailing constant segments: the last vertex is already the end point;
    // a curve that is a single point gets its two ends.
    if (out.t.size() == 1) {
        out.t.push_back(c.t_max());
        if (!lanes) out.points.push_back(c.evaluate_unchecked(c.t_max()));
    } else if (out.t.back() != c.t_max()) {
        out.t.back() = c.t_max();
        if (!lanes) out.points.back() = c.evaluate_unchecked(c.t_max());
    }
    if (lanes) {
        // The vertices: evaluate() at each t, as one sorted batch (the same
        // bits as one at a time), into pages advised for huge pages.
        out.points.reserve(out.t.size());
        detail::advise_huge_pages(out.points.data(), out.t.size() * sizeof(vec<D, T>));
        out.points.resize(out.t.size());
        c.evaluate(std::span<const T>(out.t), std::span<vec<D, T>>(out.points));
    }
    return out;
}

/// Adaptive tessellation at the default tolerance: default_tessellation_tolerance
/// (1e-3) times the bounding-box diagonal.
template <std::size_t D, class T>
polyline<D, T> tessellate(const catmull_rom<D, T>& c) {
    return tessellate(c, tessellation_tolerance(c));
}

}  // namespace crspline
