// crspline::geo internals: an arc being smoothed (arc_work) and what is made
// of it: its curve at its tension levels (or fitted: fit_arc), its polyline
// with each vertex's segment and u, its segments' Bézier points; and the
// plane helpers the proof uses (distances, orientation tests, wedges).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <numbers>
#include <span>
#include <utility>
#include <vector>

#include "../catmull_rom.hpp"
#include "../fit.hpp"
#include "../tessellate.hpp"
#include "../vec.hpp"
#include "report.hpp"

namespace crspline::geo {

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
    // Fitted arcs (smooth_options::fit): every input vertex of the arc, and
    // the index among them of each control point in pts (empty: not fitted).
    std::vector<p2> full;
    std::vector<std::uint32_t> src;

    std::size_t segments() const noexcept { return closed ? pts.size() : pts.size() - 1; }
    std::size_t next(std::size_t i) const noexcept { return i + 1 == pts.size() ? 0 : i + 1; }
    bool fitted() const noexcept { return !src.empty(); }
    /// The input vertices segment s covers, first to last: indices into
    /// full, increasing along the arc (a ring's past full.size() where it
    /// comes round to its first control point: full_at() wraps them).
    std::pair<std::size_t, std::size_t> span(std::size_t s) const noexcept {
        return {src[s], next(s) == 0 ? src[0] + full.size() : src[next(s)]};
    }
    /// Segment s leaves input vertices out (a fitted arc's).
    bool dropped(std::size_t s) const noexcept {
        if (src.empty()) return false;
        const auto [b, e] = span(s);
        return e != b + 1;
    }
    const p2& full_at(std::size_t k) const noexcept { return full[k % full.size()]; }
    bool linear(std::size_t s) const noexcept {
        return level[s] == linear_level && level[next(s)] == linear_level && !dropped(s);
    }
};

// The arc's curve at its tension levels. Levels only grow: an arc without
// tension is built once, as `curve`; the first tension moves it to `base`
// (one copy of the untensioned curve, never two).
inline void build_arc_curve(arc_work& a, double alpha) {
    using curve_t = catmull_rom<2>;
    if (a.fitted()) {
        // The fit's own curve (fit.hpp): Kochanek-Bartels tension per
        // vertex at the levels, natural ends; the levels only grow.
        options<2> opt;
        opt.alpha = alpha;
        opt.closed = a.closed;
        bool any = false;
        for (auto l : a.level) any = any || l > 0;
        if (any) {
            opt.kb.tension.resize(a.pts.size());
            for (std::size_t k = 0; k < a.pts.size(); ++k) opt.kb.tension[k] = tension_levels[a.level[k]];
        }
        a.curve = std::make_unique<curve_t>(std::span<const p2>(a.pts), opt);
        return;
    }
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

// Fits the arc (smooth_options::fit): its control points become a subset of
// its vertices chosen by fit() (subset mode, natural ends; an open arc's
// ends, the junctions, kept), at fit()'s tension levels. A two-point open
// arc stays its segment.
inline void fit_arc(arc_work& a, double alpha, double tolerance) {
    a.full = a.pts;
    const std::size_t n = a.pts.size();
    a.src.resize(n);
    for (std::size_t k = 0; k < n; ++k) a.src[k] = std::uint32_t(k);
    if (n <= 2 && !a.closed) return;
    fit_options<2> fo;
    fo.tolerance = tolerance;
    fo.alpha = alpha;
    fo.closed = a.closed;
    const auto r = crspline::fit(std::span<const p2>(a.full), fo);
    const auto& kb = r.curve.options().kb.tension;
    const std::size_t m = r.indices.size();
    // A ring's control points as indices increasing from its first one.
    a.pts.resize(m);
    a.src.resize(m);
    a.level.assign(m, 0);
    for (std::size_t k = 0; k < m; ++k) {
        std::size_t idx = r.indices[k];
        if (k > 0 && idx <= a.src[k - 1]) idx += n;
        a.src[k] = std::uint32_t(idx);
        a.pts[k] = a.full_at(idx);
        if (!kb.empty())
            for (std::uint8_t l = 0; l <= linear_level; ++l)
                if (kb[k] == tension_levels[l]) a.level[k] = l;
    }
    if (m == 2 && !a.closed) a.level.assign(2, linear_level);
    a.raise.assign(a.segments(), 0);
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

}  // namespace detail

}  // namespace crspline::geo
