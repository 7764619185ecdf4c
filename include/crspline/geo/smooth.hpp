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
// All distances are in the layer's own units; the layer is planar (a
// geographic layer is put in a metric frame by the caller: see
// docs/geo.md).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
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
#include "../detail/gauss_legendre.hpp"
#include "../error.hpp"
#include "../tessellate.hpp"
#include "../vec.hpp"
#include "layer.hpp"
#include "nesting.hpp"
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
/// Ordered by what a user must look at first: the larger wins.
enum class verdict : std::uint8_t {
    simple = 0,   ///< meets no other output, and itself only at its joints
    touches = 1,  ///< shares a boundary or a junction with another feature (a coverage), or its input touches one
    nested = 2,   ///< the input's rings nest invalidly (geo/nesting.hpp; the message says which): kept as they are
    crosses = 3,  ///< an input crossing remains: the input segments there are output as they are
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
        case verdict::nested: return "nested";
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
    /// false: measures only (lengths, deviations, verdicts); the output
    /// layer is the input, and the curves are tessellated only where the
    /// proof needs their pieces.
    bool polylines = true;
    /// If set, called now and then from the calling thread with the
    /// fraction of the work done, in [0, 1] (a terminal's progress line).
    std::function<void(double)> progress{};
    /// true: smooth_result::curves holds every arc's final curve (the one
    /// the proof was about), e.g. to hand to decide() (decision.hpp).
    bool keep_curves = false;
};

/// One feature's outcome. Lengths and deviations in the layer's units.
struct feature_report {
    feature_status status = feature_status::ok;
    geo::verdict verdict = geo::verdict::simple;
    double length = 0;         ///< arc length of the smoothed curves (all parts, all rings)
    double max_deviation = 0;  ///< proved bound on the distance of the curves from the input polyline
    std::string message;       ///< why, when the status is not ok; with verdict nested, which ring lies where
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
    /// Times a vertex of another arc was found in the region a segment
    /// sweeps between its input chord and its curve (its tension raised
    /// there so that the vertex keeps its side), over every round.
    std::size_t swept_vertices = 0;
};

/// One arc's final curve (smooth_options::keep_curves): its tensioned
/// Catmull-Rom curve (segments at tension 1 on both ends are their input
/// segments) and the features that use the arc, sorted.
struct arc_curve {
    catmull_rom<2> curve;
    std::vector<std::size_t> features;
};

struct smooth_result {
    layer output;                          ///< same parts, kinds, features and extra_dims; rings closed (first vertex repeated)
    std::vector<feature_report> features;  ///< one per feature of the input
    smooth_stats stats;
    std::vector<arc_curve> curves;         ///< per arc, only with smooth_options::keep_curves
};

namespace detail {

inline constexpr double tension_levels[] = {0, 0.5, 0.8, 0.95, 1};
inline constexpr std::uint8_t linear_level = 4;

/// The distinct points among at(0) .. at(n - 1) (2-D points), counted up
/// to `need` (a line needs 2, a ring 3; a ring may go back and forth over
/// the same ones).
template <class At>
std::size_t distinct_up_to(std::size_t n, std::size_t need, At&& at) {
    std::array<std::array<double, 2>, 3> seen{};
    std::size_t distinct = 0;
    for (std::size_t i = 0; i < n && distinct < need; ++i) {
        const std::array<double, 2> q = at(i);
        if (std::find(seen.begin(), seen.begin() + std::ptrdiff_t(distinct), q) == seen.begin() + std::ptrdiff_t(distinct))
            seen[distinct++] = q;
    }
    return distinct;
}

/// The proof's rounding slack: a few ulps of the largest coordinate of the
/// parts smoothed (or of the tolerance, when that is larger).
inline double rounding_slack(double scale, double tolerance) {
    return 64 * std::numeric_limits<double>::epsilon() * std::max(scale, tolerance);
}

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

// The angular interval, seen from v, of the points q other than v (those
// within slack of it): [lo, hi] with hi - lo < pi. False when not that narrow.
inline bool wedge_of(const std::array<p2, 4>& pts, const p2& v, double slack, double& lo, double& hi) {
    bool have = false;
    p2 ref{};
    double a = 0, b = 0;
    for (const p2& q : pts) {
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

// The angular interval, seen from V, holding the control points of p other
// than V itself: [lo, hi] in radians, hi - lo < pi. False when it is not
// that narrow (or every point is V).
inline bool wedge_at(const piece& p, const p2& v, double slack, double& lo, double& hi) {
    return wedge_of(p.q, v, slack, lo, hi);
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
    // The curves live on the heap only while the arc's component is being
    // proved: an arc holds two pointers, not two curves (at 10^6 arcs the
    // inline optionals were 0.8 GB of mostly empty room).
    std::unique_ptr<catmull_rom<2>> base;   // the untensioned curve, once tension is used
    std::unique_ptr<catmull_rom<2>> curve;  // the one used (the untensioned one until then)
    polyline<2> line;                     // knot vertices exact input points; t given back (vseg, vu)
    std::vector<std::uint32_t> vseg;      // segment of each polyline vertex (the piece it starts)
    std::vector<double> vu;               // local u of each vertex in that segment (1 at a segment's end)
    std::vector<std::uint8_t> raise;      // per segment: raise its vertices' tension
    double max_dev = 0;
    bool dirty = true;
    std::vector<std::array<p2, 4>> hull;  // per segment: its Bézier points
    std::vector<box<2>> hull_box;         // per segment: their box
    std::vector<std::size_t> first_piece; // per segment: its first polyline piece; one more: the piece count
    crspline::box<2> bounds{};            // of all the hulls
    double length = 0;                    // set where the curve is measured early (no topology)
    bool measured = false;                // length is set
    bool has_line = false;                // line, vseg, vu, first_piece are this curve's
    std::size_t pieces = 0;               // pieces of this curve's polyline (0: none made); kept when released

    std::size_t segments() const noexcept { return closed ? pts.size() : pts.size() - 1; }
    std::size_t next(std::size_t i) const noexcept { return i + 1 == pts.size() ? 0 : i + 1; }
    bool linear(std::size_t s) const noexcept {
        return level[s] == linear_level && level[next(s)] == linear_level;
    }
};

// The arc's curve at its tension levels. Levels only grow: an arc without
// tension is built once, as `curve`; the first tension moves it to `base`
// (one copy of the untensioned curve, never two).
inline void build_arc_curve(arc_work& a, double alpha) {
    using curve_t = catmull_rom<2>;
    auto untensioned = [&] {
        options<2> opt;
        opt.alpha = alpha;
        opt.closed = a.closed;
        return curve_t(std::span<const p2>(a.pts), opt);
    };
    bool plain = true;
    for (auto l : a.level) plain = plain && l == 0;
    if (plain) {
        if (!a.curve) a.curve = std::make_unique<curve_t>(untensioned());
        return;
    }
    if (!a.base) {
        if (a.curve) a.base = std::move(a.curve);
        else a.base = std::make_unique<curve_t>(untensioned());
    }
    const std::size_t n = a.pts.size();
    std::vector<p2> out(n), in(n);
    for (std::size_t s = 0; s < a.segments(); ++s) {
        const auto tg = a.base->tangents(s);
        out[s] = (1 - tension_levels[a.level[s]]) * tg[0];
        in[a.next(s)] = (1 - tension_levels[a.level[a.next(s)]]) * tg[1];
    }
    const auto g = a.base->grid();
    a.curve = std::make_unique<curve_t>(curve_t::hermite(std::span<const p2>(a.pts), std::span<const p2>(out),
                                                         std::span<const p2>(in),
                                                         std::span<const double>(g.data(), g.size()), a.closed));
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
    auto seg = a.curve->segment(0);  // segment s, made once per segment
    for (std::size_t k = 0; k < a.line.t.size(); ++k) {
        const double t = a.line.t[k];
        const std::size_t was = s;
        while (s + 1 < segs && t >= g[s + 1]) ++s;
        if (s != was) seg = a.curve->segment(s);
        a.vseg[k] = std::uint32_t(s);
        if (t == g[s]) {
            a.line.points[k] = a.pts[s];
            a.vu[k] = 0;
        } else if (t == g[s + 1]) {
            a.line.points[k] = a.pts[a.next(s)];
            a.vu[k] = 1;
        } else {
            a.vu[k] = seg.local(t);
        }
    }
    // The parameters are in vseg and vu now; the room tessellate() reserved
    // (for the most vertices there could be) is given back.
    std::vector<double>().swap(a.line.t);
    a.line.points.shrink_to_fit();
}

// Bézier points of segment s of the arc's curve, the ends being the arc's
// vertices themselves. The segment's curve lies in their convex hull, and
// so does its output polyline (chords between points of the curve).
inline std::array<p2, 4> segment_bezier(const arc_work& a, std::size_t s) {
    const p2 p0 = a.pts[s], p3 = a.pts[a.next(s)];
    if (a.linear(s)) return {p0, p0, p3, p3};
    const auto seg = a.curve->segment(s);
    const p2 d0 = seg.du(0.0, 1), d1 = seg.du(1.0, 1);
    return {p0, p0 + d0 / 3.0, p3 - d1 / 3.0, p3};
}

// Length, to relative accuracy `accuracy`, of the cubic with Bezier points
// b whose speed vanishes at u = 0 (b[1] == b[0]: its first vertex at tension
// 1, the tangent there zero). Then C'(u) = 3 u (p + q u) with p = 2 (b2 -
// b0), q = b3 - 3 b2 + 2 b0, and the length is 3 J, J = int_0^1 u |p + q u|
// du. The factor u is taken out exactly, so what is integrated, u sqrt(Q(u))
// with Q(u) = |p + q u|^2, is analytic but at the two complex roots z of Q:
// known in closed form, they give each piece's Bernstein ellipse (rho) and
// the 16-point Gauss rule's error bound, 64/15 M (w/2) r^-32 / (r^2 - 1) for
// M >= |f| on the ellipse of parameter r < rho (Trefethen, ATAP ch. 19; |f|
// <= T (|p| + |q| T) with T >= |u| there); a piece whose bound exceeds its
// share of accuracy * chord / 3 (the chord |b3 - b0| is at most the length)
// is halved. (arc_length's general path sees such a segment's speed vanish
// at its end and spends tens of microseconds on it; here it takes one or
// two rules.) A speed vanishing at u = 1 is the same with b reversed.
inline double end_pinned_length(const std::array<p2, 4>& b, double accuracy) noexcept {
    const p2 p = 2.0 * (b[2] - b[0]), q = b[3] - 3.0 * b[2] + 2.0 * b[0];
    const double np = norm(p), nq = norm(q), chord = norm(b[3] - b[0]);
    if (nq == 0) return 3 * np / 2;  // |p| int u du
    if (np == 0) return nq;          // 3 |q| int u^2 du
    // The roots of Q: (-(p.q) +- i |p x q|) / |q|^2 (conjugates: one rho).
    const std::complex<double> z(-dot(p, q) / (nq * nq), std::abs(cross2(p, q)) / (nq * nq));
    const double tol = accuracy * chord / 3;
    using gl = crspline::detail::gauss_legendre<16, double>;
    auto f = [&](double u) { return u * norm(p + u * q); };
    auto rule = [&](double a, double c) {
        const double m = (a + c) / 2, h = (c - a) / 2;
        double sum = 0;
        for (int k = 0; k < 8; ++k) sum += gl::w[k] * (f(m - h * gl::x[k]) + f(m + h * gl::x[k]));
        return h * sum;
    };
    double total = 0;
    // Pieces on a stack, left to right; depth bounds the halving where a
    // root sits on the interval (a kink of the speed, p parallel to q).
    struct span_t {
        double a, c;
        int depth;
    };
    span_t stack[64];
    int top = 0;
    stack[top++] = {0.0, 1.0, 0};
    while (top > 0) {
        const span_t sp = stack[--top];
        const double w = sp.c - sp.a, m = (sp.a + sp.c) / 2;
        const std::complex<double> x = (2.0 * z - (sp.a + sp.c)) / w;
        const std::complex<double> r = x + std::sqrt(x - 1.0) * std::sqrt(x + 1.0);
        const double rho = std::min(1e4, std::max(std::abs(r), 1 / std::abs(r)));
        const double rr = 1 + 0.9 * (rho - 1);
        const double T = std::abs(m) + w / 4 * (rr + 1 / rr);
        const double M = T * (np + nq * T);
        const double bound = 64.0 / 15.0 * M * (w / 2) * std::pow(rr, -32.0) / (rr * rr - 1);
        if (bound <= tol * w || sp.depth >= 48 || top + 2 > 64) {
            total += rule(sp.a, sp.c);
            continue;
        }
        // Halve at the root's real part if well inside, else in the middle.
        const double cut = z.real() > sp.a + w / 16 && z.real() < sp.c - w / 16 ? z.real() : m;
        stack[top++] = {cut, sp.c, sp.depth + 1};  // right first: the left is summed first
        stack[top++] = {sp.a, cut, sp.depth + 1};
    }
    return 3 * total;
}

// Arc length of the arc's curve: a linear segment's is its chord's; a
// segment with one end at tension 1 by end_pinned_length; the others' to
// arc_length's default accuracy, sixteen segments at a time (arc_length.hpp's
// batch, the same pieces as arc_length(segment)); summed in segment order.
inline double arc_curve_length(const arc_work& a) {
    if (a.measured) return a.length;  // measured (and released) by proof::run_alone
    const std::size_t segs = a.segments();
    std::vector<double> len(segs, 0.0);
    std::vector<std::size_t> curved;
    curved.reserve(segs);
    for (std::size_t s = 0; s < segs; ++s) {
        const bool pinned0 = a.level[s] == linear_level, pinned1 = a.level[a.next(s)] == linear_level;
        if (pinned0 && pinned1) {
            len[s] = norm(a.pts[a.next(s)] - a.pts[s]);
        } else if (pinned0 || pinned1) {
            auto b = segment_bezier(a, s);
            if (pinned1) std::swap(b[0], b[3]), std::swap(b[1], b[2]);
            len[s] = end_pinned_length(b, default_accuracy);
        } else {
            curved.push_back(s);
        }
    }
    if (!curved.empty()) {
        const auto segments = a.curve->segments();
        crspline::detail::for_each_segment_length_piece(
            curved.size(), [&](std::size_t k) { return segments[curved[k]]; }, default_accuracy,
            [&](std::size_t k, double, double, double l, const crspline::detail::rule_choice&) { len[curved[k]] += l; });
    }
    double sum = 0;
    for (double l : len) sum += l;
    return sum;
}

// ---- The proof, segment by segment (see the file comment) ----------------

// Max and min of the cubic with Bernstein coefficients c0..c3 on [0, 1]:
// the ends and the roots of its derivative (a quadratic) inside.
inline std::pair<double, double> bernstein_range(double c0, double c1, double c2, double c3) noexcept {
    double lo = std::min(c0, c3), hi = std::max(c0, c3);
    auto at = [&](double u) {
        const double v = 1 - u;
        return v * v * v * c0 + 3 * u * v * (v * c1 + u * c2) + u * u * u * c3;
    };
    auto consider = [&](double u) {
        if (!(u > 0 && u < 1)) return;
        const double x = at(u);
        lo = std::min(lo, x);
        hi = std::max(hi, x);
    };
    // Derivative / 3 in Bernstein form: d0 (1-u)^2 + 2 d1 u (1-u) + d2 u^2.
    const double d0 = c1 - c0, d1 = c2 - c1, d2 = c3 - c2;
    const double qa = d0 - 2 * d1 + d2, qb = 2 * (d1 - d0), qc = d0;
    const double big = std::max({std::abs(qa), std::abs(qb), std::abs(qc)});
    if (big == 0) return {lo, hi};
    if (std::abs(qa) <= 1e-12 * big) {
        if (qb != 0) consider(-qc / qb);
        return {lo, hi};
    }
    const double disc = qb * qb - 4 * qa * qc;
    if (disc < 0) return {lo, hi};
    const double r = std::sqrt(disc);
    const double q = -0.5 * (qb + (qb >= 0 ? r : -r));  // no cancellation
    consider(q / qa);
    if (q != 0) consider(qc / q);
    return {lo, hi};
}

// A bound on the distance of the cubic with Bézier points b from the
// segment [b0, b3] (its own input segment): with a the coordinate along the
// segment and h across it (both cubics in u), every point is at distance
// sqrt(h^2 + overshoot^2) where overshoot is how far a runs past [0, L];
// the maximum of each, found in closed form, bounds it.
inline double segment_deviation(const std::array<p2, 4>& b) noexcept {
    const p2 d = b[3] - b[0];
    const double len = norm(d);
    if (!(len > 0)) return std::max(norm(b[1] - b[0]), norm(b[2] - b[0]));
    const p2 t = d / len, n{{-t[1], t[0]}};
    double a[4], h[4];
    for (int i = 0; i < 4; ++i) {
        const p2 r = b[i] - b[0];
        a[i] = dot(r, t);
        h[i] = dot(r, n);
    }
    const auto [hlo, hhi] = bernstein_range(h[0], h[1], h[2], h[3]);
    const auto [alo, ahi] = bernstein_range(a[0], a[1], a[2], a[3]);
    const double across = std::max(-hlo, hhi), over = std::max({0.0, -alo, ahi - len});
    return std::sqrt(across * across + over * over);
}

// Whether the segment with Bézier points b is free of loops and cusps
// cheaply: its Bézier points advance strictly along its chord (each step
// by more than `slack`), so the curve's coordinate along the chord grows
// strictly and the curve is a graph over the chord. An end step that is
// exactly zero (b1 == b0 or b2 == b3: that end at tension 1) is allowed:
// the derivative 3 [(1-u)^2 h0 + 2 u (1-u) h1 + u^2 h2] of the coordinate
// is still positive on (0, 1) and at the other end, so the coordinate still
// grows strictly (decision.hpp's joint argument allows such points too).
inline bool advances_along_chord(const std::array<p2, 4>& b, double slack) noexcept {
    const p2 d = b[3] - b[0];
    const double len = norm(d);
    if (!(len > 0)) return false;
    const p2 t = d / len;
    const bool first_zero = b[1] == b[0], last_zero = b[2] == b[3];
    if (first_zero && last_zero) return dot(b[2] - b[1], t) > slack;  // the chord itself
    return (first_zero || dot(b[1] - b[0], t) > slack) && dot(b[2] - b[1], t) > slack &&
           (last_zero || dot(b[3] - b[2], t) > slack);
}

// Two point sets, each with v, whose hulls meet only at v: their wedges at
// v are disjoint (with a margin against rounding).
inline bool hulls_apart_at(const std::array<p2, 4>& p, const std::array<p2, 4>& q, const p2& v, double slack) {
    double a0, a1, b0, b1;
    if (!wedge_of(p, v, slack, a0, a1) || !wedge_of(q, v, slack, b0, b1)) return false;
    constexpr double margin = 1e-9, two_pi = 2 * std::numbers::pi;
    double s = std::fmod(b0 - a0, two_pi);
    if (s < 0) s += two_pi;
    return s > (a1 - a0) + margin && s + (b1 - b0) < two_pi - margin;
}

// hulls_apart_at's cheaper sufficient test: a line through v with every
// point of p (other than v) strictly on one side and every point of q on
// the other. The line tried is the one across the direction from p's
// points to q's (their sums, seen from v): the usual case of two
// consecutive segments of a curve turning less than a right angle.
inline bool apart_by_line(const std::array<p2, 4>& p, const std::array<p2, 4>& q, const p2& v, double slack) {
    auto near_v = [&](const p2& d) { return std::abs(d[0]) <= slack && std::abs(d[1]) <= slack; };
    p2 dir{};
    for (const p2& x : q) dir = dir + (x - v);
    for (const p2& x : p) dir = dir - (x - v);
    const double margin = slack * (std::abs(dir[0]) + std::abs(dir[1]));
    for (const p2& x : p)
        if (!near_v(x - v) && !(dot(x - v, dir) < -margin)) return false;
    for (const p2& x : q)
        if (!near_v(x - v) && !(dot(x - v, dir) > margin)) return false;
    return true;
}

// Whether w is outside the convex hull of q by more than `slack`: some
// direction n has every point of q more than slack |n| before w, or every
// one more than that beyond it. Tried: from q's centroid towards w, and
// across each pair of q's points (the hull's edge directions are among
// them). Relative to w, so rounding stays within a few ulps of the
// coordinates, far below the slack; |n|_1 >= |n|_2 keeps the margin true.
inline bool outside_hull(const std::array<p2, 4>& q, const p2& w, double slack) noexcept {
    auto apart = [&](const p2& n) {
        const double len = std::abs(n[0]) + std::abs(n[1]);
        if (!(len > 0)) return false;
        double lo = INFINITY, hi = -INFINITY;
        for (const p2& x : q) {
            const double v = dot(x - w, n);
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        return hi < -slack * len || lo > slack * len;
    };
    if (apart((q[0] + q[1] + q[2] + q[3]) / 4.0 - w)) return true;
    for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b) {
            const p2 d = q[b] - q[a];
            if (apart(p2{{-d[1], d[0]}})) return true;
        }
    return false;
}

// The winding number around w of the closed polygon v[0], ..., v[n - 1]
// (and back to v[0]), every edge of which is farther than a few ulps of
// the coordinates from w: then each orientation sign below is exact (an
// edge crossing the ray y = y_w does so at least that far from w, and the
// cross product's rounding is below that distance times the edge's rise).
inline int winding_around(std::span<const p2> v, const p2& w) noexcept {
    int wn = 0;
    const std::size_t n = v.size();
    for (std::size_t k = 0; k < n; ++k) {
        const p2 a = v[k] - w, b = v[k + 1 == n ? 0 : k + 1] - w;
        if (a[1] <= 0) {
            if (b[1] > 0 && cross2(a, b) > 0) ++wn;
        } else if (b[1] <= 0 && cross2(a, b) < 0) {
            --wn;
        }
    }
    return wn;
}

// The end point two point sets share (their first or last), if any.
inline const p2* shared_end(const std::array<p2, 4>& p, const std::array<p2, 4>& q) noexcept {
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            if (p[3 * i] == q[3 * j]) return &p[3 * i];
    return nullptr;
}

inline bool boxes_meet(const box<2>& a, const box<2>& b, double pad) noexcept {
    return !(a.lo[0] > b.hi[0] + pad || b.lo[0] > a.hi[0] + pad || a.lo[1] > b.hi[1] + pad ||
             b.lo[1] > a.hi[1] + pad);
}

// Polyline piece k of the arc (from vertex k to k + 1), with its curve
// piece's Bézier points and flatness margin.
inline piece piece_of(const arc_work& a, std::uint32_t arc_index, std::size_t k, double slack) {
    piece pc;
    const std::size_t s = a.vseg[k];
    pc.arc = arc_index;
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
        const double u0 = a.vu[k], u1 = a.vseg[k + 1] == s ? a.vu[k + 1] : 1.0;
        const double w = u1 - u0;
        pc.q[1] = pa + (w / 3) * seg.du(u0, 1);
        pc.q[2] = pb - (w / 3) * seg.du(u1, 1);
        pc.e = flatness_bound(seg, u0, u1) + slack;
    }
    pc.bounds = box<2>::of(pa);
    pc.bounds.expand(pb);
    return pc;
}

// What the proof found for a pair of arcs (or an arc with itself).
struct proof_record {
    std::size_t pairs = 0;      // segment and piece pairs examined
    std::size_t crossings = 0;  // input segment pairs that cross properly (left as they are)
    std::size_t touches = 0;    // input segment pairs that touch or overlap
};

// A segment in a sweep: its box's low x.
struct seg_ref {
    double lo;
    std::uint32_t arc, seg;
};

// The state of one proof: arcs, options, rounding slack.
struct proof {
    std::vector<arc_work>& arcs;
    const smooth_options& opt;
    double slack;

    proof(std::vector<arc_work>& a, const smooth_options& o, double rounding) : arcs(a), opt(o), slack(rounding) {}

    // Rebuilds a dirty arc: curve, polyline, Bézier hulls; flags the
    // segments that fail a test of their own (loop or cusp, deviation,
    // domain) and records the arc's deviation bound.
    void prepare(std::uint32_t i) {
        arc_work& a = arcs[i];
        build_arc_curve(a, opt.alpha);
        a.has_line = false;
        a.pieces = 0;
        if (opt.polylines) ensure_line(i);
        const std::size_t segs = a.segments();
        a.hull.resize(segs);
        a.hull_box.resize(segs);
        a.max_dev = 0;
        for (std::size_t s = 0; s < segs; ++s) {
            auto& b = a.hull[s];
            b = segment_bezier(a, s);
            box<2> bx = box<2>::of(b[0]);
            for (int j = 1; j < 4; ++j) bx.expand(b[j]);
            a.hull_box[s] = bx;
            if (s == 0) a.bounds = bx;
            a.bounds.expand(bx);
            if (a.linear(s)) continue;
            // Loops and cusps inside the segment: exact, unless it plainly advances.
            if (opt.preserve_topology && !advances_along_chord(b, slack)) {
                const auto an = analyze_segment(a.curve->segment(s));
                if (an.has_self_intersection() || an.has_cusp()) a.raise[s] = 1;
            }
            const double dev = segment_deviation(b) + slack;
            a.max_dev = std::max(a.max_dev, dev);
            if (opt.max_deviation && dev > *opt.max_deviation) a.raise[s] = 1;
            if (opt.domain) {
                bool inside = true;
                for (const p2& q : b) inside = inside && opt.domain->contains(q);
                // The hull leaves the domain: the pieces' own hulls decide.
                if (!inside) ensure_line(i);
                for (std::size_t k = a.first_piece[s]; !inside && k < a.first_piece[s + 1]; ++k) {
                    const piece pc = piece_of(a, i, k, slack);
                    bool in = true;
                    for (const p2& q : pc.q) in = in && opt.domain->contains(q);
                    if (!in) {
                        a.raise[s] = 1;
                        break;
                    }
                }
            }
        }
    }

    // The arc's polyline (tessellated once per curve) and its pieces per segment.
    void ensure_line(std::uint32_t i) {
        arc_work& a = arcs[i];
        if (a.has_line) return;
        tessellate_arc(a, opt.tolerance);
        const std::size_t segs = a.segments();
        a.first_piece.assign(segs + 1, 0);
        for (std::size_t k = a.line.points.size() - 1; k-- > 0;) a.first_piece[a.vseg[k]] = k;
        a.first_piece[segs] = a.line.points.size() - 1;
        a.has_line = true;
        a.pieces = a.line.points.size() - 1;
    }

    void fail(const piece& pc) {
        if (!pc.linear) arcs[pc.arc].raise[pc.seg] = 1;
    }

    // Containment (issue 39). Every input vertex stays on its arc and no
    // new crossing is allowed, so a vertex w of another arc can change side
    // of this arc's ring (or line) only through the region a segment sweeps
    // between its input chord and its curve: the winding number around w
    // of the output ring minus that of the input ring is the sum, over the
    // segments, of the winding numbers around w of the loops "curve, then
    // the input chord back". So where every such loop's winding around
    // every vertex of every other arc is 0, every part keeps its side of
    // every ring: holes stay in their shells, islands stay out, lines stay
    // on their side. Proved here for segment s of arc i and a vertex w not
    // one of its ends: w outside the hull of the segment's Bézier points
    // (which holds the loop), else piece by piece: w farther from each
    // piece's chord than the piece's flatness margin, or outside the
    // piece's own hull (so the loop of pieces has the winding of the polygon
    // of their chords), farther than the slack from the input chord, and
    // the winding of that polygon 0. False: not proved (the caller raises
    // the segment's tension; at tension 1 nothing is swept).
    bool outside_swept(std::uint32_t i, std::size_t s, const p2& w) {
        arc_work& a = arcs[i];
        if (a.linear(s)) return true;
        const p2 p0 = a.pts[s], p3 = a.pts[a.next(s)];
        if (w == p0 || w == p3) return true;
        const box<2>& bx = a.hull_box[s];
        if (w[0] < bx.lo[0] - slack || w[0] > bx.hi[0] + slack || w[1] < bx.lo[1] - slack ||
            w[1] > bx.hi[1] + slack)
            return true;
        if (outside_hull(a.hull[s], w, slack)) return true;
        if (!(point_segment_distance(w, p0, p3) > slack)) return false;
        ensure_line(i);
        const std::size_t k0 = a.first_piece[s], k1 = a.first_piece[s + 1];
        for (std::size_t k = k0; k < k1; ++k) {
            const piece pc = piece_of(a, i, k, slack);
            if (point_segment_distance(w, pc.q[0], pc.q[3]) > pc.e + slack) continue;
            if (!outside_hull(pc.q, w, slack)) return false;
        }
        return winding_around(std::span<const p2>(a.line.points.data() + k0, k1 - k0 + 1), w) == 0;
    }

    // The ends of segment t of arc j against the region segment s of arc i
    // sweeps (and the other way round); a vertex inside raises the
    // segment's tension, as an unproved pair does.
    void prove_sides(std::uint32_t i, std::size_t s, std::uint32_t j, std::size_t t) {
        const auto& ha = arcs[i].hull[s];
        const auto& hb = arcs[j].hull[t];
        if (!arcs[i].linear(s) && !(outside_swept(i, s, hb[0]) && outside_swept(i, s, hb[3]))) {
            arcs[i].raise[s] = 1;
            ++swept;
        }
        if (!arcs[j].linear(t) && !(outside_swept(j, t, ha[0]) && outside_swept(j, t, ha[3]))) {
            arcs[j].raise[t] = 1;
            ++swept;
        }
    }

    // Segment s of arc i against segment t of arc j (not the same segment).
    void prove_segments(std::uint32_t i, std::size_t s, std::uint32_t j, std::size_t t, proof_record& rec) {
        arc_work& a = arcs[i];
        arc_work& b = arcs[j];
        ++rec.pairs;
        const auto& ha = a.hull[s];
        const auto& hb = b.hull[t];
        const bool la = a.linear(s), lb = b.linear(t);
        // Containment: each segment's ends against the other's swept region
        // (across arcs only: an arc's own vertices cannot change its side).
        if (i != j && !(la && lb)) prove_sides(i, s, j, t);
        const p2* v = shared_end(ha, hb);
        // Segment level: hulls meeting only at a shared end.
        if (v && (apart_by_line(ha, hb, *v, slack) || hulls_apart_at(ha, hb, *v, slack))) return;
        if (la && lb) {
            // Two input segments: apart, or the input itself meets here
            // (left as it is): a proper crossing or a touch.
            if (!v && segment_distance(ha[0], ha[3], hb[0], hb[3]) > 0) return;
            ++(segments_cross(ha[0], ha[3], hb[0], hb[3]) ? rec.crossings : rec.touches);
            return;
        }
        // Where the input segments themselves meet away from a shared end,
        // the proof can only end at the input: go straight there.
        if (!v && segments_meet(ha[0], ha[3], hb[0], hb[3])) {
            if (!la) jumps.push_back({i, s});
            if (!lb) jumps.push_back({j, t});
            return;
        }
        // Piece level: each piece within its flatness margin of its chord.
        ensure_line(i);
        ensure_line(j);
        for (std::size_t k = a.first_piece[s]; k < a.first_piece[s + 1]; ++k) {
            const piece p = piece_of(a, i, k, slack);
            for (std::size_t m = b.first_piece[t]; m < b.first_piece[t + 1]; ++m) {
                const piece q = piece_of(b, j, m, slack);
                if (!boxes_meet(p.bounds, q.bounds, p.e + q.e + slack)) continue;
                ++rec.pairs;
                const p2* w = shared_end(p.q, q.q);
                const bool proved = w ? hulls_apart_at(p.q, q.q, *w, slack)
                                      : segment_distance(p.q[0], p.q[3], q.q[0], q.q[3]) > p.e + q.e + slack;
                if (proved) continue;
                fail(p);
                fail(q);
            }
        }
    }

    // Every pair of segments of arc i (j == i) or of arcs i and j whose
    // padded boxes meet: a sweep along x.
    proof_record prove_arcs(std::uint32_t i, std::uint32_t j) {
        proof_record rec;
        std::vector<seg_ref>& refs = scratch;
        refs.clear();
        const double pad = slack;
        auto add = [&](std::uint32_t x, const box<2>* other) {
            const arc_work& a = arcs[x];
            for (std::size_t s = 0; s < a.segments(); ++s)
                if (!other || boxes_meet(a.hull_box[s], *other, pad))
                    refs.push_back({a.hull_box[s].lo[0], x, std::uint32_t(s)});
        };
        if (i == j) {
            add(i, nullptr);
        } else {
            add(i, &arcs[j].bounds);
            add(j, &arcs[i].bounds);
        }
        std::sort(refs.begin(), refs.end(), [](const seg_ref& x, const seg_ref& y) { return x.lo < y.lo; });
        for (std::size_t p = 0; p < refs.size(); ++p) {
            const auto& rp = refs[p];
            const box<2>& bp = arcs[rp.arc].hull_box[rp.seg];
            for (std::size_t q = p + 1; q < refs.size(); ++q) {
                const auto& rq = refs[q];
                if (rq.lo > bp.hi[0] + pad) break;
                if (rq.arc == rp.arc && i != j) continue;  // two arcs: only pairs across them
                const box<2>& bq = arcs[rq.arc].hull_box[rq.seg];
                if (!boxes_meet(bp, bq, pad)) continue;
                prove_segments(rp.arc, rp.seg, rq.arc, rq.seg, rec);
            }
        }
        return rec;
    }

    // Without topology no pair is proved: each arc's rounds (deviation,
    // domain) are its own, run to the end one arc at a time, its length
    // taken and its curve and hulls released (memory stays that of the
    // output). The same levels, round by round, as the rounds of run().
    void run_alone() {
        crossing.assign(arcs.size(), 0);
        for (std::uint32_t i = 0; i < arcs.size(); ++i) {
            if (opt.progress && i % 4096 == 0) opt.progress(0.8 * double(i) / double(arcs.size()));
            alone(i);
        }
    }

    // One arc's rounds without topology (run_alone()), then its length;
    // its curve and hulls released unless smooth_options::keep_curves.
    void alone(std::uint32_t i) {
        constexpr std::size_t max_rounds = 64;
        {
            arc_work& a = arcs[i];
            for (std::size_t round = 1;; ++round) {
                rounds = std::max(rounds, round);
                std::fill(a.raise.begin(), a.raise.end(), 0);
                prepare(i);
                bool failed = false;
                for (std::size_t s = 0; s < a.segments(); ++s) {
                    if (!a.raise[s]) continue;
                    failed = true;
                    for (std::size_t v : {s, a.next(s)}) {
                        const std::uint8_t to = round >= max_rounds / 2 ? linear_level : std::uint8_t(a.level[v] + 1);
                        a.level[v] = std::min(linear_level, std::max(a.level[v], to));
                    }
                }
                a.dirty = false;
                if (!failed || round >= max_rounds) break;
            }
            a.length = arc_curve_length(a);
            a.measured = true;
            if (opt.keep_curves) return;  // smooth() hands it over
            a.curve.reset();
            a.base.reset();
            std::vector<std::array<p2, 4>>().swap(a.hull);
            std::vector<crspline::box<2>>().swap(a.hull_box);
        }
    }

    // The pairs of arcs (i < j, as (i << 32) | j, sorted) whose boxes come
    // within the slack: each arc in the cells of a uniform grid its padded
    // box covers (cells the size of the mean box), a pair reported by the
    // cell holding the low corner of the two boxes' overlap; arcs covering
    // more than 16 cells each way are tested against every arc instead.
    // (A sweep along x alone looked at every pair in a column of a grid
    // layout: n sqrt(n).)
    std::vector<std::uint64_t> arc_pairs() const {
        const std::size_t n = arcs.size();
        std::vector<std::uint64_t> out;
        if (n < 2) return out;
        double w = 0, h = 0, x0 = INFINITY, y0 = INFINITY;
        for (const auto& a : arcs) {
            w += a.bounds.hi[0] - a.bounds.lo[0];
            h += a.bounds.hi[1] - a.bounds.lo[1];
            x0 = std::min(x0, a.bounds.lo[0]);
            y0 = std::min(y0, a.bounds.lo[1]);
        }
        const double cell = std::max({w / double(n), h / double(n), 64 * slack, 1e-300});
        auto index = [&](double v, double origin) { return std::int64_t(std::floor((v - origin) / cell)); };
        constexpr std::int64_t big = 16;
        std::vector<std::pair<std::uint64_t, std::uint32_t>> cells;  // (cell key, arc)
        std::vector<std::uint32_t> large;
        for (std::uint32_t i = 0; i < n; ++i) {
            const auto& b = arcs[i].bounds;
            const std::int64_t cx0 = index(b.lo[0] - slack, x0), cx1 = index(b.hi[0] + slack, x0);
            const std::int64_t cy0 = index(b.lo[1] - slack, y0), cy1 = index(b.hi[1] + slack, y0);
            if (cx1 - cx0 >= big || cy1 - cy0 >= big) {
                large.push_back(i);
                continue;
            }
            for (std::int64_t cx = cx0; cx <= cx1; ++cx)
                for (std::int64_t cy = cy0; cy <= cy1; ++cy)
                    cells.push_back({(std::uint64_t(cx + (1 << 30)) << 32) | std::uint64_t(cy + (1 << 30)), i});
        }
        std::sort(cells.begin(), cells.end());
        for (std::size_t g = 0; g < cells.size();) {
            std::size_t e = g;
            while (e < cells.size() && cells[e].first == cells[g].first) ++e;
            for (std::size_t p = g; p < e; ++p)
                for (std::size_t q = p + 1; q < e; ++q) {
                    const std::uint32_t i = std::min(cells[p].second, cells[q].second),
                                        j = std::max(cells[p].second, cells[q].second);
                    const auto &bi = arcs[i].bounds, &bj = arcs[j].bounds;
                    if (!boxes_meet(bi, bj, slack)) continue;
                    // Once: in the cell of the overlap's low corner.
                    const std::int64_t cx = index(std::max(bi.lo[0], bj.lo[0]) - slack, x0);
                    const std::int64_t cy = index(std::max(bi.lo[1], bj.lo[1]) - slack, y0);
                    if (((std::uint64_t(cx + (1 << 30)) << 32) | std::uint64_t(cy + (1 << 30))) != cells[g].first) continue;
                    out.push_back((std::uint64_t(i) << 32) | j);
                }
            g = e;
        }
        std::vector<std::uint8_t> is_large(n, 0);
        for (std::uint32_t i : large) is_large[i] = 1;
        for (std::uint32_t i : large)
            for (std::uint32_t j = 0; j < n; ++j)
                if (j != i && !(is_large[j] && j < i) && boxes_meet(arcs[i].bounds, arcs[j].bounds, slack))
                    out.push_back((std::uint64_t(std::min(i, j)) << 32) | std::max(i, j));
        std::sort(out.begin(), out.end());
        return out;
    }

    // The bounds of the arc's first curve, the union of its segments' hull
    // boxes as prepare() finds them: arc_pairs() needs every arc's before
    // any arc is proved. Neither the curve nor the hulls are kept: prepare()
    // builds the same curve again when the arc's component comes, while it
    // is in cache (holding every arc's curve until then was most of the
    // memory at 10^6 arcs, all of it fresh pages, read back from DRAM).
    void first_bounds(std::uint32_t i) {
        arc_work& a = arcs[i];
        build_arc_curve(a, opt.alpha);
        for (std::size_t s = 0; s < a.segments(); ++s) {
            const auto b = segment_bezier(a, s);
            box<2> bx = box<2>::of(b[0]);
            for (int j = 1; j < 4; ++j) bx.expand(b[j]);
            if (s == 0) a.bounds = bx;
            a.bounds.expand(bx);
        }
        a.curve.reset();
        a.base.reset();
    }

    // An arc whose component is proved: its length taken; its curve (unless
    // smooth_result::curves wants it), its hulls and, without output
    // polylines, its polyline released.
    void finish(std::uint32_t i) {
        arc_work& a = arcs[i];
        a.length = arc_curve_length(a);
        a.measured = true;
        std::vector<std::array<p2, 4>>().swap(a.hull);
        std::vector<crspline::box<2>>().swap(a.hull_box);
        std::vector<std::size_t>().swap(a.first_piece);
        if (!opt.keep_curves) {
            a.curve.reset();
            a.base.reset();
        }
        if (!opt.polylines) {
            a.line = {};
            std::vector<std::uint32_t>().swap(a.vseg);
            std::vector<double>().swap(a.vu);
            a.has_line = false;  // a.pieces keeps the count
        } else if (!keep_parameters) {
            // The output needs each vertex's segment and u only to
            // interpolate extra values.
            std::vector<std::uint32_t>().swap(a.vseg);
            std::vector<double>().swap(a.vu);
        }
    }

    // Rounds, component by component. Arcs are joined (directly or through
    // others) by their candidate pairs, those whose first boxes meet; only
    // arcs of one component can raise each other's tension, so each
    // component runs its rounds to the end alone and then releases its
    // curves and hulls (finish). The levels, round by round, are those of
    // rounds over the whole layer (the same candidates; a component with
    // nothing left to prove does nothing in later rounds), and so is every
    // number out; what changes is memory: one component's curves and hulls
    // at a time beside the polylines, not every arc's at once (10^6 walks
    // smoothed in 9.5 GB instead of about 16; BENCHMARKS.md).
    void run() {
        const std::size_t n = arcs.size();
        self.assign(n, {});
        crossing.assign(n, 0);
        if (!opt.preserve_topology) {
            run_alone();
            return;
        }
        rounds = 1;  // an empty layer too: one round with nothing to prove
        for (std::uint32_t i = 0; i < n; ++i) first_bounds(i);
        std::vector<std::uint64_t> candidates = arc_pairs();
        // Components: union-find over the candidate pairs; a root is the
        // smallest arc of its component.
        std::vector<std::uint32_t> parent(n);
        for (std::uint32_t i = 0; i < n; ++i) parent[i] = i;
        auto find = [&](std::uint32_t x) {
            while (parent[x] != x) x = parent[x] = parent[parent[x]];
            return x;
        };
        for (const std::uint64_t key : candidates) {
            const std::uint32_t x = find(std::uint32_t(key >> 32)), y = find(std::uint32_t(key & 0xffffffffu));
            if (x != y) parent[std::max(x, y)] = std::min(x, y);
        }
        // Each component's arcs and candidates (in key order), listed by root.
        std::vector<std::size_t> arc_start(n + 1, 0), key_start(n + 1, 0);
        for (std::uint32_t i = 0; i < n; ++i) ++arc_start[(parent[i] = find(i)) + 1];
        for (const std::uint64_t key : candidates) ++key_start[parent[std::uint32_t(key >> 32)] + 1];
        for (std::size_t r = 0; r < n; ++r) {
            arc_start[r + 1] += arc_start[r];
            key_start[r + 1] += key_start[r];
        }
        std::vector<std::uint32_t> members(n);
        std::vector<std::uint64_t> keys(candidates.size());
        {
            std::vector<std::size_t> at(arc_start.begin(), arc_start.end() - 1);
            for (std::uint32_t i = 0; i < n; ++i) members[at[parent[i]]++] = i;
            at.assign(key_start.begin(), key_start.end() - 1);
            for (const std::uint64_t key : candidates) keys[at[parent[std::uint32_t(key >> 32)]]++] = key;
        }
        std::vector<std::uint64_t>().swap(candidates);
        dirty.assign(n, 0);
        for (std::size_t r = 0; r < n; ++r) {
            const std::size_t first = arc_start[r], size = arc_start[r + 1] - first;
            if (size == 0) continue;
            // The proof is 80% of the work; a report where the count of
            // arcs done passes a multiple of 4096 (as in run_alone()).
            if (opt.progress && (first + 4095) / 4096 != (first + size + 4095) / 4096)
                opt.progress(0.8 * double(first) / double(n));
            const std::span<const std::uint32_t> m(members.data() + first, size);
            run_component(m, std::span<const std::uint64_t>(keys.data() + key_start[r], key_start[r + 1] - key_start[r]));
            for (const std::uint32_t i : m) finish(i);
        }
    }

    // One component's rounds: rebuild its dirty arcs, prove the pairs that
    // involve one, raise tension where a proof failed; until every pair is
    // proved. Pairs of clean arcs keep the record of the round that proved
    // them.
    void run_component(std::span<const std::uint32_t> members, std::span<const std::uint64_t> candidates) {
        constexpr std::size_t max_rounds = 64;
        previous.clear();
        across.clear();
        for (std::size_t round = 1;; ++round) {
            rounds = std::max(rounds, round);
            for (const std::uint32_t i : members) {
                auto& a = arcs[i];
                dirty[i] = a.dirty;
                std::fill(a.raise.begin(), a.raise.end(), 0);
                if (a.dirty) prepare(i);
            }
            for (const std::uint32_t i : members)
                if (dirty[i]) self[i] = prove_arcs(i, i);
            // The candidates come in key order, and so does `across`.
            previous.swap(across);
            across.clear();
            for (const std::uint64_t key : candidates) {
                const auto i = std::uint32_t(key >> 32), j = std::uint32_t(key & 0xffffffffu);
                if (dirty[i] || dirty[j]) {
                    across.push_back({key, prove_arcs(i, j)});
                } else {
                    // Unchanged since the round that proved them.
                    auto it = std::lower_bound(previous.begin(), previous.end(), key,
                                               [](const auto& e, std::uint64_t k) { return e.first < k; });
                    across.push_back({key, it != previous.end() && it->first == key ? it->second : prove_arcs(i, j)});
                }
            }
            // Raise tension where needed.
            bool failed = false;
            for (const auto& [x, s] : jumps) {
                arc_work& a = arcs[x];
                a.raise[s] = 1;
                a.level[s] = a.level[a.next(s)] = linear_level;
            }
            jumps.clear();
            for (const std::uint32_t i : members) {
                auto& a = arcs[i];
                a.dirty = false;
                for (std::size_t s = 0; s < a.segments(); ++s) {
                    if (!a.raise[s]) continue;
                    failed = true;
                    a.dirty = true;
                    for (std::size_t v : {s, a.next(s)}) {
                        // After many rounds, straight to the last resort.
                        const std::uint8_t to = round >= max_rounds / 2 ? linear_level : std::uint8_t(a.level[v] + 1);
                        a.level[v] = std::min(linear_level, std::max(a.level[v], to));
                    }
                }
            }
            if (!failed || round >= max_rounds) break;  // the cap cannot be reached: levels only grow
        }
        // What the final proof found.
        auto note = [&](std::uint32_t i, const proof_record& r) {
            if (r.crossings) crossing[i] = 2;
            else if (r.touches) crossing[i] = std::max<std::uint8_t>(crossing[i], 1);
        };
        auto count = [&](const proof_record& r) {
            pairs += r.pairs;
            crossings += r.crossings;
            touches += r.touches;
        };
        for (const std::uint32_t i : members) {
            count(self[i]);
            note(i, self[i]);
        }
        for (const auto& [key, r] : across) {
            count(r);
            note(std::uint32_t(key >> 32), r);
            note(std::uint32_t(key & 0xffffffffu), r);
        }
    }

    bool keep_parameters = true;  // false: finish() releases vseg and vu of the polylines it keeps
    std::vector<seg_ref> scratch;
    std::vector<std::pair<std::uint32_t, std::size_t>> jumps;   // (arc, segment) to take to the input
    std::vector<proof_record> self;                              // per arc, with itself
    std::vector<std::pair<std::uint64_t, proof_record>> across;  // per pair of arcs whose boxes meet, by key
    std::vector<std::pair<std::uint64_t, proof_record>> previous;  // the round before's
    std::vector<std::uint8_t> dirty;                             // per arc: rebuilt this round
    std::vector<std::uint8_t> crossing;                          // per arc: 2 an input crossing, 1 a touch
    std::size_t rounds = 0, pairs = 0, crossings = 0, touches = 0;
    std::size_t swept = 0;  // (segment, vertex) pairs found in a swept region, every round
};

}  // namespace detail

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
    if (!opt.preserve_topology && !opt.polylines) {
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
            for (const auto& [ai, reversed] : topo.part_arcs(clean_of[p])) {
                rep.length += arc_length_of[ai];
                rep.max_deviation = std::max(rep.max_deviation, arcs[ai].max_dev);
            }
        }
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
        for (const auto& [ai, reversed] : topo.part_arcs(clean_of[p])) {
            const auto& a = arcs[ai];
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
                    for (std::size_t c = 0; c < E; ++c) {
                        const double e0 = in.extra[src[s] * E + c], e1 = in.extra[src[a.next(s)] * E + c];
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
