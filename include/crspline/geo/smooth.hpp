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
//   and the feature's verdict says `crosses`). The proof, pair of polyline
//   pieces by pair (each piece within its flatness bound e of its chord):
//     * pieces of one cubic segment: the segment has no loop or cusp
//       (analyze_segment, exact);
//     * pieces that share an end point V: the Bézier control points of each
//       lie in a wedge at V narrower than pi, and the two wedges are
//       disjoint, so the pieces (inside their control hulls) meet only at V;
//     * other pieces: their chords are more than e1 + e2 apart.
//   Where a pair is not proved, the tension of the vertices of the
//   segments involved goes up one level (0, 0.5, 0.8, 0.95, 1): tension 1
//   at both ends makes the segment the input segment itself (a Hermite
//   cubic with zero end tangents is its chord), exact, so the last resort
//   is the input, and two input segments are proved apart by their exact
//   distance;
// - with max_deviation: no curve point is farther than that from the input
//   polyline, proved per piece by max(distance of the piece's chord ends to
//   the input segment) + e (the distance to a segment is convex along the
//   chord), raised by local tension the same way;
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
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "../analysis.hpp"
#include "../arc_length.hpp"
#include "../catmull_rom.hpp"
#include "../detail/format.hpp"
#include "../error.hpp"
#include "../tessellate.hpp"
#include "../vec.hpp"
#include "layer.hpp"
#include "topology.hpp"

namespace crspline::geo {

/// What happened to a feature.
enum class feature_status : std::uint8_t {
    ok = 0,          ///< smoothed
    empty = 1,       ///< no vertices: nothing to smooth, output empty
    degenerate = 2,  ///< a part with too few distinct points, passed through (others smoothed)
    invalid = 3,     ///< a non-finite coordinate: the feature passed through unchanged
};

/// How a feature's output meets the others and itself.
enum class verdict : std::uint8_t {
    simple = 0,   ///< meets no other output, and itself only at its joints
    touches = 1,  ///< shares a boundary or a junction with another feature (a coverage), or its input touches one
    crosses = 2,  ///< an input crossing remains: the input segments there are output as they are
};

inline const char* to_string(feature_status s) noexcept {
    switch (s) {
        case feature_status::ok: return "ok";
        case feature_status::empty: return "empty";
        case feature_status::degenerate: return "degenerate";
        case feature_status::invalid: return "invalid";
    }
    return "?";
}
inline const char* to_string(verdict v) noexcept {
    switch (v) {
        case verdict::simple: return "simple";
        case verdict::touches: return "touches";
        case verdict::crosses: return "crosses";
    }
    return "?";
}

/// How to smooth. Every choice has a visible default except the tolerance.
struct smooth_options {
    double alpha = 0.5;                   ///< knot exponent in [0, 1]; centripetal by default
    double tolerance = 0;                 ///< output polyline within this of the curve; > 0, required
    std::optional<double> max_deviation{};  ///< no curve point farther than this from the input polyline
    bool preserve_topology = true;        ///< shared arcs and the crossing proof; false: part by part, unchecked
    /// If given, every curve stays inside this box (proved by its pieces'
    /// control points, raised by tension like the rest): a geographic
    /// layer's frame keeps latitudes within the poles and longitudes within
    /// the antimeridian. Inputs outside it are left as they are there.
    std::optional<box<2>> domain{};
};

/// One feature's outcome. Lengths and deviations in the layer's units.
struct feature_report {
    feature_status status = feature_status::ok;
    geo::verdict verdict = geo::verdict::simple;
    double length = 0;         ///< arc length of the smoothed curves (all parts, all rings)
    double max_deviation = 0;  ///< proved bound on the distance of the curves from the input polyline
    std::string message;       ///< why, when the status is not ok
};

/// Counts of what smooth() did, for reports and tests.
struct smooth_stats {
    std::size_t arcs = 0;                ///< arcs smoothed (each once)
    std::size_t shared_arcs = 0;         ///< arcs used by more than one part
    std::size_t junctions = 0;
    std::size_t rounds = 0;              ///< proof rounds (1 when nothing needed tension)
    std::size_t tensioned_vertices = 0;  ///< arc vertices left with tension > 0
    std::size_t linear_segments = 0;     ///< segments output as their input segment (tension 1)
    std::size_t pieces = 0;              ///< polyline pieces in the final proof
    std::size_t pairs_checked = 0;       ///< candidate pairs examined in the final proof
    std::size_t input_crossings = 0;     ///< pairs of input segments that cross (left as they are)
    std::size_t input_touches = 0;       ///< pairs of input segments that touch or overlap without crossing
};

struct smooth_result {
    layer output;                          ///< same parts, kinds, features and extra_dims; rings closed (first vertex repeated)
    std::vector<feature_report> features;  ///< one per feature of the input
    smooth_stats stats;
};

namespace detail {

inline constexpr double tension_levels[] = {0, 0.5, 0.8, 0.95, 1};
inline constexpr std::uint8_t linear_level = 4;

using p2 = vec<2>;

inline double cross2(const p2& a, const p2& b) noexcept { return a[0] * b[1] - a[1] * b[0]; }

// Distance from p to the segment [a, b].
inline double point_segment_distance(const p2& p, const p2& a, const p2& b) noexcept {
    const p2 d = b - a, w = p - a;
    const double l2 = dot(d, d);
    const double f = l2 > 0 ? std::clamp(dot(w, d) / l2, 0.0, 1.0) : 0.0;
    return norm(w - f * d);
}

// Whether the closed segments [a, b] and [c, d] meet (exact orientation
// signs of double arithmetic; used only to tell an input crossing).
inline bool segments_meet(const p2& a, const p2& b, const p2& c, const p2& d) noexcept {
    auto orient = [](const p2& p, const p2& q, const p2& r) {
        const double v = cross2(q - p, r - p);
        return (v > 0) - (v < 0);
    };
    auto on = [](const p2& p, const p2& q, const p2& r) {  // r on [p, q], given collinear
        return std::min(p[0], q[0]) <= r[0] && r[0] <= std::max(p[0], q[0]) && std::min(p[1], q[1]) <= r[1] &&
               r[1] <= std::max(p[1], q[1]);
    };
    const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (o1 != o2 && o3 != o4) return true;
    return (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) ||
           (o4 == 0 && on(c, d, b));
}

// Whether [a, b] and [c, d] cross properly: each one's ends strictly on
// both sides of the other's line.
inline bool segments_cross(const p2& a, const p2& b, const p2& c, const p2& d) noexcept {
    auto orient = [](const p2& p, const p2& q, const p2& r) {
        const double v = cross2(q - p, r - p);
        return (v > 0) - (v < 0);
    };
    const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
    return o1 * o2 < 0 && o3 * o4 < 0;
}

// Distance between the segments [a, b] and [c, d].
inline double segment_distance(const p2& a, const p2& b, const p2& c, const p2& d) noexcept {
    if (segments_meet(a, b, c, d)) return 0;
    return std::min(std::min(point_segment_distance(a, c, d), point_segment_distance(b, c, d)),
                    std::min(point_segment_distance(c, a, b), point_segment_distance(d, a, b)));
}

// One polyline piece: a chord with its curve piece's control points.
struct piece {
    std::uint32_t arc = 0, seg = 0;
    std::array<p2, 4> q{};  // Bézier points of the curve piece: q[0], q[3] the chord's ends
    double e = 0;           // the curve piece is within e of the chord (0: linear, exact)
    bool linear = false;
    box<2> bounds{};
};

// The angular interval, seen from V, holding the control points of p other
// than V itself: [lo, hi] in radians, hi - lo < pi. False when it is not
// that narrow (or every point is V).
inline bool wedge_at(const piece& p, const p2& v, double slack, double& lo, double& hi) {
    bool have = false;
    p2 ref{};
    double a = 0, b = 0;
    for (const p2& q : p.q) {
        const p2 d = q - v;
        if (std::abs(d[0]) <= slack && std::abs(d[1]) <= slack) continue;
        if (!have) {
            ref = d;
            have = true;
            continue;
        }
        const double ang = std::atan2(cross2(ref, d), dot(ref, d));
        a = std::min(a, ang);
        b = std::max(b, ang);
    }
    if (!have || b - a >= std::numbers::pi * 0.999) return false;
    const double base = std::atan2(ref[1], ref[0]);
    lo = base + a;
    hi = base + b;
    return true;
}

// Pieces p and q sharing the end point v meet nowhere else: their wedges at
// v are disjoint (with a margin against rounding).
inline bool wedges_apart(const piece& p, const piece& q, const p2& v, double slack) {
    double a0, a1, b0, b1;
    if (!wedge_at(p, v, slack, a0, a1) || !wedge_at(q, v, slack, b0, b1)) return false;
    constexpr double margin = 1e-9, two_pi = 2 * std::numbers::pi;
    double s = std::fmod(b0 - a0, two_pi);
    if (s < 0) s += two_pi;
    return s > (a1 - a0) + margin && s + (b1 - b0) < two_pi - margin;
}

// An arc being smoothed.
struct arc_work {
    std::vector<p2> pts;
    std::vector<std::uint8_t> level;  // tension level per vertex
    bool closed = false;
    std::optional<catmull_rom<2>> base;   // alpha curve, no tension
    std::optional<catmull_rom<2>> curve;  // the one used
    polyline<2> line;                     // knot vertices exact input points
    std::vector<std::uint32_t> vseg;      // segment of each polyline vertex (the piece it starts)
    std::vector<double> vu;               // local u of each vertex in that segment (1 at a segment's end)
    std::vector<std::uint8_t> raise;      // per segment: raise its vertices' tension
    double max_dev = 0;
    bool dirty = true;

    std::size_t segments() const noexcept { return closed ? pts.size() : pts.size() - 1; }
    std::size_t next(std::size_t i) const noexcept { return i + 1 == pts.size() ? 0 : i + 1; }
    bool linear(std::size_t s) const noexcept {
        return level[s] == linear_level && level[next(s)] == linear_level;
    }
};

inline void build_arc_curve(arc_work& a, double alpha) {
    using curve_t = catmull_rom<2>;
    if (!a.base) {
        options<2> opt;
        opt.alpha = alpha;
        opt.closed = a.closed;
        a.base.emplace(std::span<const p2>(a.pts), opt);
    }
    bool plain = true;
    for (auto l : a.level) plain = plain && l == 0;
    if (plain) {
        a.curve = a.base;
        return;
    }
    const std::size_t n = a.pts.size();
    std::vector<p2> out(n), in(n);
    for (std::size_t s = 0; s < a.segments(); ++s) {
        const auto tg = a.base->tangents(s);
        out[s] = (1 - tension_levels[a.level[s]]) * tg[0];
        in[a.next(s)] = (1 - tension_levels[a.level[a.next(s)]]) * tg[1];
    }
    const auto g = a.base->grid();
    a.curve = curve_t::hermite(std::span<const p2>(a.pts), std::span<const p2>(out), std::span<const p2>(in),
                               std::span<const double>(g.data(), g.size()), a.closed);
}

// Tessellates the arc's curve; the vertices at knots become the input
// points exactly; records each vertex's segment and u.
inline void tessellate_arc(arc_work& a, double tolerance) {
    a.line = tessellate(*a.curve, tolerance);
    const auto g = a.curve->grid();
    const std::size_t segs = a.segments();
    a.vseg.assign(a.line.t.size(), 0);
    a.vu.assign(a.line.t.size(), 0);
    std::size_t s = 0;
    for (std::size_t k = 0; k < a.line.t.size(); ++k) {
        const double t = a.line.t[k];
        while (s + 1 < segs && t >= g[s + 1]) ++s;
        a.vseg[k] = std::uint32_t(s);
        if (t == g[s]) {
            a.line.points[k] = a.pts[s];
            a.vu[k] = 0;
        } else if (t == g[s + 1]) {
            a.line.points[k] = a.pts[a.next(s)];
            a.vu[k] = 1;
        } else {
            a.vu[k] = a.curve->segment(s).local(t);
        }
    }
}

}  // namespace detail

/// Smooths the layer (see the file comment for what is promised). Throws
/// invalid_input for bad options or arrays that disagree; bad coordinates
/// make their feature `invalid` instead.
inline smooth_result smooth(const layer& in, const smooth_options& opt) {
    using detail::p2;
    check_layer(in);
    if (!(opt.alpha >= 0 && opt.alpha <= 1))
        throw invalid_input("alpha must be in [0, 1], got " + crspline::detail::num(opt.alpha));
    if (!(opt.tolerance > 0 && std::isfinite(opt.tolerance)))
        throw invalid_input("tolerance must be positive and finite, got " + crspline::detail::num(opt.tolerance));
    if (opt.max_deviation && !(*opt.max_deviation > 0 && std::isfinite(*opt.max_deviation)))
        throw invalid_input("max_deviation must be positive and finite, got " +
                            crspline::detail::num(*opt.max_deviation));
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
    std::vector<clean_part> clean;
    std::vector<std::size_t> clean_of(nparts, SIZE_MAX);  // part -> index in clean, or pass-through
    for (std::size_t p = 0; p < nparts; ++p) {
        const std::size_t f = in.part_features[p];
        auto& rep = res.features[f];
        if (rep.status == feature_status::invalid || in.part_size(p) == 0) continue;
        clean_part c;
        c.ring = in.part_kinds[p] == part_kind::ring;
        c.feature = f;
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
        // Distinct points, counted up to `need` (a ring may go back and forth).
        std::vector<std::array<double, 2>> seen;
        for (const auto& q : c.points) {
            if (seen.size() == need) break;
            if (std::find(seen.begin(), seen.end(), q) == seen.end()) seen.push_back(q);
        }
        const std::size_t distinct = seen.size();
        if (distinct < need) {
            rep.status = feature_status::degenerate;
            rep.message = "part " + std::to_string(part_index[p]) + " (" + (c.ring ? "ring" : "line") + ") has " +
                          std::to_string(distinct) + " distinct point" + (distinct == 1 ? "" : "s") +
                          ", a " + (c.ring ? "ring" : "line") + " needs " + std::to_string(need) +
                          ": passed through unchanged";
            continue;
        }
        clean_of[p] = clean.size();
        clean.push_back(std::move(c));
    }
    // 2. Arcs.
    const topology topo = build_topology(clean, opt.preserve_topology);
    std::vector<detail::arc_work> arcs(topo.arcs.size());
    for (std::size_t i = 0; i < arcs.size(); ++i) {
        auto& a = arcs[i];
        const auto& t = topo.arcs[i];
        a.closed = t.closed;
        for (std::size_t v : t.vertices) a.pts.push_back(p2{{topo.points[v][0], topo.points[v][1]}});
        // A two-point open arc is its segment.
        a.level.assign(a.pts.size(), a.pts.size() == 2 && !a.closed ? detail::linear_level : 0);
        a.raise.assign(a.segments(), 0);
    }
    // Rounding slack: a few ulps of the largest coordinate.
    double scale = 0;
    for (const auto& p : topo.points) scale = std::max({scale, std::abs(p[0]), std::abs(p[1])});
    const double slack = 64 * std::numeric_limits<double>::epsilon() * std::max(scale, tol);

    // 3. Rounds: build, tessellate, prove; raise tension where not proved.
    std::vector<detail::piece> pieces;
    std::vector<std::uint8_t> arc_crossing(arcs.size(), 0);
    constexpr std::size_t max_rounds = 64;
    for (std::size_t round = 1;; ++round) {
        res.stats.rounds = round;
        bool failed = false;
        for (std::size_t i = 0; i < arcs.size(); ++i) {
            auto& a = arcs[i];
            std::fill(a.raise.begin(), a.raise.end(), 0);
            if (!a.dirty) continue;
            detail::build_arc_curve(a, opt.alpha);
            detail::tessellate_arc(a, tol);
            // Loops and cusps inside a segment (exact); only where tension
            // leaves curvature.
            if (opt.preserve_topology)
                for (std::size_t s = 0; s < a.segments(); ++s) {
                    if (a.linear(s)) continue;
                    const auto an = analyze_segment(a.curve->segment(s));
                    if (an.has_self_intersection() || an.has_cusp()) a.raise[s] = 1;
                }
        }
        // Pieces, deviation.
        pieces.clear();
        for (std::size_t i = 0; i < arcs.size(); ++i) {
            auto& a = arcs[i];
            a.max_dev = 0;
            for (std::size_t k = 0; k + 1 < a.line.points.size(); ++k) {
                const std::size_t s = a.vseg[k];
                detail::piece pc;
                pc.arc = std::uint32_t(i);
                pc.seg = std::uint32_t(s);
                pc.linear = a.linear(s);
                const p2 pa = a.line.points[k], pb = a.line.points[k + 1];
                pc.q[0] = pa;
                pc.q[3] = pb;
                if (pc.linear) {
                    pc.q[1] = pa;
                    pc.q[2] = pb;
                } else {
                    const auto seg = a.curve->segment(s);
                    // The next vertex is in this segment, or is its end knot.
                    const double u0 = a.vu[k], u1e = a.vseg[k + 1] == s ? a.vu[k + 1] : 1.0;
                    const double w = u1e - u0;
                    pc.q[1] = pa + (w / 3) * seg.du(u0, 1);
                    pc.q[2] = pb - (w / 3) * seg.du(u1e, 1);
                    pc.e = flatness_bound(seg, u0, u1e) + slack;
                }
                pc.bounds = box<2>::of(pa);
                pc.bounds.expand(pb);
                const p2 sa = a.pts[s], sb = a.pts[a.next(s)];
                const double dev = pc.linear ? 0.0
                                             : std::max(detail::point_segment_distance(pa, sa, sb),
                                                        detail::point_segment_distance(pb, sa, sb)) +
                                                   pc.e;
                a.max_dev = std::max(a.max_dev, dev);
                if (opt.max_deviation && dev > *opt.max_deviation && !pc.linear) a.raise[s] = 1;
                if (opt.domain && !pc.linear)
                    for (const p2& q : pc.q)
                        if (!opt.domain->contains(q)) a.raise[s] = 1;
                pieces.push_back(pc);
            }
        }
        // Pairs, by a sweep along x over boxes padded by the largest margin.
        std::size_t pairs = 0, crossings = 0, touches = 0;
        std::fill(arc_crossing.begin(), arc_crossing.end(), 0);
        if (opt.preserve_topology) {
            double emax = 0;
            for (const auto& pc : pieces) emax = std::max(emax, pc.e);
            const double pad = 2 * emax + slack;
            std::vector<std::uint32_t> order(pieces.size());
            for (std::size_t k = 0; k < order.size(); ++k) order[k] = std::uint32_t(k);
            std::sort(order.begin(), order.end(),
                      [&](auto x, auto y) { return pieces[x].bounds.lo[0] < pieces[y].bounds.lo[0]; });
            auto fail = [&](const detail::piece& pc) {
                if (!pc.linear) arcs[pc.arc].raise[pc.seg] = 1;
            };
            for (std::size_t oi = 0; oi < order.size(); ++oi) {
                const auto& p = pieces[order[oi]];
                for (std::size_t oj = oi + 1; oj < order.size(); ++oj) {
                    const auto& q = pieces[order[oj]];
                    if (q.bounds.lo[0] > p.bounds.hi[0] + pad) break;
                    if (q.bounds.lo[1] > p.bounds.hi[1] + pad || p.bounds.lo[1] > q.bounds.hi[1] + pad) continue;
                    if (p.arc == q.arc && p.seg == q.seg) continue;
                    ++pairs;
                    // A shared end point: the wedge test.
                    const p2* shared = nullptr;
                    for (int i = 0; i < 2 && !shared; ++i)
                        for (int j = 0; j < 2 && !shared; ++j)
                            if (p.q[3 * i] == q.q[3 * j]) shared = &p.q[3 * i];
                    bool proved;
                    if (shared) {
                        proved = detail::wedges_apart(p, q, *shared, slack);
                    } else {
                        const double d = detail::segment_distance(p.q[0], p.q[3], q.q[0], q.q[3]);
                        proved = d > p.e + q.e + (p.linear && q.linear ? 0.0 : slack);
                    }
                    if (proved) continue;
                    if (p.linear && q.linear) {
                        // The input itself meets here: left as it is. A
                        // proper crossing (each segment's ends strictly on
                        // both sides of the other) or a touch.
                        const bool proper = detail::segments_cross(p.q[0], p.q[3], q.q[0], q.q[3]);
                        ++(proper ? crossings : touches);
                        for (auto ai : {p.arc, q.arc})
                            arc_crossing[ai] = std::max<std::uint8_t>(arc_crossing[ai], proper ? 2 : 1);
                        continue;
                    }
                    fail(p);
                    fail(q);
                }
            }
        }
        res.stats.pairs_checked = pairs;
        res.stats.input_crossings = crossings;
        res.stats.input_touches = touches;
        res.stats.pieces = pieces.size();
        // Raise tension where needed.
        for (auto& a : arcs) {
            a.dirty = false;
            for (std::size_t s = 0; s < a.segments(); ++s) {
                if (!a.raise[s]) continue;
                failed = true;
                a.dirty = true;
                for (std::size_t v : {s, a.next(s)}) {
                    // After many rounds, straight to the last resort.
                    const std::uint8_t to = round >= max_rounds / 2 ? detail::linear_level
                                                                    : std::uint8_t(a.level[v] + 1);
                    a.level[v] = std::min(detail::linear_level, std::max(a.level[v], to));
                }
            }
        }
        if (!failed) break;
        if (round >= max_rounds) break;  // cannot happen: levels only grow and linear pairs never fail
    }

    // 4. Extras along the arcs, lengths, the output layer.
    for (const auto& t : topo.arcs) {
        ++res.stats.arcs;
        if (t.uses > 1) ++res.stats.shared_arcs;
    }
    for (std::size_t v = 0; v < topo.junction.size(); ++v) res.stats.junctions += topo.junction[v];
    std::vector<double> arc_length_of(arcs.size(), 0);
    for (std::size_t i = 0; i < arcs.size(); ++i) {
        auto& a = arcs[i];
        for (auto l : a.level) res.stats.tensioned_vertices += l > 0 && !(a.pts.size() == 2 && !a.closed);
        double len = 0;
        for (std::size_t s = 0; s < a.segments(); ++s) {
            if (a.linear(s)) {
                ++res.stats.linear_segments;
                len += norm(a.pts[a.next(s)] - a.pts[s]);
            } else {
                len += arc_length(a.curve->segment(s));
            }
        }
        arc_length_of[i] = len;
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
    std::vector<double> ex(E);
    for (std::size_t p = 0; p < nparts; ++p) {
        const std::size_t f = in.part_features[p];
        auto& rep = res.features[f];
        if (clean_of[p] == SIZE_MAX) {
            // Passed through unchanged.
            for (std::size_t v = in.part_offsets[p]; v < in.part_offsets[p + 1]; ++v)
                emit(p2{{in.xy[2 * v], in.xy[2 * v + 1]}}, E ? &in.extra[v * E] : nullptr);
            out.part_offsets.push_back(out.vertex_count());
            continue;
        }
        const std::size_t start = out.vertex_count();
        bool first_arc = true;
        for (const auto& [ai, reversed] : topo.parts[clean_of[p]].arcs) {
            const auto& a = arcs[ai];
            const auto& src = topo.arcs[ai].source;
            rep.length += arc_length_of[ai];
            rep.max_deviation = std::max(rep.max_deviation, a.max_dev);
            const std::size_t m = a.line.points.size();
            for (std::size_t j = 0; j < m; ++j) {
                const std::size_t k = reversed ? m - 1 - j : j;
                if (!first_arc && j == 0) continue;  // the junction, already out
                const std::size_t s = a.vseg[k];
                const double u = a.vu[k];
                for (std::size_t c = 0; c < E; ++c) {
                    const double e0 = in.extra[src[s] * E + c], e1 = in.extra[src[a.next(s)] * E + c];
                    ex[c] = u == 0 ? e0 : u == 1 ? e1 : e0 + u * (e1 - e0);
                }
                emit(a.line.points[k], ex.data());
            }
            first_arc = false;
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
    // 5. Verdicts.
    std::vector<std::vector<std::size_t>> junction_features(topo.points.size());
    for (const auto& t : topo.arcs)
        if (!t.closed)
            for (std::size_t v : {t.vertices.front(), t.vertices.back()})
                for (std::size_t f : t.features) junction_features[v].push_back(f);
    for (auto& jf : junction_features) {
        std::sort(jf.begin(), jf.end());
        jf.erase(std::unique(jf.begin(), jf.end()), jf.end());
    }
    for (std::size_t i = 0; i < topo.arcs.size(); ++i) {
        const auto& t = topo.arcs[i];
        bool touches = t.features.size() > 1;
        if (!t.closed)
            for (std::size_t v : {t.vertices.front(), t.vertices.back()})
                touches = touches || junction_features[v].size() > 1;
        for (std::size_t f : t.features) {
            auto& rep = res.features[f];
            if (arc_crossing[i] == 2) rep.verdict = verdict::crosses;
            else if ((touches || arc_crossing[i] == 1) && rep.verdict == verdict::simple) rep.verdict = verdict::touches;
        }
    }
    return res;
}

}  // namespace crspline::geo
