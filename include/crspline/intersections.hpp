// crspline: intersections of a Catmull-Rom curve with itself.
//
// Between different segments: Bézier subdivision with rejection by boxes
// and by the pieces' chords down to a tolerance, then a Gauss-Newton polish
// of C_i(u) = C_j(v); two pieces that are nearly straight and at an angle
// meet at most once, and are polished at once instead of subdivided on.
// In 2-D crossings are found exactly (the polish converges to the crossing
// to rounding); in 3-D and higher, curves generically miss each other, and
// what is reported are closest approaches closer than the tolerance.
// Adjacent segments always share their joint: that trivial meeting is
// excluded (near the joint the two pieces are checked to be monotone along
// the joint tangent, so they cannot meet there again).
// Within a segment: the exact loops of analyze_segment (segments {i, i}).
// Where two segments overlap (collinear pieces, or any stretch within the
// tolerance of each other) the meetings found along it are merged into one
// interval per pair of segments (overlaps).//
// The pieces and the tests on a pair of them are in
// detail/intersection_pieces.hpp; here the search per pair of segments and
// over the whole curve.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "analysis.hpp"
#include "catmull_rom.hpp"
#include "detail/box_tree.hpp"
#include "detail/intersection_pieces.hpp"
#include "segment.hpp"
#include "vec.hpp"

namespace crspline {

/// Default tolerance of find_intersections, relative to the curve's scale
/// (the diagonal of the bounding box of its Bézier points).
inline constexpr double default_intersection_tolerance = 1e-9;

/// One meeting of the curve with itself.
template <std::size_t D, class T = double>
struct curve_intersection {
    std::array<std::size_t, 2> segments{};  ///< i <= j; i == j is a loop inside segment i
    std::array<T, 2> u{};                   ///< local parameters on segments[0] and segments[1]
    vec<D, T> point{};                      ///< the meeting point (on segments[0])
    T distance = 0;                         ///< |C_i(u_i) - C_j(u_j)|: 0 to rounding for a crossing
};

/// A stretch where two segments run within the tolerance of each other (a
/// collinear overlap): one interval per pair of segments instead of the
/// thousands of crossings a search would find along it.
template <std::size_t D, class T = double>
struct curve_overlap {
    std::array<std::size_t, 2> segments{};  ///< i < j
    std::array<T, 2> u{};                   ///< [start, end] of the stretch on segments[0], local, start < end
    std::array<T, 2> v{};                   ///< the matching local parameters on segments[1] (either order)
};

template <std::size_t D, class T = double>
struct intersection_result {
    std::vector<curve_intersection<D, T>> intersections;
    std::vector<curve_overlap<D, T>> overlaps;  ///< runs of meetings merged into intervals
    std::vector<std::size_t> folds;  ///< collinear segments that retrace themselves (1-D folds)
    bool complete = true;            ///< false if a pair of segments exhausted the work budget
                                     ///< (overlapping collinear pieces meet in a continuum)
    bool any() const noexcept { return !intersections.empty() || !overlaps.empty() || !folds.empty(); }
};

namespace detail {

/// What segment_pair_meetings uses and returns, kept across the pairs of a
/// whole-curve search so that no pair allocates: the subdivision's stack
/// and the meetings found; and the choice of the transversal shortcut (a
/// seam for the tests, which compare the search with it and without it)
/// with the count of cells it closed.
template <std::size_t D, class T>
struct pair_workspace {
    struct cell {
        sub_bezier<D, T> a, b;
        T try_below;  // attempt the transversal shortcut only at cells smaller than this
    };
    std::vector<cell> stack;
    std::vector<std::array<T, 3>> found;
    bool shortcut = true;
    std::size_t shortcuts = 0;  // cells closed by the shortcut, over every pair searched with this workspace
};

/// Meetings of segments A and B closer than tol (the per-pair step of
/// find_intersections), into work.found: Bézier subdivision with
/// rejection by boxes and across chords, then a polish. Everything is relative to A's origin, so a
/// curve far from the origin of coordinates is searched as precisely as one
/// near it. Excludes the shared joint of adjacent segments. Each meeting is
/// {u, v, distance}; sets complete = false when the budget of sub-pair
/// visits runs out (overlapping collinear pieces meet in a continuum).
///
/// The common crossing is found without subdividing down to the tolerance:
/// a cell whose pieces are transversal (above) meets at most once, so one
/// polish from where the chords meet finds that meeting; when it lands in
/// the cell, within tol and off the joint, the cell is done (a leaf of the
/// cell that the subdivision would have reached holds points within about
/// tol of each other, so near that one meeting, and its polish would
/// converge to it: a duplicate).
/// Otherwise the cell is split as before, the shortcut tried again only
/// three levels further down.
template <std::size_t D, class T>
void segment_pair_meetings(const cubic_segment<D, T>& A, const cubic_segment<D, T>& B, pair_joint joint, T tol,
                           bool& complete, pair_workspace<D, T>& work, std::size_t budget = 200000) {
    using point = vec<D, T>;
    using sub = sub_bezier<D, T>;
    const bool adjacent = joint != pair_joint::none, next = joint == pair_joint::next;
    const auto ba0 = relative_bezier(A, point{}), bb0 = relative_bezier(B, point(B.origin - A.origin));
    const T ju = next ? T(1) : T(0), jv = next ? T(0) : T(1);
    point tangent{};
    if (adjacent) {
        const auto& S = next ? B : A;  // the segment that starts at the joint
        const auto& b = next ? bb0 : ba0;
        tangent = S.du(T(0), 1);
        if (!(norm(tangent) > 0)) tangent = S.du(T(0), 2);  // zero speed at the joint
        if (!(norm(tangent) > 0)) tangent = b[3] - b[0];
    }
    auto& stack = work.stack;
    auto& found = work.found;
    stack.clear();
    found.clear();
    stack.push_back({sub{ba0, T(0), T(1)}, sub{bb0, T(0), T(1)}, std::numeric_limits<T>::infinity()});
    // Keeps r unless it repeats a meeting already found.
    const auto keep = [&](const std::array<T, 3>& r) {
        for (const auto& f : found)
            if ((std::abs(f[0] - r[0]) < T(1e-7) && std::abs(f[1] - r[1]) < T(1e-7)) ||
                norm(relative_at(A, f[0]) - relative_at(A, r[0])) <= 2 * tol)
                return;
        found.push_back(r);
    };
    const auto at_joint = [&](const std::array<T, 3>& r) {
        return adjacent && std::abs(r[0] - ju) < T(1e-6) && std::abs(r[1] - jv) < T(1e-6);
    };
    std::size_t visits = 0;
    while (!stack.empty()) {
        if (++visits > budget) { complete = false; break; }
        const auto [a, b, try_below] = stack.back();
        stack.pop_back();
        const auto ba = box_of(a.b), bb = box_of(b.b);
        if (!boxes_meet(ba, bb, tol)) continue;
        const bool corner = adjacent && (a.u0 == ju || a.u1 == ju) && (b.u0 == jv || b.u1 == jv);
        if (corner) {
            // Both pieces monotone along the joint tangent, on its two
            // sides: they meet only at the joint.
            const point d = next ? tangent : -tangent;  // direction of travel i -> j through the joint
            if (monotone_along(a.b, d) && monotone_along(b.b, d)) continue;
            if (!next && monotone_along(a.b, tangent) && monotone_along(b.b, tangent)) continue;
        } else if (apart_across(a.b, b.b, tol) || apart_across(b.b, a.b, tol)) {
            continue;  // more than tol apart across one of the chords
        }
        const T sa = norm(ba[1] - ba[0]), sb = norm(bb[1] - bb[0]);
        const bool leaf = (sa <= tol && sb <= tol) || (a.u1 - a.u0 < T(1e-12) && b.u1 - b.u0 < T(1e-12));
        if (leaf) {
            if (corner) continue;  // the joint itself
            const auto r = polish(A, B, (a.u0 + a.u1) / 2, (b.u0 + b.u1) / 2);
            if (!(r[2] <= tol)) continue;
            if (at_joint(r)) continue;  // not the joint (polish can slide into it)
            keep(r);
            continue;
        }
        T below = try_below;
        if (work.shortcut && !corner && sa + sb < try_below) {
            if (transversal(a.b, b.b)) {
                const auto s = chord_meeting(a, b);
                const auto r = polish(A, B, s[0], s[1]);
                // In the cell, and inside both segments: a meeting at a
                // segment's end (the polish held at u or v = 0 or 1, as
                // where a crossing lies just past it, on the next segment)
                // is left to the leaves, as before.
                const bool inside = a.u0 <= r[0] && r[0] <= a.u1 && b.u0 <= r[1] && r[1] <= b.u1 && r[0] > 0 &&
                                    r[0] < 1 && r[1] > 0 && r[1] < 1;
                if (r[2] <= tol && inside && !at_joint(r)) {
                    ++work.shortcuts;
                    keep(r);
                    continue;
                }
            }
            below = (sa + sb) / 8;
        }
        // Split the larger piece (both when similar).
        if (sa >= sb) {
            const auto h = split_half(a);
            stack.push_back({h[0], b, below});
            stack.push_back({h[1], b, below});
        } else {
            const auto h = split_half(b);
            stack.push_back({a, h[0], below});
            stack.push_back({a, h[1], below});
        }
    }
}

/// segment_pair_meetings with a workspace of its own: the meetings,
/// {u, v, distance} each.
template <std::size_t D, class T>
std::vector<std::array<T, 3>> segment_pair_meetings(const cubic_segment<D, T>& A, const cubic_segment<D, T>& B,
                                                    pair_joint joint, T tol, bool& complete,
                                                    std::size_t budget = 200000) {
    pair_workspace<D, T> work;
    segment_pair_meetings(A, B, joint, tol, complete, work, budget);
    return std::move(work.found);
}

// Distance from A(u) to B near B(v): Newton on |A(u) - B(v)|^2 in v from
// the given v (updated), relative to the pair's origins like polish.
template <std::size_t D, class T>
T distance_near(const cubic_segment<D, T>& A, const cubic_segment<D, T>& B, T u, T& v) {
    const vec<D, T> p = (A.origin - B.origin) + relative_at(A, u);
    for (int it = 0; it < 12; ++it) {
        const vec<D, T> r = p - relative_at(B, v), d1 = B.du(v, 1), d2 = B.du(v, 2);
        const T g = -dot(d1, r), h = dot(d1, d1) - dot(d2, r);
        if (!(h > 0)) break;
        const T nv = std::clamp(v - g / h, T(0), T(1));
        if (nv == v) break;
        v = nv;
    }
    return norm(p - relative_at(B, v));
}

// Removes from `found` the meetings of A and B that lie along one stretch
// within tol of each other (consecutive meetings, by u, with the curve
// between them within tol of B at a quarter, half and three quarters) and
// returns those stretches, each extended by bisection to where A leaves
// B's tolerance: {u0, u1, v0, v1}. Isolated meetings stay in `found`.
template <std::size_t D, class T>
std::vector<std::array<T, 4>> take_overlaps(const cubic_segment<D, T>& A, const cubic_segment<D, T>& B, T tol,
                                            std::vector<std::array<T, 3>>& found) {
    std::vector<std::array<T, 4>> runs;
    if (found.size() < 2) return runs;
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a[0] < b[0]; });
    const auto joined = [&](const std::array<T, 3>& f, const std::array<T, 3>& g) {
        for (const T s : {T(0.25), T(0.5), T(0.75)}) {
            T v = f[1] + s * (g[1] - f[1]);
            if (!(distance_near(A, B, f[0] + s * (g[0] - f[0]), v) <= tol)) return false;
        }
        return true;
    };
    // From inside (u_in, v_in) towards u_out: the farthest u still within tol.
    const auto extend = [&](T u_in, T v_in, T u_out) {
        T v = v_in;
        if (distance_near(A, B, u_out, v) <= tol) return std::array<T, 2>{u_out, v};
        T lo = u_in, hi = u_out, v_lo = v_in;
        for (int it = 0; it < 60 && lo != hi; ++it) {
            const T mid = (lo + hi) / 2;
            T vm = v_lo;
            if (distance_near(A, B, mid, vm) <= tol) lo = mid, v_lo = vm;
            else hi = mid;
        }
        return std::array<T, 2>{lo, v_lo};
    };
    std::vector<std::array<T, 3>> rest;
    for (std::size_t k = 0; k < found.size();) {
        std::size_t e = k;
        while (e + 1 < found.size() && joined(found[e], found[e + 1])) ++e;
        if (e > k) {
            const auto a = extend(found[k][0], found[k][1], T(0)), b = extend(found[e][0], found[e][1], T(1));
            runs.push_back({a[0], b[0], a[1], b[1]});
        } else {
            rest.push_back(found[k]);
        }
        k = e + 1;
    }
    found = std::move(rest);
    return runs;
}

template <std::size_t D, class T, class Pairs>
intersection_result<D, T> find_intersections_among(const catmull_rom<D, T>& c, T tolerance, const Pairs& candidate_pairs);

template <std::size_t D, class T, class Pairs, class Visitor>
bool visit_intersections_among(const catmull_rom<D, T>& c, T tolerance, const Pairs& candidate_pairs, Visitor& visit);

}  // namespace detail

/// The search of find_intersections, each finding handed over as it is
/// found instead of kept, for a curve with millions of meetings (crspline
/// analyze at 10^6 points): visit(const curve_intersection<D, T>&),
/// visit(const curve_overlap<D, T>&) and visit.fold(std::size_t) are called
/// in the order find_intersections lists them. Returns `complete`.
template <std::size_t D, class T, class Visitor>
bool visit_intersections(const catmull_rom<D, T>& c, T tolerance, Visitor&& visit) {
    return detail::visit_intersections_among(c, tolerance, detail::tree_pairs{}, visit);
}

/// All meetings of the curve with itself closer than `tolerance` (a
/// distance; 0 means default_intersection_tolerance times the curve's
/// scale): between non-adjacent segments, between adjacent segments away
/// from their shared joint, and loops inside segments. The pairs of
/// segments whose control-point boxes meet come from a bounding-volume
/// hierarchy (O(n log n + k) for k such pairs), each pair checked exactly.
template <std::size_t D, class T>
intersection_result<D, T> find_intersections(const catmull_rom<D, T>& c, T tolerance = T(0)) {
    return detail::find_intersections_among(c, tolerance, detail::tree_pairs{});
}

namespace detail {

// The search, given how to find the candidate pairs (a seam for the tests:
// the tree, or every pair i < j as a reference). candidate_pairs(boxes, pad)
// returns pair_rows that include every pair i < j whose boxes meet within
// pad; each is then checked in the order i, then j.
template <std::size_t D, class T, class Pairs>
intersection_result<D, T> find_intersections_among(const catmull_rom<D, T>& c, T tolerance, const Pairs& candidate_pairs) {
    intersection_result<D, T> out;
    struct keep {
        intersection_result<D, T>& out;
        void operator()(const curve_intersection<D, T>& x) { out.intersections.push_back(x); }
        void operator()(const curve_overlap<D, T>& x) { out.overlaps.push_back(x); }
        void fold(std::size_t i) { out.folds.push_back(i); }
    } visit{out};
    out.complete = visit_intersections_among(c, tolerance, candidate_pairs, visit);
    return out;
}

// The search itself, each finding handed to `visit` (visit_intersections).
template <std::size_t D, class T, class Pairs, class Visitor>
bool visit_intersections_among(const catmull_rom<D, T>& c, T tolerance, const Pairs& candidate_pairs, Visitor& visit) {
    using point = vec<D, T>;
    bool complete = true;
    const std::size_t n = c.segment_count();
    // Each segment's box of its Bézier points (not the points themselves:
    // at 10^6 segments they would be 64 MB more held through the search);
    // scale and tolerance from their union.
    std::vector<detail::box<D, T>> boxes(n);
    // Zero-length segments (a knot interval of 0: coincident points with
    // alpha > 0, or a segment whose Bezier points are one point) join the
    // segments on either side at their shared point, as a joint does:
    // segments joined through a run of them are neighbours (issue 31: the
    // line 0,0 / 1,0 / 1,0 / 2,0 does not cross itself at 1,0). zero_before[k]
    // counts them among segments [0, k); empty when there are none.
    std::vector<std::size_t> zero_before;
    for (std::size_t i = 0; i < n; ++i) {
        const auto bx = detail::box_of(c.bezier(i));
        boxes[i] = {bx[0], bx[1]};
        if (c.segment(i).h == 0 || bx[0] == bx[1]) {
            if (zero_before.empty()) zero_before.assign(n + 1, 0);
            zero_before[i + 1] = 1;
        }
    }
    for (std::size_t k = 0; k < zero_before.size() && k < n; ++k) zero_before[k + 1] += zero_before[k];
    // Whether every segment in [a, b) has zero length (true when empty).
    const auto all_zero = [&](std::size_t a, std::size_t b) {
        return a >= b || (!zero_before.empty() && zero_before[b] - zero_before[a] == b - a);
    };
    point lo = boxes[0].lo, hi = boxes[0].hi;
    for (const auto& bx : boxes)
        for (std::size_t k = 0; k < D; ++k) { lo[k] = std::min(lo[k], bx.lo[k]); hi[k] = std::max(hi[k], bx.hi[k]); }
    const T scale = norm(hi - lo);
    const T tol = tolerance > 0 ? tolerance : T(default_intersection_tolerance) * scale;
    if (!(scale > 0)) return complete;

    // Within segments: exact (a segment monotone along a direction has
    // neither a loop nor a fold, and is not analysed).
    for (std::size_t i = 0; i < n; ++i) {
        if (detail::monotone_segment(c.segment(i))) continue;
        const auto a = analyze_segment(c.segment(i));
        if (a.fold) visit.fold(i);
        for (const auto& [u, v] : a.self_intersection)
            visit(curve_intersection<D, T>{{i, i}, {u, v}, c.segment(i).at(u), norm(c.segment(i).at(u) - c.segment(i).at(v))});
    }

    // Candidate pairs by their boxes in absolute coordinates: pad by the
    // rounding of those coordinates too, so no pair is dropped for it (the
    // per-pair search below is relative and exact to the tolerance).
    const T pad = tol + T(8) * std::numeric_limits<T>::epsilon() * std::max(max_abs(lo), max_abs(hi));
    const pair_rows candidates = candidate_pairs(boxes, pad);
    detail::pair_workspace<D, T> work;
    for (std::size_t i = 0; i < n; ++i)
        for (const std::size_t j : candidates.row(i)) {
            if (!detail::boxes_meet(boxes[i], boxes[j], pad)) continue;
            // Joint of adjacent segments: (end of i, start of j) or, closing
            // a closed curve, (start of i = 0, end of j = n - 1); either
            // through zero-length segments between them.
            const bool next = all_zero(i + 1, j);
            const bool wrap = c.closed() && n > 2 && all_zero(0, i) && all_zero(j + 1, n);
            // A zero-length segment is its neighbours' shared point: they
            // meet it there and nowhere else.
            if ((next || wrap) && (all_zero(i, i + 1) || all_zero(j, j + 1))) continue;
            const auto joint = next ? detail::pair_joint::next : wrap ? detail::pair_joint::wrap : detail::pair_joint::none;
            const auto& A = c.segment(i);
            const auto& B = c.segment(j);
            detail::segment_pair_meetings(A, B, joint, tol, complete, work);
            auto& found = work.found;
            for (const auto& r : detail::take_overlaps(A, B, tol, found))
                visit(curve_overlap<D, T>{{i, j}, {r[0], r[1]}, {r[2], r[3]}});
            for (const auto& f : found) visit(curve_intersection<D, T>{{i, j}, {f[0], f[1]}, A.at(f[0]), f[2]});
        }
    return complete;
}

}  // namespace detail

}  // namespace crspline
