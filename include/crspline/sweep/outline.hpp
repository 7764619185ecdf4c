// crspline strokes, internals: the raw outline of a polyline stroked at
// half width d, as closed rings whose nonzero-winding region is the stroke.
//
// The stroke is the union of one rectangle per edge, a wedge at each
// vertex on the outer side of the turn (the join) and the caps. Walked as
// the left offsets forwards, the end cap, the right offsets backwards and
// the start cap, with each inner side of a turn passing through the vertex
// itself (offset, vertex, next offset), the rings are the sum of those
// pieces' boundaries, each piece oriented the same way: the winding number
// of a point is minus the number of pieces covering it, so the nonzero
// region is their union, overlaps, the offset's cusps and loops included.
// nonzero.hpp resolves it into simple rings.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "nonzero.hpp"

namespace crspline {

enum class stroke_join { round, miter, bevel };
enum class stroke_cap { butt, round, square };

}  // namespace crspline

namespace crspline::detail {

struct outline_style {
    double d = 1;              ///< half width
    stroke_join join = stroke_join::round;
    double miter_limit = 4;    ///< miter length / width, as SVG's stroke-miterlimit
    stroke_cap cap = stroke_cap::butt;
    double tol = 1e-3;         ///< the joins' and caps' share of the tolerance
};

/// Arc around c from angle a0 turning by `sweep` (either sign), inscribed
/// within tol of the circle of radius d; end points excluded.
inline void arc_points(const p2& c, double d, double a0, double sweep, double tol, std::vector<p2>& out) {
    const double step = tol < d ? 2 * std::acos(1 - tol / d) : std::numbers::pi / 2;
    const auto n = std::size_t(std::ceil(std::abs(sweep) / step));
    for (std::size_t k = 1; k < n; ++k) {
        const double a = a0 + sweep * double(k) / double(n);
        out.push_back(c + d * p2{{std::cos(a), std::sin(a)}});
    }
}

/// Points of the join at vertex p between unit directions e0 and e1, on
/// side `side` (+1 left, -1 right), in the order walked forwards. `corner`:
/// the curve has a corner here (the style's join); otherwise a smooth turn
/// of the tessellation (round, within tol: one mitre point when that is
/// within tol of the arc).
inline void join_points(const p2& p, const p2& e0, const p2& e1, double side, bool corner, const outline_style& st,
                        std::vector<p2>& out) {
    const p2 n0 = side * p2{{-e0[1], e0[0]}}, n1 = side * p2{{-e1[1], e1[0]}};
    const double cr = e0[0] * e1[1] - e0[1] * e1[0], cs = std::clamp(e0[0] * e1[0] + e0[1] * e1[1], -1.0, 1.0);
    const double theta = std::atan2(std::abs(cr), cs);  // turn angle in [0, pi]
    const double d = st.d;
    const p2 a = p + d * n0, b = p + d * n1;
    if (!(theta > 1e-12)) {  // straight on: one point
        out.push_back((a + b) / 2.0);
        return;
    }
    const bool inner = side * cr > 0;  // turning towards this side
    if (inner) {
        out.push_back(a);
        out.push_back(p);
        out.push_back(b);
        return;
    }
    const double half = theta / 2;
    const p2 mid = n0 + n1;
    const double ml = norm(mid);
    const auto miter = [&] { return p + (d / std::cos(half)) * (mid / ml); };
    const stroke_join style = corner ? st.join : stroke_join::round;
    if (style == stroke_join::round && ml > 0 && d * (1 / std::cos(half) - 1) <= st.tol) {
        out.push_back(miter());
        return;
    }
    out.push_back(a);
    if (style == stroke_join::round) {
        // From n0 to n1 the short way (the outer side).
        arc_points(p, d, std::atan2(n0[1], n0[0]), side > 0 ? -theta : theta, st.tol, out);
    } else if (style == stroke_join::miter && ml > 0 && 1 / std::cos(half) <= st.miter_limit) {
        out.push_back(miter());
    }
    out.push_back(b);
}

/// The cap at end point p with outward unit direction e, walked from the
/// left offset p + d n to the right one p - d n (n the left normal of the
/// direction of travel into p).
inline void cap_points(const p2& p, const p2& e, const outline_style& st, std::vector<p2>& out) {
    const p2 left{{-e[1], e[0]}};  // left normal of e (the travel direction at the end)
    const double d = st.d;
    out.push_back(p + d * left);
    if (st.cap == stroke_cap::square) {
        out.push_back(p + d * left + d * e);
        out.push_back(p - d * left + d * e);
    } else if (st.cap == stroke_cap::round) {
        arc_points(p, d, std::atan2(left[1], left[0]), -std::numbers::pi, st.tol, out);
    }
    out.push_back(p - d * left);
}

/// The rings of the stroke of a polyline (no two consecutive points equal;
/// a closed one without its repeated first point). corner[i]: the curve has
/// a corner at vertex i.
inline std::vector<std::vector<p2>> stroke_rings(const std::vector<p2>& pts, const std::vector<bool>& corner,
                                                 bool closed, const outline_style& st) {
    const std::size_t n = pts.size();
    std::vector<std::vector<p2>> rings;
    if (n == 0) return rings;
    if (n == 1) {
        // A point: a disc (round cap), a square (square cap), nothing (butt).
        if (closed || st.cap == stroke_cap::butt) return rings;
        std::vector<p2> r;
        const p2 e{{1, 0}};
        cap_points(pts[0], e, st, r);
        cap_points(pts[0], -e, st, r);
        rings.push_back(r);
        return rings;
    }
    const std::size_t ne = closed ? n : n - 1;
    std::vector<p2> dir(ne);
    for (std::size_t i = 0; i < ne; ++i) {
        const p2 v = pts[(i + 1) % n] - pts[i];
        dir[i] = v / norm(v);
    }
    if (closed) {
        std::vector<p2> left, right;
        for (std::size_t i = 0; i < n; ++i) join_points(pts[i], dir[(i + ne - 1) % ne], dir[i], 1, corner[i], st, left);
        for (std::size_t i = n; i-- > 0;) {
            std::vector<p2> j;
            join_points(pts[i], dir[(i + ne - 1) % ne], dir[i], -1, corner[i], st, j);
            right.insert(right.end(), j.rbegin(), j.rend());
        }
        rings.push_back(std::move(left));
        rings.push_back(std::move(right));
        return rings;
    }
    std::vector<p2> r;
    const double d = st.d;
    r.push_back(pts[0] + d * p2{{-dir[0][1], dir[0][0]}});
    for (std::size_t i = 1; i + 1 < n; ++i) join_points(pts[i], dir[i - 1], dir[i], 1, corner[i], st, r);
    cap_points(pts[n - 1], dir[ne - 1], st, r);
    for (std::size_t i = n - 1; i-- > 1;) {
        std::vector<p2> j;
        join_points(pts[i], dir[i - 1], dir[i], -1, corner[i], st, j);
        r.insert(r.end(), j.rbegin(), j.rend());
    }
    cap_points(pts[0], -dir[0], st, r);
    r.erase(r.begin());  // the start cap ends where the ring began
    rings.push_back(std::move(r));
    return rings;
}

}  // namespace crspline::detail
