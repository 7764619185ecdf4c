// crspline: the nearest point of a curve to a query point.
//
// On one segment the squared distance |C(u) - q|^2 is a degree-6
// polynomial; its stationary points are the real roots of the degree-5
// polynomial g(u) = (C(u) - q) . C'(u). The minimum over u in [0, 1] is at
// one of those roots or at an end, so the answer is exact up to rounding
// (no sampling, no tolerance to choose).
//
// A curve is searched globally: every segment is considered, and a segment
// is skipped only when the box of its Bézier control points (which holds the
// segment, by the convex-hull property) is farther than the best distance
// found so far. nearest_index puts those boxes in a bounding-volume
// hierarchy so that a query on a long curve visits few segments.
//
// Accuracy: the reported distance is within 1e-12 of the curve's scale (its
// bounding-box diagonal) of the true distance; in practice within a few
// rounding errors of |q - origin| + |coefficients|.
//
// Ties: among candidates with equal squared distance the smallest t wins,
// then the smallest segment index (a knot shared by two segments). The
// order is total, so the global search, the index and the batch forms
// return identical results.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "catmull_rom.hpp"
#include "detail/box_tree.hpp"
#include "detail/format.hpp"
#include "detail/polynomial.hpp"
#include "error.hpp"
#include "segment.hpp"
#include "vec.hpp"

namespace crspline {

/// The nearest point of a curve: its parameter, squared distance, segment
/// and position (the segment's cubic at that parameter).
template <std::size_t D, class T = double>
struct nearest_result {
    T t = 0;
    T distance_sq = 0;
    std::size_t segment = 0;
    vec<D, T> point{};
};

/// The nearest point of one segment, in its local parameter u in [0, 1].
template <class T = double>
struct segment_nearest {
    T u = 0;
    T distance_sq = 0;
};

/// Nearest point of one cubic segment (u in [0, 1]) to q. Among equal
/// distances the smallest u wins.
template <std::size_t D, class T>
segment_nearest<T> nearest(const cubic_segment<D, T>& s, const vec<D, T>& q) {
    // 1. Work relative to the segment's origin, for precision far from zero.
    const vec<D, T> d = q - s.origin;
    auto distance_sq = [&](T u) {
        const vec<D, T> e = u * (s.c1 + u * (s.c2 + u * s.c3)) - d;
        return dot(e, e);
    };
    // 2. g(u) = (C(u) - q) . C'(u), summed over the coordinates.
    std::array<T, 6> g{};
    for (std::size_t k = 0; k < D; ++k) {
        const std::array<T, 4> f{-d[k], s.c1[k], s.c2[k], s.c3[k]};
        const std::array<T, 3> df{s.c1[k], T(2) * s.c2[k], T(3) * s.c3[k]};
        const auto m = detail::multiply(f, df);
        for (std::size_t i = 0; i < g.size(); ++i) g[i] += m[i];
    }
    // 3. Candidates: u = 0, the strict local minima in order (zeros where
    //    g rises: maxima and saddles cannot be nearest), u = 1.
    segment_nearest<T> best{T(0), distance_sq(T(0))};
    auto consider = [&](T u) {
        const T d2 = distance_sq(u);
        if (d2 < best.distance_sq) best = {u, d2};
    };
    for (T u : detail::rising_roots(g)) consider(u);
    consider(T(1));
    // 4. Polish the winner with Newton steps on (C - q) . C', evaluated from
    //    the vectors (more accurate than g's expanded coefficients); a step
    //    is kept only while it shortens the distance.
    for (int it = 0; it < 4; ++it) {
        const T u0 = best.u;
        const vec<D, T> e = u0 * (s.c1 + u0 * (s.c2 + u0 * s.c3)) - d, e1 = s.du(u0, 1), e2 = s.du(u0, 2);
        const T slope = dot(e1, e1) + dot(e, e2);
        if (!(slope > 0)) break;  // not a strict local minimum: nothing to refine
        const T u = std::clamp(u0 - dot(e, e1) / slope, T(0), T(1));
        const T d2 = distance_sq(u);
        if (!(d2 < best.distance_sq)) break;
        best = {u, d2};
    }
    return best;
}

namespace detail {

/// Box of a segment's Bézier control points, widened by the rounding of the
/// conversion and of evaluation so that it holds every computed point.
template <std::size_t D, class T>
box<D, T> segment_box(const cubic_segment<D, T>& s) noexcept {
    const auto b = to_bezier(s);
    box<D, T> r{b[0], b[0]};
    for (const auto& p : b) r = merge(r, box<D, T>{p, p});
    const T margin = T(16) * std::numeric_limits<T>::epsilon() *
                     (max_abs(s.origin) + max_abs(s.c1) + max_abs(s.c2) + max_abs(s.c3));
    for (std::size_t k = 0; k < D; ++k) {
        r.lo[k] -= margin;
        r.hi[k] += margin;
    }
    return r;
}

/// A lower bound on the computed squared distance from q to anything in the
/// box: the box distance, shrunk by a relative slack for rounding in both.
template <std::size_t D, class T>
T lower_bound_sq(const box<D, T>& b, const vec<D, T>& q) noexcept {
    T s = 0;
    for (std::size_t k = 0; k < D; ++k) {
        const T e = std::max({b.lo[k] - q[k], q[k] - b.hi[k], T(0)});
        s += e * e;
    }
    return s * (T(1) - T(64 * D) * std::numeric_limits<T>::epsilon());
}

/// The total order of the results: distance, then t, then segment.
template <std::size_t D, class T>
bool better(const nearest_result<D, T>& a, const nearest_result<D, T>& b) noexcept {
    if (a.distance_sq != b.distance_sq) return a.distance_sq < b.distance_sq;
    if (a.t != b.t) return a.t < b.t;
    return a.segment < b.segment;
}

/// A result no real candidate loses to.
template <std::size_t D, class T>
nearest_result<D, T> no_result() noexcept {
    const T inf = std::numeric_limits<T>::infinity();
    return {inf, inf, std::numeric_limits<std::size_t>::max(), vec<D, T>{}};
}

/// Segment i's nearest point, in the curve's global parameter.
template <class Segments, std::size_t D, class T>
nearest_result<D, T> solve_segment(const Segments& segments, std::span<const T> grid, std::size_t i,
                                   const vec<D, T>& q) {
    const cubic_segment<D, T> s = segments[i];
    const segment_nearest<T> r = nearest(s, q);
    // The end knot exactly at u = 1, and never past it by rounding.
    const T t = r.u == T(1) ? grid[i + 1] : std::min(s.t0 + r.u * s.h, grid[i + 1]);
    return {t, r.distance_sq, i, s.at(r.u)};
}

template <std::size_t D, class T>
void check_query(const vec<D, T>& q, std::optional<std::size_t> index) {
    for (std::size_t k = 0; k < D; ++k)
        if (!std::isfinite(q[k]))
            throw invalid_input("query " + (index ? std::to_string(*index) + " " : std::string()) + "coordinate " +
                                std::to_string(k) + " is not finite (" + num(double(q[k])) + ")");
}

}  // namespace detail

/// Nearest point of the curve to q, over every segment (pruned by the
/// control-point boxes). O(N) per query; see nearest_index for many queries
/// on long curves. Throws invalid_input when q has a non-finite coordinate.
template <std::size_t D, class T>
nearest_result<D, T> nearest(const catmull_rom<D, T>& curve, const vec<D, T>& q) {
    detail::check_query(q, std::nullopt);
    const auto segments = curve.segments();
    const auto grid = curve.grid();
    const std::size_t n = segments.size();
    // 1. A lower bound on the distance to each segment.
    std::vector<T> bound(n);
    for (std::size_t i = 0; i < n; ++i) bound[i] = detail::lower_bound_sq(detail::segment_box(segments[i]), q);
    // 2. Solve the most promising segment first.
    const std::size_t first = std::size_t(std::min_element(bound.begin(), bound.end()) - bound.begin());
    nearest_result<D, T> best = detail::solve_segment(segments, grid, first, q);
    // 3. Then the others that might still beat it, nearest bound first.
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < n; ++i)
        if (i != first && !(bound[i] > best.distance_sq)) order.push_back(i);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return bound[a] != bound[b] ? bound[a] < bound[b] : a < b; });
    for (std::size_t i : order) {
        if (bound[i] > best.distance_sq) break;
        const auto r = detail::solve_segment(segments, grid, i, q);
        if (detail::better(r, best)) best = r;
    }
    return best;
}

/// Counters of one indexed query, for benchmarks and tests.
template <std::size_t D, class T = double>
struct nearest_search {
    nearest_result<D, T> result;
    std::size_t nodes_visited = 0;    ///< hierarchy nodes whose bound was tested
    std::size_t segments_solved = 0;  ///< segments whose degree-5 problem was solved
};

/// A bounding-volume hierarchy over a curve's segments for fast nearest-point
/// queries: a binary tree of the segments' control-point boxes (median split
/// on the longest axis of the box centres, up to 4 segments per leaf) in one
/// flat array, searched depth first, nearer child first, pruning any box
/// farther than the best distance found. Results are identical to
/// nearest(curve, q).
///
/// Lifetime: the index refers to the curve's segments and knots without
/// copying them. The curve must outlive the index (moving the curve keeps its
/// storage and is fine; destroying or assigning to it is not).
template <std::size_t D, class T = double>
class nearest_index {
public:
    using point = vec<D, T>;
    using result_type = nearest_result<D, T>;
    static constexpr std::size_t leaf_size = detail::box_tree<D, T>::leaf_size;

    explicit nearest_index(const catmull_rom<D, T>& curve) : segments_(curve.segments()), grid_(curve.grid()) {
        const std::size_t n = segments_.size();
        if (n >= std::numeric_limits<std::uint32_t>::max())
            throw invalid_input("too many segments for nearest_index (" + std::to_string(n) + ")");
        // Every segment's box, in the tree (detail/box_tree.hpp).
        std::vector<detail::box<D, T>> boxes(n);
        for (std::size_t i = 0; i < n; ++i) boxes[i] = detail::segment_box(segments_[i]);
        tree_ = detail::box_tree<D, T>(boxes);
    }

    /// Nearest point of the curve to q (identical to nearest(curve, q)).
    result_type nearest(const point& q) const { return search(q).result; }

    /// Nearest points for many queries. Throws invalid_input naming the
    /// first query with a non-finite coordinate; empty input is fine.
    std::vector<result_type> nearest(std::span<const point> queries) const {
        for (std::size_t j = 0; j < queries.size(); ++j) detail::check_query(queries[j], j);
        std::vector<result_type> out(queries.size());
        for (std::size_t j = 0; j < queries.size(); ++j) out[j] = search_unchecked(queries[j]).result;
        return out;
    }

    /// The query with its counters.
    nearest_search<D, T> search(const point& q) const {
        detail::check_query(q, std::nullopt);
        return search_unchecked(q);
    }

    std::size_t node_count() const noexcept { return tree_.nodes().size(); }
    std::size_t segment_count() const noexcept { return segments_.size(); }

private:
    typename catmull_rom<D, T>::segment_view segments_;
    std::span<const T> grid_;
    detail::box_tree<D, T> tree_;

    nearest_search<D, T> search_unchecked(const point& q) const {
        nearest_search<D, T> s{detail::no_result<D, T>(), 0, 0};
        nearest_result<D, T>& best = s.result;
        // Depth first with an explicit stack of (node, bound); the tree is
        // balanced, so its depth is below 2 + log2(N) <= 34.
        std::array<std::pair<std::uint32_t, T>, 72> stack;
        std::size_t top = 0;
        const auto& nodes = tree_.nodes();
        stack[top++] = {0, detail::lower_bound_sq(nodes[0].bounds, q)};
        ++s.nodes_visited;
        while (top > 0) {
            const auto [id, bound] = stack[--top];
            if (bound > best.distance_sq) continue;
            const auto& nd = nodes[id];
            if (nd.count > 0) {
                // A leaf: test each segment's own box, solve the survivors.
                for (std::size_t k = nd.first; k < nd.first + nd.count; ++k) {
                    if (detail::lower_bound_sq(tree_.item_box(k), q) > best.distance_sq) continue;
                    ++s.segments_solved;
                    const auto r = detail::solve_segment(segments_, grid_, tree_.item(k), q);
                    if (detail::better(r, best)) best = r;
                }
                continue;
            }
            // An inner node: push the farther child first, so the nearer one is searched first.
            const std::uint32_t a = id + 1, b = nd.second;
            const T ba = detail::lower_bound_sq(nodes[a].bounds, q), bb = detail::lower_bound_sq(nodes[b].bounds, q);
            s.nodes_visited += 2;
            const bool a_first = !(bb < ba);
            const std::pair<std::uint32_t, T> near{a_first ? a : b, a_first ? ba : bb};
            const std::pair<std::uint32_t, T> far{a_first ? b : a, a_first ? bb : ba};
            if (!(far.second > best.distance_sq)) stack[top++] = far;
            if (!(near.second > best.distance_sq)) stack[top++] = near;
        }
        return s;
    }
};

/// Nearest points for many queries: each result is identical to
/// nearest(curve, queries[j]). For more than a few queries it builds a
/// nearest_index once. Throws invalid_input naming the first query with a
/// non-finite coordinate; empty input gives an empty result.
template <std::size_t D, class T>
std::vector<nearest_result<D, T>> nearest(const catmull_rom<D, T>& curve, std::span<const vec<D, T>> queries) {
    for (std::size_t j = 0; j < queries.size(); ++j) detail::check_query(queries[j], j);
    if (queries.size() >= 4) return nearest_index<D, T>(curve).nearest(queries);
    std::vector<nearest_result<D, T>> out;
    out.reserve(queries.size());
    for (const auto& q : queries) out.push_back(nearest(curve, q));
    return out;
}

}  // namespace crspline
