// crspline::geo: a layer cut into arcs between junctions (the TopoJSON /
// mapshaper idea), so that a boundary two polygons share is one arc,
// smoothed once, and both rebuild their rings from the same polyline.
//
// Vertices are identified by their exact coordinates (x, y; -0 is 0). A
// vertex is a junction when its set of distinct neighbours along all
// parts' edges does not have exactly two members (where a shared boundary
// starts or ends, three or more boundaries meet, a ring touches itself, or
// a line ends), or when it is a line's end. Each part is cut at its
// junctions into arcs; the same vertex sequence met again (either way
// round) is the same arc. A ring with no junction is one closed arc.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <utility>
#include <vector>

namespace crspline::geo {

/// One arc: a run of distinct vertices (ids into topology::points).
struct arc {
    std::vector<std::size_t> vertices;  ///< ids; an open arc runs from a junction to a junction
    bool closed = false;                ///< a ring without junctions (the first vertex is not repeated)
    std::vector<std::size_t> source;    ///< layer vertex of each vertex, in the first part that made the arc (empty: clean_layer::with_sources false)
    std::size_t uses = 0;               ///< how many part traversals use it
    std::vector<std::size_t> features;  ///< the features that use it, each once, sorted
};

/// Vertex identities, arcs and junctions of a set of cleaned parts.
struct topology {
    std::vector<std::array<double, 2>> points;  ///< one per distinct vertex
    std::vector<std::uint8_t> junction;         ///< per vertex id
    std::vector<arc> arcs;
    /// Each input part given to build() rebuilt from arcs, each arc forward
    /// or reversed, in order: part q's (arc index, reversed) pairs are
    /// part_arc_list[part_arc_at[q] .. part_arc_at[q + 1]) (one array for
    /// all parts, not one per part: part_arcs(q) gives them).
    std::vector<std::pair<std::size_t, bool>> part_arc_list;
    std::vector<std::size_t> part_arc_at;
    std::span<const std::pair<std::size_t, bool>> part_arcs(std::size_t q) const noexcept {
        return {part_arc_list.data() + part_arc_at[q], part_arc_at[q + 1] - part_arc_at[q]};
    }
};

namespace detail {
struct point_key {
    std::uint64_t x, y;
    friend bool operator==(const point_key&, const point_key&) = default;
};
struct point_key_hash {
    std::size_t operator()(const point_key& k) const noexcept {
        std::uint64_t h = k.x * 0x9E3779B97F4A7C15ull;
        h ^= (k.y + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2));
        return std::size_t(h ^ (h >> 29));
    }
};
inline point_key key_of(double x, double y) noexcept {
    // -0 and +0 are the same place.
    if (x == 0) x = 0;
    if (y == 0) y = 0;
    point_key k{};
    std::memcpy(&k.x, &x, sizeof x);
    std::memcpy(&k.y, &y, sizeof y);
    return k;
}
}  // namespace detail

/// One cleaned part for build(): distinct consecutive vertices (a ring
/// without its closing repeat), the layer index of each, ring or line, and
/// the feature it belongs to.
struct clean_part {
    std::vector<std::array<double, 2>> points;
    std::vector<std::size_t> source;
    bool ring = false;
    std::size_t feature = 0;
};

/// Cleaned parts in flat arrays, one of each for the whole layer (not two
/// blocks per part: at 10^6 parts, freeing those scattered blocks cost more
/// than filling them). Part q's points and sources are [at[q], at[q + 1]).
/// Without sources (with_sources false: a layer without extra values has
/// nothing to interpolate from them) none are kept, and the arcs have none.
struct clean_layer {
    std::vector<std::array<double, 2>> points;
    std::vector<std::size_t> source;
    std::vector<std::size_t> at{0};
    std::vector<std::uint8_t> ring;
    std::vector<std::size_t> feature;
    bool with_sources = true;

    std::size_t size() const noexcept { return ring.size(); }
    std::size_t size_of(std::size_t q) const noexcept { return at[q + 1] - at[q]; }
    std::span<const std::array<double, 2>> points_of(std::size_t q) const noexcept {
        return {points.data() + at[q], size_of(q)};
    }
    std::span<const std::size_t> source_of(std::size_t q) const noexcept {
        if (!with_sources) return {};
        return {source.data() + at[q], size_of(q)};
    }
    void add(const clean_part& c) {
        points.insert(points.end(), c.points.begin(), c.points.end());
        if (with_sources) source.insert(source.end(), c.source.begin(), c.source.end());
        at.push_back(points.size());
        ring.push_back(c.ring);
        feature.push_back(c.feature);
    }
};

namespace detail {
// build_topology() with vertex ids held as Id (32 bits where they fit:
// half the memory of size_t, all of it fresh pages at 10^6 lines).
template <class Id>
topology build_topology_with(const clean_layer& parts, bool share) {
    topology topo;
    const std::size_t total = parts.points.size();
    topo.points.reserve(share ? 0 : total);
    // Every part's vertex ids, in one array (part q's from ids_at[q]).
    std::vector<Id> ids(total);
    const std::vector<std::size_t>& ids_at = parts.at;
    if (share) {
        // Vertex ids by exact coordinates, in order of first occurrence: an
        // open-addressing table (a power of two at least twice the
        // vertices, probed linearly) whose slots hold an id in their low
        // 40 bits (10^12 vertices: 16 TB of coordinates) and 24 more bits
        // of the key's hash above, so a probe
        // reads the point of a slot's id only when those bits agree (most
        // probes at a full slot are other points: they cost no second
        // random read). The slot of the vertex a few ahead is prefetched:
        // at 10^7 vertices and more the table is far larger than the caches.
        constexpr std::uint64_t empty = ~std::uint64_t(0), id_mask = (std::uint64_t(1) << 40) - 1;
        std::size_t cap = 16;
        int bits = 4;
        while (cap < 2 * total) cap *= 2, ++bits;
        std::vector<std::uint64_t> table(cap, empty);
        const std::size_t mask = cap - 1;
        topo.points.reserve(total);
        const detail::point_key_hash hasher;
        auto mixed_of = [&](const std::array<double, 2>& p) {
            // The hash's top bits (Fibonacci hashing): round coordinates
            // have low mantissa bits that are all zero.
            return std::uint64_t(hasher(detail::key_of(p[0], p[1]))) * 0x9E3779B97F4A7C15ull;
        };
        auto slot_of = [&](std::uint64_t mixed) { return std::size_t(mixed >> (64 - bits)) & mask; };
        auto tag_of = [](std::uint64_t mixed) { return (mixed & 0xFFFFFFull) << 40; };
        // The vertex `ahead` places on in the running order over every
        // part's vertices, across part ends (parts of 10-50 vertices would
        // otherwise start with several unprefetched, serialized misses).
        constexpr std::size_t ahead = 16;
        std::size_t v = 0;  // running index over every part's vertices
        for (std::size_t q = 0; q < parts.size(); ++q) {
            const auto pts = parts.points_of(q);
            const std::size_t n = pts.size();
            for (std::size_t i = 0; i < n; ++i, ++v) {
#if defined(__GNUC__) || defined(__clang__)
                if (v + ahead < total) __builtin_prefetch(&table[slot_of(mixed_of(parts.points[v + ahead]))]);
#endif
                const std::array<double, 2>& p = pts[i];
                const detail::point_key k = detail::key_of(p[0], p[1]);
                const std::uint64_t mixed = mixed_of(p), tag = tag_of(mixed);
                for (std::size_t h = slot_of(mixed);; h = (h + 1) & mask) {
                    const std::uint64_t e = table[h];
                    if (e == empty) {
                        const std::size_t id = topo.points.size();
                        table[h] = tag | std::uint64_t(id);
                        topo.points.push_back(p);
                        ids[v] = Id(id);
                        break;
                    }
                    if ((e & ~id_mask) == tag) {
                        const std::size_t id = std::size_t(e & id_mask);
                        const auto& o = topo.points[id];
                        if (detail::key_of(o[0], o[1]) == k) {
                            ids[v] = Id(id);
                            break;
                        }
                    }
                }
            }
        }
        topo.points.shrink_to_fit();
    } else {
        for (const auto& p : parts.points) {
            ids[topo.points.size()] = Id(topo.points.size());
            topo.points.push_back(p);
        }
    }
    // Junctions: a vertex whose distinct neighbours are not exactly two, or
    // a line's end. Neighbours are few: a small sorted list per vertex.
    const std::size_t nv = topo.points.size();
    topo.junction.assign(nv, 0);
    auto ends = [&](std::size_t q) {
        if (!parts.ring[q]) topo.junction[ids[ids_at[q]]] = topo.junction[ids[ids_at[q + 1] - 1]] = 1;
    };
    if (share) {
        // Up to 3 neighbours kept per vertex (3 means "more than 2"), as
        // 32-bit ids where they fit (half the memory of size_t).
        auto find_junctions = [&](auto id_type) {
            using nb_id = decltype(id_type);
            constexpr nb_id none = std::numeric_limits<nb_id>::max();
            std::vector<std::array<nb_id, 3>> nb(nv, {none, none, none});
            auto link = [&](std::size_t a, std::size_t b) {
                auto& s = nb[a];
                for (std::size_t k = 0; k < 3; ++k) {
                    if (s[k] == nb_id(b)) return;
                    if (s[k] == none) {
                        s[k] = nb_id(b);
                        return;
                    }
                }
            };
            for (std::size_t q = 0; q < parts.size(); ++q) {
                const Id* ids_q = ids.data() + ids_at[q];
                const std::size_t n = ids_at[q + 1] - ids_at[q];
                const std::size_t edges = parts.ring[q] ? n : n - 1;
                for (std::size_t i = 0; i < edges; ++i) {
                    const std::size_t a = ids_q[i], b = ids_q[i + 1 == n ? 0 : i + 1];
                    link(a, b);
                    link(b, a);
                }
                ends(q);
            }
            for (std::size_t x = 0; x < nv; ++x)
                if (nb[x][2] != none || nb[x][1] == none) topo.junction[x] = 1;
        };
        if (nv < std::numeric_limits<std::uint32_t>::max()) find_junctions(std::uint32_t{});
        else find_junctions(std::size_t{});
    } else {
        for (std::size_t q = 0; q < parts.size(); ++q) ends(q);
    }
    // Arcs, each vertex sequence once (in a canonical direction): found by
    // a hash of the sequence (an open-addressing table of (hash, arc),
    // doubled when half full), then compared. Without sharing every part's
    // ids are its own, so no two sequences can be equal: no lookup.
    std::size_t seen_cap = 64;
    while (seen_cap < 2 * parts.size()) seen_cap *= 2;
    std::vector<std::pair<std::uint64_t, std::size_t>> seen(share ? seen_cap : 0, {0, SIZE_MAX});
    std::size_t seen_count = 0;
    auto hash_of = [](const std::vector<std::size_t>& seq, bool closed) {
        std::uint64_t h = closed ? 0x9E3779B97F4A7C15ull : 0x632BE59BD9B4E019ull;
        for (std::size_t v : seq) h = (h ^ std::uint64_t(v)) * 0x100000001B3ull + (h >> 29);
        return h;
    };
    auto seen_slot = [&](std::uint64_t h) { return std::size_t((h * 0x9E3779B97F4A7C15ull) >> 32) & (seen.size() - 1); };
    auto seen_insert = [&](std::uint64_t h, std::size_t index) {
        std::size_t k = seen_slot(h);
        while (seen[k].second != SIZE_MAX) k = (k + 1) & (seen.size() - 1);
        seen[k] = {h, index};
    };
    topo.part_arc_at.assign(parts.size() + 1, 0);
    topo.part_arc_list.reserve(parts.size());
    topo.arcs.reserve(parts.size());
    auto add_arc = [&](std::size_t q, std::vector<std::size_t> seq, std::vector<std::size_t> src, bool closed) {
        bool reversed = false;
        if (closed) {
            // Canonical: start at the smallest id, go towards the smaller neighbour.
            const std::size_t n = seq.size();
            const std::size_t m = std::size_t(std::min_element(seq.begin(), seq.end()) - seq.begin());
            std::rotate(seq.begin(), seq.begin() + std::ptrdiff_t(m), seq.end());
            if (!src.empty()) std::rotate(src.begin(), src.begin() + std::ptrdiff_t(m), src.end());
            if (seq[n - 1] < seq[1]) {
                std::reverse(seq.begin() + 1, seq.end());
                if (!src.empty()) std::reverse(src.begin() + 1, src.end());
                reversed = true;
            }
        } else {
            // Reversed if the reversed sequence is lexicographically smaller.
            const std::size_t n = seq.size();
            std::size_t i = 0;
            while (i < n && seq[n - 1 - i] == seq[i]) ++i;
            if (i < n && seq[n - 1 - i] < seq[i]) {
                std::reverse(seq.begin(), seq.end());
                std::reverse(src.begin(), src.end());
                reversed = true;
            }
        }
        std::size_t index = topo.arcs.size();
        if (share) {
            const std::uint64_t h = hash_of(seq, closed);
            for (std::size_t k = seen_slot(h); seen[k].second != SIZE_MAX; k = (k + 1) & (seen.size() - 1))
                if (seen[k].first == h && topo.arcs[seen[k].second].closed == closed &&
                    topo.arcs[seen[k].second].vertices == seq) {
                    index = seen[k].second;
                    break;
                }
            if (index == topo.arcs.size()) {
                if (2 * (seen_count + 1) > seen.size()) {
                    std::vector<std::pair<std::uint64_t, std::size_t>> old(2 * seen.size(), {0, SIZE_MAX});
                    old.swap(seen);
                    for (const auto& e : old)
                        if (e.second != SIZE_MAX) seen_insert(e.first, e.second);
                }
                seen_insert(h, index);
                ++seen_count;
            }
        }
        if (index == topo.arcs.size()) topo.arcs.push_back({std::move(seq), closed, std::move(src), 0, {}});
        arc& a = topo.arcs[index];
        ++a.uses;
        auto pos = std::lower_bound(a.features.begin(), a.features.end(), parts.feature[q]);
        if (pos == a.features.end() || *pos != parts.feature[q]) a.features.insert(pos, parts.feature[q]);
        topo.part_arc_list.push_back({index, reversed});
    };
    // Vertices [i, j] (indices into the part, cyclically for a ring) as an arc.
    auto cut = [&](std::size_t q, std::size_t i, std::size_t j) {
        const Id* s = ids.data() + ids_at[q];
        const auto src = parts.source_of(q);
        // A ring with one junction is one arc from it round to it again.
        const std::size_t n = ids_at[q + 1] - ids_at[q], m = (j + n - i) % n == 0 ? n + 1 : (j + n - i) % n + 1;
        std::vector<std::size_t> seq(m), ssrc(src.empty() ? 0 : m);
        for (std::size_t k = 0, x = i; k < m; ++k, x = x + 1 == n ? 0 : x + 1) {
            seq[k] = s[x];
            if (!src.empty()) ssrc[k] = src[x];
        }
        add_arc(q, std::move(seq), std::move(ssrc), false);
    };
    for (std::size_t q = 0; q < parts.size(); ++q) {
        const Id* s = ids.data() + ids_at[q];
        const std::size_t n = ids_at[q + 1] - ids_at[q];
        if (parts.ring[q]) {
            std::size_t first = n;
            for (std::size_t i = 0; i < n; ++i)
                if (topo.junction[s[i]]) {
                    first = i;
                    break;
                }
            if (first == n) {
                const auto src = parts.source_of(q);
                add_arc(q, std::vector<std::size_t>(s, s + n), std::vector<std::size_t>(src.begin(), src.end()), true);
                topo.part_arc_at[q + 1] = topo.part_arc_list.size();
                continue;
            }
            // From the first junction round to it again, cut at each junction.
            std::size_t from = first;
            for (std::size_t k = 1; k <= n; ++k) {
                const std::size_t i = (first + k) % n;
                if (topo.junction[s[i]]) {
                    cut(q, from, i);
                    from = i;
                }
            }
        } else {
            std::size_t from = 0;
            for (std::size_t i = 1; i < n; ++i)
                if (topo.junction[s[i]]) {
                    cut(q, from, i);
                    from = i;
                }
        }
        topo.part_arc_at[q + 1] = topo.part_arc_list.size();
    }
    return topo;
}
}  // namespace detail

/// Cuts the parts into arcs. With `share` false every part is one arc of
/// its own (no junctions, nothing shared): smoothing part by part.
inline topology build_topology(const clean_layer& parts, bool share) {
    if (parts.points.size() < std::numeric_limits<std::uint32_t>::max())
        return detail::build_topology_with<std::uint32_t>(parts, share);
    return detail::build_topology_with<std::size_t>(parts, share);
}

/// The same from one cleaned part per element.
inline topology build_topology(const std::vector<clean_part>& parts, bool share) {
    clean_layer flat;
    for (const auto& part : parts) flat.add(part);
    return build_topology(flat, share);
}

}  // namespace crspline::geo
