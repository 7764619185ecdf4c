// tests/fit: the true minimum count of a subset fit without tension, by
// exhaustive dynamic programming over the curve's four-point windows.
//
// A segment a -> b of the curve through the chosen points depends on its
// neighbours z (before a) and c (after b): its end tangents come from them.
// The state is the last three chosen points (z, a, b); a step to c proves
// the segment a -> b with its four points (detail::fit_problem's segment,
// the formula the fit tries its candidates with, and prove_segment, the
// fit's own proof). Open lines only; the last segment is proved on arrival
// at the last point. Spans are limited to `max_span` input segments (a
// segment spanning more is not tried).
#pragma once

#include <cstddef>
#include <limits>
#include <map>
#include <tuple>
#include <vector>

#include <crspline/fit.hpp>

namespace fit_optimum {

template <std::size_t D, class T>
std::size_t optimum_count(const crspline::detail::fit_problem<D, T>& pb, std::size_t max_span) {
    using crspline::detail::fit_none;
    const std::size_t n = pb.size(), last = n - 1;
    std::map<std::tuple<std::size_t, std::size_t, std::size_t, std::size_t>, bool> memo;
    auto passes = [&](std::size_t z, std::size_t a, std::size_t b, std::size_t c) {
        const auto key = std::make_tuple(z, a, b, c);
        auto it = memo.find(key);
        if (it != memo.end()) return it->second;
        const auto seg = pb.segment(z == fit_none ? nullptr : &pb.pts[z], pb.pts[a], pb.pts[b],
                                    c == fit_none ? nullptr : &pb.pts[c], 0, 0);
        const crspline::detail::poly_range<D, T> pr{pb.pts, a, b - a + 1};
        const bool ok = crspline::detail::prove_segment(seg, pr, pb.tolerance, pb.slack).proved;
        memo.emplace(key, ok);
        return ok;
    };
    // best[(z, a, b)]: fewest points of a valid prefix ending ... z, a, b
    // (segments before a -> b proved); z = fit_none at the start.
    const std::size_t inf = std::numeric_limits<std::size_t>::max();
    std::map<std::tuple<std::size_t, std::size_t, std::size_t>, std::size_t> best;
    for (std::size_t b = 1; b <= std::min(last, max_span); ++b) best[{fit_none, 0, b}] = 2;
    std::size_t answer = inf;
    // States in order of b, then a: every predecessor state has a smaller b.
    for (std::size_t b = 1; b <= last; ++b) {
        for (std::size_t a = b > max_span ? b - max_span : 0; a < b; ++a) {
            for (std::size_t z : [&] {
                     std::vector<std::size_t> zs{fit_none};
                     for (std::size_t y = a > max_span ? a - max_span : 0; y < a; ++y) zs.push_back(y);
                     return zs;
                 }()) {
                auto it = best.find({z, a, b});
                if (it == best.end()) continue;
                const std::size_t k = it->second;
                if (b == last) {
                    if (passes(z, a, b, fit_none)) answer = std::min(answer, k);
                    continue;
                }
                for (std::size_t c = b + 1; c <= std::min(last, b + max_span); ++c) {
                    if (!passes(z, a, b, c)) continue;
                    auto& slot = best[{a, b, c}];
                    if (slot == 0 || k + 1 < slot) slot = k + 1;
                }
            }
        }
    }
    return answer;
}

}  // namespace fit_optimum
