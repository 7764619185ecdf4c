// crspline: fit()'s proof and repair of a chosen selection: the curve is
// built (catmull_rom, the curve returned) and every segment proved against
// its input points (fit_proof.hpp) with its real neighbours. A failed
// segment with a moved end first has its ends put back on their input
// points; one that covers more than one input segment then has the tension
// of its two vertices raised (one level, up to 0.8), then is split at its
// middle input point; one that covers a single input segment has its
// vertices' tension raised up to 1, where the segment is that input segment
// itself (exact). Levels only grow and points are only added, so the
// repairs end, at worst with the input polyline itself. Only segments whose
// four points or levels changed are proved again.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "../catmull_rom.hpp"
#include "fit_model.hpp"
#include "fit_proof.hpp"

namespace crspline::detail {

inline constexpr std::size_t fit_none = std::size_t(-1);

/// A fitted selection: control points as (unrolled) input indices (the
/// input point each one stands for, and where its segment's coverage
/// starts), their positions (the input points themselves in subset mode),
/// their tension levels, and the proved bounds.
template <std::size_t D, class T>
struct fit_selection {
    std::vector<std::size_t> idx;
    std::vector<vec<D, T>> pos;
    std::vector<std::uint8_t> level;
    T curve_to_input = 0, input_to_curve = 0;
};

/// Builds the curve of a selection (a closed curve's last entry, the first
/// point again, dropped).
template <std::size_t D, class T>
catmull_rom<D, T> selection_curve(const fit_problem<D, T>& pb, const std::vector<vec<D, T>>& pos,
                                  const std::vector<std::uint8_t>& level) {
    const std::size_t nv = pb.closed ? pos.size() - 1 : pos.size();
    return catmull_rom<D, T>(std::span<const vec<D, T>>(pos.data(), nv),
                             pb.curve_options(std::span<const std::uint8_t>(level.data(), nv)));
}

/// Proves the selection's curve segment by segment and repairs it until
/// every segment keeps the tolerance. `idx` holds unrolled indices from 0
/// to the last point (the size of the input when closed); `pos` the control
/// points, one per entry of idx (moved ones in free mode; empty: the input
/// points at idx). A failed segment with a moved end first has its ends put
/// back on their input points; then the repairs of the file comment.
template <std::size_t D, class T>
fit_selection<D, T> prove_and_repair(const fit_problem<D, T>& pb, std::vector<std::size_t> idx,
                                     std::vector<vec<D, T>> pos = {}, std::vector<std::uint8_t> level = {}) {
    const bool closed = pb.closed;
    if (level.empty()) level.assign(idx.size(), pb.base_level);
    if (!closed) level.front() = level.back() = 0;  // an open curve's ends take no tension
    std::vector<std::uint8_t> moved(idx.size(), 0);
    if (pos.empty()) {
        for (std::size_t i : idx) pos.push_back(pb.at(i));
    } else {
        for (std::size_t k = 0; k < idx.size(); ++k) moved[k] = !(pos[k] == pb.at(idx[k]));
    }
    // Per segment: the key it was proved with (4 indices, 4 levels, 4
    // moved flags: a moved point never moves again, only back) and its bounds.
    struct record {
        std::array<std::size_t, 4> ids{};
        std::array<std::uint8_t, 8> lv{};
        bool proved = false;
        T c2i = 0, i2c = 0;
    };
    std::vector<record> rec;
    for (std::size_t round = 0;; ++round) {
        const std::size_t nseg = idx.size() - 1, nv = closed ? nseg : idx.size();
        if (closed) {
            level.back() = level.front();
            pos.back() = pos.front();
            moved.back() = moved.front();
        }
        const catmull_rom<D, T> curve = selection_curve(pb, pos, level);
        // Keys and proofs, reusing those whose key did not change.
        std::vector<record> next(nseg);
        std::vector<std::size_t> failed;
        std::size_t reuse = 0;
        for (std::size_t s = 0; s < nseg; ++s) {
            record r;
            for (int q = 0; q < 4; ++q) {
                const std::ptrdiff_t k = std::ptrdiff_t(s) - 1 + q;
                if (closed) {
                    const std::size_t v = std::size_t((k % std::ptrdiff_t(nv) + std::ptrdiff_t(nv)) % std::ptrdiff_t(nv));
                    r.ids[q] = idx[v], r.lv[q] = level[v], r.lv[4 + q] = moved[v];
                } else if (k >= 0 && k < std::ptrdiff_t(idx.size())) {
                    const std::size_t v = std::size_t(k);
                    r.ids[q] = idx[v], r.lv[q] = level[v], r.lv[4 + q] = moved[v];
                } else {
                    r.ids[q] = fit_none;
                }
            }
            r.ids[2] = idx[s + 1];  // unrolled: the closing segment ends at the last index
            while (reuse < rec.size() && rec[reuse].ids[1] < r.ids[1]) ++reuse;
            if (reuse < rec.size() && rec[reuse].ids == r.ids && rec[reuse].lv == r.lv) {
                next[s] = rec[reuse];
            } else {
                const std::size_t a = idx[s], b = idx[s + 1];
                const poly_range<D, T> pr{pb.pts, a >= pb.size() ? a - pb.size() : a, b - a + 1, pb.odd_middles};
                const auto res = prove_segment(curve.segment(s), pr, pb.tolerance, pb.slack);
                r.proved = res.proved;
                r.c2i = res.curve_to_input;
                r.i2c = res.input_to_curve;
                next[s] = r;
            }
            if (!next[s].proved) failed.push_back(s);
        }
        rec = std::move(next);
        if (failed.empty()) break;
        // Repairs: moved ends back; raise tension (to 0.8 on long segments,
        // to 1 on single input segments); else split at the middle input point.
        std::vector<std::size_t> insert;
        auto can_raise = [&](std::size_t v) { return closed || (v != 0 && v + 1 != idx.size()); };
        bool changed = false;
        for (std::size_t s : failed) {
            const std::size_t a = idx[s], b = idx[s + 1];
            if (moved[s] || moved[s + 1]) {
                for (std::size_t v : {s, s + 1}) {
                    pos[v] = pb.at(idx[v]);
                    moved[v] = 0;
                }
                if (closed && s + 1 == nseg) pos.front() = pos.back(), moved.front() = 0;
                if (closed && s == 0) pos.back() = pos.front(), moved.back() = 0;
                changed = true;
                continue;
            }
            const std::uint8_t cap = b - a > 1 ? 2 : fit_top_level;
            bool raised = false;
            for (std::size_t v : {s, s + 1}) {
                if (can_raise(v) && level[v] < cap) {
                    ++level[v];
                    raised = true;
                }
            }
            if (closed) {
                level.front() = std::max(level.front(), level.back());
                level.back() = level.front();
            }
            if (!raised && b - a > 1) insert.push_back(s);
            changed = changed || raised;
        }
        if (!insert.empty()) {
            std::vector<std::size_t> ni;
            std::vector<vec<D, T>> np;
            std::vector<std::uint8_t> nl, nm;
            std::size_t q = 0;
            for (std::size_t k = 0; k < idx.size(); ++k) {
                ni.push_back(idx[k]), np.push_back(pos[k]), nl.push_back(level[k]), nm.push_back(moved[k]);
                if (q < insert.size() && insert[q] == k) {
                    const std::size_t mid = idx[k] + (idx[k + 1] - idx[k]) / 2;
                    ni.push_back(mid), np.push_back(pb.at(mid)), nl.push_back(pb.base_level), nm.push_back(0);
                    ++q;
                }
            }
            idx = std::move(ni), pos = std::move(np), level = std::move(nl), moved = std::move(nm);
            changed = true;
        }
        // Every repair changes something, and each can happen only finitely
        // often; a segment that fails at its input segment with both ends
        // at tension 1 would be a broken proof.
        if (!changed) throw std::logic_error("crspline::fit: a segment at tension 1 failed its proof");
    }
    fit_selection<D, T> out;
    out.idx = std::move(idx);
    out.pos = std::move(pos);
    out.level = std::move(level);
    for (const auto& r : rec) {
        out.curve_to_input = std::max(out.curve_to_input, r.c2i);
        out.input_to_curve = std::max(out.input_to_curve, r.i2c);
    }
    return out;
}

}  // namespace crspline::detail
