// crspline::geo internals: the proof of no new crossings and no changed
// containment, pair by pair of segments, arc by arc, round by round, with
// tension (or a fitted arc's vertices) raised where a pair is not proved.
// See smooth.hpp's file comment for the argument.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "length.hpp"
#include "sides.hpp"

namespace crspline::geo {

namespace detail {

// What the proof found for a pair of arcs (or an arc with itself).
struct proof_record {
    std::size_t pairs = 0;      // segment and piece pairs examined
    std::size_t crossings = 0;  // input segment pairs that cross properly (left as they are)
    std::size_t touches = 0;    // input segment pairs that touch or overlap
};

// A segment in a sweep: its box's low x.
struct seg_ref {
    double lo;
    std::uint32_t arc, seg;
};

// The proof over pairs of segments and arcs, round by round (see smooth.hpp).
struct proof : proof_base {
    proof(std::vector<arc_work>& a, const smooth_options& o, double rounding) : proof_base(a, o, rounding) {}

    // Segment s of arc i against segment t of arc j (not the same segment).
    void prove_segments(std::uint32_t i, std::size_t s, std::uint32_t j, std::size_t t, proof_record& rec) {
        arc_work& a = arcs[i];
        arc_work& b = arcs[j];
        ++rec.pairs;
        const auto& ha = a.hull[s];
        const auto& hb = b.hull[t];
        const bool la = a.linear(s), lb = b.linear(t);
        // Containment: each segment's ends against the other's swept region
        // (across arcs only: an arc's own vertices cannot change its side).
        if (i != j && !(la && lb)) prove_sides(i, s, j, t);
        const p2* v = shared_end(ha, hb);
        // Segment level: hulls meeting only at a shared end.
        if (v && (apart_by_line(ha, hb, *v, slack) || hulls_apart_at(ha, hb, *v, slack))) return;
        if (la && lb) {
            // Two input segments: apart, or the input itself meets here
            // (left as it is): a proper crossing or a touch.
            if (!v && segment_distance(ha[0], ha[3], hb[0], hb[3]) > 0) return;
            ++(segments_cross(ha[0], ha[3], hb[0], hb[3]) ? rec.crossings : rec.touches);
            return;
        }
        // Where the input segments themselves meet away from a shared end,
        // the proof can only end at the input: go straight there.
        if (!v && segments_meet(ha[0], ha[3], hb[0], hb[3])) {
            // (A fitted segment that left input vertices out is not its
            // input segment: those vertices come back first.)
            if (a.dropped(s)) a.raise[s] = 1;
            else if (!la) jumps.push_back({i, s});
            if (b.dropped(t)) b.raise[t] = 1;
            else if (!lb) jumps.push_back({j, t});
            return;
        }
        // Piece level: each piece within its flatness margin of its chord.
        ensure_line(i);
        ensure_line(j);
        for (std::size_t k = a.first_piece[s]; k < a.first_piece[s + 1]; ++k) {
            const piece p = piece_of(a, i, k, slack);
            for (std::size_t m = b.first_piece[t]; m < b.first_piece[t + 1]; ++m) {
                const piece q = piece_of(b, j, m, slack);
                if (!boxes_meet(p.bounds, q.bounds, p.e + q.e + slack)) continue;
                ++rec.pairs;
                const p2* w = shared_end(p.q, q.q);
                const bool proved = w ? hulls_apart_at(p.q, q.q, *w, slack)
                                      : segment_distance(p.q[0], p.q[3], q.q[0], q.q[3]) > p.e + q.e + slack;
                if (proved) continue;
                fail(p);
                fail(q);
            }
        }
    }

    // Every pair of segments of arc i (j == i) or of arcs i and j whose
    // padded boxes meet: a sweep along x.
    proof_record prove_arcs(std::uint32_t i, std::uint32_t j) {
        proof_record rec;
        std::vector<seg_ref>& refs = scratch;
        refs.clear();
        const double pad = slack;
        auto add = [&](std::uint32_t x, const box<2>* other) {
            const arc_work& a = arcs[x];
            for (std::size_t s = 0; s < a.segments(); ++s)
                if (!other || boxes_meet(a.hull_box[s], *other, pad))
                    refs.push_back({a.hull_box[s].lo[0], x, std::uint32_t(s)});
        };
        if (i == j) {
            add(i, nullptr);
        } else {
            add(i, &arcs[j].bounds);
            add(j, &arcs[i].bounds);
        }
        std::sort(refs.begin(), refs.end(), [](const seg_ref& x, const seg_ref& y) { return x.lo < y.lo; });
        for (std::size_t p = 0; p < refs.size(); ++p) {
            const auto& rp = refs[p];
            const box<2>& bp = arcs[rp.arc].hull_box[rp.seg];
            for (std::size_t q = p + 1; q < refs.size(); ++q) {
                const auto& rq = refs[q];
                if (rq.lo > bp.hi[0] + pad) break;
                if (rq.arc == rp.arc && i != j) continue;  // two arcs: only pairs across them
                const box<2>& bq = arcs[rq.arc].hull_box[rq.seg];
                if (!boxes_meet(bp, bq, pad)) continue;
                prove_segments(rp.arc, rp.seg, rq.arc, rq.seg, rec);
            }
        }
        return rec;
    }

    // Without topology no pair is proved: each arc's rounds (deviation,
    // domain) are its own, run to the end one arc at a time, its length
    // taken and its curve and hulls released (memory stays that of the
    // output). The same levels, round by round, as the rounds of run().
    void run_alone() {
        crossing.assign(arcs.size(), 0);
        for (std::uint32_t i = 0; i < arcs.size(); ++i) {
            if (opt.progress && i % 4096 == 0) opt.progress(0.8 * double(i) / double(arcs.size()));
            alone(i);
        }
    }

    // One arc's rounds without topology (run_alone()), then its length;
    // its curve and hulls released unless smooth_options::keep_curves.
    void alone(std::uint32_t i) {
        constexpr std::size_t max_rounds = 64;
        {
            arc_work& a = arcs[i];
            for (std::size_t round = 1;; ++round) {
                rounds = std::max(rounds, round);
                std::fill(a.raise.begin(), a.raise.end(), 0);
                prepare(i);
                const bool failed = apply_raises(a, round >= max_rounds / 2);
                a.dirty = false;
                if (!failed || round >= max_rounds) break;
            }
            a.length = arc_curve_length(a);
            a.measured = true;
            if (opt.keep_curves) return;  // smooth() hands it over
            a.curve.reset();
            a.base.reset();
            std::vector<std::array<p2, 4>>().swap(a.hull);
            std::vector<crspline::box<2>>().swap(a.hull_box);
        }
    }

    // The pairs of arcs (i < j, as (i << 32) | j, sorted) whose boxes come
    // within the slack: each arc in the cells of a uniform grid its padded
    // box covers (cells the size of the mean box), a pair reported by the
    // cell holding the low corner of the two boxes' overlap; arcs covering
    // more than 16 cells each way are tested against every arc instead.
    // (A sweep along x alone looked at every pair in a column of a grid
    // layout: n sqrt(n).)
    std::vector<std::uint64_t> arc_pairs() const {
        const std::size_t n = arcs.size();
        std::vector<std::uint64_t> out;
        if (n < 2) return out;
        double w = 0, h = 0, x0 = INFINITY, y0 = INFINITY;
        for (const auto& a : arcs) {
            w += a.bounds.hi[0] - a.bounds.lo[0];
            h += a.bounds.hi[1] - a.bounds.lo[1];
            x0 = std::min(x0, a.bounds.lo[0]);
            y0 = std::min(y0, a.bounds.lo[1]);
        }
        const double cell = std::max({w / double(n), h / double(n), 64 * slack, 1e-300});
        auto index = [&](double v, double origin) { return std::int64_t(std::floor((v - origin) / cell)); };
        constexpr std::int64_t big = 16;
        std::vector<std::pair<std::uint64_t, std::uint32_t>> cells;  // (cell key, arc)
        std::vector<std::uint32_t> large;
        for (std::uint32_t i = 0; i < n; ++i) {
            const auto& b = arcs[i].bounds;
            const std::int64_t cx0 = index(b.lo[0] - slack, x0), cx1 = index(b.hi[0] + slack, x0);
            const std::int64_t cy0 = index(b.lo[1] - slack, y0), cy1 = index(b.hi[1] + slack, y0);
            if (cx1 - cx0 >= big || cy1 - cy0 >= big) {
                large.push_back(i);
                continue;
            }
            for (std::int64_t cx = cx0; cx <= cx1; ++cx)
                for (std::int64_t cy = cy0; cy <= cy1; ++cy)
                    cells.push_back({(std::uint64_t(cx + (1 << 30)) << 32) | std::uint64_t(cy + (1 << 30)), i});
        }
        std::sort(cells.begin(), cells.end());
        for (std::size_t g = 0; g < cells.size();) {
            std::size_t e = g;
            while (e < cells.size() && cells[e].first == cells[g].first) ++e;
            for (std::size_t p = g; p < e; ++p)
                for (std::size_t q = p + 1; q < e; ++q) {
                    const std::uint32_t i = std::min(cells[p].second, cells[q].second),
                                        j = std::max(cells[p].second, cells[q].second);
                    const auto &bi = arcs[i].bounds, &bj = arcs[j].bounds;
                    if (!boxes_meet(bi, bj, slack)) continue;
                    // Once: in the cell of the overlap's low corner.
                    const std::int64_t cx = index(std::max(bi.lo[0], bj.lo[0]) - slack, x0);
                    const std::int64_t cy = index(std::max(bi.lo[1], bj.lo[1]) - slack, y0);
                    if (((std::uint64_t(cx + (1 << 30)) << 32) | std::uint64_t(cy + (1 << 30))) != cells[g].first) continue;
                    out.push_back((std::uint64_t(i) << 32) | j);
                }
            g = e;
        }
        std::vector<std::uint8_t> is_large(n, 0);
        for (std::uint32_t i : large) is_large[i] = 1;
        for (std::uint32_t i : large)
            for (std::uint32_t j = 0; j < n; ++j)
                if (j != i && !(is_large[j] && j < i) && boxes_meet(arcs[i].bounds, arcs[j].bounds, slack))
                    out.push_back((std::uint64_t(std::min(i, j)) << 32) | std::max(i, j));
        std::sort(out.begin(), out.end());
        return out;
    }

    // The bounds of the arc's first curve, the union of its segments' hull
    // boxes as prepare() finds them: arc_pairs() needs every arc's before
    // any arc is proved. Neither the curve nor the hulls are kept: prepare()
    // builds the same curve again when the arc's component comes, while it
    // is in cache (holding every arc's curve until then was most of the
    // memory at 10^6 arcs, all of it fresh pages, read back from DRAM).
    void first_bounds(std::uint32_t i) {
        arc_work& a = arcs[i];
        if (a.fitted()) {
            a.bounds = fitted_bounds(a.full);
            return;
        }
        build_arc_curve(a, opt.alpha);
        for (std::size_t s = 0; s < a.segments(); ++s) {
            const auto b = segment_bezier(a, s);
            box<2> bx = box<2>::of(b[0]);
            for (int j = 1; j < 4; ++j) bx.expand(b[j]);
            if (s == 0) a.bounds = bx;
            a.bounds.expand(bx);
        }
        a.curve.reset();
        a.base.reset();
    }

    // An arc whose component is proved: its length taken; its curve (unless
    // smooth_result::curves wants it), its hulls and, without output
    // polylines, its polyline released.
    void finish(std::uint32_t i) {
        arc_work& a = arcs[i];
        a.length = arc_curve_length(a);
        a.measured = true;
        std::vector<std::array<p2, 4>>().swap(a.hull);
        std::vector<crspline::box<2>>().swap(a.hull_box);
        std::vector<std::size_t>().swap(a.first_piece);
        if (!opt.keep_curves) {
            a.curve.reset();
            a.base.reset();
        }
        if (!opt.polylines) {
            a.line = {};
            std::vector<std::uint32_t>().swap(a.vseg);
            std::vector<double>().swap(a.vu);
            a.has_line = false;  // a.pieces keeps the count
        } else if (!keep_parameters) {
            // The output needs each vertex's segment and u only to
            // interpolate extra values.
            std::vector<std::uint32_t>().swap(a.vseg);
            std::vector<double>().swap(a.vu);
        }
    }

    // Rounds, component by component. Arcs are joined (directly or through
    // others) by their candidate pairs, those whose first boxes meet; only
    // arcs of one component can raise each other's tension, so each
    // component runs its rounds to the end alone and then releases its
    // curves and hulls (finish). The levels, round by round, are those of
    // rounds over the whole layer (the same candidates; a component with
    // nothing left to prove does nothing in later rounds), and so is every
    // number out; what changes is memory: one component's curves and hulls
    // at a time beside the polylines, not every arc's at once (10^6 walks
    // smoothed in 9.5 GB instead of about 16; BENCHMARKS.md).
    void run() {
        const std::size_t n = arcs.size();
        self.assign(n, {});
        crossing.assign(n, 0);
        if (!opt.preserve_topology) {
            run_alone();
            return;
        }
        rounds = 1;  // an empty layer too: one round with nothing to prove
        for (std::uint32_t i = 0; i < n; ++i) first_bounds(i);
        std::vector<std::uint64_t> candidates = arc_pairs();
        // Components: union-find over the candidate pairs; a root is the
        // smallest arc of its component.
        std::vector<std::uint32_t> parent(n);
        for (std::uint32_t i = 0; i < n; ++i) parent[i] = i;
        auto find = [&](std::uint32_t x) {
            while (parent[x] != x) x = parent[x] = parent[parent[x]];
            return x;
        };
        for (const std::uint64_t key : candidates) {
            const std::uint32_t x = find(std::uint32_t(key >> 32)), y = find(std::uint32_t(key & 0xffffffffu));
            if (x != y) parent[std::max(x, y)] = std::min(x, y);
        }
        // Each component's arcs and candidates (in key order), listed by root.
        std::vector<std::size_t> arc_start(n + 1, 0), key_start(n + 1, 0);
        for (std::uint32_t i = 0; i < n; ++i) ++arc_start[(parent[i] = find(i)) + 1];
        for (const std::uint64_t key : candidates) ++key_start[parent[std::uint32_t(key >> 32)] + 1];
        for (std::size_t r = 0; r < n; ++r) {
            arc_start[r + 1] += arc_start[r];
            key_start[r + 1] += key_start[r];
        }
        std::vector<std::uint32_t> members(n);
        std::vector<std::uint64_t> keys(candidates.size());
        {
            std::vector<std::size_t> at(arc_start.begin(), arc_start.end() - 1);
            for (std::uint32_t i = 0; i < n; ++i) members[at[parent[i]]++] = i;
            at.assign(key_start.begin(), key_start.end() - 1);
            for (const std::uint64_t key : candidates) keys[at[parent[std::uint32_t(key >> 32)]]++] = key;
        }
        std::vector<std::uint64_t>().swap(candidates);
        dirty.assign(n, 0);
        for (std::size_t r = 0; r < n; ++r) {
            const std::size_t first = arc_start[r], size = arc_start[r + 1] - first;
            if (size == 0) continue;
            // The proof is 80% of the work; a report where the count of
            // arcs done passes a multiple of 4096 (as in run_alone()).
            if (opt.progress && (first + 4095) / 4096 != (first + size + 4095) / 4096)
                opt.progress(0.8 * double(first) / double(n));
            const std::span<const std::uint32_t> m(members.data() + first, size);
            run_component(m, std::span<const std::uint64_t>(keys.data() + key_start[r], key_start[r + 1] - key_start[r]));
            for (const std::uint32_t i : m) finish(i);
        }
    }

    // One component's rounds: rebuild its dirty arcs, prove the pairs that
    // involve one, raise tension where a proof failed; until every pair is
    // proved. Pairs of clean arcs keep the record of the round that proved
    // them.
    void run_component(std::span<const std::uint32_t> members, std::span<const std::uint64_t> candidates) {
        constexpr std::size_t max_rounds = 64;
        previous.clear();
        across.clear();
        for (std::size_t round = 1;; ++round) {
            rounds = std::max(rounds, round);
            for (const std::uint32_t i : members) {
                auto& a = arcs[i];
                dirty[i] = a.dirty;
                std::fill(a.raise.begin(), a.raise.end(), 0);
                if (a.dirty) prepare(i);
            }
            for (const std::uint32_t i : members)
                if (dirty[i]) self[i] = prove_arcs(i, i);
            // The candidates come in key order, and so does `across`.
            previous.swap(across);
            across.clear();
            for (const std::uint64_t key : candidates) {
                const auto i = std::uint32_t(key >> 32), j = std::uint32_t(key & 0xffffffffu);
                if (dirty[i] || dirty[j]) {
                    across.push_back({key, prove_arcs(i, j)});
                } else {
                    // Unchanged since the round that proved them.
                    auto it = std::lower_bound(previous.begin(), previous.end(), key,
                                               [](const auto& e, std::uint64_t k) { return e.first < k; });
                    across.push_back({key, it != previous.end() && it->first == key ? it->second : prove_arcs(i, j)});
                }
            }
            // Raise tension where needed.
            bool failed = false;
            for (const auto& [x, s] : jumps) {
                arc_work& a = arcs[x];
                a.raise[s] = 1;
                a.level[s] = a.level[a.next(s)] = linear_level;
            }
            jumps.clear();
            for (const std::uint32_t i : members) {
                auto& a = arcs[i];
                // After many rounds, straight to the last resort.
                a.dirty = apply_raises(a, round >= max_rounds / 2);
                failed = failed || a.dirty;
            }
            if (!failed || round >= max_rounds) break;  // the cap cannot be reached: levels only grow
        }
        // What the final proof found.
        auto note = [&](std::uint32_t i, const proof_record& r) {
            if (r.crossings) crossing[i] = 2;
            else if (r.touches) crossing[i] = std::max<std::uint8_t>(crossing[i], 1);
        };
        auto count = [&](const proof_record& r) {
            pairs += r.pairs;
            crossings += r.crossings;
            touches += r.touches;
        };
        for (const std::uint32_t i : members) {
            count(self[i]);
            note(i, self[i]);
        }
        for (const auto& [key, r] : across) {
            count(r);
            note(std::uint32_t(key >> 32), r);
            note(std::uint32_t(key & 0xffffffffu), r);
        }
    }

    bool keep_parameters = true;  // false: finish() releases vseg and vu of the polylines it keeps
    std::vector<seg_ref> scratch;
    std::vector<std::pair<std::uint32_t, std::size_t>> jumps;   // (arc, segment) to take to the input
    std::vector<proof_record> self;                              // per arc, with itself
    std::vector<std::pair<std::uint64_t, proof_record>> across;  // per pair of arcs whose boxes meet, by key
    std::vector<std::pair<std::uint64_t, proof_record>> previous;  // the round before's
    std::vector<std::uint8_t> dirty;                             // per arc: rebuilt this round
    std::vector<std::uint8_t> crossing;                          // per arc: 2 an input crossing, 1 a touch
    std::size_t rounds = 0, pairs = 0, crossings = 0, touches = 0;
};

}  // namespace detail

}  // namespace crspline::geo
