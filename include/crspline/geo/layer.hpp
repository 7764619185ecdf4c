// crspline::geo: a layer of lines and polygon rings, as the smoothing sees it.
//
// A layer is flat arrays, the shape GIS formats and NumPy hand over:
// every vertex's x, y (and optional extra values such as Z and M), parts
// as ranges of vertices (a line or a ring), each part belonging to a
// feature. A feature is one row of the user's table (a polygon with its
// holes, a multi-polygon, a line, a multi-line); the smoothing reports per
// feature, never dropping one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "../error.hpp"

namespace crspline::geo {

/// What a part is: an open line or a closed ring (the first vertex may be
/// repeated at the end, as GIS formats do; it need not be).
enum class part_kind : std::uint8_t { line = 0, ring = 1 };

/// What a ring is in its polygon, where the caller knows (GeoJSON, Shapely):
/// an outer ring (a shell) starts a polygon, an inner ring (a hole) belongs
/// to the nearest outer ring before it in the same feature. Lines, and
/// rings of unknown role, are `none`. Used to report invalid nesting in the
/// input (geo/nesting.hpp); the smoothing itself keeps every relation.
enum class ring_role : std::uint8_t { none = 0, outer = 1, inner = 2 };

/// Lines and rings in flat arrays.
struct layer {
    std::size_t extra_dims = 0;                 ///< values per vertex beyond x and y (Z, M, ...)
    std::vector<double> xy;                     ///< x0, y0, x1, y1, ...
    std::vector<double> extra;                  ///< extra_dims values per vertex
    std::vector<std::size_t> part_offsets{0};   ///< part p: vertices [part_offsets[p], part_offsets[p + 1])
    std::vector<part_kind> part_kinds;          ///< one per part
    std::vector<std::size_t> part_features;     ///< the feature of each part, < feature_count
    std::size_t feature_count = 0;              ///< features may have no part (empty geometries)
    std::vector<ring_role> part_roles;          ///< one per part, or empty (roles unknown)

    std::size_t vertex_count() const noexcept { return xy.size() / 2; }
    std::size_t part_count() const noexcept { return part_kinds.size(); }
    std::size_t part_size(std::size_t p) const noexcept { return part_offsets[p + 1] - part_offsets[p]; }

    /// Appends a part of feature `feature` (feature_count grows to hold it):
    /// `xy` holds 2 values per vertex, `extra` extra_dims per vertex.
    void add_part(std::size_t feature, part_kind kind, std::span<const double> xy_values,
                  std::span<const double> extra_values = {}, ring_role role = ring_role::none) {
        if (xy_values.size() % 2 != 0)
            throw invalid_input("part " + std::to_string(part_count()) + ": xy has " +
                                std::to_string(xy_values.size()) + " values, not 2 per vertex");
        const std::size_t n = xy_values.size() / 2;
        if (extra_values.size() != n * extra_dims)
            throw invalid_input("part " + std::to_string(part_count()) + ": extra has " +
                                std::to_string(extra_values.size()) + " values, expected " +
                                std::to_string(n * extra_dims) + " (" + std::to_string(extra_dims) +
                                " per vertex)");
        xy.insert(xy.end(), xy_values.begin(), xy_values.end());
        extra.insert(extra.end(), extra_values.begin(), extra_values.end());
        part_offsets.push_back(part_offsets.back() + n);
        if (role != ring_role::none || !part_roles.empty()) {  // roles kept from the first one given
            part_roles.resize(part_kinds.size(), ring_role::none);
            part_roles.push_back(role);
        }
        part_kinds.push_back(kind);
        part_features.push_back(feature);
        if (feature >= feature_count) feature_count = feature + 1;
    }
};

/// Throws invalid_input, naming the field and index, unless the arrays of
/// the layer agree with each other. (Coordinates are checked per feature by
/// the smoothing: a bad one makes its feature `invalid`, not the call fail.)
inline void check_layer(const layer& l) {
    if (l.xy.size() % 2 != 0)
        throw invalid_input("xy has " + std::to_string(l.xy.size()) + " values, not 2 per vertex");
    const std::size_t n = l.vertex_count();
    if (l.extra.size() != n * l.extra_dims)
        throw invalid_input("extra has " + std::to_string(l.extra.size()) + " values, expected " +
                            std::to_string(n * l.extra_dims) + " (" + std::to_string(l.extra_dims) +
                            " per vertex for " + std::to_string(n) + " vertices)");
    const std::size_t parts = l.part_kinds.size();
    if (l.part_offsets.size() != parts + 1)
        throw invalid_input("part_offsets has " + std::to_string(l.part_offsets.size()) + " values, expected " +
                            std::to_string(parts + 1) + " (one per part and one more)");
    if (l.part_features.size() != parts)
        throw invalid_input("part_features has " + std::to_string(l.part_features.size()) + " values, expected " +
                            std::to_string(parts) + " (one per part)");
    if (l.part_offsets[0] != 0)
        throw invalid_input("part_offsets[0] must be 0, got " + std::to_string(l.part_offsets[0]));
    for (std::size_t p = 0; p < parts; ++p) {
        if (l.part_offsets[p + 1] < l.part_offsets[p])
            throw invalid_input("part_offsets[" + std::to_string(p + 1) + "] = " +
                                std::to_string(l.part_offsets[p + 1]) + " is less than part_offsets[" +
                                std::to_string(p) + "] = " + std::to_string(l.part_offsets[p]));
        if (l.part_features[p] >= l.feature_count)
            throw invalid_input("part_features[" + std::to_string(p) + "] = " + std::to_string(l.part_features[p]) +
                                " is not below feature_count " + std::to_string(l.feature_count));
        if (l.part_kinds[p] != part_kind::line && l.part_kinds[p] != part_kind::ring)
            throw invalid_input("part_kinds[" + std::to_string(p) + "] = " +
                                std::to_string(int(l.part_kinds[p])) + " is neither line (0) nor ring (1)");
    }
    if (!l.part_roles.empty()) {
        if (l.part_roles.size() != parts)
            throw invalid_input("part_roles has " + std::to_string(l.part_roles.size()) + " values, expected " +
                                std::to_string(parts) + " (one per part) or none");
        for (std::size_t p = 0; p < parts; ++p) {
            const auto r = l.part_roles[p];
            if (r != ring_role::none && r != ring_role::outer && r != ring_role::inner)
                throw invalid_input("part_roles[" + std::to_string(p) + "] = " + std::to_string(int(r)) +
                                    " is neither none (0), outer (1) nor inner (2)");
            if (r != ring_role::none && l.part_kinds[p] != part_kind::ring)
                throw invalid_input("part_roles[" + std::to_string(p) + "]: a line has no ring role");
            if (r == ring_role::inner) {
                std::size_t q = p;
                while (q > 0 && l.part_features[q - 1] == l.part_features[p] && l.part_roles[q - 1] == ring_role::inner) --q;
                if (q == 0 || l.part_features[q - 1] != l.part_features[p] || l.part_roles[q - 1] != ring_role::outer)
                    throw invalid_input("part_roles[" + std::to_string(p) +
                                        "]: an inner ring must follow an outer ring of the same feature");
            }
        }
    }
    if (l.part_offsets[parts] != n)
        throw invalid_input("part_offsets ends at " + std::to_string(l.part_offsets[parts]) + ", not at the " +
                            std::to_string(n) + " vertices of xy");
}

}  // namespace crspline::geo
