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

/// The paper's bounding volumes for a curve built with knot exponent alpha.
/// Interior segments: the edge extruded by the Eq. 6 bound (two-sided) and
/// balls of the Eq. 8 radius at the vertices; `local` uses the suprema over
/// the neighbours' lengths (local_eq6_factor, local_eq8_factor: infinite for
/// alpha < 1/2, where the paper has no bound). End segments of an open curve
/// (no neighbour on one side, end conditions instead of Eq. 2) and segments
/// that are not plain Catmull-Rom (tension, Kochanek-Bartels) get the box of
/// their actual Bézier points instead (lambda range of the hull, half width
/// 3/4 of the larger Bézier height), which holds for any cubic.
template <std::size_t D, class T>
bounding_volumes<D, T> paper_bounding_volumes(const catmull_rom<D, T>& c, double alpha,
                                              volume_kind kind = volume_kind::tightened) {
    bounding_volumes<D, T> v;
    const auto an = analyze(c);
    const std::size_t n = c.segment_count(), np = c.points().size();
    std::vector<T> radius(np, T(0));
    for (std::size_t i = 0; i < n; ++i) {
        if (!an[i].bounds) {
            v.boxes.push_back(detail::bezier_box(i, an[i]));
            continue;
        }
        const auto& b = *an[i].bounds;
        edge_box<D, T> e;
        e.segment = i;
        e.a = an[i].bezier[0];
        e.b = an[i].bezier[3];
        T r1, r2;
        if (kind == volume_kind::local) {
            e.half_width = b.d2 * T(local_eq6_factor(alpha));
            r1 = r2 = b.d2 * T(local_eq8_factor(alpha));
        } else {
            // The printed formulas in r = d1/d2, d3/d2 and alpha (Eq. 8 is
            // then identically 0 at alpha = 1/2, not the sqrt of the knots'
            // rounding).
            e.half_width = paper_eq6_two_sided(b.d1, b.d2, b.d3, alpha);
            r1 = paper_eq8(b.d2, b.d1 / b.d2, alpha);
            r2 = paper_eq8(b.d2, b.d3 / b.d2, alpha);
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
/// centripetal segments have been seen to cross at 20.9 degrees, none
/// between 30 and 60 (tests/reference/SOURCES.md). pi/3 is the safe value.
inline constexpr double safe_adjacent_angle = std::numbers::pi / 3;

enum class certify_rule {
    none,               ///< certified
    not_centripetal,    ///< rule 1: the curve is not the plain centripetal curve of its points
    coincident_points,  ///< a zero-length polygon edge: the angle rule has no angle
    adjacent_angle,     ///< rule 2: a polygon angle <= safe_adjacent_angle
    overlapping_boxes,  ///< rule 3: boxes of two non-adjacent segments overlap
};

inline const char* to_string(certify_rule r) noexcept {
    switch (r) {
        case certify_rule::none: return "none";
        case certify_rule::not_centripetal: return "not_centripetal";
        case certify_rule::coincident_points: return "coincident_points";
        case certify_rule::adjacent_angle: return "adjacent_angle";
        case certify_rule::overlapping_boxes: return "overlapping_boxes";
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
    std::optional<std::array<std::size_t, 2>> segments;  ///< overlapping_boxes: the pair
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

}  // namespace detail

/// Section 5's three rules: (1) centripetal: the knots are the centripetal
/// ones and every interior segment is the plain Catmull-Rom segment of its
/// points (tension 0, no Kochanek-Bartels); the end segments of an open
/// curve, shaped by end conditions the paper does not cover, must have no
/// cusp, loop or fold (checked exactly); (2) every polygon angle between two
/// segments exceeds options.safe_angle (pi/3); (3) the boxes of
/// non-adjacent segments are disjoint: interior segments use the edge
/// extruded by the two-sided Eq. 6 bound (Theorem 3: a centripetal segment
/// never leaves [0, 1] along its edge, so no balls are needed), end segments
/// the box of their Bézier points. A certified curve has no
/// self-intersection. When certification fails, the first failing rule is
/// reported with where it failed, and (options.search_on_failure) the
/// exact search says whether the curve actually intersects itself.
template <std::size_t D, class T>
certificate<D, T> certify_intersection_free(const catmull_rom<D, T>& c, const certify_options& opt = {}) {
    certificate<D, T> cert;
    const auto pts = c.points();
    const auto grid = c.grid();
    const std::size_t n = c.segment_count(), np = pts.size();
    const bool closed = c.closed();
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

    // Coincident consecutive points: zero edges.
    for (std::size_t i = 0; i < n; ++i)
        if (!(grid[i + 1] > grid[i]) || !(norm(pts[(i + 1) % np] - pts[i]) > 0)) {
            cert.vertex = (i + 1) % np;
            return fail(certify_rule::coincident_points,
                        "points " + std::to_string(i) + " and " + std::to_string((i + 1) % np) + " coincide");
        }

    // Rule 1: centripetal knots, plain interior segments, clean end segments.
    for (std::size_t i = 0; i < n; ++i) {
        const T h = grid[i + 1] - grid[i], want = std::sqrt(norm(pts[(i + 1) % np] - pts[i]));
        if (std::abs(h - want) > T(16) * std::numeric_limits<T>::epsilon() * (want + std::abs(grid[i + 1]))) {
            cert.segment = i;
            return fail(certify_rule::not_centripetal,
                        "knot interval " + std::to_string(i) + " is not |P(i+1) - P(i)|^(1/2)");
        }
    }
    const auto an = analyze(c);
    for (std::size_t i = 0; i < n; ++i) {
        const bool interior = closed || (i > 0 && i + 1 < n);
        if (interior && !an[i].bounds && n > 1) {
            cert.segment = i;
            return fail(certify_rule::not_centripetal,
                        "segment " + std::to_string(i) + " is not the plain Catmull-Rom segment (tension or Kochanek-Bartels)");
        }
        if (an[i].has_cusp() || an[i].has_self_intersection()) {
            cert.segment = i;
            return fail(certify_rule::not_centripetal,
                        "segment " + std::to_string(i) + " has a cusp, loop or fold (an end condition)");
        }
    }

    // Rule 2: the polygon angle at every vertex between two segments.
    const std::size_t first = closed ? 0 : 1, last = closed ? np : np - 1;
    for (std::size_t k = first; k < last && n > 1; ++k) {
        const T ang = detail::angle_between(pts[(k + np - 1) % np] - pts[k], pts[(k + 1) % np] - pts[k]);
        if (!(ang > T(opt.safe_angle))) {
            cert.vertex = k;
            cert.angle = ang;
            return fail(certify_rule::adjacent_angle,
                        "polygon angle at vertex " + std::to_string(k) + " is " +
                            detail::degrees(double(ang)) + " degrees, not above " +
                            detail::degrees(opt.safe_angle));
        }
    }

    // Rule 3: boxes of non-adjacent segments are disjoint.
    std::vector<edge_box<D, T>> boxes(n);
    T scale = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (an[i].bounds) {
            boxes[i].segment = i;
            boxes[i].a = an[i].bezier[0];
            boxes[i].b = an[i].bezier[3];
            boxes[i].half_width = an[i].bounds->eq6;
        } else {
            boxes[i] = detail::bezier_box(i, an[i]);
        }
        scale = std::max({scale, max_abs(pts[i]), max_abs(pts[(i + 1) % np])});
    }
    // Rounding of the box geometry: a few ulps of the coordinates.
    const T margin = T(64) * std::numeric_limits<T>::epsilon() * scale;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 2; j < n; ++j) {
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

}  // namespace crspline
