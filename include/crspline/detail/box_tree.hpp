// crspline internal: a bounding-volume hierarchy over axis-aligned boxes,
// shared by the nearest-point index (one query against the tree) and the
// all-pairs steps of the intersection search and the certificate (the tree
// against itself: every pair of boxes that meet, in O(n log n + k) for k
// such pairs instead of n^2 / 2 tests).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "../vec.hpp"

namespace crspline::detail {

/// Axis-aligned box.
template <std::size_t D, class T>
struct box {
    vec<D, T> lo, hi;
};

template <std::size_t D, class T>
box<D, T> merge(const box<D, T>& a, const box<D, T>& b) noexcept {
    box<D, T> r = a;
    for (std::size_t k = 0; k < D; ++k) {
        r.lo[k] = std::min(r.lo[k], b.lo[k]);
        r.hi[k] = std::max(r.hi[k], b.hi[k]);
    }
    return r;
}

/// Do a and b meet when one of them is grown by pad on every side? The tree
/// applies this same test to unions of boxes; since a union's bounds are the
/// exact minimum and maximum of its members' and rounding of `x + pad` is
/// monotone in x, a pair of member boxes that meet always lies under a
/// pair of nodes that meet: the pruning never loses a pair.
template <std::size_t D, class T>
bool boxes_meet(const box<D, T>& a, const box<D, T>& b, T pad) noexcept {
    for (std::size_t k = 0; k < D; ++k)
        if (a.lo[k] > b.hi[k] + pad || b.lo[k] > a.hi[k] + pad) return false;
    return true;
}

/// Pairs of indices i < j as rows: row(i) lists the partners j > i of i in
/// increasing order, so iterating i, then row(i), visits the pairs in the
/// order of the nested loop `for i, for j > i`.
struct pair_rows {
    std::vector<std::size_t> offsets;         // n + 1 entries
    std::vector<std::uint32_t> partners;      // row i: partners[offsets[i], offsets[i + 1])
    std::span<const std::uint32_t> row(std::size_t i) const noexcept {
        return {partners.data() + offsets[i], offsets[i + 1] - offsets[i]};
    }
    std::size_t pair_count() const noexcept { return partners.size(); }
};

/// Rows from an unordered list of pairs {i, j} with i < j < n (each once).
inline pair_rows rows_of(std::size_t n, const std::vector<std::array<std::uint32_t, 2>>& pairs) {
    // 1. Counting sort on i.
    pair_rows r;
    r.offsets.assign(n + 1, 0);
    for (const auto& p : pairs) ++r.offsets[p[0] + 1];
    for (std::size_t i = 0; i < n; ++i) r.offsets[i + 1] += r.offsets[i];
    r.partners.resize(pairs.size());
    std::vector<std::size_t> fill(r.offsets.begin(), r.offsets.end() - 1);
    for (const auto& p : pairs) r.partners[fill[p[0]]++] = p[1];
    // 2. Each row in increasing j.
    for (std::size_t i = 0; i < n; ++i)
        std::sort(r.partners.begin() + std::ptrdiff_t(r.offsets[i]), r.partners.begin() + std::ptrdiff_t(r.offsets[i + 1]));
    return r;
}

/// A binary tree of boxes in one flat array: median split on the longest
/// axis of the box centres, up to leaf_size boxes per leaf. A leaf holds
/// items [first, first + count) of the leaf order; an inner node (count ==
/// 0) has children at its own index + 1 and at `second`. The caller checks
/// that the number of boxes fits in 32 bits.
template <std::size_t D, class T>
class box_tree {
public:
    using box_type = box<D, T>;
    static constexpr std::size_t leaf_size = 4;
    struct node {
        box_type bounds;
        std::uint32_t first = 0, count = 0, second = 0;
    };

    box_tree() = default;

    explicit box_tree(const std::vector<box_type>& boxes) {
        const std::size_t n = boxes.size();
        // 1. Every box's centre.
        std::vector<vec<D, T>> centres(n);
        order_.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            centres[i] = (boxes[i].lo + boxes[i].hi) / T(2);
            order_[i] = std::uint32_t(i);
        }
        // 2. The tree, built top down.
        if (n > 0) {
            nodes_.reserve(2 * (n / leaf_size + 1));
            build(boxes, centres, 0, n);
        }
        // 3. The boxes in leaf order, for a per-item test.
        boxes_.resize(n);
        for (std::size_t k = 0; k < n; ++k) boxes_[k] = boxes[order_[k]];
    }

    std::size_t size() const noexcept { return order_.size(); }
    const std::vector<node>& nodes() const noexcept { return nodes_; }
    /// The original index of the k-th item in leaf order, and its box.
    std::uint32_t item(std::size_t k) const noexcept { return order_[k]; }
    const box_type& item_box(std::size_t k) const noexcept { return boxes_[k]; }

    /// Calls f(i, j) with i < j once for every pair of boxes that meet
    /// within pad (boxes_meet), in no particular order: the tree against
    /// itself, descending only into pairs of nodes that meet.
    template <class F>
    void for_each_meeting_pair(T pad, F&& f) const {
        if (nodes_.empty()) return;
        auto report = [&](std::size_t k, std::size_t l) {
            if (boxes_meet(boxes_[k], boxes_[l], pad)) f(std::min(order_[k], order_[l]), std::max(order_[k], order_[l]));
        };
        std::vector<std::pair<std::uint32_t, std::uint32_t>> stack{{0, 0}};
        while (!stack.empty()) {
            const auto [a, b] = stack.back();
            stack.pop_back();
            const node& na = nodes_[a];
            const node& nb = nodes_[b];
            if (a == b) {
                // A node against itself: within a leaf, or each child with
                // itself and the two children with each other.
                if (na.count > 0) {
                    for (std::size_t k = na.first; k < na.first + na.count; ++k)
                        for (std::size_t l = k + 1; l < na.first + na.count; ++l) report(k, l);
                } else {
                    stack.push_back({a + 1, a + 1});
                    stack.push_back({na.second, na.second});
                    stack.push_back({a + 1, na.second});
                }
                continue;
            }
            if (!boxes_meet(na.bounds, nb.bounds, pad)) continue;
            if (na.count > 0 && nb.count > 0) {
                for (std::size_t k = na.first; k < na.first + na.count; ++k)
                    for (std::size_t l = nb.first; l < nb.first + nb.count; ++l) report(k, l);
                continue;
            }
            // Open the larger node (an inner one).
            const bool open_a = nb.count > 0 || (na.count == 0 && extent(na.bounds) >= extent(nb.bounds));
            if (open_a) {
                stack.push_back({a + 1, b});
                stack.push_back({na.second, b});
            } else {
                stack.push_back({a, b + 1});
                stack.push_back({a, nb.second});
            }
        }
    }

private:
    std::vector<node> nodes_;
    std::vector<std::uint32_t> order_;  // original indices in leaf order
    std::vector<box_type> boxes_;       // their boxes, in the same order

    static T extent(const box_type& b) noexcept {
        T s = 0;
        for (std::size_t k = 0; k < D; ++k) s += b.hi[k] - b.lo[k];
        return s;
    }

    std::uint32_t build(const std::vector<box_type>& boxes, const std::vector<vec<D, T>>& centres, std::size_t begin,
                        std::size_t end) {
        const std::uint32_t self = std::uint32_t(nodes_.size());
        nodes_.push_back({});
        // 1. The union of the boxes, and the extent of their centres.
        box_type b = boxes[order_[begin]];
        box_type c{centres[order_[begin]], centres[order_[begin]]};
        for (std::size_t k = begin + 1; k < end; ++k) {
            b = merge(b, boxes[order_[k]]);
            c = merge(c, box_type{centres[order_[k]], centres[order_[k]]});
        }
        nodes_[self].bounds = b;
        if (end - begin <= leaf_size) {
            nodes_[self].first = std::uint32_t(begin);
            nodes_[self].count = std::uint32_t(end - begin);
            return self;
        }
        // 2. Median split on the longest axis of the centres.
        std::size_t axis = 0;
        for (std::size_t k = 1; k < D; ++k)
            if (c.hi[k] - c.lo[k] > c.hi[axis] - c.lo[axis]) axis = k;
        const std::size_t mid = begin + (end - begin) / 2;
        std::nth_element(order_.begin() + std::ptrdiff_t(begin), order_.begin() + std::ptrdiff_t(mid),
                         order_.begin() + std::ptrdiff_t(end), [&](std::uint32_t x, std::uint32_t y) {
                             return centres[x][axis] != centres[y][axis] ? centres[x][axis] < centres[y][axis] : x < y;
                         });
        // 3. Children: the left one right after this node.
        build(boxes, centres, begin, mid);
        const std::uint32_t right = build(boxes, centres, mid, end);
        nodes_[self].second = right;
        return self;
    }
};

/// The pairs i < j of boxes that meet within pad, through the tree: the
/// candidate-pair step of find_intersections and of the certificate.
/// Exactly the pairs of the nested loop over all i < j that pass
/// boxes_meet, in the same order.
struct tree_pairs {
    template <std::size_t D, class T>
    pair_rows operator()(const std::vector<box<D, T>>& boxes, T pad) const {
        // Two walks of the tree: the first counts each row's pairs, the
        // second puts them in place (rows_of's counting sort without its
        // list of all pairs, 8 bytes a pair and twice that while it grew:
        // the largest thing a search of a long random walk held).
        const box_tree<D, T> tree(boxes);
        const std::size_t n = boxes.size();
        pair_rows r;
        r.offsets.assign(n + 1, 0);
        tree.for_each_meeting_pair(pad, [&](std::uint32_t i, std::uint32_t) { ++r.offsets[i + 1]; });
        for (std::size_t i = 0; i < n; ++i) r.offsets[i + 1] += r.offsets[i];
        r.partners.resize(r.offsets[n]);
        // offsets[i + 1] as row i's cursor: it starts at row i's first
        // place and ends at row i + 1's, where it belongs.
        for (std::size_t i = n; i > 0; --i) r.offsets[i] = r.offsets[i - 1];
        tree.for_each_meeting_pair(pad, [&](std::uint32_t i, std::uint32_t j) { r.partners[r.offsets[i + 1]++] = j; });
        for (std::size_t i = 0; i < n; ++i)
            std::sort(r.partners.begin() + std::ptrdiff_t(r.offsets[i]), r.partners.begin() + std::ptrdiff_t(r.offsets[i + 1]));
        return r;
    }
};

}  // namespace crspline::detail
