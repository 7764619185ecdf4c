// crspline: bounding volumes of a Catmull-Rom curve (the paper's Figure 5)
// and the certificate of Section 5 that a curve does not intersect itself.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "analysis.hpp"
#include "catmull_rom.hpp"
#include "detail/analysis_common.hpp"
#include "detail/box_tree.hpp"
#include "intersections.hpp"
#include "vec.hpp"

namespace crspline {

// ---------------------------------------------------------------------------
// Bounding volumes (Figure 5)
// ---------------------------------------------------------------------------

/// The polygon edge [a, b] extruded perpendicular to itself: the points x
/// with lambda = (x - a).(b - a) / |b - a|^2 in [lambda_min, lambda_max] and
/// distance to the line ab at most half_width. A rectangle in 2-D, a solid
/// cylinder in 3-D and above.
template <std::size_t D, class T = double>
struct edge_box {
    std::size_t segment = 0;
    vec<D, T> a{}, b{};
    T lambda_min = 0, lambda_max = 1;
    T half_width = 0;
    bool contains(const vec<D, T>& x, T slack = T(0)) const noexcept {
        const vec<D, T> e = b - a;
        const T L2 = dot(e, e);
        if (!(L2 > 0)) return norm(x - a) <= half_width + slack;
        const T L = std::sqrt(L2);
        const T lam = dot(x - a, e) / L2;
        if (lam < lambda_min - slack / L || lam > lambda_max + slack / L) return false;
        return norm(detail::perpendicular_part(x - a, e / L)) <= half_width + slack;
    }
};

/// A ball around a polygon vertex (needed when the curve can overshoot the
/// vertex along the edge: alpha != 1/2, Eq. 8).
template <std::size_t D, class T = double>
struct vertex_ball {
    std::size_t vertex = 0;
    vec<D, T> center{};
    T radius = 0;
};

enum class volume_kind {
    local,      ///< from each edge's own length (Figure 5, top row)
    tightened,  ///< with the neighbours' lengths, Eq. 6 and Eq. 8 (bottom row)
};

template <std::size_t D, class T = double>
struct bounding_volumes {
    std::vector<edge_box<D, T>> boxes;   ///< one per segment
    std::vector<vertex_ball<D, T>> balls;  ///< one per vertex with a nonzero radius
    /// Is x inside the union of the volumes of segment `segment` (its box and
    /// the balls at its two vertices)?
    bool segment_contains(std::size_t segment, const vec<D, T>& x, T slack = T(0)) const noexcept {
        const auto& box = boxes[segment];
        if (box.contains(x, slack)) return true;
        for (const auto& b : balls)
            if ((b.center == box.a || b.center == box.b) && norm(x - b.center) <= b.radius + slack) return true;
        return false;
    }
};

namespace detail {

// Box from the segment's actual Bézier points: lambda range of the hull,
// half width 3/4 of the larger Bézier height (valid for any cubic).
template <std::size_t D, class T>
edge_box<D, T> bezier_box(std::size_t i, const segment_analysis<D, T>& an) {
    edge_box<D, T> e;
    e.segment = i;
    e.a = an.bezier[0];
    e.b = an.bezier[3];
    e.half_width = an.bezier_bound;
    if (an.projection) {
        e.lambda_min = std::min({T(0), an.projection->bezier[0], an.projection->bezier[1]});
        e.lambda_max = std::max({T(1), an.projection->bezier[0], an.projection->bezier[1]});
    }
    return e;
}

}  // namespace detail

/// The paper's bounding volumes of a curve, for the knots it was built with
/// (catmull_rom::options()). Interior segments: the edge extruded by the
/// Eq. 6 bound (two-sided) and balls of the Eq. 8 radius at the vertices;
/// `local` uses the suprema over the neighbours' lengths (local_eq6_factor,
/// local_eq8_factor: infinite for alpha < 1/2, where the paper has no
/// bound). For knots from alpha the printed formulas in alpha are used; for
/// an explicit grid the same bounds in general knots (paper_bounds::eq6,
/// eq8_start, eq8_end), and `local` has no factor (boxes from the Bézier
/// points). End segments of an open curve (no neighbour on one side, end
/// conditions instead of Eq. 2) and segments that are not plain
/// Catmull-Rom (tension, Kochanek-Bartels) get the box of their actual
/// Bézier points instead (lambda range of the hull, half width 3/4 of the
/// larger Bézier height), which holds for any cubic.
template <std::size_t D, class T>
bounding_volumes<D, T> paper_bounding_volumes(const catmull_rom<D, T>& c,
                                              volume_kind kind = volume_kind::tightened) {
    const std::optional<double> alpha = c.options().alpha;
    bounding_volumes<D, T> v;
    const auto an = analyze(c);
    const std::size_t n = c.segment_count(), np = c.points().size();
    std::vector<T> radius(np, T(0));
    for (std::size_t i = 0; i < n; ++i) {
        if (!an[i].bounds || (!alpha && kind == volume_kind::local)) {
            v.boxes.push_back(detail::bezier_box(i, an[i]));
            continue;
        }
        const auto& b = *an[i].bounds;
        edge_box<D, T> e;
        e.segment = i;
        e.a = an[i].bezier[0];
        e.b = an[i].bezier[3];
        T r1, r2;
        if (!alpha) {
            // Explicit grid: the same bounds written in general knots.
            e.half_width = b.eq6;
            r1 = b.eq8_start;
            r2 = b.eq8_end;
        } else if (kind == volume_kind::local) {
            e.half_width = b.d2 * T(local_eq6_factor(*alpha));
            r1 = r2 = b.d2 * T(local_eq8_factor(*alpha));
        } else {
            // The printed formulas in r = d1/d2, d3/d2 and alpha (Eq. 8 is
            // then identically 0 at alpha = 1/2, not the sqrt of the knots'
            // rounding).
            e.half_width = paper_eq6_two_sided(b.d1, b.d2, b.d3, *alpha);
            r1 = paper_eq8(b.d2, b.d1 / b.d2, *alpha);
            r2 = paper_eq8(b.d2, b.d3 / b.d2, *alpha);
        }
        v.boxes.push_back(e);
        radius[i] = std::max(radius[i], r1);
        radius[(i + 1) % np] = std::max(radius[(i + 1) % np], r2);
    }
    for (std::size_t k = 0; k < np; ++k)
        if (radius[k] > 0) v.balls.push_back({k, c.points()[k], radius[k]});
    return v;
}

// ---------------------------------------------------------------------------
// Certificate (Section 5)
// ---------------------------------------------------------------------------

/// The smallest polygon angle the certificate accepts at a vertex between
/// two segments. The paper's summary says pi/6, but its Section 5 derives
/// pi/3 (each side's curve may enter the "V" by gamma < pi/6); adjacent
/// interior centripetal segments have been seen to cross at polygon angles
/// of at least 28.9 degrees (one confirmed exactly at 28.72), none between
/// 30 and 60 (tests/reference/SOURCES.md). pi/3 is the safe value. The rule
/// covers only two interior segments of a plain centripetal curve; every
/// other adjacent pair is proved apart by an exact check (adjacent_pair).
inline constexpr double safe_adjacent_angle = std::numbers::pi / 3;

enum class certify_rule {
    none,               ///< certified
    not_centripetal,    ///< rule 1: the curve is not the plain centripetal curve of its points
    coincident_points,  ///< a zero-length polygon edge: the angle rule has no angle
    adjacent_angle,     ///< rule 2: a polygon angle <= safe_adjacent_angle
    overlapping_boxes,  ///< rule 3: boxes of two non-adjacent segments overlap
    adjacent_pair,      ///< two adjacent segments the angle rule does not cover (an end segment,
                        ///< tension, Kochanek-Bartels) that the exact check could not prove apart
};

inline const char* to_string(certify_rule r) noexcept {
    switch (r) {
        case certify_rule::none: return "none";
        case certify_rule::not_centripetal: return "not_centripetal";
        case certify_rule::coincident_points: return "coincident_points";
        case certify_rule::adjacent_angle: return "adjacent_angle";
        case certify_rule::overlapping_boxes: return "overlapping_boxes";
        case certify_rule::adjacent_pair: return "adjacent_pair";
    }
    return "unknown";
}

struct certify_options {
    double safe_angle = safe_adjacent_angle;  ///< rule 2 threshold (radians)
    bool search_on_failure = true;            ///< run find_intersections when not certified
    double tolerance = 0;                     ///< for that search (0: its default)
};

template <std::size_t D, class T = double>
struct certificate {
    bool certified = false;
    certify_rule failed_rule = certify_rule::none;
    std::optional<std::size_t> vertex;                   ///< coincident_points, adjacent_angle: the vertex
    std::optional<std::size_t> segment;                  ///< not_centripetal: the offending segment, if one
    std::optional<std::array<std::size_t, 2>> segments;  ///< overlapping_boxes, adjacent_pair: the pair
    T angle = 0;                                         ///< adjacent_angle: the angle there (radians)
    std::string detail;                                  ///< one line saying what failed
    std::optional<bool> intersects;                      ///< when not certified and searched: does it?
    intersection_result<D, T> search;                    ///< that search's findings
};

namespace detail {

// Do two boxes overlap? 2-D: exact separating-axis test on the rectangles
// (the four edge normals). Other dimensions: conservative, through the
// capsules that contain the boxes (the chord over [lambda_min, lambda_max]
// with radius half_width): disjoint capsules imply disjoint boxes.
template <std::size_t D, class T>
bool boxes_overlap(const edge_box<D, T>& p, const edge_box<D, T>& q, T margin) {
    auto ends = [](const edge_box<D, T>& e) {
        const vec<D, T> d = e.b - e.a;
        return std::array<vec<D, T>, 2>{e.a + e.lambda_min * d, e.a + e.lambda_max * d};
    };
    const auto pe = ends(p), qe = ends(q);
    if constexpr (D == 2) {
        auto corners = [](const std::array<vec<2, T>, 2>& s, T w) {
            vec<2, T> d = s[1] - s[0];
            const T L = norm(d);
            vec<2, T> nrm = L > 0 ? vec<2, T>{{-d[1] / L, d[0] / L}} : vec<2, T>{{0, 1}};
            if (!(L > 0)) d = vec<2, T>{{w, 0}};  // a point: a square of half width w
            const vec<2, T> o = L > 0 ? vec<2, T>{} : vec<2, T>{{-w, 0}};
            return std::array<vec<2, T>, 4>{s[0] + o + w * nrm, s[0] + o - w * nrm, s[1] - o + w * nrm,
                                            s[1] - o - w * nrm};
        };
        const auto cp = corners(pe, p.half_width), cq = corners(qe, q.half_width);
        auto separated_on = [&](const vec<2, T>& axis) {
            T a0 = std::numeric_limits<T>::infinity(), a1 = -a0, b0 = a0, b1 = -a0;
            for (const auto& x : cp) { a0 = std::min(a0, dot(x, axis)); a1 = std::max(a1, dot(x, axis)); }
            for (const auto& x : cq) { b0 = std::min(b0, dot(x, axis)); b1 = std::max(b1, dot(x, axis)); }
            const T len = norm(axis);
            return a1 + margin * len < b0 || b1 + margin * len < a0;
        };
        for (const auto* cc : {&cp, &cq}) {
            const vec<2, T> e1 = (*cc)[2] - (*cc)[0], e2 = (*cc)[1] - (*cc)[0];
            for (const auto& e : {e1, e2})
                if (norm(e) > 0 && separated_on(vec<2, T>{{-e[1], e[0]}})) return false;
        }
        return true;
    } else {
        // Distance between the segments pe and qe (clamped closest points).
        const vec<D, T> d1 = pe[1] - pe[0], d2 = qe[1] - qe[0], r = pe[0] - qe[0];
        const T a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
        T s = 0, t = 0;
        if (a <= 0 && e <= 0) {
        } else if (a <= 0) {
            t = std::clamp(f / e, T(0), T(1));
        } else {
            const T cc = dot(d1, r);
            if (e <= 0) {
                s = std::clamp(-cc / a, T(0), T(1));
            } else {
                const T b = dot(d1, d2), den = a * e - b * b;
                s = den > 0 ? std::clamp((b * f - cc * e) / den, T(0), T(1)) : T(0);
                t = (b * s + f) / e;
                if (t < 0) { t = 0; s = std::clamp(-cc / a, T(0), T(1)); }
                else if (t > 1) { t = 1; s = std::clamp((b - cc) / a, T(0), T(1)); }
            }
        }
        const T dist = norm((pe[0] + s * d1) - (qe[0] + t * d2));
        return !(dist > p.half_width + q.half_width + margin);
    }
}

// Exact check that two adjacent segments meet only at their joint.
//
// a and b are the Bézier points of the two segments relative to the joint J,
// a[3] = b[0] = 0 exactly (the joint is a stored point, the end of one
// segment and the start of the next by construction). Each Bézier point is
// known to within `pad` (its rounding; see the caller). Subdivide both
// pieces (de Casteljau, which keeps the joint at exactly 0 in the pieces
// that touch it) and discard a pair of pieces when
//   * their control boxes, each grown by pad, are disjoint: the convex hulls
//     contain the pieces; or
//   * they both touch the joint and some direction d puts every control
//     point of the piece of a except the joint strictly behind J and every
//     one of the piece of b except the joint strictly ahead of it
//     (d.(x - J) < -pad |d|, resp. > pad |d|): a point of a piece other than
//     J is a convex combination giving a positive weight to a point other
//     than J, so the pieces lie in opposite open half-spaces except at J.
// Returns true when every pair of pieces was discarded (the two segments
// meet only at J), false when the budget or the depth ran out: the caller
// then reports that it could not prove them apart, which is never wrong.
// Rounding of the subdivision: every level adds at most ~2 eps of the
// largest |control point| per coordinate; pad is chosen by the caller to
// cover 64 levels in all D coordinates, and depth stops well before.
template <std::size_t D, class T>
bool adjacent_pair_apart(const std::array<vec<D, T>, 4>& a, const std::array<vec<D, T>, 4>& b, T pad,
                         std::size_t budget = 20000) {
    struct piece {
        std::array<vec<D, T>, 4> b;
        int depth;
    };
    // A piece touches the joint while its end (for a) or start (for b) is 0.
    auto split = [](const piece& p) {
        const auto& q = p.b;
        const T h = T(0.5);
        const auto a0 = lerp(q[0], q[1], h), a1 = lerp(q[1], q[2], h), a2 = lerp(q[2], q[3], h);
        const auto q0 = lerp(a0, a1, h), q1 = lerp(a1, a2, h);
        const auto m = lerp(q0, q1, h);
        return std::array<piece, 2>{piece{{q[0], a0, q0, m}, p.depth + 1}, piece{{m, q1, a2, q[3]}, p.depth + 1}};
    };
    auto apart_at_joint = [&](const std::array<vec<D, T>, 4>& pa, const std::array<vec<D, T>, 4>& pb) {
        // Candidate directions: the pieces' own directions at the joint
        // (first nonzero control-point difference) and their bisector.
        vec<D, T> da{}, db{};
        for (int k = 2; k >= 0 && !(norm(da) > 0); --k) da = pa[3] - pa[std::size_t(k)];
        for (int k = 1; k <= 3 && !(norm(db) > 0); ++k) db = pb[std::size_t(k)] - pb[0];
        std::array<vec<D, T>, 3> dirs{da, db, vec<D, T>{}};
        if (norm(da) > 0 && norm(db) > 0) dirs[2] = da / norm(da) + db / norm(db);
        for (const auto& d : dirs) {
            const T len = norm(d);
            if (!(len > 0)) continue;
            bool ok = true;
            for (std::size_t k = 0; k < 3 && ok; ++k) ok = dot(pa[k], d) < -pad * len;
            for (std::size_t k = 1; k < 4 && ok; ++k) ok = dot(pb[k], d) > pad * len;
            if (ok) return true;
        }
        return false;
    };
    auto hull_box = [&](const std::array<vec<D, T>, 4>& q) {
        std::array<vec<D, T>, 2> bx{q[0], q[0]};
        for (const auto& x : q)
            for (std::size_t k = 0; k < D; ++k) {
                bx[0][k] = std::min(bx[0][k], x[k]);
                bx[1][k] = std::max(bx[1][k], x[k]);
            }
        return bx;
    };
    const vec<D, T> zero{};
    std::vector<std::pair<piece, piece>> stack{{piece{a, 0}, piece{b, 0}}};
    std::size_t visits = 0;
    while (!stack.empty()) {
        if (++visits > budget) return false;
        const auto [pa, pb] = stack.back();
        stack.pop_back();
        const auto ba = hull_box(pa.b), bb = hull_box(pb.b);
        bool disjoint = false;
        for (std::size_t k = 0; k < D && !disjoint; ++k)
            disjoint = ba[0][k] - pad > bb[1][k] + pad || bb[0][k] - pad > ba[1][k] + pad;
        if (disjoint) continue;
        const bool corner = pa.b[3] == zero && pb.b[0] == zero;
        if (corner && apart_at_joint(pa.b, pb.b)) continue;
        if (pa.depth >= 48 && pb.depth >= 48) return false;  // too close to decide: not proved
        const T sa = norm(ba[1] - ba[0]), sb = norm(bb[1] - bb[0]);
        if ((sa >= sb && pa.depth < 48) || pb.depth >= 48) {
            const auto h = split(pa);
            stack.push_back({h[0], pb});
            stack.push_back({h[1], pb});
        } else {
            const auto h = split(pb);
            stack.push_back({pa, h[0]});
            stack.push_back({pa, h[1]});
        }
    }
    return true;
}

// An axis-aligned box around everything boxes_overlap can count as part of
// e, grown by twice (margin + slack): when two such boxes do not meet,
// boxes_overlap finds the pair separated. Why: e lies within the chord
// [ends] grown by half_width (a 2-D zero-length chord is a square of half
// diagonal sqrt(2) half_width, hence 2 half_width there), so disjoint boxes
// put the volumes more than 2 (margin + slack) apart per box; the
// separating-axis test sees at least 1/sqrt(2) of that distance on an edge
// normal of a rectangle (the distance is realized between a vertex and
// either an edge or a vertex, whose normal cone is at most 90 degrees
// wide), the capsule test sees all of it, and both compute their
// quantities within a few ulps of the coordinates and widths, far below
// slack = 64 eps (|ends| + half_width). Non-finite geometry gets the
// infinite box, as boxes_overlap counts it as overlapping.
template <std::size_t D, class T>
box<D, T> overlap_candidate_box(const edge_box<D, T>& e, T margin) {
    const vec<D, T> d = e.b - e.a;
    const vec<D, T> p0 = e.a + e.lambda_min * d, p1 = e.a + e.lambda_max * d;  // as boxes_overlap's ends()
    const T w = norm(p1 - p0) > 0 ? e.half_width : T(2) * e.half_width;
    const T slack = T(64) * std::numeric_limits<T>::epsilon() * (max_abs(p0) + max_abs(p1) + e.half_width);
    const T grow = w + T(2) * (margin + slack);
    box<D, T> r;
    for (std::size_t k = 0; k < D; ++k) {
        r.lo[k] = std::min(p0[k], p1[k]) - grow;
        r.hi[k] = std::max(p0[k], p1[k]) + grow;
    }
    if (!std::isfinite(grow) || !std::isfinite(max_abs(r.lo)) || !std::isfinite(max_abs(r.hi))) {
        const T inf = std::numeric_limits<T>::infinity();
        for (std::size_t k = 0; k < D; ++k) { r.lo[k] = -inf; r.hi[k] = inf; }
    }
    return r;
}

template <std::size_t D, class T, class Pairs>
certificate<D, T> certify_among(const catmull_rom<D, T>& c, const certify_options& opt, const Pairs& candidate_pairs);

}  // namespace detail

/// Section 5's rules, made sound for every curve catmull_rom builds:
///
///  (1) centripetal knots: the curve was built with alpha = 1/2 (read from
///      catmull_rom::options(), never guessed from the numbers); an explicit
///      grid or another alpha fails not_centripetal. No segment may have a
///      cusp, loop or fold (checked exactly: analyze()). Centripetal
///      interior segments never do (Theorem 3); end segments (end
///      conditions) and segments with tension or Kochanek-Bartels values
///      may, and are checked the same way.
///  (2) adjacent segments: two interior segments of a plain centripetal
///      curve (no tension, no Kochanek-Bartels) are apart when the polygon
///      angle at their shared vertex exceeds options.safe_angle (pi/3; the
///      paper's Section 5 argument, measured: crossings exist up to at least
///      28.9 degrees, none found above 30). Every other adjacent pair -- an
///      end segment of an open curve with any end condition (natural and
///      reflect included: their safety was only ever measured), or a
///      segment with tension or Kochanek-Bartels values -- is proved apart
///      by an exact subdivision check (detail::adjacent_pair_apart, with
///      the rounding of its arithmetic bounded), or fails adjacent_pair.
///  (3) the boxes of non-adjacent segments are disjoint: interior plain
///      segments use the edge extruded by the two-sided Eq. 6 bound
///      (Theorem 3: a centripetal segment never leaves [0, 1] along its
///      edge, so no balls are needed), all others the box of their Bézier
///      points (valid for any cubic).
///
/// A certified curve has no self-intersection. Every test is done relative
/// to the curve's own points, so the answer does not change when the curve
/// is moved. When certification fails, the first failing rule is reported
/// with where it failed, and (options.search_on_failure) the search says
/// whether the curve actually intersects itself. Rule 3 checks only the
/// pairs whose axis-aligned boxes meet, found through a bounding-volume
/// hierarchy (O(n log n) for a curve that passes), and reports the failing
/// pair (i, j) with the smallest i, then j.
template <std::size_t D, class T>
certificate<D, T> certify_intersection_free(const catmull_rom<D, T>& c, const certify_options& opt = {}) {
    return detail::certify_among(c, opt, detail::tree_pairs{});
}

namespace detail {

// The certificate, given how to find rule 3's candidate pairs (a seam for
// the tests: the tree, or every pair i < j as a reference).
// candidate_pairs(boxes, 0) returns pair_rows that include every pair
// i < j whose boxes meet; each is checked in the order i, then j.
template <std::size_t D, class T, class Pairs>
certificate<D, T> certify_among(const catmull_rom<D, T>& c, const certify_options& opt, const Pairs& candidate_pairs) {
    certificate<D, T> cert;
    const auto pts = c.points();
    const auto grid = c.grid();
    const auto& built = c.options();
    const std::size_t n = c.segment_count(), np = pts.size();
    const bool closed = c.closed();
    const bool plain = !c.given_tangents() && built.tension == T(0) && built.kb.empty();
    auto fail = [&](certify_rule r, std::string why) {
        cert.certified = false;
        cert.failed_rule = r;
        cert.detail = std::move(why);
        if (opt.search_on_failure) {
            cert.search = find_intersections(c, T(opt.tolerance));
            cert.intersects = cert.search.any();
        }
        return cert;
    };
    auto end_segment = [&](std::size_t i) { return !closed && (i == 0 || i + 1 == n); };

    // Coincident consecutive points: zero edges.
    for (std::size_t i = 0; i < n; ++i)
        if (!(grid[i + 1] > grid[i]) || !(norm(pts[(i + 1) % np] - pts[i]) > 0)) {
            cert.vertex = (i + 1) % np;
            return fail(certify_rule::coincident_points,
                        "points " + std::to_string(i) + " and " + std::to_string((i + 1) % np) + " coincide");
        }

    // Rule 1: centripetal knots, as built; no segment cusps, loops or folds.
    if (c.given_tangents())
        return fail(certify_rule::not_centripetal,
                    "the tangents were given (a Hermite curve), not the centripetal Catmull-Rom ones");
    if (!built.alpha)
        return fail(certify_rule::not_centripetal, "the knots were given as an explicit grid, not from alpha = 0.5");
    if (*built.alpha != centripetal)
        return fail(certify_rule::not_centripetal,
                    "the knots are from alpha = " + detail::num(*built.alpha) + ", not 0.5 (centripetal)");
    // One segment's analysis at a time (the whole analysis of 10^6
    // segments held here took 0.5 GB); rule 3 analyses them again for
    // their boxes, only when rules 1 and 2 pass.
    for (std::size_t i = 0; i < n; ++i) {
        const auto an = analyze(c, i);
        if (an.has_cusp() || an.has_self_intersection()) {
            cert.segment = i;
            std::string why = end_segment(i) ? " (shaped by its end condition)"
                              : !plain       ? " (shaped by tension or Kochanek-Bartels values)"
                                             : "";
            return fail(certify_rule::not_centripetal,
                        "segment " + std::to_string(i) + " has a cusp, loop or fold" + why);
        }
    }

    // Rule 2: adjacent pairs. The angle rule for two interior plain
    // segments; the exact check for every other pair.
    const std::size_t first = closed ? 0 : 1, last = closed ? np : np - 1;
    for (std::size_t k = first; k < last && n > 1; ++k) {
        const std::size_t before = (k + n - 1) % n, after = k % n;  // the segments ending and starting at vertex k
        if (plain && !end_segment(before) && !end_segment(after)) {
            const T ang = detail::angle_between(pts[(k + np - 1) % np] - pts[k], pts[(k + 1) % np] - pts[k]);
            if (!(ang > T(opt.safe_angle))) {
                cert.vertex = k;
                cert.angle = ang;
                return fail(certify_rule::adjacent_angle,
                            "polygon angle at vertex " + std::to_string(k) + " is " +
                                detail::degrees(double(ang)) + " degrees, not above " +
                                detail::degrees(opt.safe_angle));
            }
            continue;
        }
        // Bézier points relative to the joint P(k), from the stored points
        // and tangents (B1 = P + h/3 v), so the joint is exactly 0 in both.
        const vec<D, T> J = pts[k];
        const auto [va0, va1] = c.tangents(before);
        const auto [vb0, vb1] = c.tangents(after);
        const T ha = grid[before + 1] - grid[before], hb = grid[after + 1] - grid[after];
        const vec<D, T> pa0 = pts[before] - J, pb3 = pts[(after + 1) % np] - J;
        const std::array<vec<D, T>, 4> a{pa0, pa0 + (ha / T(3)) * va0, -((ha / T(3)) * va1), vec<D, T>{}};
        const std::array<vec<D, T>, 4> b{vec<D, T>{}, (hb / T(3)) * vb0, pb3 - (hb / T(3)) * vb1, pb3};
        T M = 0;
        for (std::size_t q = 0; q < 4; ++q) M = std::max({M, max_abs(a[q]), max_abs(b[q])});
        // Rounding of these points (a few eps of M) and of 48 levels of
        // halving (at most 1.5 eps of M per level and coordinate), in D
        // coordinates: 128 D eps M covers both with room.
        const T pad = T(128) * T(D) * std::numeric_limits<T>::epsilon() * M;
        if (!detail::adjacent_pair_apart(a, b, pad)) {
            cert.vertex = k;
            cert.segments = std::array<std::size_t, 2>{std::min(before, after), std::max(before, after)};
            const std::string which = end_segment(before) || end_segment(after)
                                          ? "an end segment (end condition)"
                                          : "tension or Kochanek-Bartels values";
            return fail(certify_rule::adjacent_pair,
                        "segments " + std::to_string(before) + " and " + std::to_string(after) +
                            " (joined at vertex " + std::to_string(k) + ", " + which +
                            ", not covered by the angle rule) could not be proved apart");
        }
    }

    // Rule 3: boxes of non-adjacent segments are disjoint. Boxes are taken
    // relative to the first point, so their rounding (and the margin that
    // covers it) is relative to the curve's extent, not its position.
    const vec<D, T> ref = pts[0];
    std::vector<edge_box<D, T>> boxes(n);
    T scale = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const auto an = analyze(c, i);
        if (an.bounds) {
            boxes[i].segment = i;
            boxes[i].a = an.bezier[0];
            boxes[i].b = an.bezier[3];
            boxes[i].half_width = an.bounds->eq6;
        } else {
            boxes[i] = detail::bezier_box(i, an);
        }
        boxes[i].a -= ref;
        boxes[i].b -= ref;
        scale = std::max({scale, max_abs(boxes[i].a), max_abs(boxes[i].b)});
    }
    // Rounding of the box geometry: a few ulps of the coordinates.
    const T margin = T(64) * std::numeric_limits<T>::epsilon() * scale;
    std::vector<box<D, T>> candidate_boxes(n);
    for (std::size_t i = 0; i < n; ++i) candidate_boxes[i] = detail::overlap_candidate_box(boxes[i], margin);
    const pair_rows candidates = candidate_pairs(candidate_boxes, T(0));
    for (std::size_t i = 0; i < n; ++i)
        for (const std::size_t j : candidates.row(i)) {
            if (j < i + 2) continue;                       // adjacent
            if (closed && i == 0 && j == n - 1) continue;  // adjacent across the seam
            if (detail::boxes_overlap(boxes[i], boxes[j], margin)) {
                cert.segments = std::array<std::size_t, 2>{i, j};
                return fail(certify_rule::overlapping_boxes,
                            "boxes of segments " + std::to_string(i) + " and " + std::to_string(j) + " overlap");
            }
        }
    cert.certified = true;
    cert.failed_rule = certify_rule::none;
    return cert;
}

}  // namespace detail

}  // namespace crspline
