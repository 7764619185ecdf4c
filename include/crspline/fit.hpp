// crspline: fitting a Catmull-Rom curve with few control points to dense or
// noisy samples, within a proved tolerance.
//
// fit(points, options) returns a curve and a report. What it promises, for
// every input it accepts:
// - every point of the curve is within `tolerance` of the input polyline,
//   and every input point within `tolerance` of the curve: proved segment
//   by segment against the input points the segment covers (see
//   detail/fit_proof.hpp), rounding included; `deviation` is the largest
//   bound proved (<= tolerance);
// - mode subset: the control points are input points (`indices`), the
//   first and last of an open line among them;
// - mode free: the control points may move off the input points, onto the
//   middles of the input segments (detail/fit_free.hpp), for noisy data;
//   proved the same way;
// - always met: where no choice of points keeps the tolerance (a curve
//   through every input point can overshoot a sharp kink), the tension of
//   the vertices there is raised (0.5, 0.8, 0.95, 1, as Kochanek-Bartels
//   tension per vertex, so the curve remembers it): at 1 on both ends a
//   segment is its input segment, exact. The choice itself sets each
//   vertex's tension (0 to 0.95) where that saves points;
// - a closed curve keeps three control points at least, at any tolerance.
//
// Bad input throws invalid_input: a tolerance that is not a positive
// number, or below the rounding floor of the coordinates (the message names
// the floor) or below fit_smallest_tolerance; a non-finite coordinate, or
// one beyond fit_largest_coordinate (index and coordinate named); fewer
// than 2 distinct points (3 for a closed curve); an end condition other
// than natural or reflect (the fit chooses the ends' tangents), or any on a
// closed curve.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "catmull_rom.hpp"
#include "detail/fit_free.hpp"
#include "detail/fit_model.hpp"
#include "detail/fit_subset.hpp"
#include "detail/format.hpp"
#include "end_condition.hpp"
#include "error.hpp"
#include "vec.hpp"

namespace crspline {

enum class fit_mode {
    subset,  ///< control points are input points
    free,    ///< control points may move (noisy data)
};

/// How to fit. `tolerance` has no default: it is the fit's one question.
template <std::size_t D, class T = double>
struct fit_options {
    double tolerance = 0;               ///< distance allowed both ways, in the points' units (> 0)
    fit_mode mode = fit_mode::subset;
    std::optional<double> alpha{};      ///< knot exponent in [0, 1]; default centripetal (0.5)
    bool closed = false;                ///< the points are a ring (first point not repeated)
    T tension = 0;                      ///< the curve's tension in [0, 1] (raised per vertex where needed)
    end_condition<D, T> start = end_condition<D, T>::natural();  ///< natural or reflect
    end_condition<D, T> end = end_condition<D, T>::natural();    ///< natural or reflect
};

/// The fitted curve and what was proved about it.
template <std::size_t D, class T = double>
struct fit_result {
    catmull_rom<D, T> curve;
    /// Proved bound on the distance both ways (<= tolerance).
    T deviation = 0;
    /// The two directions: curve to input polyline, input points to curve.
    T curve_to_input = 0, input_to_curve = 0;
    /// Subset mode: the input index of each control point (empty in free mode).
    std::vector<std::size_t> indices;
    /// Control points of the curve.
    std::size_t count = 0;
    /// Vertices whose tension was raised above the curve's own.
    std::size_t tensioned = 0;
    /// The rounding floor of the input: tolerances at or below it are refused.
    T rounding_floor = 0;
};

/// Largest absolute coordinate of the points (the scale of the rounding).
template <std::size_t D, class T>
T fit_scale(std::span<const vec<D, T>> points) noexcept {
    T m = 0;
    for (const auto& p : points) m = std::max(m, max_abs(p));
    return m;
}

/// The rounding floor: 256 ulps of the largest coordinate. The proof allows
/// a quarter of it for the rounding of its own arithmetic, so a tolerance
/// must be larger.
template <std::size_t D, class T>
T fit_rounding_floor(std::span<const vec<D, T>> points) noexcept {
    return T(256) * std::numeric_limits<T>::epsilon() * std::max(fit_scale(points), std::numeric_limits<T>::min());
}

/// The largest coordinate fit() accepts: differences of two coordinates,
/// squared and summed over D, with room for a product of two such, stay
/// finite (sqrt(max / (16 D)): 2.4e153 for 2-D doubles, 3.3e18 for 2-D floats).
template <std::size_t D, class T>
T fit_largest_coordinate() noexcept {
    return std::sqrt(std::numeric_limits<T>::max() / T(16 * D));
}

/// The smallest tolerance fit() accepts: its square a normal number
/// (1.5e-154 for doubles, 1.1e-19 for floats).
template <class T>
T fit_smallest_tolerance() noexcept {
    return std::sqrt(std::numeric_limits<T>::min());
}

namespace detail {

template <std::size_t D, class T>
void check_fit_input(std::span<const vec<D, T>> points, const fit_options<D, T>& opt) {
    const double tol = opt.tolerance;
    if (!(tol > 0) || !std::isfinite(tol))
        throw invalid_input("fit: tolerance must be a positive finite number, got " + num(tol));
    // The proof's arithmetic squares distances: they must stay finite, and
    // the tolerance's square a normal number (beyond, an overflow gave a
    // "proof" of a straight line through a random walk, and an underflow a
    // proof that could not close).
    const T hi = fit_largest_coordinate<D, T>(), lo = fit_smallest_tolerance<T>();
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t k = 0; k < D; ++k) {
            if (!std::isfinite(points[i][k]))
                throw invalid_input("fit: point " + std::to_string(i) + " has a non-finite coordinate " +
                                    std::to_string(k) + ": " + num(double(points[i][k])));
            if (!(std::abs(points[i][k]) <= hi))
                throw invalid_input("fit: point " + std::to_string(i) + " coordinate " + std::to_string(k) + " is " +
                                    num(double(points[i][k])) + ", beyond the " + num(double(hi)) +
                                    " the proof's arithmetic covers (its squared distances must stay finite): "
                                    "scale the points and the tolerance");
        }
    if (opt.alpha && !(*opt.alpha >= 0 && *opt.alpha <= 1))
        throw invalid_input("fit: alpha must be in [0, 1], got " + num(*opt.alpha));
    if (!(opt.tension >= 0 && opt.tension <= 1))
        throw invalid_input("fit: tension must be in [0, 1], got " + num(double(opt.tension)));
    using kind = typename end_condition<D, T>::kind;
    if (opt.start.type == kind::tangent || opt.end.type == kind::tangent)
        throw invalid_input("fit: the end conditions must be natural or reflect (the fit chooses the end tangents)");
    if (opt.closed && (opt.start.type != kind::natural || opt.end.type != kind::natural))
        throw invalid_input(std::string("fit: a closed curve takes no end conditions, got ") +
                            (opt.start.type != kind::natural ? "start" : "end") + " reflect");
    const std::size_t need = opt.closed ? 3 : 2;
    if (points.size() < need)
        throw invalid_input("fit: needs at least " + std::to_string(need) + " points" + (opt.closed ? " (closed)" : "") +
                            ", got " + std::to_string(points.size()));
    if (!(tol >= double(lo)))
        throw invalid_input("fit: tolerance " + num(tol) + " is below " + num(double(lo)) +
                            ", the smallest the proof's arithmetic covers (its square must be a normal number): "
                            "scale the points and the tolerance");
    const T floor = fit_rounding_floor(points);
    if (!(T(tol) > floor))
        throw invalid_input("fit: tolerance " + num(tol) + " is at or below the rounding floor " +
                            num(double(floor)) + " of the coordinates (256 ulps of the largest, " +
                            num(double(fit_scale(points))) + ")");
}

}  // namespace detail

/// Fits a curve with few control points within `opt.tolerance` of the
/// points, both ways (see the file comment). Throws invalid_input on bad input.
template <std::size_t D, class T>
fit_result<D, T> fit(std::span<const vec<D, T>> points, const fit_options<D, T>& opt) {
    detail::check_fit_input(points, opt);
    // 1. Consecutive duplicates (and a closing repeat of the first point)
    //    carry no shape: drop them, remembering where each kept point was.
    std::vector<vec<D, T>> pts;
    std::vector<std::size_t> origin;
    pts.reserve(points.size());
    origin.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!pts.empty() && points[i] == pts.back()) continue;
        pts.push_back(points[i]);
        origin.push_back(i);
    }
    if (opt.closed)
        while (pts.size() > 1 && pts.back() == pts.front()) {
            pts.pop_back();
            origin.pop_back();
        }
    const std::size_t need = opt.closed ? 3 : 2;
    if (pts.size() < need)
        throw invalid_input("fit: needs at least " + std::to_string(need) + " distinct points" +
                            (opt.closed ? " (closed)" : "") + ", got " + std::to_string(pts.size()));
    // 2. The problem: options, tolerance, rounding slack.
    detail::fit_problem<D, T> pb;
    pb.pts = std::span<const vec<D, T>>(pts);
    pb.closed = opt.closed;
    pb.alpha = opt.alpha.value_or(0.5);
    pb.tension = opt.tension;
    pb.start_reflect = opt.start.type == end_condition<D, T>::kind::reflect;
    pb.end_reflect = opt.end.type == end_condition<D, T>::kind::reflect;
    pb.tolerance = T(opt.tolerance);
    const T floor = fit_rounding_floor(std::span<const vec<D, T>>(pts));
    pb.slack = floor / T(4);
    // 3. Choose, prove, repair. The search starts every vertex at tension
    //    level 2 (0.8: where a curve through stair steps bulges, tension
    //    keeps it nearer its chords and saves points); the improvement then
    //    sets each vertex's level (0 to 0.95) where that lets it drop a
    //    point. Where that choice hardly needs its tension (at most one
    //    vertex in 5 keeps the tolerance only with it: a smooth line), the
    //    search runs again from level 0, which wins a tie (a smooth line
    //    keeps no tension, and takes fewer points: 13 instead of 16 on an
    //    ellipse). The first search walks greedily, the second looks two
    //    segments ahead (fit_subset.hpp): with one in 20 there, 45 noisy
    //    sines took 6% more points than with the lookahead in both, with
    //    one in 5 0.5% fewer. On the real corpus (BENCHMARKS.md) the second
    //    search runs on a fifth of the lines: running it on every line saved
    //    0.5% of the points at twice the time. (Lowering every level again as far as
    //    the tolerance allows changed the corpus' counts by under 0.2%, and
    //    with the layer's proofs, which hold less tension worse, kept 19%
    //    more points on the NYC boroughs.)
    detail::fit_selection<D, T> sel;
    bool smooth = true;
    for (std::uint8_t base : {std::uint8_t(2), std::uint8_t(0)}) {
        if (base == 0 && !smooth) break;
        pb.base_level = base;
        std::size_t tensioned = 0, chosen = 0;
        std::size_t* count_needed = base == 2 ? &tensioned : nullptr;  // the second search's is not asked
        detail::fit_selection<D, T> s = opt.mode == fit_mode::subset ? detail::fit_subset(pb, count_needed, chosen)
                                                                     : detail::fit_free(pb, count_needed, chosen);
        if (base == 2) smooth = 5 * tensioned <= chosen;
        if (sel.idx.empty() || s.idx.size() <= sel.idx.size()) sel = std::move(s);
    }
    // 4. The report.
    const std::size_t nv = opt.closed ? sel.idx.size() - 1 : sel.idx.size();
    std::vector<std::uint8_t> levels(sel.level.begin(), sel.level.begin() + std::ptrdiff_t(nv));
    std::vector<vec<D, T>> cp(nv);
    for (std::size_t k = 0; k < nv; ++k) cp[k] = sel.pos[k];
    fit_result<D, T> r{catmull_rom<D, T>(std::span<const vec<D, T>>(cp), pb.curve_options(levels)), 0, 0, 0, {}, 0, 0, 0};
    r.curve_to_input = sel.curve_to_input;
    r.input_to_curve = sel.input_to_curve;
    r.deviation = std::max(r.curve_to_input, r.input_to_curve);
    r.count = nv;
    r.rounding_floor = floor;
    for (auto l : levels) r.tensioned += l > 0;
    if (opt.mode == fit_mode::subset) {
        r.indices.resize(nv);
        for (std::size_t k = 0; k < nv; ++k) r.indices[k] = origin[sel.idx[k] % pts.size()];
    }
    return r;
}

/// The same for a vector of points.
template <std::size_t D, class T>
fit_result<D, T> fit(const std::vector<vec<D, T>>& points, const fit_options<D, T>& opt) {
    return fit(std::span<const vec<D, T>>(points), opt);
}

}  // namespace crspline
