// crspline: the knot index, which segment owns a parameter t.
//
// A bucket table over the domain [g[0], g[nseg]]: one bucket per segment,
// each listing the few segments that can own a t falling in it. Locating t
// is then O(1) on average, counted without a branch; a branch-free binary
// search finishes the rare crowded bucket (O(log N) at worst, for very
// uneven knots). catmull_rom::locate() is the public face; the batch
// kernels (batch_kernels.hpp) use the table directly, hoisted out of their
// loops.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

#include "../error.hpp"
#include "storage.hpp"

namespace crspline::detail {

template <class T>
class knot_index {
public:
    /// Builds the table over the knots g[0 .. nseg] (nondecreasing, nseg >= 1).
    /// Throws invalid_input when nseg does not fit the table's 32-bit entries.
    void build(const T* g, std::size_t nseg) {
        // One bucket per segment. Segment i starts in bucket b(i) computed with
        // the same arithmetic as locate(), so monotonicity gives: every segment
        // with b(i) < b starts at or before any t in bucket b, none with b(i) > b
        // does. The owner of t is thus between the last segment starting before
        // bucket b and the last one starting in it.
        if (nseg >= std::numeric_limits<std::uint32_t>::max())
            throw invalid_input("too many segments (" + std::to_string(nseg) + ")");
        const T span = g[nseg] - g[0];
        const std::size_t nb = nseg;
        scale_ = span > 0 ? T(nb) / span : T(0);
        max_ = T(nb - 1);
        if (!std::isfinite(scale_)) scale_ = 0;
        // Count the segments starting in each bucket (count of bucket b at
        // [b + 1]), then turn the counts into indices in place: no branch on
        // the data, no temporary.
        first_.assign(nb + 1, 0);
        for (std::size_t i = 0; i < nseg; ++i) ++first_[bucket_of(g[i], g[0], scale_, max_) + 1];
        // first_[b] = last segment starting before bucket b (or 0);
        // first_[b + 1] = last segment starting in or before bucket b.
        std::size_t before = 0;  // segments starting in buckets < b
        for (std::size_t b = 0; b < nb; ++b) {
            const std::size_t count = first_[b + 1];
            first_[b] = std::uint32_t(before > 0 ? before - 1 : 0);
            before += count;
        }
        first_[nb] = std::uint32_t(nseg - 1);
    }

    /// Index of the segment of the knots g[0 .. nseg] (those the table was
    /// built on) that owns t, clamped to the first and last segment (NaN
    /// gives the first).
    std::size_t locate(T t, const T* g, std::size_t nseg) const noexcept {
        return locate_in(t, g, nseg, first_.data(), scale_, max_);
    }

    // The table, for kernels that hoist it out of their loops.
    const std::uint32_t* first() const noexcept { return first_.data(); }
    T scale() const noexcept { return scale_; }
    T bucket_max() const noexcept { return max_; }

    // locate() on explicit arrays: knots g[0..nseg], the bucket table, its
    // scale and last index. The bucket of t: floor((t - t_min) * scale)
    // clamped to [0, bmax]. The same arithmetic for knots (build) and
    // queries, and monotone in t.
    static std::size_t bucket_of(T t, T t_min, T scale, T bmax) noexcept {
        T x = (t - t_min) * scale;
        x = x > T(0) ? x : T(0);  // also maps NaN to 0
        x = x < bmax ? x : bmax;
        return std::size_t(std::int64_t(x));  // 0 <= x < 2^32: no unsigned-conversion branch
    }

    static std::size_t locate_in(T t, const T* g, std::size_t nseg, const std::uint32_t* first, T scale,
                                 T bmax) noexcept {
        const std::size_t b = bucket_of(t, g[0], scale, bmax);
        const std::size_t lo = first[b], hi = first[b + 1];
        // The owner is the last i in [lo, hi] with g[i] <= t (g[lo] <= t
        // holds by construction, or t is before the start or NaN and lo = 0).
        if (hi - lo <= 3) {
            // Common case: count the candidates after lo that start at or
            // before t. Compares and adds, no branch to mispredict (a loop
            // whose trip count depends on t cost about half the time of a
            // random evaluation). Knots past hi need no mask: they start in a
            // later bucket, so (bucket arithmetic being monotone) they are
            // greater than t, except the last knot when t >= t_max, which the
            // final min() covers. min(.., nseg) keeps the reads in the array.
            const std::size_t i = lo + std::size_t(g[std::min(lo + 1, nseg)] <= t) +
                                  std::size_t(g[std::min(lo + 2, nseg)] <= t) +
                                  std::size_t(g[std::min(lo + 3, nseg)] <= t);
            return std::min(i, nseg - 1);
        }
        const T* base = g + lo;
        std::size_t len = hi - lo + 1;
        while (len > 1) {
            const std::size_t half = len / 2;
            base = (base[half] <= t) ? base + half : base;
            len -= half;
        }
        return std::size_t(base - g);
    }

private:
    // Bucket b holds the segments first_[b] .. first_[b + 1] as candidates.
    storage<std::uint32_t> first_;
    T scale_ = 0, max_ = 0;
};

}  // namespace crspline::detail
