// crspline: what fit() builds, as formulas it can try cheaply: the
// Catmull-Rom segment between two chosen points from its neighbours, the
// curve's options and the per-vertex tension levels (catmull_rom.hpp's
// construction, written for one segment at a time), and the final curve.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "../catmull_rom.hpp"
#include "../end_condition.hpp"
#include "../segment.hpp"
#include "../vec.hpp"

namespace crspline::detail {

/// Tension levels a vertex may be raised through where no choice of points
/// keeps the tolerance (geo/smooth.hpp's levels): at 1 a vertex's tangent is
/// zero, and a segment with both ends at 1 is its chord.
inline constexpr double fit_tension_levels[] = {0, 0.5, 0.8, 0.95, 1};
inline constexpr std::uint8_t fit_top_level = 4;
/// The highest level the choice gives a vertex to save a point (0.95;
/// 1, a corner, is left to the repairs). Measured on the real corpus of
/// BENCHMARKS.md while this was chosen: up to 0.8 kept 1.1% more points, up
/// to 1 0.4% fewer at a fifth more time.
inline constexpr std::uint8_t fit_improve_level = 3;

/// Bounds that keep the choice's time linear in the points where a segment
/// covers very many of them (a densely sampled smooth line: each test of a
/// segment looks at every input point it covers: without them a 4,000-point
/// sine took 3 s, and time grew with the square of the points). Measured
/// when they were set (BENCHMARKS.md, "Fit on densely sampled lines"): the
/// real corpus' subset choices the same, free mode's counts within 0.05%,
/// the NYC boroughs' GIS fit 11,879 control points instead of 11,878.
/// - where the reach from a point covers 64 input points or more, the
///   choice's candidates lie on a grid of a 64th to a 128th of it
///   (subset_search::on_grid; a grid of a 16th cost the GIS fit 3%), and
///   the reach itself is found to that grid's step (subset_search::reach);
/// - a merge in the improvement tries 64 points at most, evenly spread.
/// (The quick test also sampled its curve, 64 points at most: it now looks
/// at three points of it, fit_proof.hpp's fit_probes.)
inline constexpr std::size_t fit_choose_grid = 64;
inline constexpr std::size_t fit_merge_tries = 64;

/// The fit's fixed choices: the points (consecutive duplicates removed),
/// closed or open, alpha, the global tension and the kinds of the two ends.
template <std::size_t D, class T>
struct fit_problem {
    using point = vec<D, T>;
    std::span<const point> pts;
    bool closed = false;
    /// pts holds the input points at even indices and the middles of the
    /// input segments at odd ones (free mode): the middles are candidates
    /// for control points, but not input points to prove near the curve.
    bool odd_middles = false;
    double alpha = 0.5;
    T tension = 0;
    bool start_reflect = false, end_reflect = false;  // otherwise natural
    T tolerance = 0, slack = 0;
    /// The tension level every vertex starts at (the search tries its
    /// candidates at it; the repairs raise it where needed).
    std::uint8_t base_level = 0;

    std::size_t size() const noexcept { return pts.size(); }
    /// The point at an unrolled index (a closed curve's index size() is 0 again).
    const point& at(std::size_t i) const noexcept { return pts[i >= pts.size() ? i - pts.size() : i]; }

    T interval(const point& a, const point& b) const noexcept {
        const T d = norm(b - a);
        if (alpha == 0) return d > 0 ? T(1) : T(0);
        if (alpha == 0.5) return std::sqrt(d);
        if (alpha == 1) return d;
        return T(std::pow(double(d), alpha));
    }
    /// The plain Catmull-Rom tangent dx/dt at x between l and r, whose
    /// intervals h0 = interval(l, x) and h1 = interval(x, r) the caller has
    /// at hand (segment() takes each of its three once).
    point vertex_tangent(const point& l, const point& x, const point& r, T h0, T h1) const noexcept {
        if (!(h0 > 0) || !(h1 > 0)) return point{};
        return (h1 * ((x - l) / h0) + h0 * ((r - x) / h1)) / (h0 + h1);
    }

    /// A segment's three knot intervals: interval(p, a), interval(a, b) and
    /// interval(b, n) (0 for an absent neighbour).
    struct knots {
        T before = 0, h = 0, after = 0;
    };

    /// The segment from a to b (u in [0, 1]) with neighbours p (before a)
    /// and n (after b), absent at an open curve's ends, and the tension
    /// levels of a and b; as catmull_rom builds it up to rounding.
    cubic_segment<D, T> segment(const point* p, const point& a, const point& b, const point* n, std::uint8_t la,
                                std::uint8_t lb) const noexcept {
        return segment(p, a, b, n, la, lb, knots{p ? interval(*p, a) : T(0), interval(a, b), n ? interval(b, *n) : T(0)});
    }
    /// The same with the intervals at hand (the search keeps them by index
    /// pair: each is a function of its two points).
    cubic_segment<D, T> segment(const point* p, const point& a, const point& b, const point* n, std::uint8_t la,
                                std::uint8_t lb, const knots& k) const noexcept {
        const T h = k.h;
        const point v = h > 0 ? (b - a) / h : point{};
        const T keep = T(1) - tension;
        const T ka = T(1) - T(fit_tension_levels[la]), kb = T(1) - T(fit_tension_levels[lb]);
        point ta, tb;
        if (!p && !n) {
            ta = tb = v;  // two points: a straight line, whatever the options
        } else {
            const point cra = p ? vertex_tangent(*p, a, b, k.before, h) : point{};
            const point crb = n ? vertex_tangent(a, b, *n, h, k.after) : point{};
            if (p) ta = keep * (ka * cra);
            else ta = keep * (start_reflect ? v : (T(3) * v - kb * crb) / T(2));
            if (n) tb = keep * (kb * crb);
            else tb = keep * (end_reflect ? v : (T(3) * v - ka * cra) / T(2));
        }
        return cubic_segment<D, T>::hermite(a, b, h * ta, h * tb, T(0), T(1));
    }

    /// The curve's options: alpha, closed, ends, tension, and the tension
    /// levels as Kochanek-Bartels tension per vertex (none when all are 0).
    crspline::options<D, T> curve_options(std::span<const std::uint8_t> levels) const {
        crspline::options<D, T> o;
        o.alpha = alpha;
        o.closed = closed;
        o.tension = tension;
        o.start = start_reflect ? end_condition<D, T>::reflect() : end_condition<D, T>::natural();
        o.end = end_reflect ? end_condition<D, T>::reflect() : end_condition<D, T>::natural();
        bool any = false;
        for (auto l : levels) any = any || l > 0;
        if (any) {
            o.kb.tension.resize(levels.size());
            for (std::size_t i = 0; i < levels.size(); ++i) o.kb.tension[i] = T(fit_tension_levels[levels[i]]);
        }
        return o;
    }
};

}  // namespace crspline::detail
