// crspline: clearance, the least distance between non-adjacent parts of
// curves in any dimension (branch and bound over pairs of Bezier pieces).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#include "../catmull_rom.hpp"
#include "../detail/box_tree.hpp"
#include "../vec.hpp"

namespace crspline {

/// Where the least distance is attained: local parameter u of segment[k] of
/// curve[k], the two points, and a lower bound: the true least distance lies
/// in [lower_bound, distance], and distance - lower_bound <= the accuracy
/// asked for (unless `exhausted`).
template <std::size_t D>
struct clearance_result {
    double distance = std::numeric_limits<double>::infinity();  ///< infinity: no pair to measure
    double lower_bound = std::numeric_limits<double>::infinity();
    std::array<std::size_t, 2> curve{};
    std::array<std::size_t, 2> segment{};
    std::array<double, 2> u{};
    std::array<vec<D>, 2> points{};
    bool exhausted = false;  ///< the work budget ran out before the accuracy was reached
};

namespace detail {

// Branch and bound over pairs of Bézier pieces, in any dimension. Lower
// bound of a pair: the larger of the gap between the control points' boxes
// and the gap of their projections on the line through the two pieces'
// control-point centroids (the convex hulls contain the pieces). Upper
// bound: the distance between the pieces' end points, which lie on the
// curves. Pairs are taken in order of their lower bound; the search stops
// when the best lower bound reaches the distance found less the accuracy.
// Floating point throughout (the bounds are rounded to a few ulps of the
// coordinates, which the accuracy must exceed).
template <std::size_t D>
clearance_result<D> clearance_among(const std::vector<std::vector<std::array<vec<D>, 4>>>& curves,
                                    const std::vector<std::array<std::size_t, 4>>& segment_pairs, double accuracy,
                                    std::size_t budget) {
    using V = vec<D>;
    struct piece {
        std::array<V, 4> b;
        double u0, u1;
        std::size_t curve, segment;
    };
    struct item {
        double lower;
        piece a, b;
        bool operator<(const item& o) const noexcept { return lower > o.lower; }  // min-heap
    };
    clearance_result<D> best;
    auto lower = [](const piece& a, const piece& b) {
        double gap = 0;
        V ca{}, cb{};
        for (std::size_t k = 0; k < D; ++k) {
            double alo = a.b[0][k], ahi = alo, blo = b.b[0][k], bhi = blo;
            for (const auto& x : a.b) { alo = std::min(alo, x[k]); ahi = std::max(ahi, x[k]); }
            for (const auto& x : b.b) { blo = std::min(blo, x[k]); bhi = std::max(bhi, x[k]); }
            const double g = std::max(blo - ahi, alo - bhi);
            if (g > 0) gap += g * g;
        }
        for (std::size_t q = 0; q < 4; ++q) { ca += a.b[q] / 4.0; cb += b.b[q] / 4.0; }
        double lb = std::sqrt(gap);
        const V d = cb - ca;
        const double L = norm(d);
        if (L > 0) {
            const V n = d / L;
            double amax = -std::numeric_limits<double>::infinity(), bmin = -amax;
            for (const auto& x : a.b) amax = std::max(amax, dot(x, n));
            for (const auto& x : b.b) bmin = std::min(bmin, dot(x, n));
            lb = std::max(lb, bmin - amax);
        }
        return std::max(lb, 0.0);
    };
    auto upper = [&](const piece& a, const piece& b) {
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) {
                const V& x = a.b[i ? 3 : 0];
                const V& y = b.b[j ? 3 : 0];
                const double dd = norm(x - y);
                if (dd < best.distance) {
                    best.distance = dd;
                    best.curve = {a.curve, b.curve};
                    best.segment = {a.segment, b.segment};
                    best.u = {i ? a.u1 : a.u0, j ? b.u1 : b.u0};
                    best.points = {x, y};
                }
            }
    };
    auto split = [](const piece& p) {
        const auto& q = p.b;
        const V a0 = lerp(q[0], q[1], 0.5), a1 = lerp(q[1], q[2], 0.5), a2 = lerp(q[2], q[3], 0.5);
        const V q0 = lerp(a0, a1, 0.5), q1 = lerp(a1, a2, 0.5), m = lerp(q0, q1, 0.5);
        const double um = (p.u0 + p.u1) / 2;
        return std::array<piece, 2>{piece{{q[0], a0, q0, m}, p.u0, um, p.curve, p.segment},
                                    piece{{m, q1, a2, q[3]}, um, p.u1, p.curve, p.segment}};
    };
    auto extent = [](const piece& p) { return norm(p.b[3] - p.b[0]) + norm(p.b[1] - p.b[0]) + norm(p.b[2] - p.b[3]); };
    std::priority_queue<item> heap;
    for (const auto& sp : segment_pairs) {
        const piece a{curves[sp[0]][sp[1]], 0, 1, sp[0], sp[1]}, b{curves[sp[2]][sp[3]], 0, 1, sp[2], sp[3]};
        upper(a, b);
        heap.push({lower(a, b), a, b});
    }
    std::size_t visits = 0;
    while (!heap.empty()) {
        const item it = heap.top();
        if (it.lower >= best.distance - accuracy) break;
        heap.pop();
        if (++visits > budget) {
            best.exhausted = true;
            best.lower_bound = it.lower;
            return best;
        }
        const bool split_a = extent(it.a) >= extent(it.b);
        const auto h = split(split_a ? it.a : it.b);
        for (const auto& c : h) {
            const piece& a = split_a ? c : it.a;
            const piece& b = split_a ? it.b : c;
            upper(a, b);
            const double lb = lower(a, b);
            if (lb < best.distance - accuracy) heap.push({lb, a, b});
        }
    }
    best.lower_bound = heap.empty() ? best.distance : std::min(best.distance, heap.top().lower);
    // Points relative to nothing: the curves were given as they are.
    return best;
}

// The segment pairs that can hold the least distance: the pairs whose
// boxes come within `reach` (found with the box tree), without
// neighbours in one curve (consecutive segments, through zero-length
// ones, and across a closed curve's seam) when `self`.
template <std::size_t D>
std::vector<std::array<std::size_t, 4>> clearance_pairs(const std::vector<std::vector<std::array<vec<D>, 4>>>& curves,
                                                        const std::vector<bool>& closed, bool self, bool between) {
    std::vector<box<D, double>> boxes;
    std::vector<std::array<std::size_t, 2>> id;
    std::vector<std::vector<std::size_t>> rank(curves.size());  // order among non-point segments
    std::vector<std::size_t> count(curves.size());
    for (std::size_t c = 0; c < curves.size(); ++c) {
        for (std::size_t s = 0; s < curves[c].size(); ++s) {
            const auto& g = curves[c][s];
            rank[c].push_back(count[c]);
            if (g[0] == g[1] && g[1] == g[2] && g[2] == g[3]) continue;  // a point
            ++count[c];
            box<D, double> bx{g[0], g[0]};
            for (const auto& x : g)
                for (std::size_t k = 0; k < D; ++k) {
                    bx.lo[k] = std::min(bx.lo[k], x[k]);
                    bx.hi[k] = std::max(bx.hi[k], x[k]);
                }
            boxes.push_back(bx);
            id.push_back({c, s});
        }
    }
    auto neighbours = [&](std::size_t c, std::size_t s, std::size_t t) {
        const std::size_t a = rank[c][s], b = rank[c][t], n = count[c];
        const std::size_t d = a > b ? a - b : b - a;
        return d <= 1 || (closed[c] && d + 1 == n);
    };
    // Reach: from the largest box, widened until a pair is found. Once the
    // pairs within `reach` hold one at distance found <= reach, every pair
    // closer than that has boxes within reach: they are all there.
    double reach = 0, whole = 0;
    box<D, double> all{};
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        all = i ? merge(all, boxes[i]) : boxes[i];
        for (std::size_t k = 0; k < D; ++k) reach = std::max(reach, boxes[i].hi[k] - boxes[i].lo[k]);
    }
    for (std::size_t k = 0; k < D && !boxes.empty(); ++k) whole += all.hi[k] - all.lo[k];
    reach = std::max(reach, std::numeric_limits<double>::min());
    const box_tree<D, double> tree(boxes);
    while (true) {
        std::vector<std::array<std::size_t, 4>> pairs;
        double found = std::numeric_limits<double>::infinity();
        tree.for_each_meeting_pair(reach, [&](std::uint32_t i, std::uint32_t j) {
            const auto a = id[i], b = id[j];
            const bool same = a[0] == b[0];
            if (same ? (!self || neighbours(a[0], a[1], b[1])) : !between) return;
            pairs.push_back({a[0], a[1], b[0], b[1]});
            for (const std::size_t p : {std::size_t(0), std::size_t(3)})
                for (const std::size_t q : {std::size_t(0), std::size_t(3)})
                    found = std::min(found, norm(curves[a[0]][a[1]][p] - curves[b[0]][b[1]][q]));
        });
        if (found <= reach || reach > whole) return pairs;  // all there, or every pair was looked at
        reach = std::isfinite(found) ? found : 4 * reach;
    }
}

template <std::size_t D>
std::vector<std::array<vec<D>, 4>> relative_bezier(const catmull_rom<D>& c, const vec<D>& ref) {
    auto b = c.bezier();
    for (auto& s : b)
        for (auto& x : s) x = x - ref;
    return b;
}

template <std::size_t D>
clearance_result<D> clearance_of(std::vector<std::vector<std::array<vec<D>, 4>>> curves, const std::vector<bool>& closed,
                                 const vec<D>& ref, bool self, bool between, double accuracy, std::size_t budget) {
    double size = 0;
    for (const auto& c : curves)
        for (const auto& s : c)
            for (const auto& x : s) size = std::max(size, max_abs(x));
    if (!(accuracy > 0)) accuracy = 1e-10 * size;
    const auto pairs = clearance_pairs<D>(curves, closed, self, between);
    auto r = clearance_among<D>(curves, pairs, accuracy, budget);
    for (auto& x : r.points) x = x + ref;
    return r;
}

}  // namespace detail

/// The least distance between non-adjacent segments of a curve (segments
/// that are not consecutive, through zero-length segments and across a
/// closed curve's seam), any dimension, to within `accuracy` (0: 1e-10 of
/// the curve's extent from its first point). Crossings inside a segment or
/// between neighbours are decide()'s business, not measured here. A tube of
/// radius r around a 3-D curve has no self-contact between non-adjacent
/// segments when the clearance exceeds 2 r (and, near the joints, when the
/// curvature stays below 1 / r).
template <std::size_t D>
clearance_result<D> clearance(const catmull_rom<D>& c, double accuracy = 0, std::size_t budget = 1u << 22) {
    const vec<D> ref = c.points()[0];
    return detail::clearance_of<D>({detail::relative_bezier(c, ref)}, {c.closed()}, ref, true, false, accuracy, budget);
}

/// The least distance between two curves (curve 0 is a, 1 is b).
template <std::size_t D>
clearance_result<D> clearance(const catmull_rom<D>& a, const catmull_rom<D>& b, double accuracy = 0,
                              std::size_t budget = 1u << 22) {
    const vec<D> ref = a.points()[0];
    return detail::clearance_of<D>({detail::relative_bezier(a, ref), detail::relative_bezier(b, ref)},
                                   {a.closed(), b.closed()}, ref, false, true, accuracy, budget);
}

}  // namespace crspline
