// crspline strokes, internals: the region a set of closed polygons covers
// with a nonzero winding number, as simple rings (counterclockwise outer
// boundaries, clockwise holes).
//
// 1. Every pair of crossing edges is cut at its crossing (a grid of cells
//    finds the pairs); the pieces share the crossing's vertex.
//    Collinear edges that overlap (to within 1e-10 of the extent: a path
//    that retraces itself) are cut at each other's ends instead, and pieces
//    with the same two ends merged into one that counts its directions
//    (twice the same way: 2; there and back: 0, dropped).
// 2. Each piece's winding number on either side: a ray from its midpoint,
//    across it (along x for a steep piece, along y for a flat one), counts
//    the other pieces it crosses (the half-open rule at vertices), each as
//    many times as it counts; the piece itself adds its count on its left.
//    A piece with a nonzero winding on one side only is boundary, kept with
//    the region on its left.
// 3. The kept pieces are linked into rings, taking at a vertex where
//    several leave the one that turns most to the left: rings that touch at
//    a point come out as separate simple rings.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <unordered_map>
#include <vector>

#include "../vec.hpp"

namespace crspline::detail {

using p2 = vec<2, double>;

inline double orient(const p2& a, const p2& b, const p2& c) noexcept {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

inline double ring_area(const std::vector<p2>& r) noexcept {
    double s = 0;
    for (std::size_t i = 0, n = r.size(); i < n; ++i) {
        const p2 &a = r[i], &b = r[(i + 1) % n];
        s += a[0] * b[1] - a[1] * b[0];
    }
    return s / 2;
}

inline bool inside_ring(const std::vector<p2>& r, const p2& q) noexcept {
    bool in = false;
    for (std::size_t i = 0, n = r.size(), j = n - 1; i < n; j = i++) {
        const p2 &a = r[i], &b = r[j];
        if ((a[1] > q[1]) != (b[1] > q[1]) && q[0] < (b[0] - a[0]) * (q[1] - a[1]) / (b[1] - a[1]) + a[0]) in = !in;
    }
    return in;
}

/// A polygon: its outer ring (counterclockwise) and holes (clockwise),
/// first vertex not repeated.
struct ring_polygon {
    std::vector<p2> exterior;
    std::vector<std::vector<p2>> holes;
};

/// The nonzero-winding region of the closed rings (each first vertex not
/// repeated) as polygons.
inline std::vector<ring_polygon> nonzero_region(const std::vector<std::vector<p2>>& rings) {
    // 0. Vertices, merged when within `near` of each other (1e-10 of the
    //    extent: the same point computed two ways, as where a path retraces
    //    itself and both sides' outlines pass through it), and edges.
    double lo_x = std::numeric_limits<double>::infinity(), lo_y = lo_x, hi_x = -lo_x, hi_y = -lo_x;
    for (const auto& r : rings)
        for (const auto& p : r) lo_x = std::min(lo_x, p[0]), hi_x = std::max(hi_x, p[0]), lo_y = std::min(lo_y, p[1]), hi_y = std::max(hi_y, p[1]);
    const double extent = std::max({hi_x - lo_x, hi_y - lo_y, std::numeric_limits<double>::min()});
    const double near = 1e-10 * extent;
    std::vector<p2> pts;
    std::map<std::pair<double, double>, std::uint32_t> id_of;
    struct cell_hash {
        std::size_t operator()(const std::pair<std::int64_t, std::int64_t>& c) const noexcept {
            return std::size_t(std::uint64_t(c.first) * 0x9E3779B97F4A7C15u ^ std::uint64_t(c.second) * 0xC2B2AE3D27D4EB4Fu);
        }
    };
    std::unordered_map<std::pair<std::int64_t, std::int64_t>, std::vector<std::uint32_t>, cell_hash> near_cells;
    auto vid = [&](const p2& p) {
        const auto exact = id_of.find({p[0], p[1]});
        if (exact != id_of.end()) return exact->second;
        const auto cx = std::int64_t(std::floor((p[0] - lo_x) / near)), cy = std::int64_t(std::floor((p[1] - lo_y) / near));
        for (std::int64_t y = cy - 1; y <= cy + 1; ++y)
            for (std::int64_t x = cx - 1; x <= cx + 1; ++x) {
                const auto it = near_cells.find({x, y});
                if (it == near_cells.end()) continue;
                for (const auto q : it->second)
                    if (norm(pts[q] - p) <= near) return id_of[{p[0], p[1]}] = q;
            }
        const auto id = std::uint32_t(pts.size());
        pts.push_back(p);
        near_cells[{cx, cy}].push_back(id);
        return id_of[{p[0], p[1]}] = id;
    };
    std::vector<std::array<std::uint32_t, 2>> edges;
    for (const auto& r : rings)
        for (std::size_t i = 0; i < r.size(); ++i) {
            const auto a = vid(r[i]), b = vid(r[(i + 1) % r.size()]);
            if (a != b) edges.push_back({a, b});
        }
    if (edges.empty()) return {};
    // 1. Crossings, through a grid of about one edge per cell.
    const std::size_t ne = edges.size();
    const std::size_t cells = std::max<std::size_t>(1, std::size_t(std::sqrt(double(ne))));
    const double cw = (hi_x - lo_x) / double(cells) * (1 + 1e-12) + 1e-300, ch = (hi_y - lo_y) / double(cells) * (1 + 1e-12) + 1e-300;
    auto cell_range = [&](double a, double b, double lo, double size) {
        const auto c0 = std::size_t(std::clamp((std::min(a, b) - lo) / size, 0.0, double(cells - 1)));
        const auto c1 = std::size_t(std::clamp((std::max(a, b) - lo) / size, 0.0, double(cells - 1)));
        return std::array<std::size_t, 2>{c0, c1};
    };
    std::vector<std::vector<std::uint32_t>> grid(cells * cells);
    for (std::uint32_t e = 0; e < ne; ++e) {
        const p2 &a = pts[edges[e][0]], &b = pts[edges[e][1]];
        const auto xr = cell_range(a[0], b[0], lo_x, cw), yr = cell_range(a[1], b[1], lo_y, ch);
        for (std::size_t y = yr[0]; y <= yr[1]; ++y)
            for (std::size_t x = xr[0]; x <= xr[1]; ++x) grid[y * cells + x].push_back(e);
    }
    std::vector<std::vector<std::pair<double, std::uint32_t>>> cuts(ne);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> tested;
    for (const auto& cell : grid)
        for (std::size_t i = 0; i < cell.size(); ++i)
            for (std::size_t j = i + 1; j < cell.size(); ++j) tested.push_back({std::min(cell[i], cell[j]), std::max(cell[i], cell[j])});
    std::sort(tested.begin(), tested.end());
    tested.erase(std::unique(tested.begin(), tested.end()), tested.end());
    const double snap = 1e-12;
    for (const auto& [e, f] : tested) {
        const auto &E = edges[e], &F = edges[f];
        const p2 &a = pts[E[0]], &b = pts[E[1]], &c = pts[F[0]], &d = pts[F[1]];
        const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
        const p2 r = b - a, s = d - c;
        const double rr = dot(r, r), ss = dot(s, s), nn = near * near;
        if (rr > 0 && ss > 0 && o1 * o1 <= nn * rr && o2 * o2 <= nn * rr && o3 * o3 <= nn * ss && o4 * o4 <= nn * ss) {
            // Collinear (each end within `near` of the other's line) and
            // overlapping: each cut at the other's ends inside it, at those
            // very vertices, so that the overlap becomes pieces with the same
            // two ends (merged below, their directions summed): a path that
            // retraces itself gives outline edges twice over, whose windings
            // must add up.
            const double tc = dot(c - a, r) / rr, td = dot(d - a, r) / rr;
            if (std::max(std::min(tc, td), 0.0) < std::min(std::max(tc, td), 1.0) - snap) {
                for (const auto& [t, v] : {std::pair{tc, F[0]}, std::pair{td, F[1]}})
                    if (t > snap && t < 1 - snap && v != E[0] && v != E[1]) cuts[e].push_back({t, v});
                const double ta = dot(a - c, s) / ss, tb = dot(b - c, s) / ss;
                for (const auto& [t, v] : {std::pair{ta, E[0]}, std::pair{tb, E[1]}})
                    if (t > snap && t < 1 - snap && v != F[0] && v != F[1]) cuts[f].push_back({t, v});
            }
            continue;
        }
        if ((o1 > 0 && o2 > 0) || (o1 < 0 && o2 < 0) || (o3 > 0 && o4 > 0) || (o3 < 0 && o4 < 0)) continue;
        const double den = r[0] * s[1] - r[1] * s[0];
        if (den == 0) continue;  // parallel, apart (collinear ones are cut above)
        const p2 ac = c - a;
        const double te = std::clamp((ac[0] * s[1] - ac[1] * s[0]) / den, 0.0, 1.0);
        const double tf = std::clamp((ac[0] * r[1] - ac[1] * r[0]) / den, 0.0, 1.0);
        std::uint32_t v;
        if (te <= snap) v = E[0];
        else if (te >= 1 - snap) v = E[1];
        else if (tf <= snap) v = F[0];
        else if (tf >= 1 - snap) v = F[1];
        else v = vid(a + te * r);
        if (v != E[0] && v != E[1]) cuts[e].push_back({te, v});
        if (v != F[0] && v != F[1]) cuts[f].push_back({tf, v});
    }
    // Pieces; those with the same two ends merged, each with the number of
    // times it is crossed from right to left (its directions summed), and
    // dropped where they cancel.
    // lower end, upper end, the order made in, 1: along, 0: against
    std::vector<std::array<std::uint32_t, 4>> raw;
    auto add_piece = [&](std::uint32_t u, std::uint32_t v) {
        const auto k = std::uint32_t(raw.size());
        raw.push_back(u < v ? std::array<std::uint32_t, 4>{u, v, k, 1} : std::array<std::uint32_t, 4>{v, u, k, 0});
    };
    for (std::size_t e = 0; e < ne; ++e) {
        auto& c = cuts[e];
        std::sort(c.begin(), c.end());
        std::uint32_t from = edges[e][0];
        for (const auto& [t, v] : c) {
            if (v != from) add_piece(from, v);
            from = v;
        }
        if (from != edges[e][1]) add_piece(from, edges[e][1]);
    }
    // Merged, then back in the order made (the outline's order: the
    // windings' scans below run a third faster so than by vertex).
    std::sort(raw.begin(), raw.end());
    std::vector<std::array<std::uint32_t, 4>> merged;  // from, to, order, weight
    for (std::size_t i = 0; i < raw.size();) {
        int c = 0;
        std::size_t j = i;
        for (; j < raw.size() && raw[j][0] == raw[i][0] && raw[j][1] == raw[i][1]; ++j) c += raw[j][3] ? 1 : -1;
        if (c > 0) merged.push_back({raw[i][0], raw[i][1], raw[i][2], std::uint32_t(c)});
        if (c < 0) merged.push_back({raw[i][1], raw[i][0], raw[i][2], std::uint32_t(-c)});
        i = j;
    }
    std::sort(merged.begin(), merged.end(), [](const auto& x, const auto& y) { return x[2] < y[2]; });
    std::vector<std::array<std::uint32_t, 2>> pieces;
    std::vector<int> weight;  // > 0, along the piece
    for (const auto& m : merged) pieces.push_back({m[0], m[1]}), weight.push_back(int(m[3]));
    // 2. Windings, with bands along y (rays along x) and along x (rays along y).
    const std::size_t np = pieces.size();
    const std::size_t nb = std::max<std::size_t>(1, std::size_t(std::sqrt(double(np))));
    std::vector<std::vector<std::uint32_t>> band_y(nb), band_x(nb);
    const double by = (hi_y - lo_y) / double(nb) * (1 + 1e-12) + 1e-300, bx = (hi_x - lo_x) / double(nb) * (1 + 1e-12) + 1e-300;
    auto band_of = [&](double v, double lo, double size) {
        return std::size_t(std::clamp((v - lo) / size, 0.0, double(nb - 1)));
    };
    for (std::uint32_t k = 0; k < np; ++k) {
        const p2 &a = pts[pieces[k][0]], &b = pts[pieces[k][1]];
        for (std::size_t i = band_of(std::min(a[1], b[1]), lo_y, by); i <= band_of(std::max(a[1], b[1]), lo_y, by); ++i)
            band_y[i].push_back(k);
        for (std::size_t i = band_of(std::min(a[0], b[0]), lo_x, bx); i <= band_of(std::max(a[0], b[0]), lo_x, bx); ++i)
            band_x[i].push_back(k);
    }
    // Winding of q by the ray along +x (swap: along +y, in swapped coordinates).
    auto winding = [&](const p2& q, std::uint32_t skip, bool swap) {
        const auto& band = swap ? band_x[band_of(q[0], lo_x, bx)] : band_y[band_of(q[1], lo_y, by)];
        auto sw = [&](const p2& p) { return swap ? p2{{p[1], p[0]}} : p; };
        const p2 qq = sw(q);
        int w = 0;
        for (const auto k : band) {
            if (k == skip) continue;
            const p2 a = sw(pts[pieces[k][0]]), b = sw(pts[pieces[k][1]]);
            if (a[1] <= qq[1] && qq[1] < b[1] && orient(a, b, qq) > 0) w += weight[k];
            else if (b[1] <= qq[1] && qq[1] < a[1] && orient(a, b, qq) < 0) w -= weight[k];
        }
        return swap ? -w : w;
    };
    std::vector<std::array<std::uint32_t, 2>> kept;
    for (std::uint32_t k = 0; k < np; ++k) {
        const p2 &a = pts[pieces[k][0]], &b = pts[pieces[k][1]];
        const p2 m = (a + b) / 2.0, d = b - a;
        const bool swap = std::abs(d[0]) > std::abs(d[1]);
        const int w = winding(m, k, swap);
        // The piece's own crossing: its weight on its left (see the header).
        const int c = weight[k];
        int left, right;
        const double along = swap ? d[0] : d[1];  // up in the ray's frame
        if (!swap) left = along > 0 ? w + c : w, right = along > 0 ? w : w - c;
        else left = along > 0 ? w : w + c, right = along > 0 ? w - c : w;
        if ((left != 0) == (right != 0)) continue;
        kept.push_back(left != 0 ? pieces[k] : std::array<std::uint32_t, 2>{pieces[k][1], pieces[k][0]});
    }
    // 3. Rings: at each vertex, the outgoing piece that turns most to the left.
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> out_of;
    for (std::uint32_t k = 0; k < kept.size(); ++k) out_of[kept[k][0]].push_back(k);
    std::vector<char> used(kept.size(), 0);
    std::vector<std::vector<p2>> outers, holes;
    for (std::uint32_t start = 0; start < kept.size(); ++start) {
        if (used[start]) continue;
        std::vector<p2> ring;
        std::uint32_t cur = start;
        used[cur] = 1;
        while (true) {
            ring.push_back(pts[kept[cur][0]]);
            const std::uint32_t v = kept[cur][1];
            if (v == kept[start][0]) break;
            const p2 back = pts[kept[cur][0]] - pts[v];
            const double base = std::atan2(back[1], back[0]);
            std::int64_t best = -1;
            double best_turn = 10;
            for (const auto k : out_of[v]) {
                if (used[k]) continue;
                const p2 d = pts[kept[k][1]] - pts[v];
                double turn = base - std::atan2(d[1], d[0]);  // clockwise angle from the way back
                while (turn <= 0) turn += 2 * std::numbers::pi;
                while (turn > 2 * std::numbers::pi) turn -= 2 * std::numbers::pi;
                if (turn < best_turn) best_turn = turn, best = k;
            }
            if (best < 0) break;  // an open chain (rounding): closed as it is
            cur = std::uint32_t(best);
            used[cur] = 1;
        }
        // Spikes (a, b, a) and repeated points out; slivers of no area dropped.
        std::vector<p2> clean;
        for (const auto& p : ring) {
            if (!clean.empty() && clean.back() == p) continue;
            if (clean.size() >= 2 && clean[clean.size() - 2] == p) {
                clean.pop_back();
                continue;
            }
            clean.push_back(p);
        }
        while (clean.size() >= 2 && clean.front() == clean.back()) clean.pop_back();
        if (clean.size() < 3) continue;
        const double area = ring_area(clean);
        if (!(std::abs(area) > 1e-24 * extent * extent)) continue;
        (area > 0 ? outers : holes).push_back(std::move(clean));
    }
    // 4. Each hole to the smallest outer ring around it.
    std::vector<ring_polygon> result(outers.size());
    std::vector<double> areas(outers.size());
    for (std::size_t i = 0; i < outers.size(); ++i) result[i].exterior = outers[i], areas[i] = ring_area(outers[i]);
    for (auto& h : holes) {
        // A point of the filled side of the hole's longest edge.
        std::size_t e = 0;
        double longest = -1;
        for (std::size_t i = 0; i < h.size(); ++i) {
            const double l = norm(h[(i + 1) % h.size()] - h[i]);
            if (l > longest) longest = l, e = i;
        }
        const p2 a = h[e], b = h[(e + 1) % h.size()], d = b - a;
        const p2 q = (a + b) / 2.0 + 1e-6 * p2{{-d[1], d[0]}};
        std::int64_t best = -1;
        for (std::size_t i = 0; i < outers.size(); ++i)
            if (inside_ring(outers[i], q) && (best < 0 || areas[i] < areas[std::size_t(best)])) best = std::int64_t(i);
        if (best >= 0) result[std::size_t(best)].holes.push_back(std::move(h));
    }
    return result;
}

}  // namespace crspline::detail
