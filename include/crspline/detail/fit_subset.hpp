// crspline: fit()'s choice of control points among the input points.
//
// Choice. A segment from point i to point j covers the input points i..j;
// whether it keeps the tolerance depends on its neighbours too (they set its
// end tangents). reach(i, p) is the farthest j for which the segment from i
// (its chosen predecessor p) passes the proof with the next point guessed
// one step of the same length ahead, found by doubling the step and then
// halving it. With tension at every vertex (the first search) the
// walk takes the farthest point within reach that keeps the segment before
// it (its successor now known), or a point backed off; on a smooth line
// (the second search, from level 0) it takes, among the last few points
// within reach of the current one, the point from which the next reach
// goes farthest (a lookahead of two segments instead of the greedy's one),
// so that a point that makes the next segment's tangent bad is passed
// over. Then a local
// improvement removes points and merges pairs, trying the tension level of
// each vertex it touches (a vertex at 0.5 or 0.95 keeps the curve nearer
// its chords at a corner, so a point beside it can go: 9% fewer points on
// the real corpus than the best of whole-curve levels).
//
// fit_subset() then proves and repairs the choice (fit_repair.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "../catmull_rom.hpp"
#include "fit_model.hpp"
#include "fit_proof.hpp"
#include "fit_repair.hpp"

namespace crspline::detail {


/// A multiplicative mix of indices; its top bits pick an entry of the
/// search's small tables.
inline std::uint64_t fit_mix(std::size_t a, std::size_t b, std::size_t c = 0, std::size_t d = 0) noexcept {
    return std::uint64_t(a) * 0x9E3779B97F4A7C15u ^ std::uint64_t(b) * 0xC2B2AE3D27D4EB4Fu ^
           std::uint64_t(c) * 0x165667B19E3779F9u ^ std::uint64_t(d) * 0xD6E8FEB86659FD93u;
}

template <std::size_t D, class T>
class subset_search {
public:
    using point = vec<D, T>;
    explicit subset_search(const fit_problem<D, T>& pb) : pb_(pb), limits_(pb.tolerance, pb.slack) {
        const std::size_t n = pb.size();
        last_ = pb.closed ? n : n - 1;
    }

    /// Whether the segment i -> j (unrolled indices) with predecessor p and
    /// successor nx (fit_none: an open end) keeps the tolerance, with the
    /// tension levels la at i and lb at j (the base level unless given: the
    /// quick test). The answer is a function of (p, i, j, nx, la, lb): a
    /// small table of recent answers saves the tests that improve() (mostly)
    /// repeats within a few dozen calls.
    bool passes(std::size_t p, std::size_t i, std::size_t j, std::size_t nx) const {
        return passes(p, i, j, nx, pb_.base_level, pb_.base_level);
    }
    bool passes(std::size_t p, std::size_t i, std::size_t j, std::size_t nx, std::uint8_t la, std::uint8_t lb) const {
        const std::size_t lv = std::size_t(la) << 4 | lb;
        const std::array<std::size_t, 5> key{p, i, j, nx, lv};
        recent& r = recent_[(fit_mix(p, i, j, nx) ^ std::uint64_t(lv) * 0x2545F4914F6CDD1Du) >> 58];
        if (r.key == key) return r.ok;
        const point* pp = p == fit_none ? nullptr : &pb_.at(p);
        const point* np = nx == fit_none ? nullptr : &pb_.at(nx);
        const typename fit_problem<D, T>::knots k{pp ? interval(p, i) : T(0), interval(i, j), np ? interval(j, nx) : T(0)};
        const auto seg = pb_.segment(pp, pb_.at(i), pb_.at(j), np, la, lb, k);
        const poly_range<D, T> pr{pb_.pts, i >= pb_.size() ? i - pb_.size() : i, j - i + 1, pb_.odd_middles};
        r.key = key;
        // First the hull's bound (may_pass, at these levels: the inner Bezier
        // points are a third of the end tangents from the ends), then the test.
        const T across = std::max(across_chord(seg.c1, i, j), across_chord(seg.c1 + T(2) * seg.c2 + T(3) * seg.c3, i, j));
        r.ok = near_chord_line(pr, i, j, across / T(3)) && quick_segment_test(seg, pr, limits_, 1, j - i);
        return r.ok;
    }

    /// The guessed successor of the segment i -> j: one step of the same
    /// length further, the last point at most; none past an open end.
    std::size_t guess_next(std::size_t i, std::size_t j) const {
        if (j >= last_) return pb_.closed ? 1 + (j - last_) : fit_none;
        return std::min(last_, j + (j - i));
    }
    std::size_t guess_prev(std::size_t i, std::size_t j) const {
        if (!pb_.closed) return fit_none;
        const std::size_t n = pb_.size(), step = j - i;
        return (i + n - std::min(step, n - 1) % n) % n;
    }

    /// The farthest point reached from i with predecessor p.
    std::size_t reach(std::size_t p, std::size_t i) const {
        std::size_t ok = i + 1, bad = fit_none;
        for (std::size_t step = 1;; step *= 2) {
            const std::size_t j = i + 1 + step;
            if (j > last_) {
                if (ok < last_ && passes(p, i, last_, guess_next(i, last_))) return last_;
                if (ok == last_) return last_;
                bad = last_;
                break;
            }
            if (passes(p, i, j, guess_next(i, j))) {
                ok = j;
            } else {
                bad = j;
                break;
            }
        }
        // To a grid step g only where the reach covers fit_choose_grid points
        // or more: choose() puts its candidates on that grid there
        // (on_grid), and each test looks at every point it covers (a sine
        // sampled with 256,000 points: 2.3 times faster, the same counts).
        const std::size_t g = grid_step(ok - i);
        while (bad - ok > g) {
            const std::size_t mid = ok + (bad - ok) / 2;
            if (passes(p, i, mid, guess_next(i, mid))) ok = mid;
            else bad = mid;
        }
        return ok;
    }

    /// The grid step for a reach over `span` input points: 1 below
    /// fit_choose_grid, else the power of two g with g * fit_choose_grid
    /// <= span < 2 g * fit_choose_grid.
    static std::size_t grid_step(std::size_t span) noexcept {
        std::size_t g = 1;
        while (g * fit_choose_grid <= span) g *= 2;
        return g;
    }

    /// A reach of fit_choose_grid points or more puts the candidates on a
    /// grid of step g (a power of two, the reach fit_choose_grid to twice
    /// that many steps): the candidates of the states on one count share
    /// their points, so a densely sampled line, whose segments cover
    /// thousands of input points, has a bounded number of states per
    /// control point (with every point a candidate, the choice's time grew
    /// with the square of the points). The last point stays exact;
    /// duplicates go.
    template <std::size_t N>
    std::size_t on_grid(std::array<std::size_t, N>& cand, std::size_t nc, std::size_t b, std::size_t r) const {
        const std::size_t g = grid_step(r - b);
        if (g == 1) return nc;
        std::size_t out = 0;
        for (std::size_t k = 0; k < nc; ++k) {
            const std::size_t c = cand[k] == last_ ? last_ : cand[k] / g * g;
            bool seen = c <= b;
            for (std::size_t q = 0; q < out && !seen; ++q) seen = cand[q] == c;
            if (!seen) cand[out++] = c;
        }
        return out;
    }

    /// The choice: a shortest path over states (a, b), the last two chosen
    /// points, each knowing its best predecessor z. From a state, the
    /// candidates for the next point c are the last `lookahead` points
    /// within reach of b (with predecessor a) and two backed off from it
    /// (without them, a point reached at the very end of a segment can leave
    /// the next one a tangent that keeps it one input step long, and the
    /// count grew with the tolerance on an ellipse); a candidate must keep the
    /// segment a -> b within the tolerance now that its successor is known
    /// (its four points z, a, b, c are then the curve's own). States that
    /// reach the same point are kept `beam` at most, the fewest points
    /// first; a state makes `branch` successors at most, its first
    /// candidates that keep a -> b (1: a greedy walk, the backed-off
    /// candidates its fallback). Returns unrolled indices from 0 to the last
    /// point.
    std::vector<std::size_t> choose(std::size_t lookahead, std::size_t beam, std::size_t branch) const {
        struct state {
            std::size_t z, a, b, count, parent;
        };
        std::vector<state> st;
        std::vector<std::vector<std::size_t>> at(last_ + 1);
        const std::size_t start_prev = pb_.closed ? guess_prev(0, std::min<std::size_t>(last_, 8)) : fit_none;
        st.push_back({fit_none, start_prev, 0, 1, fit_none});
        at[0].push_back(0);
        std::size_t done = fit_none;
        for (std::size_t b = 0; b <= last_ && done == fit_none; ++b) {
            auto& here = at[b];
            if (here.empty()) continue;
            std::stable_sort(here.begin(), here.end(), [&](std::size_t x, std::size_t y) { return st[x].count < st[y].count; });
            if (here.size() > beam) here.resize(beam);
            for (std::size_t id : here) {
                const state s = st[id];
                const bool first = id == 0;
                if (b == last_) {
                    if (done == fit_none) done = id;  // the fewest points: sorted
                    continue;
                }
                const std::size_t r = reach(s.a, b);
                const std::size_t from = r > b + lookahead ? r - lookahead + 1 : b + 1;
                bool any = false;
                // Candidates: the last `lookahead` points within reach, and
                // two backed off (7/8 and 3/4 of the reach), which leave the
                // next segment a tangent it can keep. (A lookahead above
                // max_lookahead counts as max_lookahead; fit.hpp asks for 2.)
                constexpr std::size_t max_lookahead = 6;
                std::array<std::size_t, max_lookahead + 2> cand{};
                std::size_t nc = 0;
                for (std::size_t c = r + 1; c-- > from && nc < max_lookahead;) cand[nc++] = c;
                for (std::size_t c : {b + (r - b) * 7 / 8, b + (r - b) * 3 / 4})
                    if (c > b && c < from && (nc == 0 || cand[nc - 1] != c)) cand[nc++] = c;
                nc = on_grid(cand, nc, b, r);
                std::size_t made = 0;
                for (std::size_t ci = 0; ci < nc && made < branch; ++ci) {
                    const std::size_t c = cand[ci];
                    if (!first && !passes(s.z, s.a, b, c)) continue;
                    any = true;
                    ++made;
                    // Merge with a state (b, c) already there.
                    bool merged = false;
                    for (std::size_t o : at[c])
                        if (st[o].a == b) {
                            if (s.count + 1 < st[o].count) st[o] = {s.a, b, c, s.count + 1, id};
                            merged = true;
                            break;
                        }
                    if (!merged) {
                        st.push_back({s.a, b, c, s.count + 1, id});
                        at[c].push_back(st.size() - 1);
                    }
                }
                if (!any) {  // nothing keeps a -> b: go one point on, the repairs will prove it
                    bool merged = false;
                    for (std::size_t o : at[b + 1])
                        if (st[o].a == b) merged = true;
                    if (!merged) {
                        st.push_back({s.a, b, b + 1, s.count + 1, id});
                        at[b + 1].push_back(st.size() - 1);
                    }
                }
            }
        }
        std::vector<std::size_t> idx;
        for (std::size_t id = done; id != fit_none; id = st[id].parent) idx.push_back(st[id].b);
        std::reverse(idx.begin(), idx.end());
        return idx;
    }

    /// Local improvement of a choice and of its tension levels (`level`,
    /// one per entry of idx): each point removed where the curve keeps the
    /// tolerance without it, its two neighbours' levels tried at every level
    /// up to `max_level` (the current ones first); and each pair of
    /// neighbouring points replaced by one between their neighbours where
    /// some such point, at some level, keeps it (every segment whose four
    /// points or two levels change tried with its real neighbours). The ends
    /// of an open line stay, at level 0; a closed curve's point 0 too, at
    /// its level; a closed curve keeps three points at least. Each try looks
    /// at a window of eight points around the change, so a pass costs time
    /// linear in the points.
    void improve(std::vector<std::size_t>& idx, std::vector<std::uint8_t>& level, std::uint8_t max_level) const {
        using sidx = std::ptrdiff_t;
        const sidx n = sidx(pb_.size()), none = std::numeric_limits<sidx>::min();
        // The points kept so far (`left`, the current point's predecessors)
        // and those still to look at (idx[pos ..], the current one first);
        // a removal or a merge only moves pos, so a pass is linear.
        std::vector<std::size_t> left;
        std::vector<std::uint8_t> left_level;
        left.reserve(idx.size());
        left_level.reserve(idx.size());
        left.push_back(idx[0]);
        left_level.push_back(level[0]);
        std::size_t pos = 1;
        // The entry q places after the current one (q < 0: before it),
        // unrolled past either end of a closed curve (whose last entry is
        // point 0 one turn later); `none` past an open end. `fixed`: its
        // level may not change (an end, point 0, or an entry seen across
        // the wrap).
        struct entry {
            sidx v;
            std::uint8_t* level;
            bool fixed;
        };
        auto at = [&](sidx q) -> entry {
            const sidx nl = sidx(left.size()), nr = sidx(idx.size() - pos), total = nl + nr;
            sidx k = nl + q;  // position in left ++ idx[pos ..]
            sidx shift = 0;
            if (k < 0 || k >= total) {
                if (!pb_.closed) return {none, nullptr, true};
                // One turn: entry total - 1 is entry 0 again.
                if (k < 0) k += total - 1, shift = -n;
                else k -= total - 1, shift = n;
            }
            const bool fixed = shift != 0 || k == 0 || k == total - 1;
            if (k < nl) return {sidx(left[std::size_t(k)]) + shift, &left_level[std::size_t(k)], fixed};
            const std::size_t e = pos + std::size_t(k - nl);
            return {sidx(idx[e]) + shift, &level[e], fixed};
        };
        auto wrap = [&](sidx i) { return i == none ? fit_none : std::size_t(((i % n) + n) % n); };
        // Segment w[s] -> w[s + 1] of a window: its unrolled ends and its
        // neighbours (`some` false past an open end: nothing to test).
        struct window_segment {
            bool some;
            std::size_t z, a, b, c;
        };
        auto segment_at = [&](const std::array<sidx, 8>& w, std::size_t len, std::size_t s) -> window_segment {
            if (w[s] == none || w[s + 1] == none) return {false, 0, 0, 0, 0};
            sidx a = w[s], b = w[s + 1];
            const sidx shift = a < 0 ? n : a >= n ? -n : 0;
            a += shift, b += shift;
            const std::size_t z = s > 0 ? wrap(w[s - 1]) : fit_none;
            const std::size_t c = s + 2 < len ? wrap(w[s + 2]) : fit_none;
            return {true, z, std::size_t(a), std::size_t(b), c};
        };
        // Whether that segment passes at the levels lv[s], lv[s + 1].
        auto seg_ok = [&](const std::array<sidx, 8>& w, const std::array<std::uint8_t, 8>& lv, std::size_t len,
                          std::size_t s) {
            const window_segment g = segment_at(w, len, s);
            return !g.some || passes(g.z, g.a, g.b, g.c, lv[s], lv[s + 1]);
        };
        // Whether some levels may let it pass (may_pass).
        auto seg_may = [&](const std::array<sidx, 8>& w, std::size_t len, std::size_t s) {
            const window_segment g = segment_at(w, len, s);
            return !g.some || may_pass(g.z, g.a, g.b, g.c);
        };
        // The levels an entry may take: its own first, then the others.
        auto choices = [&](const entry& e, std::array<std::uint8_t, 8>& out) {
            std::size_t k = 0;
            out[k++] = *e.level;
            if (!e.fixed)
                for (std::uint8_t l = 0; l <= max_level; ++l)
                    if (l != *e.level) out[k++] = l;
            return k;
        };
        while (pos + 1 < idx.size()) {
            // A ring keeps three vertices at least (four before a removal or
            // a merge; and then the window below wraps at most once).
            if (pb_.closed && left.size() + (idx.size() - pos) < 5) {
                left.push_back(idx[pos]);
                left_level.push_back(level[pos]);
                ++pos;
                continue;
            }
            std::array<entry, 8> e{};
            std::array<sidx, 8> w{};
            std::array<std::uint8_t, 8> wl{};
            for (sidx q = 0; q < 8; ++q) {
                e[std::size_t(q)] = at(q - 3);
                w[std::size_t(q)] = e[std::size_t(q)].v;
                wl[std::size_t(q)] = e[std::size_t(q)].level ? *e[std::size_t(q)].level : std::uint8_t(0);
            }
            // Remove the current point: segments -2 -> -1, -1 -> +1, +1 -> +2,
            // with the levels of -1 and +1 tried.
            {
                const std::array<sidx, 8> r{w[0], w[1], w[2], w[4], w[5], w[6], w[7], none};
                std::array<std::uint8_t, 8> ca{}, cb{};
                const std::size_t na = w[2] == none ? 1 : choices(e[2], ca), nb = w[4] == none ? 1 : choices(e[4], cb);
                bool removed = false;
                const bool flat = seg_may(r, 7, 2);
                for (std::size_t ia = 0; ia < na && !removed && flat; ++ia)
                    for (std::size_t ib = 0; ib < nb && !removed; ++ib) {
                        const std::array<std::uint8_t, 8> rl{wl[0], wl[1], ca[ia], cb[ib], wl[5], wl[6], wl[7], 0};
                        if (seg_ok(r, rl, 7, 2) && seg_ok(r, rl, 7, 1) && seg_ok(r, rl, 7, 3)) {
                            if (e[2].level) *e[2].level = ca[ia];
                            if (e[4].level) *e[4].level = cb[ib];
                            removed = true;
                        }
                    }
                if (removed) {
                    ++pos;
                    continue;
                }
            }
            // Replace it and the next one by one point k between their
            // neighbours, at some level (theirs kept): every point between
            // them, or fit_merge_tries evenly spread where there are more.
            bool merged = false;
            if (pos + 2 < idx.size()) {
                const sidx span = w[5] - w[2], tries = sidx(fit_merge_tries);
                const sidx stride = span <= tries ? 1 : (span + tries - 1) / tries;
                for (sidx k = w[5] - 1; k > w[2] && !merged; k -= stride) {
                    const std::array<sidx, 8> t0{w[0], w[1], w[2], k, w[5], w[6], w[7], none};
                    // The longer of its two new segments first: it fails
                    // more often, and a test that passes looks at every
                    // input point it covers (the same answers in any
                    // order; a tenth less time on the corpus).
                    const std::size_t s1 = k - w[2] >= w[5] - k ? 2 : 3, s2 = 5 - s1;
                    if (!seg_may(t0, 7, s1) || !seg_may(t0, 7, s2)) continue;
                    for (std::uint8_t lk = 0; lk <= max_level && !merged; ++lk) {
                        const std::uint8_t l = std::uint8_t((wl[3] + lk) % (max_level + 1));  // its own first
                        const std::array<sidx, 8> t{w[0], w[1], w[2], k, w[5], w[6], w[7], none};
                        const std::array<std::uint8_t, 8> tl{wl[0], wl[1], wl[2], l, wl[5], wl[6], wl[7], 0};
                        if (seg_ok(t, tl, 7, s1) && seg_ok(t, tl, 7, s2) && seg_ok(t, tl, 7, 1) && seg_ok(t, tl, 7, 4)) {
                            idx[pos + 1] = std::size_t(k);  // the merged point, looked at next
                            level[pos + 1] = l;
                            ++pos;
                            merged = true;
                        }
                    }
                }
            }
            if (!merged) {
                left.push_back(idx[pos]);
                left_level.push_back(level[pos]);
                ++pos;
            }
        }
        left.push_back(idx.back());
        left_level.push_back(level.back());
        idx = std::move(left);
        level = std::move(left_level);
    }
    /// How many vertices of a choice need their tension: those whose two
    /// segments do not both keep the tolerance with that vertex alone at
    /// level 0 (the others as they are). fit() asks it of the choice made
    /// with every vertex starting at 0.8, to tell a line with corners (many)
    /// from a smooth one (few), where starting at 0 saves points.
    std::size_t tension_needed(const std::vector<std::size_t>& idx, const std::vector<std::uint8_t>& level) const {
        const std::size_t m = idx.size(), n = pb_.size();
        if (m < 3) return 0;
        std::vector<std::uint8_t> lv = level;
        auto ok = [&](std::size_t s) {  // segment s -> s + 1 with its real neighbours
            std::size_t z = fit_none, c = fit_none;
            if (s > 0) z = idx[s - 1] % n;
            else if (pb_.closed) z = idx[m - 2] % n;
            if (s + 2 < m) c = idx[s + 2] % n;
            else if (pb_.closed) c = idx[1] % n;
            return passes(z, idx[s], idx[s + 1], c, lv[s], lv[s + 1]);
        };
        std::size_t need = 0;
        for (std::size_t v = 1; v + 1 < m; ++v) {
            if (lv[v] == 0) continue;
            const std::uint8_t own = lv[v];
            lv[v] = 0;
            need += !(ok(v - 1) && ok(v));
            lv[v] = own;
        }
        return need;
    }

    /// Every entry at the base level; an open line's ends at 0.
    std::vector<std::uint8_t> initial_levels(std::size_t count) const {
        std::vector<std::uint8_t> level(count, pb_.base_level);
        if (!pb_.closed) level.front() = level.back() = 0;
        return level;
    }

private:
    /// Whether the segment i -> j (unrolled indices, predecessor p and
    /// successor nx as for passes()) may keep the tolerance at some tension
    /// levels of i and j. The segment lies in the hull of its Bezier points:
    /// its ends, on the chord's line, and its ends moved by a third of their
    /// du-tangents, whose parts across the line are at most those of the
    /// level-0 tangents (tension only shortens an inner vertex's tangent; an
    /// open end's natural tangent (3 v - k c) / 2, v along the chord, has at
    /// most half of c's part across; a reflected end's has none). So where
    /// an input point it covers is farther from the line than the limit
    /// plus the larger third (a 64th of the limit spared for rounding), no
    /// level passes the quick test, whose input points must be within the
    /// limit of the curve: the improvement skips the levels after one scan
    /// with no curve in it (the same choice, a third less time on the real
    /// corpus).
    bool may_pass(std::size_t p, std::size_t i, std::size_t j, std::size_t nx) const {
        const point& a = pb_.at(i);
        const point& b = pb_.at(j);
        const T h = interval(i, j);
        if (!(h > 0)) return true;
        const T keep = T(1) - pb_.tension;
        const T ca = p == fit_none ? T(0) : across_chord(pb_.vertex_tangent(pb_.at(p), a, b, interval(p, i), h), i, j);
        const T cb = nx == fit_none ? T(0) : across_chord(pb_.vertex_tangent(a, b, pb_.at(nx), h, interval(j, nx)), i, j);
        T ea = 0, eb = 0;
        if (p != fit_none || nx != fit_none) {
            ea = p != fit_none ? keep * ca : pb_.start_reflect ? T(0) : keep * cb / T(2);
            eb = nx != fit_none ? keep * cb : pb_.end_reflect ? T(0) : keep * ca / T(2);
        }
        const poly_range<D, T> pr{pb_.pts, i >= pb_.size() ? i - pb_.size() : i, j - i + 1, pb_.odd_middles};
        return near_chord_line(pr, i, j, h * std::max(ea, eb) / T(3));
    }

    /// The part of t across the line through the points at i and j (its
    /// root taken plainly: a number too large to square gives infinity, and
    /// so no bound; one too small to square is far below the 64th of the
    /// limit that near_chord_line spares).
    T across_chord(const point& t, std::size_t i, std::size_t j) const {
        const point d = pb_.at(j) - pb_.at(i);
        const T l2 = dot(d, d);
        if (!(l2 > 0) || !(l2 < std::numeric_limits<T>::infinity())) return std::numeric_limits<T>::infinity();
        const point v = t - (dot(t, d) / l2) * d;
        return std::sqrt(dot(v, v));
    }

    /// Whether every input point of the range i..j is within the limit plus
    /// e of the line through the points at i and j (with a 64th of the limit
    /// spared for rounding); true where that cannot be told. The largest
    /// squared offset is a function of (i, j) alone, kept in a small table:
    /// a merge asks for the same range at each tension level, and first for
    /// may_pass (3% less time on the corpus, the same answers).
    bool near_chord_line(const poly_range<D, T>& pr, std::size_t i, std::size_t j, T e) const {
        const point& a = pb_.at(i);
        const point d = pb_.at(j) - a;
        const T l2 = dot(d, d), cap = (limits_.input.limit + e) * (T(1) + T(1) / T(64));
        if (!(l2 > 0) || !(l2 < std::numeric_limits<T>::infinity()) || !(cap < std::numeric_limits<T>::infinity()))
            return true;
        chord_offset& c = chord_offsets_[fit_mix(i, j) >> 56];
        if (c.i != i || c.j != j) {
            T far = 0;  // a NaN offset is passed over, as a comparison with it would be
            for (std::size_t k = 1; k + 1 < pr.count; ++k) {
                if (!pr.is_input(k)) continue;
                const point w = pr[k] - a;
                const point off = w - (dot(w, d) / l2) * d;
                far = std::max(far, dot(off, off));
            }
            c = {i, j, far};
        }
        return c.far <= cap * cap;
    }

    const fit_problem<D, T>& pb_;
    const quick_limits<T> limits_;  // pb_'s, for every quick test
    std::size_t last_ = 0;
    /// pb_.interval between the points at unrolled indices a and b, kept
    /// in a small table by index pair (reach() asks for the same (p, i) at
    /// every step, choose() for the same (z, a) and (a, b) for each candidate).
    T interval(std::size_t a, std::size_t b) const {
        known_interval& e = intervals_[fit_mix(a, b) >> 56];
        if (e.a != a || e.b != b) e = {a, b, pb_.interval(pb_.at(a), pb_.at(b))};
        return e.h;
    }
    struct known_interval {
        std::size_t a = fit_none, b = fit_none;
        T h = 0;
    };
    mutable std::array<known_interval, 256> intervals_{};
    struct chord_offset {
        std::size_t i = fit_none, j = fit_none;
        T far = 0;  // the largest squared offset from the chord's line
    };
    mutable std::array<chord_offset, 256> chord_offsets_{};
    // passes()'s recent answers, by the key's mix (i is never fit_none: an
    // empty entry). These tables make a search an object for one thread.
    struct recent {
        std::array<std::size_t, 5> key{fit_none, fit_none, fit_none, fit_none, 0};
        bool ok = false;
    };
    mutable std::array<recent, 64> recent_{};
};

/// Three control points for a ring that the search took round in one or
/// two (a tolerance as large as the ring itself): a closed curve of one
/// point is no curve, and one of two goes there and back, enclosing
/// nothing (a GIS ring must keep three distinct vertices). Point 0, the
/// point farthest from it and the point farthest from the line through
/// those two (distinct points where there are), as unrolled indices in
/// order, ending with point 0 again; the proof and repairs then keep the
/// tolerance as for any choice.
template <std::size_t D, class T>
std::vector<std::size_t> fit_ring_triangle(const fit_problem<D, T>& pb) {
    const std::size_t n = pb.size();
    const vec<D, T>& a = pb.pts[0];
    std::size_t b = 1;
    T far = -1;
    for (std::size_t k = 1; k < n; ++k) {
        const T d = dot(pb.pts[k] - a, pb.pts[k] - a);
        if (d > far) far = d, b = k;
    }
    const vec<D, T> d = pb.pts[b] - a;
    std::size_t c = b == 1 ? 2 : 1;
    T off = -1;
    for (std::size_t k = 1; k < n; ++k) {
        if (k == b || pb.pts[k] == a || pb.pts[k] == pb.pts[b]) continue;
        const vec<D, T> v = fit_segment_offset(pb.pts[k], a, d, dot(d, d));
        const T o = dot(v, v);
        if (o > off) off = o, c = k;
    }
    return {0, std::min(b, c), std::max(b, c), n};
}

/// Subset mode at pb's base level: the choice, its improvement, the proof
/// and its repairs. `need` (counted only where not null: the first search
/// asks, fit.hpp) and `chosen`: the choice's vertices that need their
/// tension (tension_needed) and all of them, before the proof.
template <std::size_t D, class T>
fit_selection<D, T> fit_subset(const fit_problem<D, T>& pb, std::size_t* need, std::size_t& chosen) {
    const subset_search<D, T> search(pb);
    // The first search (every vertex at tension 0.8) walks greedily: on the
    // real corpus (BENCHMARKS.md, "Fit: a greedy first search") the choice
    // with a lookahead of two segments ended, after the improvement, with
    // as many points (within 1% either way on each part), at 1.5 times the
    // fit's time. A smooth line's second search (from level 0; fit.hpp runs
    // it where at most one vertex in 5 needs its tension) keeps the
    // lookahead: greedily there, the ellipses of the 1,600 seeded random
    // lines took 4-5% more points, and tests/fit's ellipse at tolerance
    // 0.003 kept tension and 28 points instead of 21.
    const std::size_t branch = pb.base_level == 0 ? fit_none : 1;
    std::vector<std::size_t> idx = search.choose(2, 1, branch);
    std::vector<std::uint8_t> level = search.initial_levels(idx.size());
    search.improve(idx, level, fit_improve_level);
    if (pb.closed && idx.size() < 4) {
        idx = fit_ring_triangle(pb);
        level = search.initial_levels(idx.size());
    }
    if (need) *need = search.tension_needed(idx, level);
    chosen = idx.size();
    return prove_and_repair(pb, std::move(idx), {}, std::move(level));
}

}  // namespace crspline::detail
