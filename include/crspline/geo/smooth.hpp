// crspline::geo: smoothing a layer of lines and polygon rings with its
// topology kept, proved piece by piece.
//
// What smooth() promises, for every feature it smooths:
// - every curve passes through its input vertices (the output polyline
//   holds each of them exactly, bit for bit);
// - the output polyline is within `tolerance` of the curve (tessellate()'s
//   proved bound);
// - no output curve crosses itself or another output curve unless the
//   inputs did (then only the input segments themselves are output there,
//   and the feature's verdict says `crosses`). The curve of a cubic
//   segment, and its output polyline (chords between points of it), lie in
//   the convex hull of the segment's Bézier points. The proof, pair of
//   segments by pair (candidates: those whose Bézier boxes meet, found by
//   sweeps over arcs and over each arc's segments):
//     * one segment with itself: no loop and no cusp, by its Bézier points
//       advancing strictly along its chord (the curve is then a graph over
//       the chord), else by analyze_segment (exact);
//     * segments that share an end point V: their Bézier points other than
//       V lie in two disjoint wedges at V, each narrower than pi, so the
//       hulls meet only at V;
//     * otherwise, piece by piece of their output polylines (each curve
//       piece within its flatness bound e of its chord): pieces sharing an
//       end point by the same wedge test on the pieces' Bézier points,
//       other pieces by their chords being more than e1 + e2 apart.
//   Where a pair is not proved, the tension of the vertices of the
//   segments involved goes up one level (0, 0.5, 0.8, 0.95, 1), straight
//   to 1 where the two input segments themselves meet away from a shared
//   end: tension 1 at both ends makes the segment the input segment itself
//   (a Hermite cubic with zero end tangents is its chord), exact, so the
//   last resort is the input, and two input segments are proved apart by
//   their exact distance. Each round rebuilds only the arcs whose tension
//   changed and proves only the pairs that involve one of them;
// - no part changes side of a ring (issue 39): no vertex of another arc
//   lies in the region a segment sweeps between its input chord and its
//   curve (sides.hpp; the winding numbers around a vertex of the output and
//   the input rings differ by the sum of those regions' windings), raised
//   by local tension the same way;
// - with smooth_options::fit (issue 40): each arc first fitted with a
//   subset of its vertices within that distance of its input, both ways;
//   the same proof on the fitted curves, with a fitted segment's input
//   polyline in place of its chord, and its left-out vertices brought back
//   where a proof fails for it (sides.hpp, proof.hpp);
// - with max_deviation: no curve point is farther than that from the input
//   polyline, proved per segment against its own input segment [P, Q]:
//   the coordinates of the curve along PQ and across it are cubics whose
//   extremes on [0, 1] are found in closed form; a point's distance is
//   sqrt(across^2 + overshoot^2) (overshoot: how far it runs past P or Q),
//   bounded by the two maxima; raised by local tension the same way. The
//   output polyline's chords are no farther (the distance to a segment is
//   convex);
// - coverages: with preserve_topology, a boundary shared by several parts
//   is one arc (topology.hpp), smoothed once with its junctions fixed, so
//   neighbours share it exactly: no slivers, no gaps, by construction;
// - closed rings are closed curves; multi-part features part by part,
//   holes kept (each ring is a part); extra values (Z, M) interpolated
//   linearly in each segment's parameter between the segment's vertices
//   (exact at the input vertices);
// - empty, degenerate (a line with fewer than 2 distinct points, a ring
//   with fewer than 3) and invalid (non-finite coordinates) inputs are
//   reported per feature with a status and passed through unchanged.
//
// The files: report.hpp (options and results), arcs.hpp (an arc, its curve
// and polyline), hulls.hpp (the tests on Bézier points), length.hpp,
// sides.hpp (one arc's tests and containment), proof.hpp (pairs and
// rounds), nesting.hpp (invalid nesting in the input), topology.hpp (arcs
// and junctions), layer.hpp (the flat arrays); this file runs them.
//
// All distances are in the layer's own units; the layer is planar (a
// geographic layer is put in a metric frame by the caller: see
// docs/geo.md).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "../detail/format.hpp"
#include "../error.hpp"
#include "layer.hpp"
#include "nesting.hpp"
#include "proof.hpp"
#include "report.hpp"
#include "topology.hpp"

namespace crspline::geo {

namespace detail {

// smooth() without topology and without output polylines ("length only"):
// each part is cleaned, measured and released before the next, so the
// memory is that of the output (the input passed through) and the time per
// part does not grow with the layer (no topology, no arc array, nothing
// held from one part to the next). The same numbers as the general path:
// there every part is an arc of its own, proved alone (proof::run_alone)
// with the layer's rounding slack, found here by a first pass over the
// parts that will be smoothed (the largest coordinate of their cleaned
// points is that of their input points: cleaning drops repeats only).
// `consumed`: the input itself, whose arrays the output takes at the end
// (moved, not copied), or null.
template <class CleanOne>
void measure_alone(const layer& in, const smooth_options& opt, smooth_result& res, CleanOne& clean_one,
                   layer* consumed) {
    const std::size_t nparts = in.part_count(), E = in.extra_dims;
    double scale = 0;
    for (std::size_t p = 0; p < nparts; ++p) {
        if (res.features[in.part_features[p]].status == feature_status::invalid || in.part_size(p) == 0) continue;
        const std::size_t need = in.part_kinds[p] == part_kind::ring ? 3 : 2;
        const std::size_t v0 = in.part_offsets[p], v1 = in.part_offsets[p + 1];
        double m = 0;
        for (std::size_t v = v0; v < v1; ++v) m = std::max({m, std::abs(in.xy[2 * v]), std::abs(in.xy[2 * v + 1])});
        const auto at = [&](std::size_t i) { return std::array<double, 2>{in.xy[2 * (v0 + i)], in.xy[2 * (v0 + i) + 1]}; };
        if (distinct_up_to(v1 - v0, need, at) == need) scale = std::max(scale, m);
    }
    const double slack = rounding_slack(scale, opt.tolerance);
    std::vector<arc_work> one(1);
    proof pr{one, opt, slack};
    layer& out = res.output;
    out.extra_dims = E;
    out.feature_count = in.feature_count;
    if (!consumed) {
        out.part_kinds = in.part_kinds;
        out.part_features = in.part_features;
        out.xy = in.xy;
        out.extra = in.extra;
        out.part_offsets = in.part_offsets;
    }
    for (std::size_t p = 0; p < nparts; ++p) {
        if (opt.progress && p % 4096 == 0) opt.progress(double(p) / double(nparts));
        clean_part c;
        if (!clean_one(p, c)) continue;
        arc_work& a = one[0];
        a = arc_work{};
        a.closed = c.ring;
        a.pts.resize(c.points.size());
        for (std::size_t k = 0; k < c.points.size(); ++k) a.pts[k] = p2{{c.points[k][0], c.points[k][1]}};
        // A two-point open arc is its segment.
        a.level.assign(a.pts.size(), a.pts.size() == 2 && !a.closed ? linear_level : 0);
        a.raise.assign(a.segments(), 0);
        pr.alone(0);
        auto& rep = res.features[c.feature];
        rep.length += a.length;
        rep.max_deviation = std::max(rep.max_deviation, a.max_dev);
        ++res.stats.arcs;
        if (!a.closed) res.stats.junctions += 2;  // a line's ends
        res.stats.pieces += a.pieces;
        for (auto l : a.level) res.stats.tensioned_vertices += l > 0 && !(a.pts.size() == 2 && !a.closed);
        for (std::size_t s = 0; s < a.segments(); ++s) res.stats.linear_segments += a.linear(s);
        if (opt.keep_curves) res.curves.push_back({std::move(*a.curve), {c.feature}});
    }
    if (consumed) {  // the input is read no more
        out.part_kinds = std::move(consumed->part_kinds);
        out.part_features = std::move(consumed->part_features);
        out.xy = std::move(consumed->xy);
        out.extra = std::move(consumed->extra);
        out.part_offsets = std::move(consumed->part_offsets);
    }
    res.stats.rounds = pr.rounds;
    if (opt.progress) opt.progress(1.0);
}

inline smooth_result smooth_layer(const layer& in, const smooth_options& opt, layer* consumed);

}  // namespace detail

/// Smooths the layer (see the file comment for what is promised). Throws
/// invalid_input for bad options or arrays that disagree; bad coordinates
/// make their feature `invalid` instead.
inline smooth_result smooth(const layer& in, const smooth_options& opt) {
    return detail::smooth_layer(in, opt, nullptr);
}

/// The same, taking the input's arrays: where the output layer is the input
/// (measures only: smooth_options::polylines false) they are moved into it,
/// not copied (at 10^6 lines of 30 vertices, half a gigabyte of fresh memory
/// less). Afterwards `in` is valid but unspecified.
inline smooth_result smooth(layer&& in, const smooth_options& opt) { return detail::smooth_layer(in, opt, &in); }

namespace detail {

// smooth(), reading `in`; `consumed` (the same layer, or null) gives its
// arrays to the output when that is the input, once they are read no more.
inline smooth_result smooth_layer(const layer& in, const smooth_options& opt, layer* consumed) {
    using detail::p2;
    check_layer(in);
    if (!(opt.alpha >= 0 && opt.alpha <= 1))
        throw invalid_input("alpha must be in [0, 1], got " + crspline::detail::num(opt.alpha));
    if (!(opt.tolerance > 0 && std::isfinite(opt.tolerance)))
        throw invalid_input("tolerance must be positive and finite, got " + crspline::detail::num(opt.tolerance));
    if (opt.max_deviation && !(*opt.max_deviation > 0 && std::isfinite(*opt.max_deviation)))
        throw invalid_input("max_deviation must be positive and finite, got " +
                            crspline::detail::num(*opt.max_deviation));
    if (opt.fit && !(*opt.fit > 0 && std::isfinite(*opt.fit)))
        throw invalid_input("fit must be a positive finite distance, got " + crspline::detail::num(*opt.fit));
    const double tol = opt.tolerance;
    const std::size_t nparts = in.part_count(), E = in.extra_dims;

    smooth_result res;
    res.features.assign(in.feature_count, {});
    // 1. Per feature: invalid coordinates, empty features; per part: cleaned
    //    vertices (no consecutive repeats, a ring without its closing one).
    std::vector<std::size_t> feature_vertices(in.feature_count, 0), part_index(nparts, 0);
    {
        std::vector<std::size_t> count(in.feature_count, 0);
        for (std::size_t p = 0; p < nparts; ++p) {
            const std::size_t f = in.part_features[p];
            part_index[p] = count[f]++;
            feature_vertices[f] += in.part_size(p);
            auto& rep = res.features[f];
            if (rep.status == feature_status::invalid) continue;
            for (std::size_t v = in.part_offsets[p]; v < in.part_offsets[p + 1]; ++v)
                for (std::size_t k = 0; k < 2; ++k)
                    if (!std::isfinite(in.xy[2 * v + k])) {
                        rep.status = feature_status::invalid;
                        rep.message = "part " + std::to_string(part_index[p]) + " vertex " +
                                      std::to_string(v - in.part_offsets[p]) + ": " + (k ? "y" : "x") + " is " +
                                      crspline::detail::num(in.xy[2 * v + k]);
                        v = in.part_offsets[p + 1] - 1;
                        break;
                    }
        }
        for (std::size_t f = 0; f < in.feature_count; ++f)
            if (feature_vertices[f] == 0) {
                res.features[f].status = feature_status::empty;
                res.features[f].message = "no vertices";
            }
    }
    // Part p cleaned into c; false (the feature's status and message set
    // where the part is degenerate) when it is not smoothed.
    auto clean_one = [&](std::size_t p, clean_part& c) {
        const std::size_t f = in.part_features[p];
        auto& rep = res.features[f];
        if (rep.status == feature_status::invalid || in.part_size(p) == 0) return false;
        c.ring = in.part_kinds[p] == part_kind::ring;
        c.feature = f;
        c.points.reserve(in.part_size(p));
        c.source.reserve(in.part_size(p));
        for (std::size_t v = in.part_offsets[p]; v < in.part_offsets[p + 1]; ++v) {
            const std::array<double, 2> pt{in.xy[2 * v], in.xy[2 * v + 1]};
            if (!c.points.empty() && c.points.back() == pt) continue;
            c.points.push_back(pt);
            c.source.push_back(v);
        }
        if (c.ring && c.points.size() > 1 && c.points.back() == c.points.front()) {
            c.points.pop_back();
            c.source.pop_back();
        }
        const std::size_t need = c.ring ? 3 : 2;
        const std::size_t distinct = detail::distinct_up_to(c.points.size(), need, [&](std::size_t i) { return c.points[i]; });
        if (distinct < need) {
            rep.status = feature_status::degenerate;
            rep.message = "part " + std::to_string(part_index[p]) + " (" + (c.ring ? "ring" : "line") + ") has " +
                          std::to_string(distinct) + " distinct point" + (distinct == 1 ? "" : "s") +
                          ", a " + (c.ring ? "ring" : "line") + " needs " + std::to_string(need) +
                          ": passed through unchanged";
            return false;
        }
        return true;
    };
    if (!opt.preserve_topology && !opt.polylines && !opt.fit) {
        detail::measure_alone(in, opt, res, clean_one, consumed);  // clean_one writes res's statuses
        return res;
    }
    // Invalid nesting in the input (where the rings' roles are known), for
    // the verdicts at the end; features with a bad or degenerate part are
    // passed over (read before the input's arrays may be given away).
    std::vector<std::string> nesting;
    if (!in.part_roles.empty()) {
        std::vector<bool> skip(in.feature_count, false);
        for (std::size_t f = 0; f < in.feature_count; ++f) skip[f] = res.features[f].status != feature_status::ok;
        for (std::size_t p = 0; p < nparts; ++p) {  // a degenerate part makes its feature's status say so
            const std::size_t f = in.part_features[p];
            if (skip[f]) continue;
            clean_part c;
            if (in.part_kinds[p] == part_kind::ring && !clean_one(p, c)) skip[f] = true;
        }
        nesting = find_nesting(in, skip);
    }
    // The cleaned parts in flat arrays (topology.hpp's clean_layer), each
    // cleaned in one reused clean_part; the layer vertex of each cleaned
    // vertex is kept only to interpolate extra values.
    clean_layer clean;
    clean.with_sources = E > 0;
    std::vector<std::size_t> clean_of(nparts, SIZE_MAX);  // part -> index in clean, or pass-through
    {
        clean.points.reserve(in.vertex_count());
        if (clean.with_sources) clean.source.reserve(in.vertex_count());
        clean_part c;
        for (std::size_t p = 0; p < nparts; ++p) {
            c.points.clear();
            c.source.clear();
            if (!clean_one(p, c)) continue;
            clean_of[p] = clean.size();
            clean.add(c);
        }
    }
    // 2. Arcs.
    topology topo = build_topology(clean, opt.preserve_topology);
    clean = clean_layer{};  // the topology has what is needed of it
    std::vector<detail::arc_work> arcs(topo.arcs.size());
    for (std::size_t i = 0; i < arcs.size(); ++i) {
        auto& a = arcs[i];
        const auto& t = topo.arcs[i];
        a.closed = t.closed;
        a.pts.reserve(t.vertices.size());
        for (std::size_t v : t.vertices) a.pts.push_back(p2{{topo.points[v][0], topo.points[v][1]}});
        // A two-point open arc is its segment.
        a.level.assign(a.pts.size(), a.pts.size() == 2 && !a.closed ? detail::linear_level : 0);
        a.raise.assign(a.segments(), 0);
    }
    // Rounding slack: a few ulps of the largest coordinate.
    double scale = 0;
    for (const auto& p : topo.points) scale = std::max({scale, std::abs(p[0]), std::abs(p[1])});
    const double slack = detail::rounding_slack(scale, tol);
    std::vector<std::array<double, 2>>().swap(topo.points);  // the arcs have their points
    if (opt.fit) {
        // fit() refuses a tolerance at its rounding floor; so does the layer,
        // naming the layer's floor (256 ulps of its largest coordinate, at
        // least the slack the proof allows itself).
        const double floor = std::max(256 * std::numeric_limits<double>::epsilon() * scale, 4 * slack);
        if (!(*opt.fit > floor))
            throw invalid_input("fit " + crspline::detail::num(*opt.fit) + " is at or below the rounding floor " +
                                crspline::detail::num(floor) + " of the layer (its largest coordinate is " +
                                crspline::detail::num(scale) + ")");
        for (auto& a : arcs) detail::fit_arc(a, opt.alpha, *opt.fit);
    }

    // 3. Rounds: build, tessellate, prove; raise tension where not proved.
    detail::proof pr{arcs, opt, slack};
    pr.keep_parameters = E > 0;
    pr.run();
    // What the topology still holds that the output does not need is
    // released before the output is made: each arc's vertex ids but its
    // ends (the verdicts need them) and, without extra values, the layer
    // vertex of each arc vertex. (Released before the proof instead, the
    // holes they left all over the heap made the proof's allocations 4%
    // slower at 10^6 lines.)
    std::vector<std::array<std::size_t, 2>> arc_ends(topo.arcs.size());
    for (std::size_t i = 0; i < topo.arcs.size(); ++i) {
        auto& t = topo.arcs[i];
        arc_ends[i] = {t.vertices.front(), t.vertices.back()};
        std::vector<std::size_t>().swap(t.vertices);
        if (E == 0) std::vector<std::size_t>().swap(t.source);
    }
    res.stats.rounds = pr.rounds;
    res.stats.pairs_checked = pr.pairs;
    res.stats.input_crossings = pr.crossings;
    res.stats.input_touches = pr.touches;
    res.stats.swept_vertices = pr.swept;
    res.stats.restored_vertices = pr.restored;
    for (const auto& a : arcs) res.stats.pieces += a.pieces;
    const std::vector<std::uint8_t>& arc_crossing = pr.crossing;

    // 4. Extras along the arcs, lengths, the output layer.
    for (const auto& t : topo.arcs) {
        ++res.stats.arcs;
        if (t.uses > 1) ++res.stats.shared_arcs;
    }
    for (std::size_t v = 0; v < topo.junction.size(); ++v) res.stats.junctions += topo.junction[v];
    std::vector<double> arc_length_of(arcs.size(), 0);
    for (std::size_t i = 0; i < arcs.size(); ++i) {
        if (opt.progress && i % 4096 == 0) opt.progress(0.8 + 0.2 * double(i) / double(arcs.size()));
        auto& a = arcs[i];
        for (auto l : a.level) res.stats.tensioned_vertices += l > 0 && !(a.pts.size() == 2 && !a.closed);
        for (std::size_t s = 0; s < a.segments(); ++s) res.stats.linear_segments += a.linear(s);
        arc_length_of[i] = detail::arc_curve_length(a);
        if (opt.keep_curves) res.curves.push_back({std::move(*a.curve), topo.arcs[i].features});
    }
    layer& out = res.output;
    out.extra_dims = E;
    out.feature_count = in.feature_count;
    out.part_kinds = in.part_kinds;
    out.part_features = in.part_features;
    out.part_offsets.assign(1, 0);
    auto emit = [&](const p2& p, const double* ex) {
        out.xy.push_back(p[0]);
        out.xy.push_back(p[1]);
        for (std::size_t k = 0; k < E; ++k) out.extra.push_back(ex[k]);
    };
    // The output's size is known now: reserved at once, not grown by
    // doubling (at 10^6 walks the polylines are 10^8 vertices). Each arc's
    // polyline is released once its last part has been written.
    std::vector<std::size_t> uses_left(arcs.size(), 0);
    // Measures only, the input given away: its arrays are the output's,
    // moved once the parts are read (below), neither reserved nor copied.
    const bool moved = consumed && !opt.polylines;
    if (!moved) {
        std::size_t total = 0;
        for (std::size_t p = 0; p < nparts; ++p) {
            if (clean_of[p] == SIZE_MAX || !opt.polylines) {
                total += in.part_size(p);
                continue;
            }
            for (const auto& [ai, reversed] : topo.part_arcs(clean_of[p])) {
                total += arcs[ai].line.points.size();
                ++uses_left[ai];
            }
            ++total;  // a ring's closing vertex (at most)
        }
        out.xy.reserve(2 * total);
        out.extra.reserve(E * total);
        out.part_offsets.reserve(nparts + 1);
    }
    std::vector<double> ex(E);
    for (std::size_t p = 0; p < nparts; ++p) {
        const std::size_t f = in.part_features[p];
        auto& rep = res.features[f];
        if (clean_of[p] != SIZE_MAX && !opt.polylines) {
            // Measures only: the curves' lengths and deviations, the input as output.
            if (in.part_kinds[p] != part_kind::ring) ++rep.control_points;
            for (const auto& [ai, reversed] : topo.part_arcs(clean_of[p])) {
                rep.length += arc_length_of[ai];
                rep.max_deviation = std::max(rep.max_deviation, arcs[ai].max_dev);
                rep.control_points += arcs[ai].closed ? arcs[ai].pts.size() : arcs[ai].pts.size() - 1;
            }
        }
        if (clean_of[p] == SIZE_MAX) rep.control_points += in.part_size(p);  // passed through
        if (moved) continue;
        if (clean_of[p] == SIZE_MAX || !opt.polylines) {
            // Passed through unchanged.
            for (std::size_t v = in.part_offsets[p]; v < in.part_offsets[p + 1]; ++v)
                emit(p2{{in.xy[2 * v], in.xy[2 * v + 1]}}, E ? &in.extra[v * E] : nullptr);
            out.part_offsets.push_back(out.vertex_count());
            continue;
        }
        const std::size_t start = out.vertex_count();
        bool first_arc = true;
        if (in.part_kinds[p] != part_kind::ring) ++rep.control_points;  // a line's last point
        for (const auto& [ai, reversed] : topo.part_arcs(clean_of[p])) {
            const auto& a = arcs[ai];
            rep.control_points += a.closed ? a.pts.size() : a.pts.size() - 1;
            const auto& src = topo.arcs[ai].source;
            rep.length += arc_length_of[ai];
            rep.max_deviation = std::max(rep.max_deviation, a.max_dev);
            const std::size_t m = a.line.points.size();
            for (std::size_t j = 0; j < m; ++j) {
                const std::size_t k = reversed ? m - 1 - j : j;
                if (!first_arc && j == 0) continue;  // the junction, already out
                if (E > 0) {
                    const std::size_t s = a.vseg[k];
                    const double u = a.vu[k];
                    // (A fitted arc's control point: its vertex among all.)
                    const std::size_t v0 = a.fitted() ? a.src[s] % a.full.size() : s,
                                      v1 = a.fitted() ? a.src[a.next(s)] % a.full.size() : a.next(s);
                    for (std::size_t c = 0; c < E; ++c) {
                        const double e0 = in.extra[src[v0] * E + c], e1 = in.extra[src[v1] * E + c];
                        ex[c] = u == 0 ? e0 : u == 1 ? e1 : e0 + u * (e1 - e0);
                    }
                }
                emit(a.line.points[k], ex.data());
            }
            first_arc = false;
            if (--uses_left[ai] == 0) {
                auto& done = arcs[ai];
                done.line = {};
                std::vector<std::uint32_t>().swap(done.vseg);
                std::vector<double>().swap(done.vu);
            }
        }
        // A ring ends at its first vertex (it does already when its last arc closes it).
        if (in.part_kinds[p] == part_kind::ring) {
            const std::size_t n = out.vertex_count();
            if (!(out.xy[2 * start] == out.xy[2 * (n - 1)] && out.xy[2 * start + 1] == out.xy[2 * (n - 1) + 1])) {
                out.xy.push_back(out.xy[2 * start]);
                out.xy.push_back(out.xy[2 * start + 1]);
                for (std::size_t c = 0; c < E; ++c) out.extra.push_back(out.extra[start * E + c]);
            }
        }
        out.part_offsets.push_back(out.vertex_count());
    }
    if (moved) {
        out.part_kinds = std::move(consumed->part_kinds);
        out.part_features = std::move(consumed->part_features);
        out.xy = std::move(consumed->xy);
        out.extra = std::move(consumed->extra);
        out.part_offsets = std::move(consumed->part_offsets);
    }
    // 5. Verdicts.
    // The features at each open arc's ends, as (vertex, feature) pairs,
    // sorted and unique (one flat array: a list per vertex of the layer was
    // a fresh, mostly empty 24 bytes per vertex).
    std::vector<std::pair<std::size_t, std::size_t>> junction_features;
    for (std::size_t i = 0; i < topo.arcs.size(); ++i)
        if (!topo.arcs[i].closed)
            for (std::size_t v : arc_ends[i])
                for (std::size_t f : topo.arcs[i].features) junction_features.push_back({v, f});
    // (In order already where arcs end at increasing vertex ids, as a
    // layer of separate lines does: then checked, not sorted again.)
    if (!std::is_sorted(junction_features.begin(), junction_features.end()))
        std::sort(junction_features.begin(), junction_features.end());
    junction_features.erase(std::unique(junction_features.begin(), junction_features.end()), junction_features.end());
    // The vertices where arcs of more than one feature end, sorted (few: a
    // search there, not in every pair, which missed the cache at 10^6 lines).
    std::vector<std::size_t> shared_ends;
    for (std::size_t k = 1; k < junction_features.size(); ++k)
        if (junction_features[k].first == junction_features[k - 1].first &&
            (shared_ends.empty() || shared_ends.back() != junction_features[k].first))
            shared_ends.push_back(junction_features[k].first);
    std::vector<std::pair<std::size_t, std::size_t>>().swap(junction_features);
    for (std::size_t i = 0; i < topo.arcs.size(); ++i) {
        const auto& t = topo.arcs[i];
        bool touches = t.features.size() > 1;
        if (!t.closed)
            for (std::size_t v : arc_ends[i])
                touches = touches || std::binary_search(shared_ends.begin(), shared_ends.end(), v);
        for (std::size_t f : t.features) {
            auto& rep = res.features[f];
            if (arc_crossing[i] == 2) rep.verdict = verdict::crosses;
            else if ((touches || arc_crossing[i] == 1) && rep.verdict == verdict::simple) rep.verdict = verdict::touches;
        }
    }
    for (std::size_t f = 0; f < nesting.size(); ++f) {
        if (nesting[f].empty()) continue;
        auto& rep = res.features[f];
        rep.verdict = std::max(rep.verdict, verdict::nested);
        rep.message = nesting[f];
    }
    if (opt.progress) opt.progress(1.0);
    return res;
}

}  // namespace detail

}  // namespace crspline::geo
