// crspline: fit() in free mode: the control points move off the input
// points, onto the middles of the input segments where that saves points.
//
// The candidates are the input points and the middle of each input segment
// (the polyline with its middles is the same polyline, up to the rounding
// of a middle, which the slack takes); the subset choice runs on them
// (fit_subset.hpp: the search, the improvement with its tension levels, the
// proof and its repairs), the middles being candidates for control points
// but not input points to prove near the curve. So the tolerance is proved
// both ways as in subset mode: every curve point near the polyline, every
// input point near the curve.
//
// Measured on the real corpus (BENCHMARKS.md, "Fit"): 6-9% fewer control
// points than subset mode. Tried and left out, each measured there: least
// squares on the points each segment covers after a choice at 1.1 to 1.7
// times the tolerance (its moved points mostly failed the proof and went
// back: 0.1% fewer points at twice the time); a pattern search on the
// largest sampled deviation (left as many segments over the tolerance as it
// brought under); candidates on a smoothed copy of the input (its corners
// cut by more than the tolerance); thirds of the segments besides middles
// (1.5% fewer points at twice the time); middles moved off their segments
// toward a smoothing of their neighbours, by up to 0.15-0.5 of the
// tolerance, the curve then proved within the tolerance less that move of
// the polyline through them (28-150% more points: the curve-to-polyline
// limit binds as much as the other).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "fit_model.hpp"
#include "fit_subset.hpp"

namespace crspline::detail {

template <std::size_t D, class T>
fit_selection<D, T> fit_free(const fit_problem<D, T>& pb, std::size_t* need, std::size_t& chosen) {
    // The candidates: each input point, then the middle of its segment.
    const std::size_t n = pb.size(), segs = pb.closed ? n : n - 1;
    std::vector<vec<D, T>> dense;
    dense.reserve(n + segs);
    T scale = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const vec<D, T>& a = pb.pts[i];
        scale = std::max(scale, max_abs(a));
        dense.push_back(a);
        if (i < segs) dense.push_back(a + T(0.5) * (pb.at(i + 1) - a));
    }
    fit_problem<D, T> dp = pb;
    dp.pts = std::span<const vec<D, T>>(dense);
    dp.odd_middles = true;
    // A rounded middle is off its segment by at most half an ulp of each
    // coordinate: D ulps of the largest coordinate bound its distance, so
    // the proofs against the polyline with its middles, that much stricter,
    // hold for the input polyline.
    dp.slack = pb.slack + T(D) * std::numeric_limits<T>::epsilon() * scale;
    return fit_subset(dp, need, chosen);
}

}  // namespace crspline::detail
