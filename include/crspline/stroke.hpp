// crspline: strokes in the plane. The region within width / 2 of a 2-D
// curve (a line buffer), as simple polygons with holes where the stroke
// overlaps itself: the union, not a self-overlapping outline.
//
//   auto r = crspline::stroke(curve, 2.0, {.join = crspline::stroke_join::round});
//   // r.polygons[i].exterior (counterclockwise), .holes (clockwise)
//
// Within `tolerance` of the true stroke (both ways): half of it for the
// curve's tessellation (tessellate.hpp's proof: the polyline's stroke is
// then within that of the curve's, the stroke being the Minkowski sum with
// a disc), half for the arcs of round joins and caps (inscribed polygons,
// or one mitre point where that is within the tolerance of the arc). The
// join style applies where the curve has a corner (one-sided tangents that
// differ at a knot, as at a cusp of a uniform curve or next to coincident
// points); along the smooth curve the stroke is the disc's sweep, whatever
// the style. The offset's cusps and loops, and the places where distant
// parts of the stroke overlap, are resolved by the nonzero rule
// (sweep/nonzero.hpp): every crossing of the raw outline is cut there.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "bounds.hpp"
#include "catmull_rom.hpp"
#include "detail/format.hpp"
#include "error.hpp"
#include "sweep/nonzero.hpp"
#include "sweep/outline.hpp"
#include "tessellate.hpp"
#include "vec.hpp"

namespace crspline {

/// The default stroke tolerance, relative to the curve's bounding-box
/// diagonal plus the width.
inline constexpr double default_stroke_tolerance = 1e-3;

struct stroke_options {
    stroke_join join = stroke_join::round;
    double miter_limit = 4;  ///< mitre length over width above which a mitre becomes a bevel (SVG's rule)
    stroke_cap cap = stroke_cap::butt;
    double tolerance = 0;    ///< distance; 0: default_stroke_tolerance x (diagonal + width)
};

/// One polygon: outer ring counterclockwise, holes clockwise, first vertex
/// not repeated.
struct stroke_polygon {
    std::vector<vec<2>> exterior;
    std::vector<std::vector<vec<2>>> holes;
};

struct stroke_result {
    std::vector<stroke_polygon> polygons;
    double tolerance = 0;                 ///< the tolerance met
    std::size_t tessellation_vertices = 0;  ///< the curve's polyline the stroke was made from
};

namespace detail {

/// Whether the curve has a corner at knot k: its arriving and departing
/// directions differ (by the first derivative that does not vanish, across
/// segments of zero length).
inline bool corner_at_knot(const catmull_rom<2>& c, std::size_t k) {
    const std::size_t ns = c.segment_count();
    auto constant = [&](std::size_t i) {
        const auto& s = c.segment(i);
        return s.c1 == vec<2>{} && s.c2 == vec<2>{} && s.c3 == vec<2>{};
    };
    auto dir = [](const vec<2>& a, const vec<2>& b) -> std::optional<vec<2>> {
        if (norm(a) > 0) return a / norm(a);
        if (norm(b) > 0) return b / norm(b);
        return std::nullopt;
    };
    std::optional<std::size_t> before, after;
    for (std::size_t j = 0; j < ns; ++j) {
        const std::size_t i = c.closed() ? (k + ns - 1 - j) % ns : (k >= 1 + j ? k - 1 - j : ns);
        if (i >= ns) break;
        if (!constant(i)) { before = i; break; }
    }
    for (std::size_t j = 0; j < ns; ++j) {
        const std::size_t i = c.closed() ? (k + j) % ns : k + j;
        if (i >= ns) break;
        if (!constant(i)) { after = i; break; }
    }
    if (!before || !after) return false;
    const auto& a = c.segment(*before);
    const auto& b = c.segment(*after);
    const auto ea = dir(a.du(1, 1), -1.0 * a.du(1, 2)), eb = dir(b.du(0, 1), b.du(0, 2));
    if (!ea || !eb) return false;
    return dot(*ea, *eb) < std::cos(1e-6);
}

}  // namespace detail

/// The stroke of a 2-D curve at the given width (see the top of this file).
/// Throws spec_error naming "width", "miter_limit" or "tolerance".
inline stroke_result stroke(const catmull_rom<2>& curve, double width, const stroke_options& opt = {}) {
    using namespace detail;
    if (!(width > 0) || !std::isfinite(width))
        throw spec_error("width", std::nullopt, std::nullopt, num(width),
                         "width: must be positive and finite, got " + num(width));
    if (!(opt.miter_limit >= 1) || !std::isfinite(opt.miter_limit))
        throw spec_error("miter_limit", std::nullopt, std::nullopt, num(opt.miter_limit),
                         "miter_limit: must be at least 1 and finite, got " + num(opt.miter_limit));
    if (!(opt.tolerance >= 0) || !std::isfinite(opt.tolerance))
        throw spec_error("tolerance", std::nullopt, std::nullopt, num(opt.tolerance),
                         "tolerance: must be positive and finite (0: the default), got " + num(opt.tolerance));
    const double tol =
        opt.tolerance > 0 ? opt.tolerance : default_stroke_tolerance * (double(bounding_box(curve).diagonal()) + width);
    // 1. The curve's polyline within tol / 2, consecutive repeats out, and its corners.
    const auto line = tessellate(curve, tol / 2);
    std::vector<p2> pts;
    std::vector<bool> corner;
    const auto grid = curve.grid();
    for (std::size_t k = 0; k < line.points.size(); ++k) {
        if (!pts.empty() && pts.back() == line.points[k]) continue;
        pts.push_back(line.points[k]);
        const auto it = std::lower_bound(grid.begin(), grid.end(), line.t[k]);
        bool c = false;
        if (it != grid.end() && *it == line.t[k]) {
            const auto knot = std::size_t(it - grid.begin());
            if (curve.closed() || (knot > 0 && knot + 1 < grid.size())) c = corner_at_knot(curve, knot % curve.segment_count());
        }
        corner.push_back(c);
    }
    const bool closed = curve.closed() && pts.size() >= 2;
    if (closed && pts.front() == pts.back()) pts.pop_back(), corner.pop_back();
    if (closed) corner[0] = corner_at_knot(curve, 0);
    // 2. The raw outline and its nonzero region.
    outline_style st;
    st.d = width / 2;
    st.join = opt.join;
    st.miter_limit = opt.miter_limit;
    st.cap = opt.cap;
    st.tol = tol / 2;
    const auto rings = stroke_rings(pts, corner, closed, st);
    stroke_result out;
    out.tolerance = tol;
    out.tessellation_vertices = line.points.size();
    for (auto& p : nonzero_region(rings)) out.polygons.push_back({std::move(p.exterior), std::move(p.holes)});
    return out;
}

/// Strokes are of plane curves: for another dimension, a spec_error naming "curve".
template <std::size_t D>
    requires(D != 2)
stroke_result stroke(const catmull_rom<D>&, double, const stroke_options& = {}) {
    throw spec_error("curve", std::nullopt, std::nullopt, std::to_string(D),
                     "curve: stroke needs a 2-D curve, got a " + std::to_string(D) + "-D one");
}

}  // namespace crspline
