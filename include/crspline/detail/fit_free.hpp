// crspline: fit() in free mode: the control points move off the input.
//
// 1. Breakpoints: the subset choice (and its improvement, tension levels
//    included) at the tolerance and at a relaxed one (1.1 times it; the
//    fewer points proved at the tolerance win, the subset fit itself among
//    them). Measured on the real corpus: relaxing by 1.1 saves more points
//    than by 1.2, 1.3 or 1.7 (whose moved points fail the proof more often).
//    Control point k stands for input point idx[k]; segment k covers the
//    input points idx[k] .. idx[k + 1].
// 2. Least squares: each input point gets the parameter of its nearest
//    point on its segment; then each control point in turn moves to
//    minimize the squared distances of the points its four segments cover
//    at those parameters (Gauss-Newton on the one point: the curve is
//    linear in a control point while the knots stay, its weight w_k at
//    each parameter found by moving it). Three sweeps.
// 3. Proof: prove_and_repair, which puts the ends of any failed segment
//    back on their input points and then repairs as in subset mode; so the
//    tolerance is proved as in subset mode, and a free fit has at most the
//    subset fit's repairs to fall back on.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "../nearest.hpp"
#include "fit_model.hpp"
#include "fit_subset.hpp"

namespace crspline::detail {

template <std::size_t D, class T>
class free_mover {
public:
    using point = vec<D, T>;
    free_mover(const fit_problem<D, T>& pb, const std::vector<std::size_t>& idx, std::vector<point>& pos,
               const std::vector<std::uint8_t>& level)
        : pb_(pb), idx_(idx), pos_(pos), level_(level) {
        nv_ = pb.closed ? idx.size() - 1 : idx.size();
        u_.resize(idx.back() - idx.front() + 1);
    }

    // Segment s of the current control points (the model's formula).
    cubic_segment<D, T> segment(std::size_t s) const {
        const std::size_t nseg = idx_.size() - 1;
        const point* p = nullptr;
        const point* n = nullptr;
        if (pb_.closed) {
            p = &pos_[(s + nv_ - 1) % nv_];
            n = &pos_[(s + 2) % nv_];
        } else {
            if (s > 0) p = &pos_[s - 1];
            if (s + 2 <= nseg) n = &pos_[s + 2];
        }
        const std::size_t b = s + 1 == idx_.size() - 1 && pb_.closed ? 0 : s + 1;
        return pb_.segment(p, pos_[s], pos_[b], n, level_[s], level_[b]);
    }

    // Parameters: each input point's nearest point on its segment.
    void parameterize() {
        for (std::size_t s = 0; s + 1 < idx_.size(); ++s) {
            const auto seg = segment(s);
            for (std::size_t k = idx_[s]; k < idx_[s + 1]; ++k) u_[k] = nearest(seg, pb_.at(k)).u;
        }
    }

    // Squared error of the points covered by segments [s0, s1); the curve
    // points it measures are appended to `at` where given.
    T error(std::size_t s0, std::size_t s1, std::vector<point>* at = nullptr) const {
        T e = 0;
        for (std::size_t s = s0; s < s1; ++s) {
            const auto seg = segment(s);
            for (std::size_t k = idx_[s]; k < idx_[s + 1]; ++k) {
                const point c = seg.at(u_[k]);
                if (at) at->push_back(c);
                const point d = c - pb_.at(k);
                e += dot(d, d);
            }
        }
        return e;
    }

    // One Gauss-Newton step on control point v.
    void move(std::size_t v) {
        const std::size_t nseg = idx_.size() - 1;
        // Segments that use v (open: clamped to the curve's; closed: v's four
        // neighbours in the unrolled order, without wrapping for simplicity).
        const std::size_t s0 = v >= 2 ? v - 2 : 0, s1 = std::min(nseg, v + 2);
        if (s0 >= s1) return;
        // The error and the curve points it measured (base).
        const point old = pos_[v];
        std::vector<point>& base = base_;
        base.clear();
        const T before = error(s0, s1, &base);
        const T delta = pb_.tolerance;
        point moved = old;
        moved[0] += delta;
        set(v, moved);
        T num_w[D] = {};
        T den = 0;
        std::size_t q = 0;
        for (std::size_t s = s0; s < s1; ++s) {
            const auto seg = segment(s);
            for (std::size_t k = idx_[s]; k < idx_[s + 1]; ++k, ++q) {
                const T w = (seg.at(u_[k])[0] - base[q][0]) / delta;
                const point r = pb_.at(k) - base[q];
                for (std::size_t c = 0; c < D; ++c) num_w[c] += w * r[c];
                den += w * w;
            }
        }
        if (!(den > 0)) {
            set(v, old);
            return;
        }
        point step;
        for (std::size_t c = 0; c < D; ++c) step[c] = num_w[c] / den;
        set(v, old + step);
        if (!(error(s0, s1) < before)) set(v, old);
    }

    void sweeps(int rounds) {
        for (int r = 0; r < rounds; ++r) {
            parameterize();
            const std::size_t first = pb_.closed ? 0 : 1, last = pb_.closed ? nv_ : nv_ - 1;
            for (std::size_t v = first; v < last; ++v) move(v);
        }
    }

private:
    void set(std::size_t v, const point& p) {
        pos_[v] = p;
        if (pb_.closed && v == 0) pos_.back() = p;
    }
    const fit_problem<D, T>& pb_;
    const std::vector<std::size_t>& idx_;
    std::vector<point>& pos_;
    const std::vector<std::uint8_t>& level_;
    std::size_t nv_ = 0;
    std::vector<T> u_;
    std::vector<point> base_;  // move()'s, kept for its capacity
};

template <std::size_t D, class T>
fit_selection<D, T> fit_free(const fit_problem<D, T>& pb) {
    fit_selection<D, T> best;
    for (double relax : {1.0, 1.1}) {
        fit_problem<D, T> loose = pb;
        loose.tolerance = T(double(pb.tolerance) * relax);
        const subset_search<D, T> search(loose);
        std::vector<std::size_t> idx = search.choose(2, 1);
        std::vector<std::uint8_t> level = search.initial_levels(idx.size());
        search.improve(idx, level, fit_improve_level);
        std::vector<vec<D, T>> pos;
        for (std::size_t i : idx) pos.push_back(pb.at(i));
        // At the tolerance itself the subset choice is proved as it is (the
        // free fit is never worse than the subset fit); relaxed, it moves.
        if (relax > 1 && idx.size() > 2) free_mover<D, T>(pb, idx, pos, level).sweeps(3);
        fit_selection<D, T> sel = prove_and_repair(pb, idx, std::move(pos), std::move(level));
        if (best.idx.empty() || sel.idx.size() < best.idx.size()) best = std::move(sel);
    }
    return best;
}

}  // namespace crspline::detail
