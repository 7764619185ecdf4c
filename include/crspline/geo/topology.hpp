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
#include <unordered_map>
#include <utility>
#include <vector>

namespace crspline::geo {

/// One arc: a run of distinct vertices (ids into topology::points).
struct arc {
    std::vector<std::size_t> vertices;  ///< ids; an open arc runs from a junction to a junction
    bool closed = false;                ///< a ring without junctions (the first vertex is not repeated)
    std::vector<std::size_t> source;    ///< layer vertex of each vertex, in the first part that made the arc
    std::size_t uses = 0;               ///< how many part traversals use it
    std::vector<std::size_t> features;  ///< the features that use it, each once, sorted
};

/// A part rebuilt from arcs: each arc forward or reversed, in order.
struct part_arcs {
    std::vector<std::pair<std::size_t, bool>> arcs;  ///< (arc index, reversed)
};

/// Vertex identities, arcs and junctions of a set of cleaned parts.
struct topology {
    std::vector<std::array<double, 2>> points;  ///< one per distinct vertex
    std::vector<std::uint8_t> junction;         ///< per vertex id
    std::vector<arc> arcs;
    std::vector<part_arcs> parts;               ///< per input part given to build()
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

/// Cuts the parts into arcs. With `share` false every part is one arc of
/// its own (no junctions, nothing shared): smoothing part by part.
inline topology build_topology(const std::vector<clean_part>& parts, bool share) {
    topology topo;
    std::size_t total = 0;
    for (const auto& part : parts) total += part.points.size();
    // Vertex ids by exact coordinates: an open-addressing table of ids (a
    // power of two at least twice the vertices, probed linearly), so no
    // allocation per vertex; ids in order of first occurrence.
    std::vector<detail::point_key> keys;
    std::vector<std::size_t> table;
    std::size_t mask = 0;
    int bits = 4;
    if (share) {
        std::size_t cap = 16;
        while (cap < 2 * total) cap *= 2, ++bits;
        table.assign(cap, SIZE_MAX);
        mask = cap - 1;
        keys.reserve(total);
        topo.points.reserve(total);
    }
    detail::point_key_hash hasher;
    auto id_of = [&](const std::array<double, 2>& p) {
        const detail::point_key k = detail::key_of(p[0], p[1]);
        // The hash's top bits (Fibonacci hashing): round coordinates have
        // low mantissa bits that are all zero.
        const std::uint64_t mixed = std::uint64_t(hasher(k)) * 0x9E3779B97F4A7C15ull;
        for (std::size_t h = std::size_t(mixed >> (64 - bits)) & mask;; h = (h + 1) & mask) {
            const std::size_t id = table[h];
            if (id == SIZE_MAX) {
                table[h] = topo.points.size();
                keys.push_back(k);
                topo.points.push_back(p);
                return table[h];
            }
            if (keys[id] == k) return id;
        }
    };
    std::vector<std::vector<std::size_t>> part_ids(parts.size());
    for (std::size_t q = 0; q < parts.size(); ++q) {
        part_ids[q].reserve(parts[q].points.size());
        for (const auto& p : parts[q].points) {
            if (share) {
                part_ids[q].push_back(id_of(p));
            } else {
                part_ids[q].push_back(topo.points.size());
                topo.points.push_back(p);
            }
        }
    }
    // Junctions: a vertex whose distinct neighbours are not exactly two, or
    // a line's end. Neighbours are few: a small sorted list per vertex.
    const std::size_t nv = topo.points.size();
    topo.junction.assign(nv, 0);
    if (share) {
        std::vector<std::array<std::size_t, 3>> nb(nv, {SIZE_MAX, SIZE_MAX, SIZE_MAX});  // up to 3 kept: 3 means "more than 2"
        auto link = [&](std::size_t a, std::size_t b) {
            auto& s = nb[a];
            for (std::size_t k = 0; k < 3; ++k) {
                if (s[k] == b) return;
                if (s[k] == SIZE_MAX) {
                    s[k] = b;
                    return;
                }
            }
        };
        for (std::size_t q = 0; q < parts.size(); ++q) {
            const auto& ids_q = part_ids[q];
            const std::size_t n = ids_q.size();
            const std::size_t edges = parts[q].ring ? n : n - 1;
            for (std::size_t i = 0; i < edges; ++i) {
                const std::size_t a = ids_q[i], b = ids_q[(i + 1) % n];
                link(a, b);
                link(b, a);
            }
            if (!parts[q].ring) topo.junction[ids_q.front()] = topo.junction[ids_q.back()] = 1;
        }
        for (std::size_t v = 0; v < nv; ++v)
            if (nb[v][2] != SIZE_MAX || nb[v][1] == SIZE_MAX) topo.junction[v] = 1;
    } else {
        for (std::size_t q = 0; q < parts.size(); ++q)
            if (!parts[q].ring) topo.junction[part_ids[q].front()] = topo.junction[part_ids[q].back()] = 1;
    }
    // Arcs, each vertex sequence once (in a canonical direction): found by
    // a hash of the sequence, then compared. Without sharing every part's
    // ids are its own, so no two sequences can be equal: no lookup.
    std::unordered_multimap<std::uint64_t, std::size_t> seen;
    auto hash_of = [](const std::vector<std::size_t>& seq, bool closed) {
        std::uint64_t h = closed ? 0x9E3779B97F4A7C15ull : 0x632BE59BD9B4E019ull;
        for (std::size_t v : seq) h = (h ^ std::uint64_t(v)) * 0x100000001B3ull + (h >> 29);
        return h;
    };
    topo.parts.resize(parts.size());
    auto add_arc = [&](std::size_t q, std::vector<std::size_t> seq, std::vector<std::size_t> src, bool closed) {
        bool reversed = false;
        if (closed) {
            // Canonical: start at the smallest id, go towards the smaller neighbour.
            const std::size_t n = seq.size();
            const std::size_t m = std::size_t(std::min_element(seq.begin(), seq.end()) - seq.begin());
            std::rotate(seq.begin(), seq.begin() + std::ptrdiff_t(m), seq.end());
            std::rotate(src.begin(), src.begin() + std::ptrdiff_t(m), src.end());
            if (seq[n - 1] < seq[1]) {
                std::reverse(seq.begin() + 1, seq.end());
                std::reverse(src.begin() + 1, src.end());
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
            auto [lo, hi] = seen.equal_range(h);
            for (auto it = lo; it != hi; ++it)
                if (topo.arcs[it->second].closed == closed && topo.arcs[it->second].vertices == seq) {
                    index = it->second;
                    break;
                }
            if (index == topo.arcs.size()) seen.emplace(h, index);
        }
        if (index == topo.arcs.size()) topo.arcs.push_back({std::move(seq), closed, std::move(src), 0, {}});
        arc& a = topo.arcs[index];
        ++a.uses;
        auto pos = std::lower_bound(a.features.begin(), a.features.end(), parts[q].feature);
        if (pos == a.features.end() || *pos != parts[q].feature) a.features.insert(pos, parts[q].feature);
        topo.parts[q].arcs.push_back({index, reversed});
    };
    for (std::size_t q = 0; q < parts.size(); ++q) {
        const auto& s = part_ids[q];
        const auto& src = parts[q].source;
        const std::size_t n = s.size();
        if (parts[q].ring) {
            std::size_t first = n;
            for (std::size_t i = 0; i < n; ++i)
                if (topo.junction[s[i]]) {
                    first = i;
                    break;
                }
            if (first == n) {
                add_arc(q, s, src, true);
                continue;
            }
            // From the first junction round to it again, cut at each junction.
            std::vector<std::size_t> seq{s[first]}, ssrc{src[first]};
            for (std::size_t k = 1; k <= n; ++k) {
                const std::size_t i = (first + k) % n;
                seq.push_back(s[i]);
                ssrc.push_back(src[i]);
                if (topo.junction[s[i]]) {
                    add_arc(q, std::move(seq), std::move(ssrc), false);
                    seq = {s[i]};
                    ssrc = {src[i]};
                }
            }
        } else {
            std::vector<std::size_t> seq{s[0]}, ssrc{src[0]};
            for (std::size_t i = 1; i < n; ++i) {
                seq.push_back(s[i]);
                ssrc.push_back(src[i]);
                if (topo.junction[s[i]]) {
                    add_arc(q, std::move(seq), std::move(ssrc), false);
                    seq = {s[i]};
                    ssrc = {src[i]};
                }
            }
        }
    }
    return topo;
}

}  // namespace crspline::geo
