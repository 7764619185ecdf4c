// crspline::geo: invalid nesting of a polygon feature's rings in the input.
//
// smooth() keeps every relation between parts (no new crossing, and no
// vertex of one part in the region another part's smoothing sweeps: see
// smooth.hpp), so an output is as valid as its input. An input that is
// already invalid stays so; this finds where, so that the feature's verdict
// says it (verdict::nested) instead of passing it on silently. The rules
// are those of the OGC simple-features model as GEOS checks them, for a
// feature whose rings' roles are known (layer::part_roles):
// - "hole outside shell": an inner ring not inside its polygon's outer ring;
// - "nested holes": an inner ring inside another inner ring of its polygon;
// - "nested shells": the outer ring of one polygon inside another polygon of
//   the same feature (inside its outer ring and in none of its holes).
// Rings that cross or touch are the smoothing's verdicts' business
// (crosses, touches); here a ring is inside another when one of its
// vertices that is not on the other ring is inside it (the rings do not
// cross, or the verdict says so anyway).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "layer.hpp"

namespace crspline::geo {

namespace detail {

// Whether the point (x, y) is inside the closed ring given by xy[2 v0 ..
// 2 v1) (the last vertex may repeat the first): +1 inside, 0 outside, -1 on
// the ring. Crossing number with exact orientation signs of the double
// coordinates (a point on an edge is found by its zero cross product and
// its position between the edge's ends).
inline int point_in_ring(const std::vector<double>& xy, std::size_t v0, std::size_t v1, double x, double y) {
    bool inside = false;
    const std::size_t n = v1 - v0;
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t a = v0 + k, b = v0 + (k + 1 == n ? 0 : k + 1);
        const double ax = xy[2 * a], ay = xy[2 * a + 1], bx = xy[2 * b], by = xy[2 * b + 1];
        const double c = (bx - ax) * (y - ay) - (by - ay) * (x - ax);
        if (c == 0 && std::min(ax, bx) <= x && x <= std::max(ax, bx) && std::min(ay, by) <= y && y <= std::max(ay, by))
            return -1;
        if ((ay > y) != (by > y)) {
            // The edge crosses the horizontal line through the point: on
            // which side? The sign of c, oriented by the edge's direction.
            if ((c > 0) == (by > ay)) inside = !inside;
        }
    }
    return inside ? 1 : 0;
}

struct ring_ref {
    std::size_t part, index;  // layer part; index of the part in its feature
    std::size_t polygon;      // the outer ring's part
    bool outer;
    double lo[2], hi[2];
};

// Whether ring b lies inside ring a: its first vertex not on a is inside.
// Boxes first: b's box must be within a's.
inline bool ring_inside(const layer& l, const ring_ref& a, const ring_ref& b) {
    if (b.lo[0] < a.lo[0] || b.lo[1] < a.lo[1] || b.hi[0] > a.hi[0] || b.hi[1] > a.hi[1]) return false;
    const std::size_t a0 = l.part_offsets[a.part], a1 = l.part_offsets[a.part + 1];
    for (std::size_t v = l.part_offsets[b.part]; v < l.part_offsets[b.part + 1]; ++v) {
        const int r = point_in_ring(l.xy, a0, a1, l.xy[2 * v], l.xy[2 * v + 1]);
        if (r >= 0) return r == 1;
    }
    return false;  // every vertex on a: the same ring, a touch, not nesting
}

}  // namespace detail

/// For each feature, the first invalid nesting of its rings found, in
/// words naming the parts (their indices within the feature), or "" where
/// there is none or the roles are unknown. `skip[f]`: features not to look
/// at (invalid coordinates, degenerate parts). Rings with fewer than 3
/// vertices are left out.
inline std::vector<std::string> find_nesting(const layer& l, const std::vector<bool>& skip) {
    std::vector<std::string> out(l.feature_count);
    if (l.part_roles.empty()) return out;
    const std::size_t parts = l.part_count();
    // The rings of each feature, in order.
    std::size_t p = 0;
    std::vector<detail::ring_ref> rings;
    std::vector<std::size_t> index_in_feature(parts, 0);
    {
        std::vector<std::size_t> count(l.feature_count, 0);
        for (std::size_t q = 0; q < parts; ++q) index_in_feature[q] = count[l.part_features[q]]++;
    }
    while (p < parts) {
        const std::size_t f = l.part_features[p];
        std::size_t e = p;
        rings.clear();
        std::size_t polygon = SIZE_MAX;
        // A feature's parts are contiguous where the layer was built by
        // add_part feature by feature; others are looked at run by run.
        while (e < parts && l.part_features[e] == f) {
            const ring_role r = l.part_roles[e];
            if (r == ring_role::outer) polygon = e;
            if (r != ring_role::none && l.part_size(e) >= 3 && polygon != SIZE_MAX) {
                detail::ring_ref g{e, index_in_feature[e], polygon, r == ring_role::outer, {0, 0}, {0, 0}};
                const std::size_t v0 = l.part_offsets[e], v1 = l.part_offsets[e + 1];
                g.lo[0] = g.hi[0] = l.xy[2 * v0];
                g.lo[1] = g.hi[1] = l.xy[2 * v0 + 1];
                for (std::size_t v = v0; v < v1; ++v)
                    for (int k = 0; k < 2; ++k) {
                        g.lo[k] = std::min(g.lo[k], l.xy[2 * v + k]);
                        g.hi[k] = std::max(g.hi[k], l.xy[2 * v + k]);
                    }
                rings.push_back(g);
            }
            ++e;
        }
        if (skip[f] || !out[f].empty() || rings.size() < 2) {
            p = e;
            continue;
        }
        auto name = [&](const detail::ring_ref& g) {
            return "part " + std::to_string(g.index) + (g.outer ? " (an outer ring)" : " (an inner ring)");
        };
        std::string found;
        for (const auto& b : rings) {
            if (!found.empty()) break;
            if (!b.outer) {
                const detail::ring_ref* shell = nullptr;
                for (const auto& a : rings)
                    if (a.part == b.polygon) shell = &a;
                if (shell && !detail::ring_inside(l, *shell, b)) {
                    found = name(b) + " lies outside its outer ring, part " + std::to_string(shell->index);
                    break;
                }
                for (const auto& a : rings)
                    if (!a.outer && a.part != b.part && a.polygon == b.polygon && detail::ring_inside(l, a, b)) {
                        found = name(b) + " lies inside another inner ring of its polygon, part " +
                                std::to_string(a.index);
                        break;
                    }
                continue;
            }
            // An outer ring inside another polygon: inside its outer ring
            // and in none of its holes.
            for (const auto& a : rings) {
                if (!a.outer || a.part == b.part || !detail::ring_inside(l, a, b)) continue;
                bool in_hole = false;
                for (const auto& h : rings)
                    if (!h.outer && h.polygon == a.part && detail::ring_inside(l, h, b)) in_hole = true;
                if (!in_hole) {
                    found = name(b) + " lies inside the polygon of " + name(a) + " (nested shells)";
                    break;
                }
            }
        }
        out[f] = found;
        p = e;
    }
    return out;
}

}  // namespace crspline::geo
